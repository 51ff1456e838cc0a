/*---------------------------------------------------------------------------*\
  mpsFsiFoam unit tests: particle shifting. Fickian shifting
  (Lind et al. 2012) leaves a regular lattice where it is, walls and flat
  free surface included; it makes a disordered block regular without
  moving its free surface into the air; it carries a linear velocity field
  to the new positions exactly; next to a wall it holds the water or
  shifts it along the wall only, as asked; its entries are checked.
\*---------------------------------------------------------------------------*/

#include <catch2/catch.hpp>
#include "testTools.H"
#include "particleShifting.H"
#include "mpsKernel.H"
#include "Random.H"
#include "tensor2D.H"

using namespace Foam;
using Catch::Matchers::Contains;

namespace
{

const scalar l0 = 0.01;
const scalar re = 2.1*l0;

// N x N fluid particles at spacing l0 (row j at y = (j + 0.5) l0), each
// moved by up to +-disorder l0, on a wall row and two dummy rows that run
// 3 l0 beyond the block on both sides; the top row and the side columns are
// flagged free surface
struct tank
{
    mpsCloud cloud;
    label N;

    tank(const label n, const scalar disorder)
    :
        N(n)
    {
        Random rnd(5);
        const label r = cloud.addRegion("tank");
        for (label j = 0; j < N; ++j)
        {
            for (label i = 0; i < N; ++i)
            {
                const vector2D d
                (
                    disorder*(2*rnd.sample01<scalar>() - 1),
                    disorder*(2*rnd.sample01<scalar>() - 1)
                );
                cloud.append(l0*(vector2D(i + 0.5, j + 0.5) + d), particleKind::fluid, r, l0);
            }
        }
        for (label i = -3; i < N + 3; ++i)
        {
            cloud.append(l0*vector2D(i + 0.5, -0.5), particleKind::wall, r, l0);
            cloud.append(l0*vector2D(i + 0.5, -1.5), particleKind::dummy, r, l0);
            cloud.append(l0*vector2D(i + 0.5, -2.5), particleKind::dummy, r, l0);
        }
        for (label j = 0; j < N; ++j)
        {
            for (label i = 0; i < N; ++i)
            {
                cloud.surface()[i + N*j] = (j == N - 1 || i == 0 || i == N - 1);
            }
        }
    }

    // Lattice column and row of fluid particle k
    label column(const label k) const { return k % N; }
    label row(const label k) const { return k/N; }
};


autoPtr<particleShifting> fickian(const std::string& entries = "")
{
    return particleShifting::New
    (
        test::dict("shifting { type fickian; " + entries + " }")
    );
}


// Standard deviation of the MPS number density (original kernel, re 2.1
// l0) over the fluid particles of rows and columns [3, N - 4] (full
// support, away from the surface), relative to the lattice value
scalar numberDensitySpread(const tank& t)
{
    const dictionary kd(test::dict("kernel { type original; }"));
    autoPtr<mpsKernel> k(mpsKernel::New(kd, re));
    const scalar n0 = k->latticeNumberDensity(l0);
    const neighbourList nbrs(t.cloud.x(), re);
    scalar sum = 0, sum2 = 0;
    label count = 0;
    for (label i = 0; i < t.N*t.N; ++i)
    {
        if
        (
            t.row(i) < 3 || t.row(i) > t.N - 4
         || t.column(i) < 3 || t.column(i) > t.N - 4
        )
        {
            continue;
        }
        scalar ni = 0;
        for (label kk = nbrs.offsets()[i]; kk < nbrs.offsets()[i + 1]; ++kk)
        {
            ni += k->w(mag(t.cloud.x()[nbrs.neighbours()[kk]] - t.cloud.x()[i]));
        }
        sum += ni/n0;
        sum2 += sqr(ni/n0);
        ++count;
    }
    const scalar mean = sum/count;
    return std::sqrt(max(sum2/count - sqr(mean), scalar(0)));
}

} // End anonymous namespace


TEST_CASE("fickian shifting leaves a regular lattice where it is")
{
    // On the lattice grad C vanishes by symmetry inside and along the wall
    // (walls shift: the rows next to it shifted as the others);
    // along the flat top it is normal to the surface and is removed. Only
    // the block's corners and side columns may move.
    tank t(12, 0);
    forAll(t.cloud.U(), i)
    {
        t.cloud.U()[i] = (t.cloud.kind()[i] == particleKind::fluid ? vector2D(1, 0.5) : vector2D(Zero));
    }
    const List<vector2D> x0(t.cloud.x());
    const List<vector2D> U0(t.cloud.U());
    const neighbourList nbrs(t.cloud.x(), re);
    fickian("diffusion fixed; surface tangential; walls shift;")->shift(t.cloud, nbrs, l0, re, 1e-3);

    scalar inside = 0, sides = 0;
    for (label i = 0; i < t.N*t.N; ++i)
    {
        const scalar d = mag(t.cloud.x()[i] - x0[i])/l0;
        if (t.column(i) >= 2 && t.column(i) <= t.N - 3)
        {
            inside = max(inside, d);    // wall rows, interior, flat top
        }
        else
        {
            sides = max(sides, d);
        }
        CHECK(mag(t.cloud.U()[i] - U0[i]) < 1e-12);   // uniform velocity
    }
    CHECK(inside < 1e-12);
    CHECK(sides > 1e-3);        // the test is not trivially zero
    for (label i = t.N*t.N; i < t.cloud.size(); ++i)
    {
        CHECK(t.cloud.x()[i] == x0[i]);     // walls and dummies stay
    }
}


TEST_CASE("fickian shifting makes a disordered block regular and keeps its surface")
{
    // 20 x 20 particles moved by up to 0.2 l0, moving at 1 m/s for 40
    // steps of 0.1 l0 (velocity diffusion, A = 2: D = 0.21 l0^2 a step)
    tank t(20, 0.2);
    const scalar dt = 0.1*l0;
    auto topRow = [&t]()
    {
        scalar y = 0;
        for (label i = t.N*(t.N - 1); i < t.N*t.N; ++i)
        {
            y += t.cloud.x()[i].y();
        }
        return y/t.N/l0;
    };
    const scalar spread0 = numberDensitySpread(t);
    const scalar top0 = topRow();
    autoPtr<particleShifting> model(fickian("surface tangential;"));
    scalar largest = 0;
    for (label step = 0; step < 40; ++step)
    {
        forAll(t.cloud.U(), i)
        {
            t.cloud.U()[i] = (t.cloud.kind()[i] == particleKind::fluid ? vector2D(0, 1) : vector2D(Zero));
        }
        const neighbourList nbrs(t.cloud.x(), re);
        largest = max(largest, model->shift(t.cloud, nbrs, l0, re, dt));
    }
    const scalar spread = numberDensitySpread(t);
    INFO("number density spread " << spread0 << " -> " << spread
        << "; top row " << top0 << " -> " << topRow() << " l0; largest shift "
        << largest/l0 << " l0");
    // A regular set: the spread falls to less than a third (measured
    // 0.084 -> 0.020)
    CHECK(spread < 0.3*spread0);
    CHECK(largest <= 0.1*l0*(1 + 1e-12));   // the cap
    // The free surface is not diffused into the air: the top row's mean
    // height moves by less than 0.1 l0 (measured -0.011 l0; with no
    // particle flagged, i.e. without the projection, it rises by 1.57 l0
    // and the spread falls only to 0.073)
    CHECK(mag(topRow() - top0) < 0.1);
}


TEST_CASE("fickian shifting with surface fixed leaves the flagged particles")
{
    tank t(12, 0.2);
    forAll(t.cloud.U(), i)
    {
        t.cloud.U()[i] = (t.cloud.kind()[i] == particleKind::fluid ? vector2D(0, 1) : vector2D(Zero));
    }
    const List<vector2D> x0(t.cloud.x());
    const neighbourList nbrs(t.cloud.x(), re);
    fickian("surface fixed;")->shift(t.cloud, nbrs, l0, re, 0.1*l0);
    scalar flagged = 0, others = 0;
    for (label i = 0; i < t.N*t.N; ++i)
    {
        const scalar d = mag(t.cloud.x()[i] - x0[i])/l0;
        (t.cloud.surface()[i] ? flagged : others) = max(t.cloud.surface()[i] ? flagged : others, d);
    }
    CHECK(flagged == 0);
    CHECK(others > 1e-3);
}


TEST_CASE("fickian shifting carries a linear velocity field exactly")
{
    // u = a + B x on a disordered block: after the shift every fluid
    // particle carries a + B x at its new position (the renormalised
    // gradient is exact for a linear field)
    tank t(10, 0.2);
    const vector2D a(0.3, -0.2);
    const tensor2D B(2, -1, 0.5, 3);    // u_x = a_x + 2 x - y, ...
    forAll(t.cloud.U(), i)
    {
        if (t.cloud.kind()[i] == particleKind::fluid)
        {
            t.cloud.U()[i] = a + (B & t.cloud.x()[i]);
        }
    }
    const List<vector2D> x0(t.cloud.x());
    const neighbourList nbrs(t.cloud.x(), re);
    fickian("coefficient 6; maxShift 0.2;")->shift(t.cloud, nbrs, l0, re, 1e-3);
    scalar moved = 0, error = 0;
    for (label i = 0; i < t.N*t.N; ++i)
    {
        moved = max(moved, mag(t.cloud.x()[i] - x0[i])/l0);
        error = max(error, mag(t.cloud.U()[i] - (a + (B & t.cloud.x()[i]))));
    }
    INFO("largest shift " << moved << " l0, velocity error " << error);
    CHECK(moved > 0.02);
    CHECK(error < 1e-12*mag(B)*t.N*l0 + 1e-13);
}


// Whether fluid particle i has a wall or dummy particle within re
bool nextToWall(const tank& t, const label i)
{
    for (label j = t.N*t.N; j < t.cloud.size(); ++j)
    {
        if (mag(t.cloud.x()[j] - t.cloud.x()[i]) < re)
        {
            return true;
        }
    }
    return false;
}


TEST_CASE("fickian shifting with walls hold leaves the water next to a wall")
{
    // A disordered block: with walls hold the particles within re of the
    // wall row or the dummies neither move nor change velocity; the
    // others shift as with walls shift, which moves both
    auto run = [](const std::string& walls, List<vector2D>& dr, List<vector2D>& dU)
    {
        tank t(12, 0.2);
        forAll(t.cloud.U(), i)
        {
            t.cloud.U()[i] =
            (
                t.cloud.kind()[i] == particleKind::fluid
              ? vector2D(0.5 + 30*t.cloud.x()[i].y(), 1) : vector2D(Zero)
            );
        }
        const List<vector2D> x0(t.cloud.x()), U0(t.cloud.U());
        List<bool> near(t.N*t.N);
        forAll(near, i)
        {
            near[i] = nextToWall(t, i);
        }
        const neighbourList nbrs(t.cloud.x(), re);
        fickian("walls " + walls + ";")->shift(t.cloud, nbrs, l0, re, 0.1*l0);
        dr.setSize(near.size());
        dU.setSize(near.size());
        forAll(near, i)
        {
            dr[i] = t.cloud.x()[i] - x0[i];
            dU[i] = t.cloud.U()[i] - U0[i];
        }
        return near;
    };
    List<vector2D> drHold, dUHold, drShift, dUShift;
    const List<bool> near = run("hold", drHold, dUHold);
    run("shift", drShift, dUShift);
    scalar heldHold = 0, heldShift = 0, awayHold = 0;
    label nNear = 0;
    forAll(near, i)
    {
        if (near[i])
        {
            ++nNear;
            heldHold = max(heldHold, mag(drHold[i]) + mag(dUHold[i]));
            heldShift = max(heldShift, mag(drShift[i])/l0);
        }
        else
        {
            // Away from the walls the two are the same shift
            CHECK(drHold[i] == drShift[i]);
            awayHold = max(awayHold, mag(drHold[i])/l0);
        }
    }
    INFO(nNear << " particles next to the wall; their largest shift "
        << heldShift << " l0 with walls shift");
    CHECK(nNear >= 12);             // the first row at least
    CHECK(heldHold == 0);
    CHECK(heldShift > 1e-3);        // not trivially still
    CHECK(awayHold > 1e-3);
}


TEST_CASE("fickian shifting with walls tangential shifts along the wall only")
{
    // Disordered in y only, so that each particle's wall and dummy
    // neighbours lie symmetrically about it and the wall's normal is y:
    // next to the wall the shift is along x alone (exactly), where walls
    // shift moves it along y as well
    auto run = [](const std::string& walls)
    {
        tank t(12, 0);
        Random rnd(7);
        for (label i = 0; i < t.N*t.N; ++i)
        {
            t.cloud.x()[i].y() += 0.2*l0*(2*rnd.sample01<scalar>() - 1);
        }
        forAll(t.cloud.U(), i)
        {
            t.cloud.U()[i] = (t.cloud.kind()[i] == particleKind::fluid ? vector2D(0, 1) : vector2D(Zero));
        }
        const List<vector2D> x0(t.cloud.x());
        List<bool> near(t.N*t.N);
        forAll(near, i)
        {
            near[i] = nextToWall(t, i) && !t.cloud.surface()[i];
        }
        const neighbourList nbrs(t.cloud.x(), re);
        fickian("walls " + walls + ";")->shift(t.cloud, nbrs, l0, re, 0.1*l0);
        scalar normal = 0, along = 0;
        label nNear = 0;
        for (label i = 0; i < t.N*t.N; ++i)
        {
            if (near[i])
            {
                ++nNear;
                normal = max(normal, mag(t.cloud.x()[i].y() - x0[i].y())/l0);
                along = max(along, mag(t.cloud.x()[i].x() - x0[i].x())/l0);
            }
        }
        CHECK(nNear >= 10);
        return std::make_pair(normal, along);
    };
    const auto tangential = run("tangential");
    const auto shifted = run("shift");
    INFO("largest normal / tangential shift next to the wall [l0]: "
        << tangential.first << " / " << tangential.second << " (tangential), "
        << shifted.first << " / " << shifted.second << " (shift)");
    CHECK(tangential.first < 1e-12);
    CHECK(tangential.second > 1e-4);
    CHECK(shifted.first > 1e-3);
}


TEST_CASE("shifting entries are checked")
{
    CHECK(particleShifting::New(test::dict("rho 1;"))->type() == "none");
    CHECK_THROWS_WITH
    (
        particleShifting::New(test::dict("shifting { type lind; }")),
        Contains("fickian") && Contains("none")
    );
    CHECK_THROWS_WITH(fickian("maxShift 0.7;"), Contains("maxShift"));
    CHECK_THROWS_WITH(fickian("coefficient 0;"), Contains("coefficient"));
    CHECK_THROWS_WITH(fickian("diffusion fixed; coefficient 0.25;"), Contains("0.1"));
    CHECK_THROWS_WITH(fickian("diffusion constant;"), Contains("velocity"));
    CHECK_THROWS_WITH(fickian("A 2;"), Contains("coefficient"));
    CHECK_THROWS_WITH(fickian("surface none;"), Contains("tangential") && Contains("fixed"));
    CHECK_THROWS_WITH(fickian("surface { a 1; }"), Contains("surface") && Contains("not a dictionary"));
    CHECK_THROWS_WITH(fickian("coeficient 2;"), Contains("coefficient"));
    CHECK_THROWS_WITH
    (
        fickian("walls slip;"),
        Contains("shift") && Contains("tangential") && Contains("hold")
    );
}


// ************************************************************************* //
