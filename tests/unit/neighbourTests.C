/*---------------------------------------------------------------------------*\
    Neighbour search: the cell-linked list neighbour lists against a brute
    force O(N^2) search on random particles (same sets), for a radius equal
    to, smaller and larger than the cell size, and for 1 and 2 threads; the
    search with a skin (neighbourSearch) against a full search while the
    points move: the same lists, candidates rebuilt only when a point has
    moved far enough or the points change; rowChunks hands every row to one
    thread once.
\*---------------------------------------------------------------------------*/

#include <catch2/catch.hpp>
#include "neighbourList.H"
#include "neighbourSearch.H"
#include "rowChunks.H"
#include "Random.H"
#include <omp.h>
#include <algorithm>

using namespace Foam;

namespace
{

List<vector2D> randomPoints(const label n, const vector2D& span, label seed)
{
    Random rnd(seed);
    List<vector2D> x(n);
    for (vector2D& p : x)
    {
        p = vector2D(span.x()*rnd.sample01<scalar>(), span.y()*rnd.sample01<scalar>());
    }
    return x;
}

List<labelList> bruteForce(const UList<vector2D>& x, const scalar radius)
{
    List<labelList> nbrs(x.size());
    forAll(x, i)
    {
        DynamicList<label> ni;
        forAll(x, j)
        {
            if (j != i && magSqr(x[j] - x[i]) < sqr(radius))
            {
                ni.append(j);
            }
        }
        nbrs[i] = std::move(ni);
    }
    return nbrs;
}

//- Number of points whose neighbour set differs from the brute force one
label nDifferent(const neighbourList& list, const List<labelList>& ref)
{
    label nDiff = (list.size() == ref.size() ? 0 : 1);
    for (label i = 0; i < min(list.size(), ref.size()); ++i)
    {
        labelList a(list[i]);
        std::sort(a.begin(), a.end());
        if (a != ref[i])
        {
            ++nDiff;
        }
    }
    return nDiff;
}

} // End anonymous namespace


TEST_CASE("neighbour lists equal brute force on random particles")
{
    // 3000 points in a 1 x 0.5 box; with radius 0.03 about 8 neighbours each
    const List<vector2D> x(randomPoints(3000, vector2D(1, 0.5), 1234));

    for (const scalar radius : {0.01, 0.03, 0.07})
    {
        INFO("radius " << radius);
        const List<labelList> ref(bruteForce(x, radius));

        label nRefPairs = 0;
        for (const labelList& r : ref)
        {
            nRefPairs += r.size();
        }
        REQUIRE(nRefPairs > x.size());     // the test is not vacuous

        const neighbourList list(x, radius);
        CHECK(list.nPairs() == nRefPairs);
        CHECK(nDifferent(list, ref) == 0);

        // Radius larger and smaller than the cell size
        for (const scalar h : {0.4*radius, 2.5*radius})
        {
            INFO("cell size " << h);
            neighbourList other;
            other.build(x, cellLinkedList(x, h), radius);
            CHECK(nDifferent(other, ref) == 0);
        }
    }
}


TEST_CASE("neighbour lists do not depend on the number of threads")
{
    const List<vector2D> x(randomPoints(20000, vector2D(2, 1), 99));
    const label nThreads = omp_get_max_threads();

    omp_set_num_threads(1);
    const neighbourList one(x, 0.02);
    omp_set_num_threads(max(label(2), nThreads));
    const neighbourList many(x, 0.02);
    omp_set_num_threads(nThreads);

    CHECK(one.offsets() == many.offsets());
    CHECK(one.neighbours() == many.neighbours());
}


TEST_CASE("neighbour lists on a lattice count the stencil")
{
    // Interior points of a square lattice with radius 2.1 l0 have 12
    // neighbours (4 at l0, 4 at sqrt(2) l0, 4 at 2 l0)
    const scalar l0 = 0.005;
    List<vector2D> x(30*30);
    forAll(x, i)
    {
        x[i] = l0*vector2D(i % 30, i / 30);
    }
    const neighbourList list(x, 2.1*l0);
    const label interior = 15*30 + 15;
    CHECK(list[interior].size() == 12);
    CHECK(list[0].size() == 5);         // a corner: 2 + 1 + 2
}


TEST_CASE("a search with a skin finds the lists a full search finds")
{
    // 4000 points in a 1 x 0.5 box moving randomly by up to 0.001 a step
    // (radius 0.03, skin 0.01: a point of the 4000 reaches half the skin
    // in some 4 steps);
    // the last 200 points are not searched (a structure's, in the fluid)
    List<vector2D> x(randomPoints(4000, vector2D(1, 0.5), 7));
    const label nActive = 3800;
    const scalar radius = 0.03, skin = 0.01;
    neighbourSearch search(radius, skin);
    Random rnd(11);
    label revision = 0;

    for (label step = 0; step < 40; ++step)
    {
        INFO("step " << step);
        for (vector2D& p : x)
        {
            p += 0.001*vector2D
            (
                2*rnd.sample01<scalar>() - 1, 2*rnd.sample01<scalar>() - 1
            );
        }
        if (step == 30)
        {
            // The points change (a removal, a redistribution): the same
            // number, others in their places
            std::reverse(x.begin(), x.begin() + nActive);
            ++revision;
        }

        // Both radii a fluid step asks for
        for (const scalar r : {radius, 0.7*radius})
        {
            neighbourList found, full;
            search.find(x, nActive, revision, r, found);
            full.build(x, r, nActive);
            CHECK(found.offsets() == full.offsets());
            CHECK(found.neighbours() == full.neighbours());
        }
    }
    // Far fewer builds than searches, and a rebuild at the change
    WARN(search.nBuilds() << " builds in " << search.nSearches() << " searches");
    CHECK(search.nSearches() == 80);
    CHECK(search.nBuilds() >= 6);
    CHECK(search.nBuilds() <= 16);

    // A skin of 0: a full search every time
    neighbourSearch none(radius, 0);
    neighbourList found, full;
    none.find(x, nActive, revision, radius, found);
    none.find(x, nActive, revision, radius, found);
    full.build(x, radius, nActive);
    CHECK(found.neighbours() == full.neighbours());
    CHECK(none.nBuilds() == 2);
}


TEST_CASE("rowChunks: every row once, each thread's rows at most a range a thread")
{
    // Rows of equal cost on 1, 2 and 3 threads, a count that is no
    // multiple of the chunk: each row taken by one thread, once; a thread
    // takes its own range upwards and then the others' from their tops,
    // so its rows form at most nThreads ranges (its own, and one a range it
    // helped with; which thread takes which depends on their speeds)
    const label chunk = 16;
    for (const label n : {0, 5, 1000, 1003})
    {
        for (const int nThreads : {1, 2, 3})
        {
            CAPTURE(n, nThreads);
            rowChunks rows(n, chunk);
            List<label> taker(n, -1), times(n, 0);
            label team = 1;
            #pragma omp parallel num_threads(nThreads)
            {
                #pragma omp single
                team = omp_get_num_threads();
                rows.forEach([&](const label i)
                {
                    #pragma omp atomic
                    ++times[i];
                    taker[i] = omp_get_thread_num();
                });
            }
            label bad = 0;
            for (label i = 0; i < n; ++i)
            {
                bad += (times[i] != 1);
            }
            CHECK(bad == 0);

            // Ranges of each thread's rows (the team as it ran)
            List<label> ranges(nThreads, 0);
            for (label i = 0; i < n; ++i)
            {
                if (i == 0 || taker[i] != taker[i - 1])
                {
                    ++ranges[taker[i]];
                }
            }
            for (label t = 0; t < nThreads; ++t)
            {
                CHECK(ranges[t] <= team);
            }
        }
    }
}
