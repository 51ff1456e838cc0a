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
#include "inputChecks.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace collisionModels
{
    defineTypeNameAndDebug(none, 0);
    addToRunTimeSelectionTable(collisionModel, none, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::collisionModels::none::none(const dictionary& dict)
:
    collisionModel(dict)
{
    inputChecks::keywords
    (
        dict,
        {"type"},
        "collision none"
    );
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::collisionModels::none::correct
(
    const mpsCloud& cloud,
    const neighbourList& nbrs,
    const scalar l0,
    const scalar dt,
    UList<vector2D>& x,
    UList<vector2D>& U
) const
{
    return 0;
}


// ************************************************************************* //
