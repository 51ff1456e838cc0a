/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | mpsFsiFoam: MPS hydroelastic slamming
   \\    /   O peration     | built on OpenFOAM v1912
    \\  /    A nd           |
     \\/     M anipulation  |
-------------------------------------------------------------------------------
License
    This file is part of mpsFsiFoam, distributed under the GNU General Public
    License version 3 or later, as OpenFOAM is.

\*---------------------------------------------------------------------------*/

#include "none.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace couplingSchemes
{
    defineTypeNameAndDebug(none, 0);
    addToRunTimeSelectionTable(couplingScheme, none, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::couplingSchemes::none::none
(
    const dictionary& dict,
    mpsFluid& fluid,
    mpsStructure& structure,
    fluidStructureInterface& interface
)
:
    couplingScheme(dict, fluid, structure, interface)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

const Foam::mpsFluid::stepInfo& Foam::couplingSchemes::none::evolve
(
    const scalar t,
    const scalar deltaT
)
{
    const mpsFluid::stepInfo& info = fluid_.step(deltaT);
    if (info.finite)
    {
        advanceStructure(structure_, t, deltaT, UList<vector2D>());
    }
    return info;
}


// ************************************************************************* //
