/*---------------------------------------------------------------------------*\
  mpsFsiFoam unit tests: the per-step operations are consistent in time.
  An operation applied once a step converges as dt -> 0 only if what it
  does over a fixed time does not depend on how many steps that time is
  cut into. Each test runs an operation alone over a fixed time at two or
  three steps and compares what it did:
    - the pairwise collision (Lee et al. 2011) against a wall, a particle
      pushed onto it by a constant acceleration: the impulse the wall takes
      over the time is the push's, at every step, though the number of
      corrections grows as 1/dt;
    - Fickian shifting in its velocity form (D = A h |u| dt, Skillen et
      al. 2013): a disordered block's displacement over a fixed time.
  And where in the step an operation acts (the fluid step, mpsFluid):
    - wallPositions: a moving wall counted in the step's number density
      where the step starts (lagged) or ends (predicted);
    - the collisions' stage (predicted, corrected): a particle that falls
      onto a wall rests on it at either, taking the same impulse.
\*---------------------------------------------------------------------------*/

#include <catch2/catch.hpp>
#include "testTools.H"
#include "collisionModel.H"
#include "particleShifting.H"
#include "neighbourList.H"
#include "mpsFluid.H"
#include "mpsKernel.H"
#include "Random.H"

using namespace Foam;

namespace
{

const scalar l0 = 0.01;

// A fluid particle starting 1.2 l0 above a wall row at 0.5 m/s towards it,
// pushed onto it at a = 100 m/s^2 (a pressure gradient's order in the
// wedge's impact) for T = 20 ms in steps of dt: the predictor (u += a dt,
// x += u dt), then the collisions. Returns the impulse per unit mass the
// collisions gave the particle, the number of corrections and its height
// at the end (in l0)
struct contact
{
    scalar impulse = 0;
    label corrections = 0;
    scalar height = 0;
};

contact pushOntoWall(const scalar dt)
{
    mpsCloud cloud;
    const label r = cloud.addRegion("contact");
    cloud.append(vector2D(0.3*l0, 1.2*l0), particleKind::fluid, r, l0);
    for (label i = -5; i <= 5; ++i)
    {
        cloud.append(vector2D(i*l0, 0), particleKind::wall, r, l0);
    }
    cloud.U()[0] = vector2D(0, -0.5);
    const dictionary props
    (
        test::dict("collision { type pairwise; alpha 0.85; e 0.2; }")
    );
    autoPtr<collisionModel> model(collisionModel::New(props));
    const scalar a = -100;
    const label nSteps = std::lround(0.02/dt);
    contact c;
    for (label step = 0; step < nSteps; ++step)
    {
        cloud.U()[0].y() += a*dt;
        cloud.x()[0] += dt*cloud.U()[0];
        const neighbourList nbrs(cloud.x(), 2.1*l0);
        List<vector2D> x(cloud.x());
        List<vector2D> U(cloud.U());
        c.corrections += model->correct(cloud, nbrs, l0, dt, x, U);
        c.impulse += U[0].y() - cloud.U()[0].y();
        cloud.x()[0] = x[0];
        cloud.U()[0] = U[0];
    }
    c.height = cloud.x()[0].y()/l0;
    return c;
}


// The fluid step's dictionary: the original kernel at 2.1 l0, no viscosity,
// the given gravity and extra entries (collision, wallPositions)
dictionary stepDict(const std::string& g, const std::string& extra)
{
    return test::dict
    (
        "rho 1000; nu 0; g (0 " + g + " 0); l0 0.01;"
        " kernel { type original; }"
        " re { numberDensity 2.1; gradient 2.1; laplacian 2.1;"
        " viscosity 2.1; }"
        " freeSurface { type improved; } pressureSolver { type PCG; } "
        + extra
    );
}

// A wall row of 2 n + 1 particles at height y, spacing l0, velocity U
void appendWallRow
(
    mpsCloud& cloud,
    const label r,
    const label n,
    const scalar y,
    const vector2D& U
)
{
    for (label i = -n; i <= n; ++i)
    {
        cloud.append(vector2D(i*l0, y), particleKind::wall, r, l0);
        cloud.U().last() = U;
    }
}

} // End anonymous namespace


TEST_CASE("the pairwise collision is consistent in time: a wall's impulse over a fixed time")
{
    // Momentum: the particle ends at rest on the wall, so the collisions
    // gave it the push's a T plus its initial speed, 2 + 0.5 = 2.5 m/s,
    // whatever the step, but for the last step's rebound, at most
    // (1 + e) a dt; they hold it where it stopped approaching, inside the
    // collision distance (measured 2.5105, 2.5027, 2.5006 m/s; height
    // 0.68760, 0.68740, 0.68739 l0)
    const contact coarse = pushOntoWall(1e-4);
    const contact medium = pushOntoWall(2.5e-5);
    const contact fine = pushOntoWall(6.25e-6);
    INFO
    (
        "impulse " << coarse.impulse << ", " << medium.impulse << ", "
        << fine.impulse << " m/s; corrections " << coarse.corrections
        << ", " << medium.corrections << ", " << fine.corrections
        << "; height " << coarse.height << ", " << medium.height << ", "
        << fine.height << " l0"
    );
    // The corrections are counted per step: their number grows with the
    // steps (measured 32, 131, 557: x4 at each quartering), each smaller
    CHECK(fine.corrections > 8*coarse.corrections);
    // Their impulse is the push's, to the last rebound: first order in dt
    CHECK(mag(coarse.impulse - 2.5) < 1.2*100*1e-4);
    CHECK(mag(medium.impulse - 2.5) < 1.2*100*2.5e-5);
    CHECK(mag(fine.impulse - 2.5) < 1.2*100*6.25e-6);
    // The resting height converges: the two finer steps within 0.01 l0
    CHECK(mag(fine.height - medium.height) < 0.01);
    CHECK(fine.height > 0.5);
    CHECK(fine.height < 0.85);
}


TEST_CASE("fickian shifting (velocity form) is consistent in time: a block's displacement over a fixed time")
{
    // A disordered 12 x 12 block moving at 1 m/s (the velocity itself not
    // advected: the shift alone), shifted over 2 ms in 20 steps and in 80:
    // D = A h |u| dt makes each step's shift proportional to dt, so the
    // displacement over the time is the same to first order in dt
    auto shiftOver = [](const label nSteps)
    {
        mpsCloud cloud;
        const label r = cloud.addRegion("block");
        Random rnd(11);
        const label N = 12;
        for (label j = 0; j < N; ++j)
        {
            for (label i = 0; i < N; ++i)
            {
                const vector2D d
                (
                    0.15*(2*rnd.sample01<scalar>() - 1),
                    0.15*(2*rnd.sample01<scalar>() - 1)
                );
                cloud.append(l0*(vector2D(i + 0.5, j + 0.5) + d), particleKind::fluid, r, l0);
            }
        }
        for (label i = -3; i < N + 3; ++i)
        {
            cloud.append(l0*vector2D(i + 0.5, -0.5), particleKind::wall, r, l0);
            cloud.append(l0*vector2D(i + 0.5, -1.5), particleKind::dummy, r, l0);
        }
        for (label k = 0; k < N*N; ++k)
        {
            cloud.surface()[k] = (k/N == N - 1 || k % N == 0 || k % N == N - 1);
        }
        autoPtr<particleShifting> model
        (
            particleShifting::New(test::dict("shifting { type fickian; }"))
        );
        const List<vector2D> x0(cloud.x());
        const scalar dt = 2e-3/nSteps;
        for (label step = 0; step < nSteps; ++step)
        {
            forAll(cloud.U(), i)
            {
                cloud.U()[i] =
                    cloud.kind()[i] == particleKind::fluid
                  ? vector2D(1, 0) : vector2D(Zero);
            }
            const neighbourList nbrs(cloud.x(), 2.1*l0);
            model->shift(cloud, nbrs, l0, 2.1*l0, dt);
        }
        List<vector2D> dx(N*N);
        forAll(dx, k)
        {
            dx[k] = cloud.x()[k] - x0[k];
        }
        return dx;
    };
    const List<vector2D> coarse(shiftOver(20));
    const List<vector2D> fine(shiftOver(80));
    scalar moved = 0, difference = 0;
    forAll(coarse, k)
    {
        moved += mag(fine[k]);
        difference += mag(fine[k] - coarse[k]);
    }
    INFO
    (
        "mean displacement " << moved/coarse.size()/l0 << " l0, mean"
        " difference between 20 and 80 steps " << difference/coarse.size()/l0
        << " l0"
    );
    CHECK(moved/coarse.size() > 0.02*l0);       // the block does move
    // First order in dt, the steps a quarter: the difference a small part
    // of the displacement (measured 2.4% of 0.045 l0; a shift that counted
    // steps would differ by a factor 4)
    CHECK(difference < 0.1*moved);
}


TEST_CASE("wallPositions: the step's number density counts a moving wall where the step starts, or where it ends")
{
    // A fluid particle at rest (no gravity, no viscosity, alone: on the
    // surface, no pressure) 1.3 l0 above a wall row that rises at 2 m/s;
    // one step of 1 ms moves the wall 0.2 l0. Its number density is the
    // kernel's sum over the wall particles at their places at the step's
    // start (lagged) or at its end (predicted), to round-off; the walls
    // end the step where they started (lagged: the structure moves them)
    // or 0.2 l0 higher (predicted)
    const scalar dt = 1e-3, V = 2;
    for (const word where : {"lagged", "predicted"})
    {
        INFO("wallPositions " << where);
        mpsCloud c;
        const label r = c.addRegion("rising wall");
        c.append(vector2D(0.3*l0, 0), particleKind::fluid, r, l0);
        appendWallRow(c, r, 5, -1.3*l0, vector2D(0, V));
        const dictionary d
        (
            stepDict("0", "collision { type none; } wallPositions " + where + ";")
        );
        mpsFluid fluid(c, d, boundBox(point(-1, -1, -1), point(1, 1, 1)));
        const List<vector2D> x0(c.x());
        fluid.step(dt);

        const scalar lift = (where == "predicted" ? V*dt : 0);
        autoPtr<mpsKernel> k(mpsKernel::New(d, 2.1*l0));
        scalar n = 0;
        for (label j = 1; j < c.size(); ++j)
        {
            n += k->w(mag(x0[j] + vector2D(0, lift) - x0[0]));
        }
        CHECK(mag(c.x()[0] - x0[0]) < 1e-12);
        CHECK(n > 0.1);
        CHECK(mag(c.n()[0] - n) < 1e-12*n);
        for (label j = 1; j < c.size(); ++j)
        {
            CHECK(mag(c.x()[j] - x0[j] - vector2D(0, lift)) < 1e-15);
        }
    }
}


TEST_CASE("the collisions' stage: a particle that falls onto a wall comes to rest in the same place at either")
{
    // A fluid particle alone (on the surface: no pressure) falls from
    // 1.2 l0 onto a wall row (spacing l0) under g = 100 m/s^2 for 20 ms in
    // whole fluid steps of 1e-4 s. The collisions stop it (it reaches the
    // wall at 0.8 m/s), slide it along the line of centres into the notch
    // between two wall particles and hold it there, the collision distance
    // 0.85 l0 from both: at x = 0.5 l0, y = sqrt(0.85^2 - 0.5^2) l0 =
    // 0.687 l0 (measured 0.511, 0.695 l0, still settling by 0.01 l0 with
    // e = 0.2). Without a pressure the stage cannot matter: predicted and
    // corrected give the same trajectory, to the last bit (where the
    // pressure acts they differ: the time-step study measures how much)
    const scalar dt = 1e-4, T = 0.02;
    List<vector2D> xEnd, UEnd;
    for (const word stage : {"predicted", "corrected"})
    {
        INFO("collision stage " << stage);
        mpsCloud c;
        const label r = c.addRegion("floor");
        c.append(vector2D(0.3*l0, 1.2*l0), particleKind::fluid, r, l0);
        appendWallRow(c, r, 5, 0, vector2D(Zero));
        mpsFluid fluid
        (
            c,
            stepDict
            (
                "-100",
                "collision { type pairwise; alpha 0.85; e 0.2; stage "
              + stage + "; }"
            ),
            boundBox(point(-1, -1, -1), point(1, 1, 1))
        );
        label corrections = 0;
        const label nSteps = std::lround(T/dt);
        for (label step = 0; step < nSteps; ++step)
        {
            corrections += fluid.step(dt).nCollisions;
        }
        const vector2D x(c.x()[0]/l0);
        INFO
        (
            "at (" << x.x() << ", " << x.y() << ") l0, " << corrections
            << " corrections"
        );
        CHECK(corrections > 10);
        CHECK(mag(x.x() - 0.5) < 0.05);
        CHECK(mag(x.y() - ::sqrt(sqr(0.85) - sqr(0.5))) < 0.02);
        xEnd.append(c.x()[0]);
        UEnd.append(c.U()[0]);
    }
    CHECK(mag(xEnd[0] - xEnd[1]) == 0);
    CHECK(mag(UEnd[0] - UEnd[1]) == 0);
}


// ************************************************************************* //
