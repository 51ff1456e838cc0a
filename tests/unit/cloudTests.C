/*---------------------------------------------------------------------------*\
    The particle cloud (mpsCloud): kinds kept in order, ids and fields kept
    together through appending, removing, reordering and sending to
    another cloud (the ranks' exchange); and the output
    round trip (lagrangian files written, then read back for a restart).
\*---------------------------------------------------------------------------*/

#include <catch2/catch.hpp>
#include "mpsCloud.H"
#include "cloudFields.H"
#include "lagrangianCloudWriter.H"
#include <iterator>
#include "IFstream.H"
#include "OStringStream.H"
#include "lagrangianCloudReader.H"
#include "particleGenerator.H"
#include "cellModel.H"
#include "wallPolyPatch.H"
#include "OSspecific.H"
#include "Time.H"
#include "testTools.H"
#include "StringStream.H"

using namespace Foam;

namespace
{

// Mark each particle's fields with its id, to check they travel together
void markById(mpsCloud& c)
{
    forAll(c.id(), i)
    {
        const label id = c.id()[i];
        c.U()[i] = vector2D(id, -id);
        c.p()[i] = 10*id;
        c.n()[i] = 100*id;
        c.surface()[i] = id % 2;
    }
}

// Every particle's fields carry its id; index(id) finds it; kinds in order
void checkConsistent(const mpsCloud& c)
{
    forAll(c.id(), i)
    {
        const label id = c.id()[i];
        INFO("particle " << i << ", id " << id);
        CHECK(c.index(id) == i);
        CHECK(c.U()[i] == vector2D(id, -id));
        CHECK(c.p()[i] == 10*id);
        CHECK(c.n()[i] == 100*id);
        CHECK(c.surface()[i] == bool(id % 2));
        CHECK(c.x()[i].x() == Approx(0.01*id));
        if (i > 0)
        {
            CHECK(int(c.kind()[i - 1]) <= int(c.kind()[i]));
        }
    }
    label total = 0;
    for (int k = 0; k < nParticleKinds; ++k)
    {
        const particleKind kind = static_cast<particleKind>(k);
        CHECK(c.begin(kind) == total);
        for (label i = c.begin(kind); i < c.end(kind); ++i)
        {
            CHECK(c.kind()[i] == kind);
        }
        total += c.count(kind);
    }
    CHECK(total == c.size());
}

// Particle at x = 0.01 id, appended with the next id
void add(mpsCloud& c, const particleKind k, const label r, const label n)
{
    List<vector2D> x(n);
    forAll(x, j)
    {
        x[j] = vector2D(0.01*(c.size() + j), 0);
    }
    c.append(x, k, r, 0.01);
}

} // End anonymous namespace


TEST_CASE("cloud keeps kinds in order and ids with their fields")
{
    mpsCloud c;
    const label r = c.addRegion("any");

    // Appended out of kind order: structure, fluid, dummy, wall, fluid
    add(c, particleKind::structure, r, 3);
    add(c, particleKind::fluid, r, 4);
    add(c, particleKind::dummy, r, 2);
    add(c, particleKind::wall, r, 3);
    add(c, particleKind::fluid, r, 2);
    REQUIRE(c.size() == 14);
    CHECK(c.count(particleKind::fluid) == 6);
    CHECK(c.count(particleKind::wall) == 3);
    CHECK(c.count(particleKind::dummy) == 2);
    CHECK(c.count(particleKind::structure) == 3);

    // Within a kind, the order of appending: fluid ids 3-6, then 12, 13
    CHECK(c.id()[0] == 3);
    CHECK(c.id()[4] == 12);
    CHECK(c.id()[5] == 13);
    CHECK(c.id()[c.begin(particleKind::structure)] == 0);

    markById(c);
    checkConsistent(c);

    SECTION("removing keeps the others and their fields; removed ids are gone")
    {
        List<bool> keep(c.size(), true);
        keep[c.index(4)] = false;     // a fluid particle
        keep[c.index(10)] = false;    // a wall particle
        c.subset(keep);
        CHECK(c.size() == 12);
        CHECK(c.index(4) == -1);
        CHECK(c.index(10) == -1);
        CHECK(c.count(particleKind::fluid) == 5);
        CHECK(c.count(particleKind::wall) == 2);
        checkConsistent(c);

        // and more appended after a removal take new ids
        add(c, particleKind::wall, r, 1);
        CHECK(c.id()[c.end(particleKind::wall) - 1] == 14);
        c.U()[c.index(14)] = vector2D(14, -14);
        c.p()[c.index(14)] = 140;
        c.n()[c.index(14)] = 1400;
        c.x()[c.index(14)] = vector2D(0.14, 0);
        checkConsistent(c);
    }

    SECTION("particles sent through a stream arrive whole (ranks' exchange)")
    {
        // Another rank's cloud: a subset of the same particles
        mpsCloud other(c);
        List<bool> keepOther(other.size(), false);
        keepOther[other.index(3)] = true;      // fluid
        keepOther[other.index(0)] = true;      // structure
        other.subset(keepOther);
        REQUIRE(other.size() == 2);

        // Send a structural, a wall, a fluid and a dummy particle
        // out of kind order; the sender's cloud is untouched
        const labelList sent
        ({
            c.index(1), c.index(9), c.index(12), c.index(7)
        });
        OStringStream os;
        c.send(sent, os);
        CHECK(c.size() == 14);

        IStringStream is(os.str());
        const labelList ids = other.receive(is);
        CHECK(ids == labelList({1, 9, 12, 7}));
        CHECK(other.size() == 6);
        CHECK(other.count(particleKind::fluid) == 2);
        CHECK(other.count(particleKind::wall) == 1);
        CHECK(other.count(particleKind::dummy) == 1);
        CHECK(other.count(particleKind::structure) == 2);
        checkConsistent(other);
        for (const label id : ids)
        {
            CHECK(other.region()[other.index(id)] == r);
            CHECK(other.spacing()[other.index(id)] == 0.01);
            CHECK_FALSE(other.halo()[other.index(id)]);
        }

        // Into an empty cloud, ids beyond any it knew (in any order)
        mpsCloud empty;
        IStringStream isEmpty(os.str());
        CHECK(empty.receive(isEmpty) == labelList({1, 9, 12, 7}));
        CHECK(empty.size() == 4);
        checkConsistent(empty);

        // An id already held is an error, not a second copy
        OStringStream again;
        c.send(labelList({c.index(3)}), again);
        IStringStream isAgain(again.str());
        FatalError.throwExceptions();
        CHECK_THROWS(other.receive(isAgain));
        FatalError.dontThrowExceptions();
    }

    SECTION("a copy has a table of its own")
    {
        mpsCloud copy(c);
        copy.p()[0] = -1;
        CHECK(c.p()[0] == 10*c.id()[0]);
        List<bool> keep(copy.size(), true);
        keep[0] = false;
        copy.subset(keep);
        CHECK(copy.size() == c.size() - 1);
        CHECK(copy.index(c.id()[0]) == -1);
        checkConsistent(c);
    }

    SECTION("the table of fields is what output writes")
    {
        const cloudFields out("wall", c);
        CHECK(out.size() == 5);
        CHECK(out.vectorFields().found("U"));
        CHECK(out.scalarFields().found("p"));
        CHECK(out.scalarFields().found("n"));
        for (const word& f : {"kind", "region", "freeSurface", "id"})
        {
            CHECK(out.labelFields().found(f));
        }
        CHECK(!out.scalarFields().found("spacing"));

        // The structure's cloud carries no fluid quantities
        const cloudFields solid("structure", c);
        CHECK(solid.size() == 3);
        CHECK(solid.vectorFields().found("U"));
        CHECK(!solid.scalarFields().found("p"));
        CHECK(!solid.scalarFields().found("n"));
        CHECK(!solid.labelFields().found("freeSurface"));
        const labelField& id = out.labelFields()["id"];
        const scalarField& p = out.scalarFields()["p"];
        forAll(id, k)
        {
            CHECK(p[k] == 10*id[k]);
            CHECK(out.positions()[k].x() == Approx(0.01*id[k]));
        }
    }

    c.clear();
    CHECK(c.size() == 0);
    CHECK(c.count(particleKind::wall) == 0);
    CHECK(c.index(0) == -1);
}


TEST_CASE("output round trip: a written cloud reads back exactly")
{
    // A case of one hexahedral cell, the domain [-0.2, 1.2] x [-0.2, 0.5]
    const fileName caseDir(fileName(getEnv("TEST_TMP").empty() ? "/tmp" : getEnv("TEST_TMP"))/"cloudRoundTrip");
    if (isDir(caseDir))
    {
        rmDir(caseDir);
    }
    mkDir(caseDir);
    autoPtr<Time> timePtr(Time::New(caseDir));
    Time& runTime = timePtr();
    runTime.setTime(0.25, 1);

    pointField points
    ({
        point(-0.2, -0.2, -0.5), point(1.2, -0.2, -0.5),
        point(1.2, 0.5, -0.5), point(-0.2, 0.5, -0.5),
        point(-0.2, -0.2, 0.5), point(1.2, -0.2, 0.5),
        point(1.2, 0.5, 0.5), point(-0.2, 0.5, 0.5)
    });
    faceList faces(cellModel::ref(cellModel::HEX).faces(identity(8)));
    polyMesh mesh
    (
        IOobject
        (
            polyMesh::defaultRegion, runTime.timeName(), runTime,
            IOobject::NO_READ, IOobject::NO_WRITE
        ),
        std::move(points),
        std::move(faces),
        labelList(6, Zero),
        labelList()
    );
    List<polyPatch*> patches
    ({
        new wallPolyPatch("walls", 6, 0, 0, mesh.boundaryMesh(), "wall")
    });
    mesh.addPatches(patches);

    // Generated, then moved on: positions, velocities and pressures to
    // full precision
    const dictionary particleDict
    (
        test::dict
        (
            "regions {"
            " water { type box; kind fluid; min (0 0); max (0.5 0.2); }"
            " tank { type strip; kind wall; points ((0 0.4) (0 0) (1 0) (1 0.4));"
            "   side right; layers 3; dummyLayers 2; } }"
        )
    );
    const boundBox domain(point(-0.2, -0.2, -0.5), point(1.2, 0.5, 0.5));
    mpsCloud written;
    particleGenerator(particleDict, 0.05, 0.01).generate(written, domain);
    const label nFluid = written.count(particleKind::fluid);
    forAll(written.x(), i)
    {
        written.x()[i] += vector2D(1e-3/3*i/written.size(), 1e-4/7);
        written.U()[i] = vector2D(std::sqrt(2.0)*i, -1.0/(i + 3));
        written.p()[i] = 1000.0/(i + 7);
    }

    // One fluid particle left the domain before the write
    List<bool> keep(written.size(), true);
    keep[3] = false;
    const label lostId = written.id()[3];
    written.subset(keep);

    const unsigned precision = IOstream::defaultPrecision();
    IOstream::defaultPrecision(17);
    const lagrangianCloudWriter writer(mesh);
    REQUIRE
    (
        writer.write(cloudFields("fluid", written), runTime.timeName())
       .empty()
    );
    REQUIRE
    (
        writer.write(cloudFields("wall", written), runTime.timeName())
       .empty()
    );
    // The fields' text is OpenFOAM's own (the writer formats the values
    // of a long list on the threads): the velocity's values, one a line,
    // as Field's operator<< writes them
    {
        const cloudFields fluid("fluid", written);
        OStringStream expected;
        expected.precision(17);
        expected << fluid.vectorFields()["U"];
        IFstream is(runTime.path()/runTime.timeName()/"lagrangian/fluid/U");
        const std::string text
        (
            (std::istreambuf_iterator<char>(is.stdStream())),
            std::istreambuf_iterator<char>()
        );
        REQUIRE(fluid.size() > 10);
        CHECK(text.find(expected.str()) != std::string::npos);
    }
    IOstream::defaultPrecision(precision);

    const lagrangianCloudReader reader(mesh);
    REQUIRE(reader.found());
    mpsCloud read;
    particleGenerator(particleDict, 0.05, 0.01).generate(read, domain);
    reader.read(read);

    REQUIRE(read.size() == written.size());
    CHECK(read.count(particleKind::fluid) == nFluid - 1);
    CHECK(read.index(lostId) == -1);
    forAll(written.id(), i)
    {
        const label j = read.index(written.id()[i]);
        REQUIRE(j >= 0);
        CHECK(read.x()[j] == written.x()[i]);
        CHECK(read.U()[j] == written.U()[i]);
        CHECK(read.p()[j] == written.p()[i]);
        CHECK(read.kind()[j] == written.kind()[i]);
        CHECK(read.region()[j] == written.region()[i]);
    }
}
