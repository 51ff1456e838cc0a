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

#include "couplingScheme.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(couplingScheme, 0);
    defineRunTimeSelectionTable(couplingScheme, dictionary);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::couplingScheme::couplingScheme
(
    const dictionary& dict,
    mpsFluid& fluid,
    mpsStructure& structure,
    fluidStructureInterface& interface
)
:
    dict_(dict),
    fluid_(fluid),
    structure_(structure),
    interface_(interface)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::couplingScheme::advanceStructure
(
    mpsStructure& structure,
    const scalar t,
    const scalar deltaT,
    const UList<vector2D>& force
)
{
    if (structure.beginStep(t, deltaT, force))
    {
        for (label s = 0; s < structure.nSubSteps(); ++s)
        {
            structure.subStep();
        }
        structure.endStep(t);
    }
}


// ************************************************************************* //
