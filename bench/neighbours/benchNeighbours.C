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

Application
    benchNeighbours

Description
    Benchmark of the neighbour search: cell-linked list plus neighbour
    lists (radius 2.1 l0 and 4.0 l0) for particles on a jittered square
    lattice of spacing l0 (the density of MPS fluid) in a 3:1 rectangle.
    Prints one line per figure: particles per second (particles divided by
    the time of one complete build, best of several), for 1 thread and for
    all threads.

    Usage: benchNeighbours [-particles "(30000 300000)"]

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "clockValue.H"
#include "neighbourList.H"
#include "Random.H"
#include <omp.h>

using namespace Foam;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

List<vector2D> jitteredLattice(const label n, const scalar l0)
{
    const label nx = label(std::sqrt(3.0*n));
    const label ny = (n + nx - 1)/nx;
    Random rnd(17);
    List<vector2D> x(n);
    forAll(x, i)
    {
        x[i] = l0*vector2D
        (
            (i % nx) + 0.5 + 0.2*(rnd.sample01<scalar>() - 0.5),
            (i / nx) + 0.5 + 0.2*(rnd.sample01<scalar>() - 0.5)
        );
    }
    (void)ny;
    return x;
}


//- Best time of nRepeat builds [s]
scalar timeBuild
(
    const List<vector2D>& x,
    const scalar radius,
    const label nRepeat,
    label& nPairs
)
{
    scalar best = GREAT;
    neighbourList list;
    for (label r = 0; r < nRepeat; ++r)
    {
        clockValue start(true);
        list.build(x, radius);
        best = min(best, start.elapsed());
    }
    nPairs = list.nPairs();
    return best;
}


int main(int argc, char *argv[])
{
    argList::noBanner();
    argList::noParallel();
    argList::addOption
    (
        "particles",
        "list",
        "numbers of particles, default (30000 300000)"
    );
    argList::addOption
    (
        "repeat",
        "n",
        "builds timed a size (the best is kept), default max(3, 3e6/n)"
    );
    argList args(argc, argv, false, false);

    const labelList sizes
    (
        args.getOrDefault<labelList>("particles", labelList({30000, 300000}))
    );

    const scalar l0 = 0.005;
    const label maxThreads = omp_get_max_threads();

    for (const label n : sizes)
    {
        const List<vector2D> x(jitteredLattice(n, l0));
        const label nRepeat =
            args.getOrDefault<label>("repeat", max(label(3), label(3e6/n)));

        {
            scalar best = GREAT;
            for (label r = 0; r < nRepeat; ++r)
            {
                clockValue start(true);
                cellLinkedList cells(x, 2.1*l0);
                best = min(best, start.elapsed());
            }
            Info<< "cellLinkedList particles=" << n << ": "
                << scalar(n)/best << " particles/s ("
                << 1e3*best << " ms per build)" << endl;
        }

        for (const scalar re : {2.1, 4.0})
        {
            for (const label nThreads : {label(1), maxThreads})
            {
                omp_set_num_threads(nThreads);
                label nPairs = 0;
                const scalar t = timeBuild(x, re*l0, nRepeat, nPairs);
                Info<< "neighbours particles=" << n << " re=" << re
                    << "l0 threads=" << nThreads << ": "
                    << scalar(n)/t << " particles/s ("
                    << 1e3*t << " ms per build, "
                    << scalar(nPairs)/n << " neighbours per particle)"
                    << endl;
                if (nThreads == maxThreads)
                {
                    break;
                }
            }
        }
    }

    return 0;
}


// ************************************************************************* //
