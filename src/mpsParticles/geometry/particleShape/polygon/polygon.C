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

#include "polygon.H"
#include "addToRunTimeSelectionTable.H"
#include "inputChecks.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace particleShapes
{
    defineTypeNameAndDebug(polygon, 0);
    addToRunTimeSelectionTable(particleShape, polygon, dictionary);
}
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

bool Foam::particleShapes::polygon::inside(const vector2D& p) const
{
    bool in = false;
    const label n = points_.size();
    for (label i = 0, j = n - 1; i < n; j = i++)
    {
        const vector2D& a = points_[i];
        const vector2D& b = points_[j];
        if
        (
            (a.y() > p.y()) != (b.y() > p.y())
         && p.x() < (b.x() - a.x())*(p.y() - a.y())/(b.y() - a.y()) + a.x()
        )
        {
            in = !in;
        }
    }
    return in;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::particleShapes::polygon::polygon(const dictionary& dict)
:
    particleShape(dict),
    points_(dict.get<List<vector2D>>("points")),
    origin_(dict.getOrDefault<vector2D>("origin", vector2D::zero))
{
    inputChecks::keywords
    (
        dict,
        {"type", "kind", "spacing", "points", "origin"},
        "region " + dict.dictName()
    );
    if (points_.size() < 3)
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'points' needs at least 3 vertices, got "
            << points_.size() << exit(FatalIOError);
    }

    // A simple outline: no two edges that do not share a vertex cross
    // (the even-odd fill of a self-intersecting one is not what was meant)
    const label n = points_.size();
    auto cross = [](const vector2D& a, const vector2D& b)
    {
        return a.x()*b.y() - a.y()*b.x();
    };
    for (label i = 0; i < n; ++i)
    {
        const vector2D& a = points_[i];
        const vector2D& b = points_[(i + 1) % n];
        for (label j = i + 2; j < n; ++j)
        {
            if (i == 0 && j == n - 1)
            {
                continue;
            }
            const vector2D& c = points_[j];
            const vector2D& d = points_[(j + 1) % n];
            const scalar d1 = cross(b - a, c - a), d2 = cross(b - a, d - a);
            const scalar d3 = cross(d - c, a - c), d4 = cross(d - c, b - c);
            if (d1*d2 < 0 && d3*d4 < 0)
            {
                FatalIOErrorInFunction(dict)
                    << "Entry 'points' of region " << dict.dictName()
                    << ": the outline crosses itself (edge " << a << " to "
                    << b << " and edge " << c << " to " << d << "); give"
                    << " the vertices in order around the shape"
                    << exit(FatalIOError);
            }
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::particleShapes::polygon::estimatedCount
(
    const scalar spacing
) const
{
    // The bounding box of the outline, one spacing larger on each side
    vector2D lo(points_[0]), hi(points_[0]);
    for (const vector2D& p : points_)
    {
        lo = min(lo, p);
        hi = max(hi, p);
    }
    const vector2D span(hi - lo);
    return (span.x()/spacing + 2)*(span.y()/spacing + 2);
}


void Foam::particleShapes::polygon::generate
(
    const scalar spacing,
    DynamicList<vector2D>& points,
    DynamicList<label>& layers
) const
{
    vector2D lo(GREAT, GREAT);
    vector2D hi(-GREAT, -GREAT);
    for (const vector2D& p : points_)
    {
        lo = min(lo, p);
        hi = max(hi, p);
    }

    const label i0 = label(std::floor((lo.x() - origin_.x())/spacing)) - 1;
    const label i1 = label(std::ceil((hi.x() - origin_.x())/spacing)) + 1;
    const label j0 = label(std::floor((lo.y() - origin_.y())/spacing)) - 1;
    const label j1 = label(std::ceil((hi.y() - origin_.y())/spacing)) + 1;

    for (label j = j0; j <= j1; ++j)
    {
        for (label i = i0; i <= i1; ++i)
        {
            const vector2D p(origin_ + spacing*vector2D(i + 0.5, j + 0.5));
            if (inside(p))
            {
                points.append(p);
                layers.append(0);
            }
        }
    }
}


// ************************************************************************* //
