/*---------------------------------------------------------------------------*\
    Kernels: lattice constants n0 and lambda against sums written out by
    hand, the values of doc/physics.md, and each kernel's defining properties.
\*---------------------------------------------------------------------------*/

#include <catch2/catch.hpp>
#include "testTools.H"
#include "mpsKernel.H"

#include <cmath>
#include <vector>

using namespace Foam;
using Catch::Matchers::Contains;

TEST_CASE("original kernel lattice sums by hand")
{
    // Square lattice, re = 2.1 l0: neighbours at l0 (4), sqrt(2) l0 (4) and
    // 2 l0 (4); at sqrt(5) l0 = 2.236 l0 they are outside.
    const scalar l0 = 0.01;
    const scalar re = 2.1*l0;
    const dictionary d(test::dict("kernel { type original; }"));
    autoPtr<mpsKernel> k(mpsKernel::New(d, re));

    const scalar w1 = 2.1 - 1;
    const scalar w2 = 2.1/std::sqrt(2.0) - 1;
    const scalar w3 = 2.1/2 - 1;
    const scalar n0 = 4*w1 + 4*w2 + 4*w3;
    const scalar lambda = sqr(l0)*(4*1*w1 + 4*2*w2 + 4*4*w3)/n0;

    CHECK(k->latticeNumberDensity(l0) == Approx(n0).epsilon(1e-12));
    CHECK(k->latticeLambda(l0) == Approx(lambda).epsilon(1e-12));

    // The table of doc/physics.md (4 to 5 digits)
    CHECK(k->latticeNumberDensity(l0) == Approx(6.5397).epsilon(2e-5));
    CHECK(k->latticeLambda(l0)/sqr(l0) == Approx(1.3884).epsilon(5e-5));
}


TEST_CASE("original kernel lattice sums at re 3.1 and 4.0 l0")
{
    const dictionary d(test::dict("kernel { type original; }"));
    const scalar l0 = 1;

    // n0 does not depend on l0 (w depends on r/re only)
    autoPtr<mpsKernel> k31(mpsKernel::New(d, 3.1*l0));
    CHECK(k31->latticeNumberDensity(l0) == Approx(18.976).epsilon(5e-5));
    CHECK(k31->latticeLambda(l0) == Approx(2.4485).epsilon(5e-5));

    autoPtr<mpsKernel> k4(mpsKernel::New(d, 4.0*l0));
    CHECK(k4->latticeNumberDensity(l0) == Approx(35.609).epsilon(5e-5));
    CHECK(k4->latticeLambda(l0) == Approx(3.7071).epsilon(5e-5));

    autoPtr<mpsKernel> k4s(mpsKernel::New(d, 4.0*0.003));
    CHECK
    (
        k4s->latticeNumberDensity(0.003)
     == Approx(k4->latticeNumberDensity(1)).epsilon(1e-12)
    );
    CHECK
    (
        k4s->latticeLambda(0.003)/sqr(0.003)
     == Approx(k4->latticeLambda(1)).epsilon(1e-12)
    );
}


TEST_CASE("polynomial kernel lattice sums by hand")
{
    const scalar l0 = 0.002;
    const scalar re = 2.1*l0;
    const dictionary d(test::dict("kernel { type polynomial; }"));
    autoPtr<mpsKernel> k(mpsKernel::New(d, re));

    auto w = [](scalar s) { return std::pow(1 - s/2.1, 3); };
    const scalar w1 = w(1);
    const scalar w2 = w(std::sqrt(2.0));
    const scalar w3 = w(2);
    const scalar n0 = 4*(w1 + w2 + w3);
    const scalar lambda = sqr(l0)*4*(w1 + 2*w2 + 4*w3)/n0;

    CHECK(k->latticeNumberDensity(l0) == Approx(n0).epsilon(1e-12));
    CHECK(k->latticeLambda(l0) == Approx(lambda).epsilon(1e-12));
}


TEST_CASE("every kernel is zero at and beyond re and positive inside")
{
    const scalar re = 0.021;
    for (const word name : {"original", "polynomial"})
    {
        INFO("kernel " << name);
        const dictionary d(test::dict("kernel { type " + name + "; }"));
        autoPtr<mpsKernel> k(mpsKernel::New(d, re));

        CHECK(k->type() == name);
        CHECK(k->re() == re);
        CHECK(k->w(re) == 0);
        CHECK(k->w(1.5*re) == 0);
        CHECK(k->w(1e3*re) == 0);

        scalar wPrev = GREAT;
        for (label i = 1; i < 100; ++i)
        {
            const scalar r = re*i/100.0;
            const scalar wi = k->w(r);
            CHECK(wi > 0);
            CHECK(wi < wPrev);      // decreasing with distance
            wPrev = wi;
        }
    }

    const dictionary dp(test::dict("kernel { type polynomial; }"));
    autoPtr<mpsKernel> kp(mpsKernel::New(dp, re));
    CHECK(kp->w(0) == Approx(1));
    CHECK(kp->w(0.5*re) == Approx(0.125));

    const dictionary d0(test::dict("kernel { type original; }"));
    autoPtr<mpsKernel> k0(mpsKernel::New(d0, re));
    CHECK(k0->w(0.5*re) == Approx(1));
    CHECK(k0->w(0.25*re) == Approx(3));
}


TEST_CASE("a row's weights equal the kernel's weight function pair by pair")
{
    // The fluid step's vectorised rows give what w and dwdr give one pair
    // at a time: values bitwise (the viscosity and the wall test moved to
    // it without changing a run's results), weights to round-off (it
    // clamps 1 - r/re at 0 where r/re rounds to 1 just inside re)
    const scalar re = 0.021;
    for (const word name : {"original", "polynomial"})
    {
        INFO("kernel " << name);
        const dictionary d(test::dict("kernel { type " + name + "; }"));
        autoPtr<mpsKernel> k(mpsKernel::New(d, re));

        // Inside, at re (both ways of rounding), beyond
        std::vector<scalar> r;
        for (label i = 1; i <= 130; ++i)
        {
            r.push_back(re*i/100.0);
        }
        r.push_back(re);
        r.push_back(re*(1 - 1e-16));
        r.push_back(std::nextafter(re, 0.0));
        const label n = r.size();

        std::vector<scalar> v(r), w(n), dw(n);
        k->values(v.data(), n, v.data());           // in place
        k->weights(r.data(), n, w.data(), dw.data());
        for (label i = 0; i < n; ++i)
        {
            INFO("r/re " << r[i]/re);
            CHECK(v[i] == k->w(r[i]));
            CHECK(w[i] == Approx(k->w(r[i])).margin(1e-15));
            CHECK(dw[i] == Approx(k->dwdr(r[i])/r[i]).margin(1e-12));
        }
    }
}


TEST_CASE("unknown kernel name lists the valid ones")
{
    const dictionary d(test::dict("kernel { type gaussian; }"));
    const std::string msg =
        test::errorOf([&]() { mpsKernel::New(d, 0.01); });
    CHECK_THAT(msg, Contains("Unknown kernel type gaussian"));
    CHECK_THAT(msg, Contains("original"));
    CHECK_THAT(msg, Contains("polynomial"));

    const dictionary dMissing(test::dict("re 2.1;"));
    CHECK_THAT
    (
        test::errorOf([&]() { mpsKernel::New(dMissing, 0.01); }),
        Contains("kernel")
    );
}
