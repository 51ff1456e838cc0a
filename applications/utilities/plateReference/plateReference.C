/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | mpsFsiFoam: MPS hydroelastic slamming
   \\    /   O peration     | built on OpenFOAM v1912
    \\  /    A nd           |
     \\/     M anipulation  |
-------------------------------------------------------------------------------
License
    This file is part of mpsFsiFoam, distributed under the GNU General Public
    License version 3 or later, as OpenFOAM is.

Application
    plateReference

Description
    The reference of the plate benchmarks (tutorials/hydrostaticPlate):
    the deflection of a rectangular plate in plane strain, clamped at its
    end faces (both, or one: a cantilever), under a uniform pressure on its
    top face and its own weight, by 2D finite elements (planeStrainPlate.H:
    nine-node quadrilaterals, 16 across the thickness), at the mid-plane of
    the mid-span (the free end of a cantilever). It is the continuum the
    particle structure discretises; beam theory leaves out the shear and
    the clamp's own compliance (at L/h = 20 the plate deflects 3% more
    than Euler-Bernoulli's beam).

Usage
    plateReference -length 1 -thickness 0.05 -E 67.5e9 -nu 0.34
        -pressure 19620 [-rho 2700 -g 9.81] [-cantilever]

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "planeStrainPlate.H"

using namespace Foam;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Mid-span deflection of a plane-strain plate clamped at its faces,"
        " by finite elements (the plate benchmarks' reference)"
    );
    argList::noParallel();
    argList::noBanner();
    argList::addOption("length", "m", "span between the clamped faces");
    argList::addOption("thickness", "m", "plate thickness");
    argList::addOption("E", "Pa", "Young's modulus");
    argList::addOption("nu", "value", "Poisson's ratio");
    argList::addOption("pressure", "Pa", "uniform pressure on the top face");
    argList::addOption("rho", "kg/m3", "plate density (own weight; default 0)");
    argList::addOption("g", "m/s2", "gravity (default 9.81)");
    argList::addBoolOption("cantilever", "clamped at x = 0 only");

    argList args(argc, argv, false, false, false);

    for (const word opt : {"length", "thickness", "E", "nu", "pressure"})
    {
        if (!args.found(opt))
        {
            FatalErrorInFunction
                << "option -" << opt << " is required (see -help)"
                << exit(FatalError);
        }
    }
    const scalar L = args.opt<scalar>("length");
    const scalar h = args.opt<scalar>("thickness");
    const scalar E = args.opt<scalar>("E");
    const scalar nu = args.opt<scalar>("nu");
    const scalar q = args.opt<scalar>("pressure");
    const scalar rho = args.getOrDefault<scalar>("rho", 0);
    const scalar g = args.getOrDefault<scalar>("g", 9.81);
    const bool bothEnds = !args.found("cantilever");

    if (L <= 0 || h <= 0 || h > L || E <= 0 || nu <= -1 || nu >= 0.5)
    {
        FatalErrorInFunction
            << "need 0 < thickness <= length, E > 0 and -1 < nu < 0.5"
            << exit(FatalError);
    }

    const int ey = 16;
    const int ex = max(1, int(std::round(ey*L/h)));
    const planeStrainPlate plate
    (
        L, h, ex, ey, E, nu, q, 0, -rho*g, bothEnds
    );
    const scalar w = plate.displacement(bothEnds ? L/2 : L, -h/2, 1);

    Info<< "Plane-strain finite elements (" << ex << " x " << ey
        << " nine-node elements): deflection " << -w << " m" << endl;

    return 0;
}


// ************************************************************************* //
