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

#include "cellLinkedList.H"
#include "error.H"

#include <algorithm>

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::cellLinkedList::cellLinkedList()
:
    h_(1),
    origin_(vector2D::zero),
    nx_(0),
    ny_(0),
    cellStart_(1, Zero),
    order_(),
    sorted_(),
    cellOfPoint_(),
    fill_()
{}


Foam::cellLinkedList::cellLinkedList
(
    const UList<vector2D>& x,
    const scalar cellSize
)
:
    cellLinkedList()
{
    build(x, cellSize);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::cellLinkedList::bounds
(
    const UList<vector2D>& x,
    vector2D& lo,
    vector2D& hi
)
{
    scalar xLo = GREAT, yLo = GREAT, xHi = -GREAT, yHi = -GREAT;
    #pragma omp parallel for schedule(static) \
        reduction(min:xLo, yLo) reduction(max:xHi, yHi)
    for (label i = 0; i < x.size(); ++i)
    {
        xLo = std::min(xLo, x[i].x());
        yLo = std::min(yLo, x[i].y());
        xHi = std::max(xHi, x[i].x());
        yHi = std::max(yHi, x[i].y());
    }
    lo = vector2D(xLo, yLo);
    hi = vector2D(xHi, yHi);
    if (x.empty())
    {
        lo = hi = vector2D::zero;
    }
}


void Foam::cellLinkedList::build
(
    const UList<vector2D>& x,
    const scalar cellSize
)
{
    vector2D lo, hi;
    bounds(x, lo, hi);
    build(x, cellSize, lo, hi);
}


void Foam::cellLinkedList::buildForRadius
(
    const UList<vector2D>& x,
    const scalar radius
)
{
    vector2D lo, hi;
    bounds(x, lo, hi);
    const scalar half = 0.5*radius;
    const scalar nHalf =
        (std::floor((hi.x() - lo.x())/half) + 1)
       *(std::floor((hi.y() - lo.y())/half) + 1);
    build(x, nHalf <= 2.0*x.size() + 64 ? half : radius, lo, hi);
}


void Foam::cellLinkedList::build
(
    const UList<vector2D>& x,
    const scalar cellSize,
    const vector2D& lo,
    const vector2D& hi
)
{
    if (!(cellSize > 0))
    {
        FatalErrorInFunction
            << "Cell size must be positive, got " << cellSize
            << exit(FatalError);
    }

    h_ = cellSize;
    origin_ = lo;

    // Count the cells in floating point first: far-flung points would
    // overflow a label
    const scalar nxs = std::floor((hi.x() - lo.x())/h_) + 1;
    const scalar nys = std::floor((hi.y() - lo.y())/h_) + 1;
    if (!(nxs*nys <= 100.0*x.size() + 1e6))
    {
        FatalErrorInFunction
            << "Cell-linked list of " << nxs << " x " << nys
            << " cells for " << x.size() << " points: are the points spread"
            << " over " << hi - lo << " with a cell size of " << h_ << '?'
            << exit(FatalError);
    }
    nx_ = label(nxs);
    ny_ = label(nys);
    const label nCells = nx_*ny_;

    // Counting sort of the points by cell
    labelList& cellOfPoint = cellOfPoint_;
    cellOfPoint.setSize(x.size());
    cellStart_.setSize(nCells + 1);
    cellStart_ = 0;

    #pragma omp parallel for schedule(static)
    for (label i = 0; i < x.size(); ++i)
    {
        label ix, iy;
        cellOf(x[i], ix, iy);
        cellOfPoint[i] = iy*nx_ + ix;
    }
    forAll(x, i)
    {
        ++cellStart_[cellOfPoint[i] + 1];
    }
    for (label c = 0; c < nCells; ++c)
    {
        cellStart_[c + 1] += cellStart_[c];
    }

    order_.setSize(x.size());
    labelList& fill = fill_;
    fill = SubList<label>(cellStart_, nCells);
    forAll(x, i)
    {
        order_[fill[cellOfPoint[i]]++] = i;
    }

    sorted_.setSize(x.size());
    #pragma omp parallel for schedule(static)
    for (label k = 0; k < order_.size(); ++k)
    {
        sorted_[k] = x[order_[k]];
    }
}


// ************************************************************************* //
