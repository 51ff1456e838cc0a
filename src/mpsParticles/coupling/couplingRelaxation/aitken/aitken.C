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

#include "aitken.H"
#include "addToRunTimeSelectionTable.H"
#include "inputChecks.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace couplingRelaxations
{
    defineTypeNameAndDebug(aitken, 0);
    addToRunTimeSelectionTable(couplingRelaxation, aitken, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::couplingRelaxations::aitken::aitken(const dictionary& dict)
:
    couplingRelaxation(dict),
    omega_(initial_),
    rOld_(),
    first_(true)
{
    inputChecks::keywords(dict, {"type", "initial"}, "relaxation aitken");
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::couplingRelaxations::aitken::beginStep()
{
    omega_ = initial_;
    first_ = true;
}


void Foam::couplingRelaxations::aitken::update
(
    UList<vector2D>& x,
    const UList<vector2D>& r
)
{
    if (!first_)
    {
        scalar num = 0, den = 0;
        forAll(r, k)
        {
            const vector2D dr(r[k] - rOld_[k]);
            num += rOld_[k] & dr;
            den += magSqr(dr);
        }
        if (den > 0)
        {
            omega_ = -omega_*num/den;
        }
    }
    forAll(x, k)
    {
        x[k] += omega_*r[k];
    }
    rOld_ = r;
    first_ = false;
}


// ************************************************************************* //
