/*---------------------------------------------------------------------------*\
    The similarity solution of constant-speed wedge entry (similarityWedge,
    the rigid limit's reference):

    - the boundary elements reproduce a harmonic function on a mixed
      problem, to second order in the element length;
    - at 30 deg the peak pressure and its height meet Zhao & Faltinsen's
      (1993) table: Cp 6.927 at z = 0.4243 V t.
\*---------------------------------------------------------------------------*/

#include <catch2/catch.hpp>
#include "similarityWedge.H"

#include <cmath>
#include <utility>

using namespace Foam;

namespace
{

typedef similarityWedge::vec vec;
typedef similarityWedge::boundaryProblem problem;

//- f = (x - x0)/r^2 about (x0, y0) = (-0.3, 0.5), outside the square, and
//  its gradient
double f(const vec& X)
{
    const double u = X.x() + 0.3, v = X.y() - 0.5, r2 = u*u + v*v;
    return u/r2;
}

vec gradF(const vec& X)
{
    const double u = X.x() + 0.3, v = X.y() - 0.5, r2 = u*u + v*v;
    return vec((v*v - u*u)/(r2*r2), -2*u*v/(r2*r2));
}

//- The largest error of the solve on the square 0 < x < 1, -1 < y < 0 with
//  n elements a side (Phi given on the top side, dPhi/dn on the others):
//  at every node, and at those more than 1/8 from the top side's corners
std::pair<double, double> squareError(const int n)
{
    problem bp;
    const vec corners[4] = {vec(0, 0), vec(0, -1), vec(1, -1), vec(1, 0)};
    for (int side = 0; side < 4; ++side)
    {
        const vec A = corners[side], B = corners[(side + 1) % 4];
        const vec t = (B - A).normalized();
        const vec nOut(t.y(), -t.x());
        for (int i = 0; i < n; ++i)
        {
            const vec P = A + double(i)/n*(B - A);
            const vec Q = A + double(i + 1)/n*(B - A);
            const bool top = side == 3;
            // a node on the top side (either of its corners) is Dirichlet
            const bool known = top || (side == 0 && i == 0);
            bp.X.push_back(P);
            bp.phiKnown.push_back(known);
            bp.phi.push_back(known ? f(P) : 0);
            bp.kind.push_back(top ? problem::unknown : problem::given);
            bp.q.push_back({{gradF(P).dot(nOut), gradF(Q).dot(nOut)}});
        }
    }
    similarityWedge::solve(bp);

    // Phi on the other sides, dPhi/dn on the top
    double all = 0, away = 0;
    const vec up(0, 1);
    for (size_t i = 0; i < bp.X.size(); ++i)
    {
        const vec& P = bp.X[i];
        const double e =
            bp.phiKnown[i]
          ? std::abs(bp.qNode[i] - gradF(P).dot(up))
          : std::abs(bp.phi[i] - f(P));
        all = std::max(all, e);
        if (std::min(P.norm(), (P - vec(1, 0)).norm()) > 0.125)
        {
            away = std::max(away, e);
        }
    }
    return std::make_pair(all, away);
}

} // End anonymous namespace


TEST_CASE("similarityWedge: boundary elements reproduce a harmonic field to second order")
{
    const std::pair<double, double> e1 = squareError(16), e2 = squareError(32);
    INFO
    (
        "largest error, 16 and 32 elements a side: " << e1.first << ", "
     << e2.first << "; away from the top corners " << e1.second << ", "
     << e2.second
    );
    // f is O(1) on the square (0.3 to 1.7), its gradient up to 3: away
    // from the corners where the given Phi meets a given flux, a few per
    // mille at 16 a side and a factor 4 less at 32 (second order; at least
    // 3 asked); at such a corner the flux's error falls as h (at least
    // by 1.5 asked), the contact point's case, where the surface meets
    // the face
    CHECK(e1.second < 3e-3);
    CHECK(e2.second < e1.second/3);
    CHECK(e2.first < e1.first/1.5);
}


TEST_CASE("similarityWedge: 30 deg meets Zhao & Faltinsen's peak pressure and its height")
{
    similarityWedge::controls c;
    c.hMin = 0.02;
    c.tauEnd = 2;
    similarityWedge wedge(30, c);
    const similarityWedge::state s = wedge.march();
    INFO("CpMax " << s.CpMax << " at z " << s.zMax << " V t; CF " << s.CF);
    // Zhao & Faltinsen (1993), table 1: 6.927 at 0.4243; this resolution
    // gives -0.6% and -0.8% (hMin 0.01: -0.5%, +0.1%)
    CHECK(std::abs(s.CpMax/6.927 - 1) < 0.015);
    CHECK(std::abs(s.zMax/0.4243 - 1) < 0.02);
    // Wagner's limit lies above: the root's (pi/(2 tan b))^2 = 7.40
    CHECK(s.CpMax < std::pow(M_PI/(2*std::tan(M_PI/6)), 2));
}
