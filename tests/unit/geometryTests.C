/*---------------------------------------------------------------------------*\
    Particle generation: shapes against counts and positions worked out by
    hand, the wedge of two panels at a deadrise angle, merged corners, and
    the errors of bad input.
\*---------------------------------------------------------------------------*/

#include <catch2/catch.hpp>
#include "testTools.H"
#include "particleGenerator.H"
#include "particleShape.H"
#include "mathematicalConstants.H"

using namespace Foam;
using Catch::Matchers::Contains;

namespace
{

const boundBox bigDomain(point(-10, -10, -1), point(10, 10, 1));

mpsCloud generate(const std::string& regions, const scalar l0 = 0.1)
{
    const dictionary d(test::dict("regions {" + regions + "}"));
    mpsCloud cloud;
    particleGenerator(d, l0, l0/5).generate(cloud, bigDomain);
    return cloud;
}

std::string generateError
(
    const std::string& regions,
    const boundBox& domain = bigDomain
)
{
    const dictionary d(test::dict("regions {" + regions + "}"));
    mpsCloud cloud;
    return test::errorOf
    (
        [&]() { particleGenerator(d, 0.1, 0.02).generate(cloud, domain); }
    );
}

} // End anonymous namespace


TEST_CASE("box fills a rectangle cell-centred")
{
    const mpsCloud c = generate
    (
        "water { type box; kind fluid; min (0 0); max (1 0.5); }"
    );
    REQUIRE(c.size() == 10*5);
    CHECK(c.count(particleKind::fluid) == 50);
    CHECK(c.x()[0].x() == Approx(0.05));
    CHECK(c.x()[0].y() == Approx(0.05));
    CHECK(c.x()[49].x() == Approx(0.95));
    CHECK(c.x()[49].y() == Approx(0.45));
    CHECK(c.spacing()[0] == 0.1);
}


TEST_CASE("polygon keeps the lattice points inside")
{
    // Right triangle with legs 1: points ((i+1/2), (j+1/2)) 0.1 inside
    // x + y < 1 need i + j <= 8: 9 + 8 + ... + 1 = 45 points
    const mpsCloud c = generate
    (
        "t { type polygon; kind fluid; points ((0 0) (1 0) (0 1)); }"
    );
    CHECK(c.size() == 45);
}


TEST_CASE("strip walls with dummy layers fill the corners once")
{
    // A U-shaped tank 1 wide, 0.5 high, 1 wall and 2 dummy layers outside
    const mpsCloud c = generate
    (
        "tank { type strip; kind wall; points ((0 0.5) (0 0) (1 0) (1 0.5));"
        " side right; layers 3; dummyLayers 2; }"
    );
    // Straight parts: 5 + 10 + 5 particles per layer; each outer corner a
    // 3 x 3 square of which the inner one is wall
    CHECK(c.count(particleKind::wall) == 5 + 10 + 5 + 2);
    CHECK(c.count(particleKind::dummy) == 2*(5 + 10 + 5) + 2*8);

    // No two particles closer than the spacing
    scalar dMin = GREAT;
    for (label i = 0; i < c.size(); ++i)
    {
        for (label j = i + 1; j < c.size(); ++j)
        {
            dMin = min(dMin, mag(c.x()[j] - c.x()[i]));
        }
    }
    CHECK(dMin == Approx(0.1));

    // All wall particles lie half a spacing outside the tank
    forAll(c.x(), i)
    {
        if (c.kind()[i] == particleKind::wall)
        {
            const vector2D& p = c.x()[i];
            const bool onLeft = mag(p.x() + 0.05) < 1e-12;
            const bool onRight = mag(p.x() - 1.05) < 1e-12;
            const bool onFloor = mag(p.y() + 0.05) < 1e-12;
            CHECK((onLeft || onRight || onFloor));
        }
    }
}


TEST_CASE("a wedge of two panels at a deadrise angle")
{
    // Panels 0.3 long, 0.002 thick, structural spacing l0/5 = 0.0004 (5
    // layers), from the keel at (0 0) upwards at deadrise 10 degrees
    const scalar beta = 10*constant::mathematical::pi/180;
    const mpsCloud c = generate
    (
        "right { type strip; kind structure; start (0 0); angle 10;"
        " length 0.3; side left; thickness 0.002; }"
        "left  { type strip; kind structure; start (0 0); angle 170;"
        " length 0.3; side right; thickness 0.002; }",
        0.002
    );
    const scalar s = 0.002/5;
    const label nAlong = label(std::round(0.3/s));
    CHECK(c.spacing()[0] == Approx(s));

    // The panels' inner layers cross at the keel; the generator merges the
    // left panel's particles there, and only there
    label nRight = 0;
    forAll(c.x(), i)
    {
        if (c.region()[i] == 0)
        {
            ++nRight;
        }
        else if (c.region()[i] == 1)
        {
            CHECK(c.x()[i].x() <= 0);
        }
    }
    CHECK(nRight == 5*nAlong);
    const label nMerged = 2*5*nAlong - c.size();
    CHECK(nMerged > 0);
    CHECK(nMerged <= 5*5);
    scalar dMin = GREAT;
    for (label i = 0; i < 200; ++i)
    {
        for (label j = 0; j < c.size(); ++j)
        {
            if (j != i)
            {
                dMin = min(dMin, mag(c.x()[j] - c.x()[i]));
            }
        }
    }
    CHECK(dMin >= 0.5*s);

    // Every particle of the right panel is (k + 1/2) s above its line
    const vector2D t(::cos(beta), ::sin(beta));
    const vector2D nrm(-t.y(), t.x());
    label nChecked = 0;
    forAll(c.x(), i)
    {
        if (c.region()[i] == 0)
        {
            const scalar d = (c.x()[i] & nrm)/s - 0.5;
            CHECK(std::abs(d - std::round(d)) < 1e-9);
            CHECK(std::round(d) >= 0);
            CHECK(std::round(d) <= 4);
            const scalar along = c.x()[i] & t;
            CHECK(along > 0);
            CHECK(along < 0.3);
            ++nChecked;
        }
    }
    CHECK(nChecked == 5*nAlong);

    // Mirror symmetry: the last particle of each panel (outer layer, tip)
    const label last = c.size() - 1;
    CHECK(c.x()[nRight - 1].x() == Approx(-c.x()[last].x()));
    CHECK(c.x()[nRight - 1].y() == Approx(c.x()[last].y()));
    CHECK
    (
        c.x()[last].y()
     == Approx((0.3 - 0.5*s)*::sin(beta) + 4.5*s*::cos(beta))
    );
}


TEST_CASE("bad regions stop with errors naming the entry")
{
    CHECK_THAT
    (
        generateError("w { type box; kind fluid; spacing -0.1;"
            " min (0 0); max (1 1); }"),
        Contains("spacing")
    );
    CHECK_THAT
    (
        generateError("w { type box; kind water; min (0 0); max (1 1); }"),
        Contains("water") && Contains("structure")
    );
    CHECK_THAT
    (
        generateError("w { type circle; kind fluid; }"),
        Contains("Unknown shape type circle") && Contains("polygon")
    );
    CHECK_THAT
    (
        generateError
        (
            "w { type box; kind fluid; min (0 0); max (1 1); }",
            boundBox(point(0, 0, -1), point(0.5, 2, 1))
        ),
        Contains("outside the domain")
    );
    CHECK_THAT
    (
        generateError
        (
            "w { type box; kind fluid; min (0 0); max (1 1); }"
            "s { type box; kind wall; min (0.5 0.5); max (2 2); }"
        ),
        Contains("overlap") && Contains("'w'") && Contains("'s'")
    );
    CHECK_THAT
    (
        generateError("w { type box; kind fluid; min (1 1); max (0 0); }"),
        Contains("max")
    );
    CHECK_THAT
    (
        generateError("w { type box; kind fluid; min (0 0); max (1 1);"
            " dummyLayers 1; }"),
        Contains("dummyLayers")
    );
}


TEST_CASE("overlapping regions of the same kind are merged")
{
    const mpsCloud c = generate
    (
        "a { type box; kind fluid; min (0 0); max (1 1); }"
        "b { type box; kind fluid; min (0.5 0); max (1.5 1); }"
    );
    CHECK(c.size() == 100 + 50);
}


TEST_CASE("wall and dummy particles may lie over structure, fluid may not")
{
    // The structure is a particle system of its own: the fluid's boundary
    // layers attached to it may cover it (spacing ratio 1), the fluid not
    const std::string overStructure
    (
        "p { type box; kind structure; min (0 0); max (1 0.4); }"
        "w { type box; kind wall; min (0 0); max (1 0.2); }"
        "d { type box; kind dummy; min (0 0.2); max (1 0.4); }"
    );
    CHECK(generateError(overStructure) == "");
    const mpsCloud c = generate(overStructure);
    CHECK(c.size() == 50*20 + 10*2 + 10*2);
    CHECK_THAT
    (
        generateError
        (
            "p { type box; kind structure; min (0 0); max (1 0.2); }"
            "f { type box; kind fluid; min (0 0); max (1 0.2); }"
        ),
        Contains("overlap") && Contains("'p'") && Contains("'f'")
    );
}
