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
namespace particleShiftings
{
    defineTypeNameAndDebug(none, 0);
    addToRunTimeSelectionTable(particleShifting, none, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::particleShiftings::none::none(const dictionary& dict)
:
    particleShifting(dict)
{
    inputChecks::keywords
    (
        dict,
        {"type"},
        "shifting none"
    );
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::particleShiftings::none::shift
(
    mpsCloud&,
    const neighbourList&,
    const scalar,
    const scalar,
    const scalar
) const
{
    return 0;
}


// ************************************************************************* //
