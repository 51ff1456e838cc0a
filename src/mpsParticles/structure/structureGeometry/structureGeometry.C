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

#include "structureGeometry.H"
#include "structureModel.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::structureGeometry::structureGeometry
(
    const List<vector2D>& X,
    const scalar ds
)
:
    X_(X),
    ds_(ds),
    nbrs_(X, 1.5*ds),
    tangent_(X.size(), vector2D(1, 0))
{
    forAll(X_, s)
    {
        scalar cxx = 0, cxy = 0, cyy = 0;
        for (label e = nbrs_.offsets()[s]; e < nbrs_.offsets()[s + 1]; ++e)
        {
            const vector2D d(X_[nbrs_.neighbours()[e]] - X_[s]);
            cxx += d.x()*d.x();
            cxy += d.x()*d.y();
            cyy += d.y()*d.y();
        }
        tangent_[s] = structureModel::principalAxis(cxx, cxy, cyy);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::structureGeometry::onFace(const label s, const vector2D& n) const
{
    for (label e = nbrs_.offsets()[s]; e < nbrs_.offsets()[s + 1]; ++e)
    {
        if (((X_[nbrs_.neighbours()[e]] - X_[s]) & n) > 0.5*ds_)
        {
            return false;
        }
    }
    return true;
}


Foam::labelList Foam::structureGeometry::surfaceLayer
(
    const labelList& particles,
    const vector2D& n
) const
{
    DynamicList<label> layer;
    for (const label s : particles)
    {
        if (onFace(s, n))
        {
            layer.append(s);
        }
    }
    return labelList(std::move(layer));
}


Foam::vector2D Foam::structureGeometry::axis
(
    const labelList& particles,
    const vector2D& end
) const
{
    vector2D mean(Zero);
    for (const label i : particles)
    {
        mean += X_[i];
    }
    mean /= max(particles.size(), label(1));
    scalar xx = 0, xy = 0, yy = 0;
    for (const label i : particles)
    {
        const vector2D d(X_[i] - mean);
        xx += d.x()*d.x();
        xy += d.x()*d.y();
        yy += d.y()*d.y();
    }
    vector2D a(structureModel::principalAxis(xx, xy, yy));
    if (((mean - end) & a) < 0)
    {
        a = -a;
    }
    return a;
}


bool Foam::structureGeometry::straddle
(
    const labelList& face,
    const vector2D& end,
    const vector2D& axis,
    const scalar d,
    label& a,
    label& b,
    scalar& weight
) const
{
    a = b = -1;
    scalar below = -GREAT, above = GREAT;
    for (const label k : face)
    {
        const scalar sk = ((X_[k] - end) & axis) - d;
        if (sk <= 0 && sk > below)
        {
            below = sk;
            a = k;
        }
        if (sk > 0 && sk < above)
        {
            above = sk;
            b = k;
        }
    }
    if (a < 0 || b < 0 || above - below > 2*ds_)
    {
        return false;
    }
    weight = -below/(above - below);
    return true;
}


// ************************************************************************* //
