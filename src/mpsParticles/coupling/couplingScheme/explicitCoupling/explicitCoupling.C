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

#include "explicitCoupling.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace couplingSchemes
{
    defineTypeNameAndDebug(explicitCoupling, 0);
    addToRunTimeSelectionTable(couplingScheme, explicitCoupling, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::couplingSchemes::explicitCoupling::explicitCoupling
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

const Foam::mpsFluid::stepInfo&
Foam::couplingSchemes::explicitCoupling::evolve
(
    const scalar t,
    const scalar deltaT
)
{
    const mpsFluid::stepInfo& info = fluid_.step(deltaT);
    if (info.finite)
    {
        interface_.transferPressure(fluid_);
        advanceStructure(structure_, t, deltaT, interface_.force());
        interface_.moveWalls();
    }
    return info;
}


// ************************************************************************* //
