/*---------------------------------------------------------------------------*\
    The structure's implicit time integration (timeIntegration
    generalisedAlpha) against the explicit Verlet integration and against
    what the generalised-alpha method promises (Chung & Hulbert 1993): the
    plate of Gray et al. (2001), 4 particles across, in its first mode;
    the tangent of coloured differences (structureTangent); its entries.
\*---------------------------------------------------------------------------*/
#include <catch2/catch.hpp>
#include "structureCases.H"
#include "structureModel.H"
#include "structureTangent.H"
#include "testTools.H"
#include "Random.H"

using namespace Foam;

namespace
{

using test::grayPlate;
using test::firstMode;
using test::tipDeflection;

std::string generalisedAlpha(const scalar rhoInf)
{
    return
        "structureModel { type rotatingParticles; }"
        " timeIntegration { type generalisedAlpha; spectralRadius "
      + std::to_string(rhoInf) + "; }" + grayPlate;
}

// The period (two upward zero crossings of the tip), the largest energy
// deviation from the start and the largest tip deflection, to tEnd
scalar period
(
    structureModel& s,
    const test::panel& p,
    const scalar tEnd,
    scalar& energyDeviation,
    scalar& amplitude
)
{
    const scalar dt = s.deltaT();
    const scalar e0 = s.kineticEnergy() + s.strainEnergy();
    scalar t = 0, yPrev = 0, dev = 0, amax = 0;
    DynamicList<scalar> crossings;
    while (t < tEnd)
    {
        s.advance(1);
        t += dt;
        const scalar y = tipDeflection(s, p);
        if (yPrev < 0 && y >= 0)
        {
            crossings.append(t - dt*y/(y - yPrev));
        }
        yPrev = y;
        amax = max(amax, mag(y));
        dev = max(dev, mag(s.kineticEnergy() + s.strainEnergy() - e0)/e0);
    }
    energyDeviation = dev;
    amplitude = amax;
    REQUIRE(crossings.size() >= 2);
    return crossings[1] - crossings[0];
}

} // End namespace


TEST_CASE("generalisedAlpha: the plate's period and amplitude as Verlet's, at 300 times its step")
{
    // Verlet at half its stable step (3e-6 s here) against the implicit
    // method at 1e-3 s (T/260): the implicit period lengthens by
    // (omega dt)^2/12 = 1.5e-4 (Hughes 2000, 9.3), the Newton iterations
    // stop at 1e-8 spacings; bound 5e-4 on the period and on the first
    // amplitude (the resolved mode keeps its energy at rho_inf 0.8:
    // the method's damping of it is O((omega dt)^3), 1e-5 a period)
    test::panel p(0.2, 0.02, 4, 4);
    scalar Tv = 0, Av = 0;
    {
        autoPtr<structureModel> s
        (
            p.model("structureModel { type rotatingParticles; }" + grayPlate)
        );
        s->setDeltaT(0.5*s->maxStableDeltaT());
        firstMode(s(), p, 0.001);
        scalar drift = 0;
        Tv = period(s(), p, 0.6, drift, Av);
    }
    autoPtr<structureModel> s(p.model(generalisedAlpha(0.8)));
    REQUIRE(s->implicit());
    s->setDeltaT(1e-3);
    firstMode(s(), p, 0.001);
    scalar drift = 0, A = 0;
    const scalar T = period(s(), p, 0.6, drift, A);
    WARN("Verlet (step " << 0.5*s->maxStableDeltaT() << " s): period " << Tv
        << " s, amplitude " << Av << " m; generalisedAlpha (step 1e-3 s): "
        << T << " s (" << 100*(T/Tv - 1) << "%), " << A << " m ("
        << 100*(A/Av - 1) << "%); " << scalar(s->nNewtonIterations())
          /s->nImplicitSteps() << " Newton iterations a step, "
        << s->nTangents() << " tangents");
    CHECK(T == Approx(Tv).epsilon(5e-4));
    CHECK(A == Approx(Av).epsilon(5e-4));
}


TEST_CASE("generalisedAlpha: spectralRadius 1 keeps the plate's energy, smaller ones take out the unresolved modes alone")
{
    // rho_inf = 1 is the trapezoidal rule: a linear structure keeps its
    // energy exactly; the plate at V_f = 0.001 is linear to 1e-6, the
    // Newton iterations stop at 1e-8 spacings: bound 1e-4 over two periods
    // at 1e-3 s (measured 1e-7). At rho_inf = 0.8 the first mode (omega dt
    // = 0.024) keeps its amplitude (the test above), and what goes is the
    // energy the Euler-Bernoulli shape puts into the plate's higher modes
    // (the second at omega dt = 0.15 loses some 1% a step): measured
    // 0.35%, bound 1% (a wrong mass or stiffness term is O(1)).
    // A random velocity field puts its energy into every mode, most of it
    // into those far above 1/dt, which rho_inf = 0 removes within a few
    // steps (their amplification tends to rho_inf) and rho_inf = 1 keeps:
    // after 10 steps of 1e-3 s, below 5% of the start against within 1e-4
    // of it.
    test::panel p(0.2, 0.02, 4, 4);
    for (const scalar rhoInf : {1.0, 0.8})
    {
        autoPtr<structureModel> s(p.model(generalisedAlpha(rhoInf)));
        s->setDeltaT(1e-3);
        firstMode(s(), p, 0.001);
        scalar drift = 0, A = 0;
        period(s(), p, 2.1*0.26, drift, A);
        WARN("rho_inf " << rhoInf << ": largest energy deviation " << drift
            << " over two periods");
        CHECK(drift < (rhoInf == 1 ? 1e-4 : 1e-2));
    }

    scalarList kept(2);
    forAll(kept, k)
    {
        const scalar rhoInf = k;
        autoPtr<structureModel> s(p.model(generalisedAlpha(rhoInf)));
        s->setDeltaT(1e-3);
        Random rnd(99);
        forAll(p.X, i)
        {
            if (!p.clamped[i])
            {
                s->v()[i] =
                    1e-3*vector2D(rnd.sample01<scalar>() - 0.5, rnd.sample01<scalar>() - 0.5);
            }
        }
        s->evaluate();
        const scalar e0 = s->kineticEnergy() + s->strainEnergy();
        s->advance(10);
        kept[k] = (s->kineticEnergy() + s->strainEnergy())/e0;
    }
    WARN("a random velocity field's energy after 10 steps of 1e-3 s: "
        << kept[0] << " of the start at rho_inf 0, " << kept[1] << " at 1");
    CHECK(kept[0] < 0.05);
    CHECK(kept[1] == Approx(1).epsilon(1e-4));
}


TEST_CASE("generalisedAlpha: each step's impulse is the load held over it")
{
    // A free plate (no clamps) under a uniform load that grows by dF a
    // step, held over each step as the coupling holds the fluid's: the
    // internal forces sum to zero, so the momentum is the impulse the
    // scheme gives the loads. Verlet's is sum(F_k dt) by construction.
    // The balance at n + 1 - alpha_f with the held load itself lags each
    // step's impulse by (1/2 - alpha_f) dt of the load's change: the
    // momentum falls short by (1/2 - alpha_f) F_N dt (at rho_inf 0.8,
    // 5.6% of the last step's impulse; a body moving at V turns that into
    // V times it of spurious work). With the load extrapolated from the
    // steps' middles, what is left is the start's transient (the first
    // load a jump from rest, whose algorithmic accelerations decay by
    // alpha_m/(1 - alpha_m) a step): a constant, the same after 40 and 80
    // steps (bound 1e-9 of the impulse; the lagged load's would differ by
    // 0.056 x 40 dF dt = 7% of the 40-step difference), and smaller than
    // the first step's impulse.
    test::panel p(0.2, 0.02, 4, 0);
    const vector2D dF(0.3, -1.0);
    const scalar dt = 1e-4;
    const label nP = p.X.size();
    for (const scalar rhoInf : {1.0, 0.8, 0.5})
    {
        scalarList deficit(2);
        forAll(deficit, run)
        {
            autoPtr<structureModel> s(p.model(generalisedAlpha(rhoInf)));
            s->setDeltaT(dt);
            scalar impulse = 0;
            for (label k = 1; k <= 40*(run + 1); ++k)
            {
                forAll(p.X, i)
                {
                    s->externalForce()[i] = scalar(k)*dF;
                }
                s->advance(1);
                impulse += nP*k*dF.y()*dt;
            }
            scalar momentum = 0;
            forAll(p.X, i)
            {
                momentum += s->mass()*s->v()[i].y();
            }
            deficit[run] = momentum - impulse;
        }
        WARN("rho_inf " << rhoInf << ": momentum minus the held loads'"
            << " impulse after 40 and 80 steps " << deficit[0] << ", "
            << deficit[1] << " (one step's growth of the impulse "
            << nP*dF.y()*dt << ")");
        CHECK(mag(deficit[1] - deficit[0]) < 1e-9*nP*mag(dF.y())*dt*40*81);
        CHECK(mag(deficit[0]) < nP*mag(dF.y())*dt);
    }
}


TEST_CASE("generalisedAlpha: a state copied with its accelerations continues as the run (the restart)")
{
    // A step depends on its start (positions, velocities, rotations, their
    // rates and the algorithmic accelerations), and on the tangent that
    // served only through the Newton tolerance (1e-10 spacings): a copy
    // that takes the state (and builds its tangent there, as a restart
    // does) continues within 1e-12 m of the run over 50 steps (measured
    // below; a state member not carried gives 1e-6 or more)
    test::panel p(0.2, 0.02, 4, 4);
    autoPtr<structureModel> a(p.model(generalisedAlpha(0.8)));
    a->setDeltaT(1e-3);
    firstMode(a(), p, 0.01);
    a->advance(37);

    autoPtr<structureModel> b(p.model(generalisedAlpha(0.8)));
    b->setDeltaT(1e-3);
    b->x() = a->x();
    b->v() = a->v();
    b->theta() = a->theta();
    b->omega() = a->omega();
    b->setTime(a->time());
    b->restored();
    b->setStepAccelerations
    (
        a->stepAcceleration(), a->stepAngularAcceleration(), a->stepLoad()
    );

    a->advance(50);
    b->advance(50);
    scalar dx = 0, dv = 0;
    forAll(p.X, i)
    {
        dx = max(dx, mag(a->x()[i] - b->x()[i]));
        dv = max(dv, mag(a->v()[i] - b->v()[i]));
    }
    WARN("after 50 steps: positions within " << dx << " m, velocities "
        << dv << " m/s");
    CHECK(dx < 1e-12);
    CHECK(dv < 1e-9);
}


TEST_CASE("structureTangent: the colouring's tangent equals a column by column one")
{
    // K by coloured differences (Curtis, Powell & Reid) against the plain
    // one, a force evaluation per unknown, on a panel 3 across with its
    // clamp: K^-1 (K e_j) = e_j, both by forward differences at 1e-7
    // spacings (each off by some 1e-7 of K) and through K's conditioning
    // (some 1e2 on this panel): measured 1.4e-5, bound 1e-4 (a column
    // given to the wrong particle is O(1)). Also on the panel twice, the
    // copy ten lengths away: two parts, each one's block factorised and
    // solved on its own, must give the same columns (a column put in the
    // other part, or at the wrong place in its own, is O(1))
    const label copies = GENERATE(1, 2);
    test::panel p(0.03, 0.003, 3, 3);
    autoPtr<structureModel> s
    (
        p.model("structureModel { type rotatingParticles; }" + grayPlate)
    );
    const label n1 = s->size();
    auto panelForces = [&]
    (
        const UList<vector2D>& x,
        const UList<scalar>& theta,
        List<vector2D>& F,
        scalarList& T
    )
    {
        const List<vector2D> x0(s->x());
        const scalarList t0(s->theta());
        s->x() = x;
        s->theta() = theta;
        s->evaluate();
        F.setSize(n1);
        T.setSize(n1);
        const scalar m = s->mass(), I = s->rotationalInertia();
        forAll(F, i)
        {
            F[i] = m*s->a()[i];
            T[i] = I*s->alpha()[i];
        }
        s->x() = x0;
        s->theta() = t0;
    };

    // The structure: the panel's particles, copy after copy
    const label n = copies*n1;
    const vector2D offset(0, 10*p.L);
    List<vector2D> X(n);
    List<bool> clamped(n);
    forAll(X, k)
    {
        X[k] = s->X()[k % n1] + scalar(k/n1)*offset;
        clamped[k] = p.clamped[k % n1];
    }
    auto forces = [&]
    (
        const UList<vector2D>& x,
        const UList<scalar>& theta,
        List<vector2D>& F,
        scalarList& T
    )
    {
        F.setSize(n);
        T.setSize(n);
        for (label c = 0; c < copies; ++c)
        {
            List<vector2D> xc(n1), Fc;
            scalarList tc(n1), Tc;
            forAll(xc, i)
            {
                xc[i] = x[c*n1 + i] - scalar(c)*offset;
                tc[i] = theta[c*n1 + i];
            }
            panelForces(xc, tc, Fc, Tc);
            forAll(Fc, i)
            {
                F[c*n1 + i] = Fc[i];
                T[c*n1 + i] = Tc[i];
            }
        }
    };
    structureTangent tangent(X, clamped, p.ds);
    List<vector2D> x(X);
    scalarList theta(n, Zero);
    // about a bent state (the tip 0.1 spacings down)
    forAll(x, i)
    {
        if (!clamped[i])
        {
            x[i].y() -= 0.1*p.ds*sqr(p.X[i % n1].x()/p.L);
        }
    }
    tangent.build(x, theta, forces);
    WARN(tangent.nColours() << " colours for " << tangent.size()
        << " unknowns in " << tangent.nParts() << " parts; "
        << tangent.nEvaluations() << " force evaluations");
    CHECK(tangent.nColours() < n1/2);
    CHECK(tangent.nParts() == copies);

    // Column by column: A = K (cM 0, cK 1), solve against K e_k
    tangent.factorise(0, 1, s->mass(), s->rotationalInertia());
    const scalar h = 1e-7*p.ds;
    List<vector2D> F0, F1, du;
    scalarList T0, T1, dth;
    forces(x, theta, F0, T0);
    scalar worst = 0;
    label checked = 0;
    forAll(x, j)
    {
        if (clamped[j] || j % 5)
        {
            continue;
        }
        List<vector2D> xp(x);
        xp[j].y() += h;
        forces(xp, theta, F1, T1);
        List<vector2D> rF(n);
        scalarList rT(n);
        forAll(rF, i)
        {
            rF[i] = -(F1[i] - F0[i])/h;
            rT[i] = -(T1[i] - T0[i])/h;
        }
        // K^-1 (K e_j) = e_j
        tangent.solve(rF, rT, du, dth);
        forAll(du, i)
        {
            const scalar expected = (i == j) ? 1 : 0;
            worst = max(worst, mag(du[i].y() - expected) + mag(du[i].x()));
        }
        ++checked;
    }
    WARN(checked << " columns: largest deviation of K^-1 K e_j from e_j " << worst);
    CHECK(worst < 1e-4);
}


TEST_CASE("timeIntegration: wrong entries stop with the entry named")
{
    test::panel p(0.01, 0.002, 2);
    const std::string aluminium = "rho 2700; E 68e9; nu 0.3; planeStrain yes;";
    CHECK_THAT
    (
        test::errorOf([&]{ p.model("structureModel { type rotatingParticles; } timeIntegration { type Newmark; }" + aluminium); }),
        Catch::Contains("Newmark") && Catch::Contains("Verlet") && Catch::Contains("generalisedAlpha")
    );
    CHECK_THAT
    (
        test::errorOf([&]{ p.model("structureModel { type rotatingParticles; } timeIntegration { type generalisedAlpha; spectralRadius 1.5; }" + aluminium); }),
        Catch::Contains("spectralRadius") && Catch::Contains("[0, 1]")
    );
    CHECK_THAT
    (
        test::errorOf([&]{ p.model("structureModel { type rotatingParticles; } timeIntegration { type generalisedAlpha; spectralRadus 0.5; }" + aluminium); }),
        Catch::Contains("spectralRadus")
    );
    CHECK_THAT
    (
        test::errorOf([&]{ p.model("structureModel { type rotatingParticles; } stiffnessDamping 1e-6; timeIntegration { type generalisedAlpha; }" + aluminium); }),
        Catch::Contains("stiffnessDamping") && Catch::Contains("spectralRadius")
    );
    CHECK_THAT
    (
        test::errorOf([&]{ p.model("structureModel { type rotatingParticles; } timeIntegration { type Verlet; spectralRadius 0.5; }" + aluminium); }),
        Catch::Contains("spectralRadius") && Catch::Contains("generalisedAlpha")
    );
    CHECK_THAT
    (
        test::errorOf([&]{ p.model("structureModel { type rigid; } timeIntegration { type generalisedAlpha; }" + aluminium); }),
        Catch::Contains("rigid") && Catch::Contains("timeIntegration")
    );
}
