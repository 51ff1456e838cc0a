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

#include "free.H"
#include "addToRunTimeSelectionTable.H"
#include "inputChecks.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace bodyMotions
{
    defineTypeNameAndDebug(free, 0);
    addToRunTimeSelectionTable(bodyMotion, free, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::bodyMotions::free::free(const dictionary& dict, const scalar t0)
:
    bodyMotion(dict, t0),
    mass_(inputChecks::number<scalar>(dict, "mass", "> 0")),
    g_(dict.getOrDefault<vector2D>("g", vector2D::zero))
{
    inputChecks::keywords
    (
        dict,
        {"type", "mass", "initialVelocity", "g"},
        "bodyMotion free"
    );
    U_ = dict.get<vector2D>("initialVelocity");
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::bodyMotions::free::update
(
    const scalar,
    const scalar dt,
    const vector2D& F
)
{
    U_ += dt*(F/mass_ + g_);
}


// ************************************************************************* //
