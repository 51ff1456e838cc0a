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

#include "continuousWalls.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace ppeSurfaceConditions
{
    defineTypeNameAndDebug(continuousWalls, 0);
    addToRunTimeSelectionTable(ppeSurfaceCondition, continuousWalls, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::ppeSurfaceConditions::continuousWalls::continuousWalls(const dictionary& dict)
:
    ppeSurfaceCondition(dict)
{}


// ************************************************************************* //
