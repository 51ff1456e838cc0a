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

#include "mpsDecomposition.H"
#include "boundBox.H"
#include "Pstream.H"
#include "PstreamBuffers.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::mpsDecomposition::binRange
(
    const scalar a,
    const scalar b,
    const scalar origin,
    const label n,
    label& lo,
    label& hi
) const
{
    lo = max(label(0), label(floor((a - origin)/binSize_)));
    hi = min(n - 1, label(floor((b - origin)/binSize_)));
}


Foam::List<Foam::labelList> Foam::mpsDecomposition::exchange
(
    mpsCloud& cloud,
    const List<DynamicList<label>>& sendLists,
    const UList<bool>& keep
)
{
    PstreamBuffers buffers(Pstream::commsTypes::nonBlocking);
    forAll(sendLists, proci)
    {
        if (proci != Pstream::myProcNo() && sendLists[proci].size())
        {
            UOPstream os(proci, buffers);
            cloud.send(sendLists[proci], os);
        }
    }
    if (keep.found(false))
    {
        cloud.subset(keep);
    }

    labelList recvSizes;
    buffers.finishedSends(recvSizes);

    List<labelList> received(Pstream::nProcs());
    forAll(recvSizes, proci)
    {
        if (proci != Pstream::myProcNo() && recvSizes[proci])
        {
            UIPstream is(proci, buffers);
            received[proci] = cloud.receive(is);
        }
    }
    return received;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::mpsDecomposition::mpsDecomposition
(
    const polyMesh& mesh,
    const scalar haloWidth
)
:
    haloWidth_(haloWidth),
    x0_(0),
    y0_(0),
    binSize_(1),
    nx_(0),
    ny_(0)
{
    // This rank's cells as boxes; each must be one (the ownership rule)
    const labelListList& cellPoints = mesh.cellPoints();
    const scalarField& V = mesh.cellVolumes();
    List<List<box>> rankBoxes(Pstream::nProcs());
    List<box>& mine = rankBoxes[Pstream::myProcNo()];
    mine.setSize(mesh.nCells());
    forAll(cellPoints, celli)
    {
        const boundBox bb(mesh.points(), cellPoints[celli], false);
        if (mag(V[celli] - bb.volume()) > 1e-6*bb.volume())
        {
            FatalErrorInFunction
                << "Cell " << celli << " of the background mesh "
                << mesh.objectRegistry::objectPath()
                << " is not an axis-aligned box (volume " << V[celli]
                << ", its bounding box's " << bb.volume() << "): under"
                << " -parallel a particle's rank is found from the cells'"
                << " boxes. Make the background mesh of axis-aligned hex"
                << " blocks (blockMesh, no curved edges)" << exit(FatalError);
        }
        mine[celli] = box({bb.min().x(), bb.min().y(), bb.max().x(),
            bb.max().y()});
    }
    Pstream::gatherList(rankBoxes);
    Pstream::scatterList(rankBoxes);

    label nBoxes = 0;
    for (const List<box>& b : rankBoxes)
    {
        nBoxes += b.size();
    }
    boxes_.setSize(nBoxes);
    boxRank_.setSize(nBoxes);
    scalar xMin = GREAT, yMin = GREAT, xMax = -GREAT, yMax = -GREAT;
    scalar sumSize = 0;
    nBoxes = 0;
    forAll(rankBoxes, proci)
    {
        for (const box& b : rankBoxes[proci])
        {
            boxes_[nBoxes] = b;
            boxRank_[nBoxes++] = proci;
            xMin = min(xMin, b[0]);
            yMin = min(yMin, b[1]);
            xMax = max(xMax, b[2]);
            yMax = max(yMax, b[3]);
            sumSize += ::sqrt((b[2] - b[0])*(b[3] - b[1]));
        }
    }
    if (!nBoxes)
    {
        return;
    }

    // Bins of about a cell's size, at most some 10^6 of them
    x0_ = xMin;
    y0_ = yMin;
    binSize_ = max
    (
        sumSize/nBoxes,
        ::sqrt((xMax - xMin)*(yMax - yMin)/1e6)
    );
    nx_ = max(label(1), label(ceil((xMax - xMin)/binSize_)));
    ny_ = max(label(1), label(ceil((yMax - yMin)/binSize_)));

    labelList count(nx_*ny_ + 1, Zero);
    for (label pass = 0; pass < 2; ++pass)
    {
        if (pass == 1)
        {
            binOffsets_.setSize(nx_*ny_ + 1);
            binOffsets_[0] = 0;
            for (label b = 0; b < nx_*ny_; ++b)
            {
                binOffsets_[b + 1] = binOffsets_[b] + count[b];
            }
            binBoxes_.setSize(binOffsets_.last());
            count = 0;
        }
        forAll(boxes_, bi)
        {
            const box& b = boxes_[bi];
            label ilo, ihi, jlo, jhi;
            binRange(b[0], b[2], x0_, nx_, ilo, ihi);
            binRange(b[1], b[3], y0_, ny_, jlo, jhi);
            for (label j = jlo; j <= jhi; ++j)
            {
                for (label i = ilo; i <= ihi; ++i)
                {
                    const label bin = i + nx_*j;
                    if (pass == 1)
                    {
                        binBoxes_[binOffsets_[bin] + count[bin]] = bi;
                    }
                    ++count[bin];
                }
            }
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::mpsDecomposition::owner(const vector2D& x) const
{
    const label i = label(floor((x.x() - x0_)/binSize_));
    const label j = label(floor((x.y() - y0_)/binSize_));
    if (i < 0 || i >= nx_ || j < 0 || j >= ny_)
    {
        return -1;
    }
    const label bin = i + nx_*j;
    for (label k = binOffsets_[bin]; k < binOffsets_[bin + 1]; ++k)
    {
        const box& b = boxes_[binBoxes_[k]];
        if
        (
            b[0] <= x.x() && x.x() < b[2]
         && b[1] <= x.y() && x.y() < b[3]
        )
        {
            return boxRank_[binBoxes_[k]];
        }
    }
    return -1;
}


void Foam::mpsDecomposition::nearRanks
(
    const vector2D& x,
    const scalar r,
    DynamicList<label>& ranks
) const
{
    ranks.clear();
    label ilo, ihi, jlo, jhi;
    binRange(x.x() - r, x.x() + r, x0_, nx_, ilo, ihi);
    binRange(x.y() - r, x.y() + r, y0_, ny_, jlo, jhi);
    const scalar r2 = sqr(r);
    for (label j = jlo; j <= jhi; ++j)
    {
        for (label i = ilo; i <= ihi; ++i)
        {
            const label bin = i + nx_*j;
            for (label k = binOffsets_[bin]; k < binOffsets_[bin + 1]; ++k)
            {
                const label rank = boxRank_[binBoxes_[k]];
                if (rank == Pstream::myProcNo() || ranks.found(rank))
                {
                    continue;
                }
                const box& b = boxes_[binBoxes_[k]];
                const scalar dx = max(max(b[0] - x.x(), x.x() - b[2]), 0.0);
                const scalar dy = max(max(b[1] - x.y(), x.y() - b[3]), 0.0);
                if (sqr(dx) + sqr(dy) <= r2)
                {
                    ranks.append(rank);
                }
            }
        }
    }
}


Foam::label Foam::mpsDecomposition::sendToOwners(mpsCloud& cloud) const
{
    if (!Pstream::parRun())
    {
        return 0;
    }
    const UList<vector2D>& x = cloud.x();
    const UList<bool>& halo = cloud.halo();
    List<DynamicList<label>> sendLists(Pstream::nProcs());
    boolList keep(cloud.size(), true);
    label nSent = 0;
    forAll(x, i)
    {
        if (halo[i])
        {
            FatalErrorInFunction
                << "distribute() with halos in the cloud: remove them first"
                << exit(FatalError);
        }
        if (replicated(cloud.kind()[i]))
        {
            continue;
        }
        const label rank = owner(x[i]);
        if (rank >= 0 && rank != Pstream::myProcNo())
        {
            sendLists[rank].append(i);
            keep[i] = false;
            ++nSent;
        }
    }
    exchange(cloud, sendLists, keep);
    return nSent;
}


void Foam::mpsDecomposition::removeHalos(mpsCloud& cloud)
{
    const UList<bool>& halo = cloud.halo();
    if (halo.found(true))
    {
        boolList keep(halo.size());
        forAll(halo, i)
        {
            keep[i] = !halo[i];
        }
        cloud.subset(keep);
    }
}


Foam::label Foam::mpsDecomposition::addHalos(mpsCloud& cloud)
{
    removeHalos(cloud);
    haloSendIds_.clear();
    haloRecvIds_.clear();
    if (!Pstream::parRun())
    {
        return 0;
    }
    const UList<vector2D>& x = cloud.x();
    List<DynamicList<label>> sendLists(Pstream::nProcs());
    DynamicList<label> ranks;
    forAll(x, i)
    {
        if (replicated(cloud.kind()[i]))
        {
            continue;
        }
        nearRanks(x[i], haloWidth_, ranks);
        for (const label rank : ranks)
        {
            sendLists[rank].append(i);
        }
    }
    haloSendIds_.setSize(Pstream::nProcs());
    forAll(sendLists, proci)
    {
        haloSendIds_[proci] =
            UIndirectList<label>(cloud.id(), sendLists[proci]);
    }
    haloRecvIds_ = exchange(cloud, sendLists, boolList(cloud.size(), true));

    UList<bool>& halo = cloud.halo();
    label nHalos = 0;
    for (const labelList& ids : haloRecvIds_)
    {
        for (const label id : ids)
        {
            halo[cloud.index(id)] = true;
        }
        nHalos += ids.size();
    }
    return nHalos;
}


bool Foam::mpsDecomposition::inMyCells(const vector2D& x) const
{
    const label rank = owner(x);
    return rank == Pstream::myProcNo() || (rank < 0 && Pstream::master());
}


void Foam::mpsDecomposition::keepOwned(mpsCloud& cloud) const
{
    if (!Pstream::parRun())
    {
        return;
    }
    boolList keep(cloud.size());
    forAll(keep, i)
    {
        keep[i] = replicated(cloud.kind()[i]) || inMyCells(cloud.x()[i]);
    }
    cloud.subset(keep);
}


Foam::boolList Foam::mpsDecomposition::writtenHere
(
    const mpsCloud& cloud
) const
{
    boolList written(cloud.size());
    forAll(written, i)
    {
        written[i] =
            !cloud.halo()[i]
         && (!replicated(cloud.kind()[i]) || inMyCells(cloud.x()[i]));
    }
    return written;
}


void Foam::mpsDecomposition::distribute(mpsCloud& cloud)
{
    removeHalos(cloud);
    sendToOwners(cloud);
    addHalos(cloud);
}


// ************************************************************************* //
