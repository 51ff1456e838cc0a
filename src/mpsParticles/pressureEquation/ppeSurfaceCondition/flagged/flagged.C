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

#include "flagged.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace ppeSurfaceConditions
{
    defineTypeNameAndDebug(flagged, 0);
    addToRunTimeSelectionTable(ppeSurfaceCondition, flagged, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::ppeSurfaceConditions::flagged::flagged(const dictionary& dict)
:
    ppeSurfaceCondition(dict)
{
    if (dict.getOrDefault<bool>("fillVoids", false))
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'fillVoids' needs surfaceCondition continuous,"
            << " extrapolated or continuousWalls (flagged sets the"
            << " particles short of neighbours to p = 0)"
            << exit(FatalIOError);
    }
}


// ************************************************************************* //
