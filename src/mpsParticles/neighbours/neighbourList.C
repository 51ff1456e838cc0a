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

#include "neighbourList.H"
#include "rowChunks.H"
#include "DynamicList.H"
#include "mathematicalConstants.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::neighbourList::neighbourList()
:
    radius_(0),
    offsets_(1, Zero),
    neighbours_(),
    cells_(),
    buffers_()
{}


Foam::neighbourList::neighbourList
(
    const UList<vector2D>& x,
    const scalar radius
)
:
    neighbourList()
{
    build(x, radius);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::neighbourList::build
(
    const UList<vector2D>& x,
    const scalar radius
)
{
    cells_.buildForRadius(x, radius);
    build(x, cells_, radius);
}


void Foam::neighbourList::build
(
    const UList<vector2D>& x,
    const scalar radius,
    const label nActive
)
{
    if (nActive >= x.size())
    {
        build(x, radius);
        return;
    }
    const SubList<vector2D> active(x, nActive);
    cells_.buildForRadius(active, radius);
    build(active, cells_, radius);
    const label nPairs = offsets_[nActive];
    offsets_.setSize(x.size() + 1, nPairs);
}


template<class AppendNeighbours>
void Foam::neighbourList::fill
(
    const label nPoints,
    const label nExpected,
    const AppendNeighbours& appendNeighbours
)
{
    offsets_.setSize(nPoints + 1);
    offsets_[0] = 0;

    // Blocks of points, each filled into its own buffer, the blocks joined
    // in order; each thread fills its own range of blocks first, the rows
    // the fluid step's loops give it (rowChunks), then helps with the
    // others' (rows cost what their neighbours do: fluid inside, at the
    // surface, walls)
    const label blockSize = 1024;
    rowChunks blocks(nPoints, blockSize);
    rowChunks joins(nPoints, blockSize);
    const label nBlocks = blocks.nChunks();
    if (buffers_.size() < nBlocks)
    {
        buffers_.setSize(nBlocks);
    }
    labelList blockStart(nBlocks + 1);

    #pragma omp parallel
    {
        blocks.forEachChunk([&](const label first, const label last)
        {
            // Work on a local list (its size is written at every append:
            // in buffers_ the lists of two threads would share a cache
            // line)
            const label b = first/blockSize;
            DynamicList<label> nbrs;
            nbrs.transfer(buffers_[b]);
            nbrs.clear();
            nbrs.reserve(nExpected*(last - first));
            for (label i = first; i < last; ++i)
            {
                appendNeighbours(i, nbrs);
                offsets_[i + 1] = nbrs.size();
            }
            buffers_[b].transfer(nbrs);
        });

        #pragma omp barrier
        #pragma omp single
        {
            blockStart[0] = 0;
            for (label b = 0; b < nBlocks; ++b)
            {
                blockStart[b + 1] = blockStart[b] + buffers_[b].size();
            }
            neighbours_.setSize(blockStart[nBlocks]);
        }

        // Shift each block's offsets and copy its neighbours in place
        joins.forEachChunk([&](const label first, const label last)
        {
            const label b = first/blockSize;
            const label shift = blockStart[b];
            for (label i = first; i < last; ++i)
            {
                offsets_[i + 1] += shift;
            }
            std::copy
            (
                buffers_[b].cbegin(),
                buffers_[b].cend(),
                neighbours_.begin() + shift
            );
        });
    }
}


void Foam::neighbourList::build
(
    const UList<vector2D>& x,
    const cellLinkedList& cells,
    const scalar radius
)
{
    radius_ = radius;
    const label nPoints = x.size();
    const scalar r2 = radius*radius;

    // Cells to visit on each side: radius may exceed the cell size
    const label reach = label(std::ceil(radius/cells.cellSize() - SMALL));
    const labelList& order = cells.order();
    const List<vector2D>& sorted = cells.sorted();

    // Expected neighbours per point: the points' mean density times the
    // area of the search circle
    const scalar area =
        max(scalar(cells.nx()*cells.ny()), scalar(1))*sqr(cells.cellSize());
    const label nExpected =
        label(1.3*constant::mathematical::pi*r2*nPoints/area) + 8;

    fill
    (
        nPoints,
        nExpected,
        [&](const label i, DynamicList<label>& nbrs)
        {
            const vector2D& xi = x[i];
            label ix, iy;
            cells.cellOf(xi, ix, iy);

            const label jx0 = max(ix - reach, label(0));
            const label jx1 = min(ix + reach, cells.nx() - 1);
            const label jy0 = max(iy - reach, label(0));
            const label jy1 = min(iy + reach, cells.ny() - 1);

            const label start = nbrs.size();
            for (label jy = jy0; jy <= jy1; ++jy)
            {
                // Cells of one row are contiguous in order()
                const label kEnd = cells.cellEnd(jx1, jy);
                for (label k = cells.cellBegin(jx0, jy); k < kEnd; ++k)
                {
                    const scalar dx = sorted[k].x() - xi.x();
                    const scalar dy = sorted[k].y() - xi.y();
                    if (dx*dx + dy*dy < r2 && order[k] != i)
                    {
                        nbrs.append(order[k]);
                    }
                }
            }
            // In index order: the list does not depend on the cells (a
            // list filtered from a larger one is the same list); an
            // insertion sort, the row being found in runs already in order
            // (each cell's points in index order)
            label* a = nbrs.data();
            for (label m = start + 1; m < nbrs.size(); ++m)
            {
                const label v = a[m];
                label l = m - 1;
                while (l >= start && a[l] > v)
                {
                    a[l + 1] = a[l];
                    --l;
                }
                a[l + 1] = v;
            }
        }
    );
}


void Foam::neighbourList::filter
(
    const neighbourList& candidates,
    const UList<vector2D>& x,
    const scalar radius
)
{
    radius_ = radius;
    const scalar r2 = radius*radius;
    const labelList& offsets = candidates.offsets();
    const labelList& nbr = candidates.neighbours();
    const label nPoints = candidates.size();
    const label nExpected =
        nPoints
      ? label(1.1*sqr(radius/candidates.radius())*nbr.size()/nPoints) + 8
      : 0;

    fill
    (
        nPoints,
        nExpected,
        [&](const label i, DynamicList<label>& nbrs)
        {
            // Each candidate written, kept where it is close enough (no
            // branch: a candidate near the radius is as likely in as out)
            const vector2D& xi = x[i];
            label m = nbrs.size();
            nbrs.setSize(m + offsets[i + 1] - offsets[i]);
            for (label k = offsets[i]; k < offsets[i + 1]; ++k)
            {
                const label j = nbr[k];
                const scalar dx = x[j].x() - xi.x();
                const scalar dy = x[j].y() - xi.y();
                nbrs[m] = j;
                m += (dx*dx + dy*dy < r2);
            }
            nbrs.setSize(m);
        }
    );
}


// ************************************************************************* //
