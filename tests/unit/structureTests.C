/*---------------------------------------------------------------------------*\
    Elastic particle structure (total-Lagrangian): the oscillating plate of
    Gray, Monaghan & Swift (2001), shared/data/oscillatingPlate_gray2001.dat:
    L = 0.2 m free, H = 0.02 m, rho = 1000, E = 2e6 Pa, nu = 0.3975, plane
    strain, clamped at one end, initial velocity of the first bending mode
    with V_f = 0.001 (linear). Euler-Bernoulli period 0.2541 s.
\*---------------------------------------------------------------------------*/

#include <catch2/catch.hpp>
#include "totalLagrangianSolid.H"
#include "DynamicList.H"

using namespace Foam;

namespace
{

//- Structural step of the plate with n particles across: 0.3 h/c
scalar plateDeltaT(const label n)
{
    const scalar E = 2e6, nu = 0.3975;
    const scalar lambda = E*nu/((1 + nu)*(1 - 2*nu));
    const scalar mu = E/(2*(1 + nu));
    return 0.3*1.3*(0.02/n)/std::sqrt((lambda + 2*mu)/1000);
}


//- The plate with n particles across the thickness; tip mid-thickness
//  particles are returned in tipA, tipB
totalLagrangianSolid plate
(
    const label n,
    const scalar Vf,
    label& tipA,
    label& tipB
)
{
    const scalar L = 0.2, H = 0.02, rho = 1000, E = 2e6, nu = 0.3975;
    const scalar ds = H/n;
    const label nx = label(std::round(L/ds));
    const label nClamp = 4;

    DynamicList<vector2D> X;
    DynamicList<bool> clamped;
    for (label i = -nClamp; i < nx; ++i)
    {
        for (label j = 0; j < n; ++j)
        {
            X.append(vector2D((i + 0.5)*ds, (j + 0.5)*ds - 0.5*H));
            clamped.append(i < 0);
            if (i == nx - 1 && j == (n - 1)/2) tipA = X.size() - 1;
            if (i == nx - 1 && j == n/2) tipB = X.size() - 1;
        }
    }

    totalLagrangianSolid::properties props;
    props.rho = rho;
    props.E = E;
    props.nu = nu;
    props.planeStrain = true;
    props.spacing = ds;
    props.dt = plateDeltaT(n);

    totalLagrangianSolid solid(props, X, clamped);

    // First mode shape, kL = 1.875
    const scalar k = 1.875/L;
    auto f = [&](const scalar x)
    {
        return (std::cos(k*L) + std::cosh(k*L))*(std::cosh(k*x) - std::cos(k*x))
             + (std::sin(k*L) - std::sinh(k*L))*(std::sinh(k*x) - std::sin(k*x));
    };
    const scalar K = E/(3*(1 - 2*nu));
    const scalar c0 = std::sqrt(K/rho);
    forAll(X, i)
    {
        if (!clamped[i])
        {
            solid.v()[i] = vector2D(0, Vf*c0*f(X[i].x())/f(L));
        }
    }
    return solid;
}

//- Period from the upward zero crossings of the tip deflection
scalar period(totalLagrangianSolid& solid, label tipA, label tipB, scalar tEnd, scalar dt, scalar& energyDrift)
{
    const label nEvery = 5;
    scalar t = 0;
    scalar yPrev = 0;
    DynamicList<scalar> crossings;
    const scalar e0 = solid.kineticEnergy() + solid.strainEnergy();
    scalar eMaxDev = 0;
    while (t < tEnd)
    {
        solid.advance(nEvery);
        t += nEvery*dt;
        const scalar y =
            0.5*(solid.x()[tipA].y() + solid.x()[tipB].y())
          - 0.5*(solid.X()[tipA].y() + solid.X()[tipB].y());
        if (yPrev < 0 && y >= 0)
        {
            // linear interpolation of the crossing time
            crossings.append(t - nEvery*dt*y/(y - yPrev));
        }
        yPrev = y;
        const scalar e = solid.kineticEnergy() + solid.strainEnergy();
        eMaxDev = max(eMaxDev, mag(e - e0)/e0);
    }
    energyDrift = eMaxDev;
    INFO("upward zero crossings of the tip: " << crossings.size());
    REQUIRE(crossings.size() >= 2);
    return crossings[1] - crossings[0];
}

} // End anonymous namespace


TEST_CASE("oscillating plate period converges from above")
{
    // Coarse plates are too soft in bending (the kernel's support is cut at
    // the faces); the period must fall towards the beam value as the
    // number of particles across the thickness grows: measured 0.330,
    // 0.290, 0.269 s for 4, 6, 10 (16: 0.262 s, 24: 0.2589 s)
    scalar previous = GREAT;
    for (const label n : {4, 6, 10})
    {
        label tipA = -1, tipB = -1;
        totalLagrangianSolid solid(plate(n, 0.001, tipA, tipB));
        scalar drift = 0;
        const scalar T = period(solid, tipA, tipB, 0.75, plateDeltaT(n), drift);
        WARN("n = " << n << ": period " << T << " s, error "
            << 100*(T/0.2541 - 1) << "% against Euler-Bernoulli");
        CHECK(T < previous);
        CHECK(T > 0.2541);
        previous = T;
    }
}


TEST_CASE("oscillating plate period within 2% with 24 particles across")
{
    // Issue 5: within 2% of 0.2541 s. Euler-Bernoulli ignores shear, which
    // lengthens the period of a plate of L/H = 10 by about 1%; measured
    // 0.2589 s (+1.9%)
    label tipA = -1, tipB = -1;
    totalLagrangianSolid solid(plate(24, 0.001, tipA, tipB));
    scalar drift = 0;
    const scalar T = period(solid, tipA, tipB, 0.55, plateDeltaT(24), drift);
    WARN("n = 24: period " << T << " s, error " << 100*(T/0.2541 - 1)
        << "%, energy drift " << 100*drift << "%");
    CHECK(T == Approx(0.2541).epsilon(0.02));
}


TEST_CASE("energy of the undamped plate is kept over two periods")
{
    // Velocity Verlet is symplectic: kinetic + strain energy oscillates
    // around its initial value without drifting; issue 5 asks for < 1%
    label tipA = -1, tipB = -1;
    totalLagrangianSolid solid(plate(6, 0.001, tipA, tipB));
    scalar drift = 0;
    period(solid, tipA, tipB, 2*0.29, plateDeltaT(6), drift);
    WARN("largest relative energy deviation " << drift);
    CHECK(drift < 0.01);
}


TEST_CASE("a rigid rotation and translation give zero strain and force")
{
    label tipA = -1, tipB = -1;
    totalLagrangianSolid solid(plate(4, 0, tipA, tipB));
    const scalar angle = 0.7;
    const tensor2D R(std::cos(angle), -std::sin(angle), std::sin(angle), std::cos(angle));
    forAll(solid.x(), i)
    {
        solid.x()[i] = (R & solid.X()[i]) + vector2D(0.3, -1.2);
    }
    solid.evaluate();
    scalar maxStrain = 0;
    scalar maxAcc = 0;
    forAll(solid.x(), i)
    {
        maxStrain = max(maxStrain, mag(solid.greenStrain(i)));
        maxAcc = max(maxAcc, mag(solid.a()[i]));
    }
    CHECK(maxStrain < 1e-12);
    // A unit strain gives E/rho/ds ~ 1e4 m/s^2 here: 1e-6 is round-off
    CHECK(maxAcc < 1e-6);

    // A stretch of 1% gives the strain it should (Green: 0.01 + 0.01^2/2)
    forAll(solid.x(), i)
    {
        solid.x()[i] = vector2D(1.01*solid.X()[i].x(), solid.X()[i].y());
    }
    solid.evaluate();
    const label mid = solid.size()/2;
    CHECK(solid.greenStrain(mid).xx() == Approx(0.01 + 0.5*0.01*0.01).epsilon(1e-9));
    CHECK(std::abs(solid.greenStrain(mid).yy()) < 1e-12);
}
