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

#include "neighbourSearch.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

bool Foam::neighbourSearch::valid
(
    const UList<vector2D>& x,
    const label nActive,
    const label revision,
    const scalar radius
) const
{
    if
    (
        revision != revision_ || x.size() != size_ || nActive != nActive_
     || radius > radius_
    )
    {
        return false;
    }

    // Each of two points may have moved by half the slack
    const scalar limit2 = sqr(0.5*(radius_ + skin_ - radius));
    scalar largest2 = 0;

    #pragma omp parallel for schedule(static) reduction(max:largest2)
    for (label i = 0; i < nActive; ++i)
    {
        largest2 = max(largest2, magSqr(x[i] - xRef_[i]));
    }
    return largest2 < limit2;
}


void Foam::neighbourSearch::build
(
    const UList<vector2D>& x,
    const label nActive,
    const label revision
)
{
    ++nBuilds_;
    candidates_.build(x, radius_ + skin_, nActive);
    xRef_ = SubList<vector2D>(x, min(nActive, x.size()));
    size_ = x.size();
    nActive_ = nActive;
    revision_ = revision;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::neighbourSearch::neighbourSearch(const scalar radius, const scalar skin)
:
    radius_(radius),
    skin_(skin),
    candidates_(),
    xRef_(),
    size_(0),
    nActive_(0),
    revision_(-1),
    nBuilds_(0),
    nSearches_(0)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

const Foam::neighbourList& Foam::neighbourSearch::candidates
(
    const UList<vector2D>& x,
    const label nActive,
    const label revision
)
{
    ++nSearches_;
    if (skin_ <= 0 || !valid(x, nActive, revision, radius_))
    {
        build(x, nActive, revision);
    }
    return candidates_;
}


void Foam::neighbourSearch::find
(
    const UList<vector2D>& x,
    const label nActive,
    const label revision,
    const scalar radius,
    neighbourList& result
)
{
    ++nSearches_;
    if (skin_ <= 0)
    {
        ++nBuilds_;
        result.build(x, radius, nActive);
        return;
    }
    if (!valid(x, nActive, revision, radius))
    {
        build(x, nActive, revision);
    }
    result.filter(candidates_, x, radius);
}


// ************************************************************************* //
