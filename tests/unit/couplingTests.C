/*---------------------------------------------------------------------------*\
    The fluid-structure interface (fluidStructureInterface): the wall
    pressures go to the structure's interface layer with weights that sum
    to one (the force balance to round-off), and the attached wall and
    dummy particles follow a rigid motion of the structure exactly.
\*---------------------------------------------------------------------------*/

#include <catch2/catch.hpp>
#include "couplingScheme.H"
#include "particleGenerator.H"
#include "Time.H"
#include "testTools.H"

using namespace Foam;

namespace
{

// A rigid panel 0.2 m x 4 mm (structural spacing 1 mm) above its wall
// layer (l0 = 5 mm, one wall and two dummy layers below it)
const scalar l0 = 0.005;

const char* particles =
    "regions {"
    " panel { type strip; kind structure; start (0 0); angle 0;"
    "   length 0.2; side left; thickness 0.004; }"
    " wet { type strip; kind wall; points ((0 0) (0.2 0)); side right;"
    "   layers 3; dummyLayers 2; } }";

const char* properties =
    "structureModel { type rigid; } rho 2700; E 68e9; nu 0.3;"
    " planeStrain yes; nSubSteps 1; clamped (panel);"
    " coupling { walls (wet); pressureRadius 1.5; }";

} // End anonymous namespace


TEST_CASE("interface: wall pressures to the interface layer, force balance")
{
    autoPtr<Time> runTime(Time::New());
    mpsCloud cloud;
    const boundBox domain(point(-1, -1, -1), point(1, 1, 1));
    particleGenerator(test::dict(particles), l0, l0/5).generate(cloud, domain);
    const dictionary props(test::dict(properties));
    mpsStructure structure(runTime(), cloud, props, 1e-4);
    fluidStructureInterface coupling(runTime(), cloud, structure, props, l0);
    REQUIRE(coupling.active());

    // A pressure varying along the wall: p = 1000 (1 + 20 x) + 3 (i % 7)
    const label wet = cloud.regionIndex("wet");
    vector2D expected(Zero);
    label nWall = 0;
    for (label i = cloud.begin(particleKind::wall); i < cloud.end(particleKind::wall); ++i)
    {
        if (cloud.region()[i] == wet)
        {
            cloud.p()[i] = 1000*(1 + 20*cloud.x()[i].x()) + 3*(i % 7);
            // -p l0 n with the normal n = (0, -1) into the fluid below
            expected += vector2D(0, cloud.p()[i]*l0);
            ++nWall;
        }
    }
    REQUIRE(nWall == 40);

    // The explicit scheme's coupling step after a fluid step: the wall
    // pressures (solved: the cloud's) to the layer, the structure's step,
    // the walls moved
    mpsFluid fluid
    (
        cloud,
        test::dict
        (
            "rho 1000; nu 1e-6; g (0 -9.81 0); l0 0.005;"
            " kernel { type original; }"
            " re { numberDensity 2.1; gradient 2.1; laplacian 2.1; viscosity 2.1; }"
            " freeSurface { type improved; } collision { type none; }"
            " pressureSolver { type PCG; }"
        ),
        domain
    );
    coupling.transferPressure(fluid);
    couplingScheme::advanceStructure(structure, 1e-4, 1e-4, coupling.force());
    coupling.moveWalls();

    // The fluid's force: -p l0 n summed over the wall particles
    CHECK(coupling.fluidForce().x() == Approx(0).margin(1e-9*expected.y()));
    CHECK(coupling.fluidForce().y() == Approx(expected.y()).epsilon(1e-12));

    // Its share on the structure: the same sum (weights sum to one), and
    // only on the layer that faces the wall (the bottom row)
    const structureModel& m = structure.model();
    // (the bottom row but its two end particles, whose face is the end)
    vector2D sum(Zero);
    scalar onUpperRows = 0;
    label nLoaded = 0;
    forAll(coupling.force(), k)
    {
        sum += coupling.force()[k];
        if (m.X()[k].y() > 0.001)
        {
            onUpperRows += mag(coupling.force()[k]);
        }
        else
        {
            CHECK(coupling.force()[k].y() >= 0);
            nLoaded += coupling.force()[k].y() > 0;
        }
    }
    CHECK(nLoaded == 198);
    CHECK(mag(sum - coupling.fluidForce()) < 1e-12*expected.y());
    CHECK(onUpperRows == 0);
    CHECK(coupling.maxImbalance() < 1e-12*expected.y());

    // The structure carries the pressure where the wall has it: over each
    // wall spacing l0 (the wall particle at its centre), the bottom row's
    // force per unit length is the local pressure (the kernel spreads a
    // wall particle's force over +-1.5 l0, symmetrically)
    label nWindows = 0;
    for (label w = 4; w < 36; ++w)
    {
        scalar F = 0;
        forAll(m.X(), k)
        {
            const vector2D& X = m.X()[k];
            if (X.y() < 0.001 && X.x() >= w*l0 && X.x() < (w + 1)*l0)
            {
                F += coupling.force()[k].y();
            }
        }
        const scalar p = 1000*(1 + 20*(w + 0.5)*l0);
        INFO("window " << w << ": " << F/l0 << " Pa against " << p);
        CHECK(F/l0 == Approx(p).epsilon(0.02));
        ++nWindows;
    }
    CHECK(nWindows == 32);
}


TEST_CASE("interface: attached walls follow a rigid motion of the structure exactly")
{
    autoPtr<Time> runTime(Time::New());
    mpsCloud cloud;
    const boundBox domain(point(-1, -1, -1), point(1, 1, 1));
    particleGenerator(test::dict(particles), l0, l0/5).generate(cloud, domain);
    const dictionary props(test::dict(properties));
    mpsStructure structure(runTime(), cloud, props, 1e-4);
    fluidStructureInterface coupling(runTime(), cloud, structure, props, l0);

    // Reference positions of the wall and dummy particles, by id
    const label wet = cloud.regionIndex("wet");
    DynamicList<label> ids;
    DynamicList<vector2D> X0;
    forAll(cloud.x(), i)
    {
        if (cloud.region()[i] == wet)
        {
            ids.append(cloud.id()[i]);
            X0.append(cloud.x()[i]);
        }
    }
    REQUIRE(ids.size() == 120);

    // The structure turned by a about c, spinning at w, and moved by d
    const vector2D c(0.1, 0.05), d(0.03, -0.02);
    const scalar a = 0.3, w = 2.0;
    auto rigid = [&](const vector2D& X)
    {
        return c + d + structureModel::rotate(a, X - c);
    };
    auto velocity = [&](const vector2D& x)
    {
        const vector2D r(x - c - d);
        return vector2D(0.5, -4) + w*vector2D(-r.y(), r.x());
    };
    structureModel& m = structure.model();
    forAll(m.x(), k)
    {
        m.x()[k] = rigid(m.X()[k]);
        m.v()[k] = velocity(m.x()[k]);
        m.theta()[k] = a;
        m.omega()[k] = w;
    }
    coupling.moveWalls();

    scalar dx = 0, du = 0;
    forAll(ids, k)
    {
        const label i = cloud.index(ids[k]);
        dx = max(dx, mag(cloud.x()[i] - rigid(X0[k])));
        du = max(du, mag(cloud.U()[i] - velocity(cloud.x()[i])));
    }
    INFO("largest position error " << dx << " m, velocity error " << du);
    CHECK(dx < 1e-14);
    CHECK(du < 1e-13);
}
