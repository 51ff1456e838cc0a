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
    if (points_.size() < 3)
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'points' needs at least 3 vertices, got "
            << points_.size() << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

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
