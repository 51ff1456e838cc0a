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

#include "prescribed.H"
#include "addToRunTimeSelectionTable.H"
#include "inputChecks.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace bodyMotions
{
    defineTypeNameAndDebug(prescribed, 0);
    addToRunTimeSelectionTable(bodyMotion, prescribed, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::bodyMotions::prescribed::prescribed
(
    const dictionary& dict,
    const scalar t0
)
:
    bodyMotion(dict, t0),
    velocity_(Function1<vector>::New("velocity", dict))
{
    inputChecks::keywords
    (
        dict,
        {"type", "velocity", "velocityCoeffs"},
        "bodyMotion prescribed"
    );
    const vector U(velocity_->value(t0));
    U_ = vector2D(U.x(), U.y());
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::bodyMotions::prescribed::update
(
    const scalar t,
    const scalar dt,
    const vector2D&
)
{
    const vector U(velocity_->value(t - 0.5*dt));
    U_ = vector2D(U.x(), U.y());
}


// ************************************************************************* //
