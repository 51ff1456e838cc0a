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

#include "strip.H"
#include "addToRunTimeSelectionTable.H"
#include "inputChecks.H"
#include "mathematicalConstants.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace particleShapes
{
    defineTypeNameAndDebug(strip, 0);
    addToRunTimeSelectionTable(particleShape, strip, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::particleShapes::strip::strip(const dictionary& dict)
:
    particleShape(dict),
    points_(),
    side_(1),
    layers_(-1),
    thickness_(0),
    offset_(dict.getOrDefault<scalar>("offset", 0))
{
    inputChecks::keywords
    (
        dict,
        {
            "type", "kind", "spacing", "dummyLayers", "points", "start",
            "angle", "length", "side", "layers", "thickness", "offset"
        },
        "region " + dict.dictName()
    );
    inputChecks::exclusive(dict, {"points", "start"});
    inputChecks::exclusive(dict, {"layers", "thickness"});
    if (dict.found("points"))
    {
        dict.readEntry("points", points_);
    }
    else if (dict.found("start"))
    {
        const vector2D start(dict.get<vector2D>("start"));
        const scalar angle =
            dict.get<scalar>("angle")*constant::mathematical::pi/180;
        const scalar length = dict.get<scalar>("length");
        if (!(length > 0))
        {
            FatalIOErrorInFunction(dict)
                << "Entry 'length' must be positive, got " << length
                << exit(FatalIOError);
        }
        points_.setSize(2);
        points_[0] = start;
        points_[1] = start + length*vector2D(::cos(angle), ::sin(angle));
    }
    else
    {
        FatalIOErrorInFunction(dict)
            << "A strip needs either 'points' (a polyline) or 'start',"
            << " 'angle' (degrees) and 'length'" << exit(FatalIOError);
    }

    if (points_.size() < 2)
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'points' needs at least 2 vertices, got "
            << points_.size() << exit(FatalIOError);
    }
    for (label i = 1; i < points_.size(); ++i)
    {
        if (mag(points_[i] - points_[i-1]) < VSMALL)
        {
            FatalIOErrorInFunction(dict)
                << "Entry 'points' has a segment of zero length at vertex "
                << i << exit(FatalIOError);
        }
    }

    const word side(dict.getOrDefault<word>("side", "left"));
    if (side == "left")
    {
        side_ = 1;
    }
    else if (side == "right")
    {
        side_ = -1;
    }
    else
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'side' is " << side << "; valid: left right"
            << exit(FatalIOError);
    }

    if (dict.found("layers"))
    {
        layers_ = dict.get<label>("layers");
        if (layers_ < 1)
        {
            FatalIOErrorInFunction(dict)
                << "Entry 'layers' must be at least 1, got " << layers_
                << exit(FatalIOError);
        }
    }
    else if (dict.found("thickness"))
    {
        thickness_ = dict.get<scalar>("thickness");
        if (!(thickness_ > 0))
        {
            FatalIOErrorInFunction(dict)
                << "Entry 'thickness' must be positive, got " << thickness_
                << exit(FatalIOError);
        }
    }
    else
    {
        FatalIOErrorInFunction(dict)
            << "A strip needs 'layers' (a count) or 'thickness' (a length)"
            << exit(FatalIOError);
    }

}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::particleShapes::strip::nLayers(const scalar spacing) const
{
    if (layers_ > 0)
    {
        return layers_;
    }
    return max(label(1), label(std::round(thickness_/spacing)));
}


Foam::scalar Foam::particleShapes::strip::estimatedCount
(
    const scalar spacing
) const
{
    // Each segment and its corner extensions, times the layers
    const scalar depth = offset_ + nLayers(spacing)*spacing;
    scalar n = 0;
    for (label segi = 0; segi + 1 < points_.size(); ++segi)
    {
        n += (mag(points_[segi + 1] - points_[segi]) + 2*mag(depth))/spacing
          + 1;
    }
    return n*nLayers(spacing);
}


void Foam::particleShapes::strip::generate
(
    const scalar spacing,
    DynamicList<vector2D>& points,
    DynamicList<label>& layers
) const
{
    const label nLayer = nLayers(spacing);
    const scalar depth = offset_ + nLayer*spacing;
    const label nSeg = points_.size() - 1;

    for (label segi = 0; segi < nSeg; ++segi)
    {
        const vector2D a(points_[segi]);
        const vector2D b(points_[segi + 1]);
        const scalar length = mag(b - a);
        const vector2D t((b - a)/length);
        const vector2D nrm(side_*vector2D(-t.y(), t.x()));

        // Continue past a joint whose outer (convex) side has the layers
        auto convex = [&](const vector2D& t0, const vector2D& t1)
        {
            const scalar cross = t0.x()*t1.y() - t0.y()*t1.x();
            return side_*cross < -SMALL;
        };

        scalar sBegin = 0;
        scalar sEnd = length;
        if (segi > 0)
        {
            const vector2D t0(points_[segi] - points_[segi - 1]);
            if (convex(t0/mag(t0), t))
            {
                sBegin = -depth;
            }
        }
        if (segi < nSeg - 1)
        {
            const vector2D t1(points_[segi + 2] - points_[segi + 1]);
            if (convex(t, t1/mag(t1)))
            {
                sEnd = length + depth;
            }
        }

        const label n = max(label(1), label(std::round(length/spacing)));
        const scalar ds = length/n;
        const label iBegin = -label(std::round(-sBegin/ds));
        const label iEnd = n + label(std::round((sEnd - length)/ds));

        for (label k = 0; k < nLayer; ++k)
        {
            const scalar d = offset_ + (k + 0.5)*spacing;
            for (label i = iBegin; i < iEnd; ++i)
            {
                // Past a joint the layer is the distance from the corner
                const label past = (i < 0 ? -i - 1 : (i >= n ? i - n : -1));
                points.append(a + ((i + 0.5)*ds)*t + d*nrm);
                layers.append(max(k, past));
            }
        }
    }
}


// ************************************************************************* //
