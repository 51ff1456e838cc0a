/*---------------------------------------------------------------------------*\
    Unit tests: the pressure equation's wall conditions (ppe.wallCondition):
    solved walls as rows, neumann walls taking the fluid's pressure (Adami,
    Hu & Adams 2012)
\*---------------------------------------------------------------------------*/

#include <catch2/catch.hpp>
#include "testTools.H"
#include "mpsFluid.H"
#include <Eigen/SparseCholesky>

using namespace Foam;

namespace
{

const scalar l0 = 0.01;
const label nx = 12, ny = 8, nWall = 16;

// A tank's corner: water nx x ny at rest on a bottom wall and beside a
// left wall nWall rows high (test::tankCorner)
void corner(mpsCloud& c)
{
    test::tankCorner(c, l0, nx, ny, nWall);
}

dictionary fluidDict(const std::string& ppe)
{
    return test::dict
    (
        "rho 1000; nu 1e-6; g (0 -9.81 0); l0 0.01;"
        " kernel { type original; }"
        " re { numberDensity 2.1; gradient 2.1; laplacian 2.1; viscosity 2.1; }"
        " ppe { source mixed; " + ppe + " }"
        " freeSurface { type improved; } collision { type none; }"
        " pressureSolver { type PCG; }"
    );
}

const boundBox domain(point(-1, -1, -1), point(1, 1, 1));

} // End anonymous namespace


TEST_CASE("neumann walls: a wall under water takes the fluid's hydrostatic pressure exactly; one the water reaches, the share of its fluid side the water holds")
{
    // The fluid's pressure hydrostatic, p_f = rho g (H - y_f): each term
    // p_f + rho g.(x_w - x_f) of a wall's sum is p(y_w), so the wall takes
    // p(y_w) times the sum of its coefficients: 1 where the water fills
    // its fluid side (the bottom under the water), the share the water
    // holds past the water's edge (the original kernel's weights of the
    // fluid neighbours over n0 less the wall and dummy neighbours'), 0 on
    // the dry left wall above the water
    mpsCloud c;
    corner(c);
    mpsFluid fluid(c, fluidDict("wallCondition neumann;"), domain);
    fluid.evaluate();
    ppeMatrix A;
    Eigen::VectorXd b, sol;
    fluid.ppe().system(2e-5, A, b, sol);

    const scalar rho = 1000, g = 9.81, H = 0.2;
    auto hydrostatic = [&](const scalar y) { return rho*g*(H - y); };
    List<scalar> p(c.size(), scalar(0));
    forAll(p, i)
    {
        if (c.kind()[i] == particleKind::fluid)
        {
            p[i] = hydrostatic(c.x()[i].y());
        }
    }
    fluid.ppe().wallPressures(p);

    // The share of a wall's fluid side the water holds, from the kernel
    const scalar re = 2.1*l0;
    auto w = [&](const scalar r) { return r < re ? re/r - 1 : 0; };
    scalar n0 = 0;
    for (label a = -3; a <= 3; ++a)
    {
        for (label bb = -3; bb <= 3; ++bb)
        {
            const scalar r = l0*::sqrt(scalar(a*a + bb*bb));
            n0 += (a || bb) ? w(r) : 0;
        }
    }
    label nFull = 0, nPart = 0, nDry = 0;
    forAll(p, i)
    {
        if (c.kind()[i] != particleKind::wall)
        {
            continue;
        }
        const vector2D& x = c.x()[i];
        scalar fluidW = 0, boundaryW = 0;
        forAll(p, j)
        {
            const scalar r = mag(c.x()[j] - x);
            if (j == i || r >= re)
            {
                continue;
            }
            (c.kind()[j] == particleKind::fluid ? fluidW : boundaryW) += w(r);
        }
        const scalar share = fluidW/max(n0 - boundaryW, fluidW);
        INFO("wall particle at (" << x.x() << ", " << x.y() << "): share " << share);
        CHECK(p[i] == Approx(share*hydrostatic(x.y())).epsilon(1e-9).margin(1e-9));
        if (x.y() < 0 && x.x() > 3*l0 && x.x() < (nx - 3)*l0)
        {
            CHECK(share == Approx(1).epsilon(1e-12));
            CHECK(p[i] == Approx(hydrostatic(x.y())).epsilon(1e-12));
            ++nFull;
        }
        else if (x.y() < 0 && x.x() > nx*l0 && x.x() < (nx + 1)*l0)
        {
            CHECK(share > 0);
            CHECK(share < 0.5);
            ++nPart;
        }
        else if (x.y() > (ny + 2.1)*l0 || x.x() > (nx + 1.1)*l0)
        {
            CHECK(p[i] == 0);
            ++nDry;
        }
    }
    CHECK(nFull == nx - 6);
    CHECK(nPart == 1);      // the next beyond the water's last column
    CHECK(nDry > 0);
}


TEST_CASE("neumann walls: the fluid's rows couple through the walls, symmetric and positive definite; the walls are no rows")
{
    // The couplings sum_w a_iw w_wf/N_w are symmetric in the two fluid
    // particles, and sum_f c_wf <= 1 keeps the system positive definite
    // (Cauchy-Schwarz): the conjugate gradients apply. With the water
    // converging (a divergence source), the two conditions' systems
    // differ only next to the walls
    auto system = [](const std::string& condition, label& nRows, scalar& asym, bool& spd)
    {
        mpsCloud c;
        corner(c);
        mpsFluid fluid(c, fluidDict("wallCondition " + condition + ";"), domain);
        fluid.evaluate();
        forAll(c.U(), i)
        {
            if (c.kind()[i] == particleKind::fluid)
            {
                c.U()[i] = -10*(c.x()[i] - vector2D(0.06, 0.04));
            }
        }
        ppeMatrix A;
        Eigen::VectorXd b, sol;
        fluid.ppe().system(2e-5, A, b, sol);
        nRows = A.rows();
        const Eigen::SparseMatrix<double> Ac(A);
        const Eigen::SparseMatrix<double> At(Ac.transpose());
        asym = (Ac - At).norm()/Ac.norm();
        Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(Ac);
        spd = ldlt.info() == Eigen::Success && ldlt.vectorD().minCoeff() > 0;
        label nWalls = 0;
        forAll(c.kind(), i)
        {
            nWalls += (c.kind()[i] == particleKind::wall);
        }
        return nWalls;
    };
    label rowsSolved = 0, rowsNeumann = 0;
    scalar asymSolved = 1, asymNeumann = 1;
    bool spdSolved = false, spdNeumann = false;
    const label nWalls = system("solved", rowsSolved, asymSolved, spdSolved);
    system("neumann", rowsNeumann, asymNeumann, spdNeumann);
    CHECK(rowsSolved == nx*ny + nWalls);
    CHECK(rowsNeumann == nx*ny);
    CHECK(asymSolved < 1e-14);
    CHECK(asymNeumann < 1e-14);
    CHECK(spdSolved);
    CHECK(spdNeumann);
}


TEST_CASE("ppe.wallCondition: an unknown condition is an error that lists the valid ones")
{
    mpsCloud c;
    corner(c);
    const std::string msg = test::errorOf([&]()
    {
        mpsFluid fluid(c, fluidDict("wallCondition nuemann;"), domain);
    });
    CHECK_THAT(msg, Catch::Matchers::Contains("nuemann"));
    CHECK_THAT(msg, Catch::Matchers::Contains("neumann"));
    CHECK_THAT(msg, Catch::Matchers::Contains("solved"));
}


// ************************************************************************* //
