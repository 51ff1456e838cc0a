/*---------------------------------------------------------------------------*\
  mpsFsiFoam unit tests: the relaxation of an iterative coupling
  (couplingRelaxation). On a linear fixed point x = A x + b with m
  unknowns, where the plain iteration diverges, IQN-ILS (Degroote et al.
  2009) is exact after at most m + 1 iterations, and with its columns
  reused the next step's is exact at once; an iteration that changes
  nothing restarts it; Aitken's relaxation is exact in two where A is a
  multiple of the identity; the entries are checked.
\*---------------------------------------------------------------------------*/

#include <catch2/catch.hpp>
#include "testTools.H"
#include "couplingRelaxation.H"
#include "Random.H"

#include <Eigen/Dense>

using namespace Foam;
using Catch::Matchers::Contains;

namespace
{

autoPtr<couplingRelaxation> relaxation(const std::string& entries)
{
    return couplingRelaxation::New
    (
        test::dict("relaxation { " + entries + " }")
    );
}

// S(x) = A x + b on n particles (m = 2n unknowns), the components in
// particle order
struct linearMap
{
    Eigen::MatrixXd A;
    Eigen::VectorXd b;

    Eigen::VectorXd operator()(const UList<vector2D>& x) const
    {
        Eigen::VectorXd v(2*x.size());
        forAll(x, k)
        {
            v(2*k) = x[k].x();
            v(2*k + 1) = x[k].y();
        }
        return A*v + b;
    }

    // The fixed point (I - A)^-1 b
    Eigen::VectorXd fixedPoint() const
    {
        const label m = b.size();
        return (Eigen::MatrixXd::Identity(m, m) - A).fullPivLu().solve(b);
    }
};

// One step's iterations from x = 0 until |r| <= 1e-10 |S(x)|: the number
// of updates, and the last guess's error relative to the fixed point
std::pair<label, scalar> iterate
(
    couplingRelaxation& model,
    const linearMap& S,
    const label maxIterations
)
{
    const label n = S.b.size()/2;
    List<vector2D> x(n, Zero), r(n);
    model.beginStep();
    label updates = 0;
    while (true)
    {
        const Eigen::VectorXd s(S(x));
        scalar r2 = 0;
        forAll(x, k)
        {
            r[k] = vector2D(s(2*k), s(2*k + 1)) - x[k];
            r2 += magSqr(r[k]);
        }
        if (r2 <= 1e-20*s.squaredNorm() || updates == maxIterations)
        {
            break;
        }
        model.update(x, r);
        ++updates;
    }
    model.endStep();
    const Eigen::VectorXd xStar(S.fixedPoint());
    scalar e2 = 0;
    forAll(x, k)
    {
        e2 += sqr(x[k].x() - xStar(2*k)) + sqr(x[k].y() - xStar(2*k + 1));
    }
    return {updates, std::sqrt(e2)/xStar.norm()};
}

// A random A of spectral radius about 1.5 (the plain iteration x = S(x)
// diverges), m unknowns
linearMap randomMap(const label m, const label seed)
{
    Random rnd(seed);
    linearMap S;
    S.A.resize(m, m);
    S.b.resize(m);
    for (label i = 0; i < m; ++i)
    {
        S.b(i) = 2*rnd.sample01<scalar>() - 1;
        for (label j = 0; j < m; ++j)
        {
            S.A(i, j) = (2*rnd.sample01<scalar>() - 1)*std::sqrt(3.0/m)*1.5;
        }
    }
    return S;
}

} // End anonymous namespace


TEST_CASE("IQN-ILS is exact on a linear problem within m + 1 iterations")
{
    const label m = 12;
    const linearMap S(randomMap(m, 3));
    const Eigen::EigenSolver<Eigen::MatrixXd> eig(S.A);
    const scalar radius = eig.eigenvalues().cwiseAbs().maxCoeff();
    REQUIRE(radius > 1);    // the plain iteration diverges

    autoPtr<couplingRelaxation> iqn(relaxation("type IQN-ILS;"));
    const auto result = iterate(iqn(), S, 100);
    autoPtr<couplingRelaxation> aitken(relaxation("type aitken;"));
    const auto byAitken = iterate(aitken(), S, 100);
    INFO("spectral radius " << radius << "; IQN-ILS: " << result.first
        << " iterations, error " << result.second << "; aitken: "
        << byAitken.first << " iterations, error " << byAitken.second);
    CHECK(result.first <= m + 1);
    CHECK(result.first >= 3);           // not a trivial problem
    CHECK(result.second < 1e-8);
}


TEST_CASE("IQN-ILS with reuse solves the next step of the same problem at once")
{
    // The differences of a linear S do not depend on b: with the first
    // step's columns spanning the space, the next step's first
    // quasi-Newton update is exact
    const label m = 8;
    linearMap S(randomMap(m, 11));
    autoPtr<couplingRelaxation> iqn(relaxation("type IQN-ILS; reuse 1;"));
    const auto first = iterate(iqn(), S, 100);
    S.b *= -2;
    S.b(0) += 1;
    const auto second = iterate(iqn(), S, 100);
    autoPtr<couplingRelaxation> plain(relaxation("type IQN-ILS;"));
    const auto without = iterate(plain(), S, 100);
    INFO("first step " << first.first << " iterations; the next "
        << second.first << " with reuse 1, " << without.first << " without");
    CHECK(first.second < 1e-8);
    CHECK(second.second < 1e-8);
    CHECK(second.first <= 2);
    CHECK(without.first > second.first);
}


TEST_CASE("IQN-ILS starts again from a relaxed step when an iteration changes nothing")
{
    // Where S is not smooth (a contact, a switch) the secant model can
    // answer with the guess it was given: the same residual comes back,
    // and the model, which learnt nothing, is dropped for a relaxed step
    autoPtr<couplingRelaxation> iqn(relaxation("type IQN-ILS; initial 0.4;"));
    List<vector2D> x(2, Zero);
    const List<vector2D> r0({vector2D(1, 0), vector2D(0, 2)});
    const List<vector2D> r1({vector2D(0.5, 0.1), vector2D(0.2, 1)});
    iqn->beginStep();
    iqn->update(x, r0);                     // x^1 = 0.4 r^0
    CHECK(mag(x[1] - vector2D(0, 0.8)) < 1e-15);
    iqn->update(x, r1);                     // a quasi-Newton step
    const List<vector2D> x2(x);
    iqn->update(x, r1);                     // nothing changed
    forAll(x, k)
    {
        CHECK(mag(x[k] - (x2[k] + 0.4*r1[k])) < 1e-15);
    }
}


TEST_CASE("Aitken's relaxation is exact in two iterations on x = a x + b")
{
    // One factor for every unknown: the secant's omega is 1/(1 - a)
    const label m = 6;
    linearMap S;
    S.A = -3*Eigen::MatrixXd::Identity(m, m);     // diverges unrelaxed
    S.b = Eigen::VectorXd::LinSpaced(m, 1, 2);
    autoPtr<couplingRelaxation> aitken(relaxation("type aitken; initial 0.3;"));
    const auto result = iterate(aitken(), S, 50);
    INFO(result.first << " iterations, error " << result.second);
    CHECK(result.first == 2);
    CHECK(result.second < 1e-12);
}


TEST_CASE("relaxation entries are checked")
{
    CHECK(couplingRelaxation::New(test::dict("scheme implicit;"))->type() == "aitken");
    CHECK_THROWS_WITH
    (
        relaxation("type broyden;"),
        Contains("aitken") && Contains("IQN-ILS")
    );
    CHECK_THROWS_WITH(relaxation("type IQN-ILS; reuse -1;"), Contains("reuse"));
    CHECK_THROWS_WITH(relaxation("type aitken; initial 0;"), Contains("initial"));
    CHECK_THROWS_WITH(relaxation("type IQN-ILS; resue 2;"), Contains("reuse"));
    CHECK_THROWS_WITH(relaxation("type aitken; reuse 2;"), Contains("reuse"));
    CHECK_THROWS_WITH(relaxation("type IQN-ILS; filter 1;"), Contains("filter"));
}


// ************************************************************************* //
