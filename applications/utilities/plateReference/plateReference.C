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

    With -table, the dynamic response of the cantilever instead: from rest,
    under a pressure p(s, t) on its top face read from a table
    (spaceTimeTable: s the distance from a point before the clamped face,
    which lies at s = -offset), by Newmark's average acceleration with the
    consistent mass (four nine-node elements across, four along a
    thickness), no gravity; writes the axial strain on the loaded (top) and
    the other (bottom) face at each gauge, as the strainProbes function
    object does, a line per step: the reference of a panel under a known
    slamming load (tutorials/panelSlammingLoad). With -table -quasiStatic,
    the static response to the table's load at each time (no inertia: the
    quasi-static strain a hydroelastic campaign compares with).

Usage
    plateReference -length 1 -thickness 0.05 -E 67.5e9 -nu 0.34
        -pressure 19620 [-rho 2700 -g 9.81] [-cantilever]
    plateReference -length 0.2966 -thickness 0.002 -E 68e9 -nu 0.3
        -rho 2700 -table p.dat -offset 0.0034 -deltaT 2e-5 -endTime 0.03
        -gauges '(0.03 0.12)' -output strainFE.dat [-quasiStatic]

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "planeStrainPlate.H"
#include "spaceTimeTable.H"
#include "OFstream.H"

using namespace Foam;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

//- Stop unless every option named is given
void require
(
    const argList& args,
    const std::initializer_list<word> options,
    const std::string& when
)
{
    for (const word& opt : options)
    {
        if (!args.found(opt))
        {
            FatalErrorInFunction
                << when.c_str() << "option -" << opt
                << " is required (see -help)" << exit(FatalError);
        }
    }
}


//- The cantilever from rest under the table's pressure: the gauges' strains
int dynamicResponse(const argList& args)
{
    const bool quasiStatic = args.found("quasiStatic");
    require
    (
        args,
        {"length", "thickness", "E", "nu", "offset", "deltaT", "endTime",
         "gauges", "output"},
        "with -table, "
    );
    if (!quasiStatic)
    {
        require(args, {"rho"}, "with -table (dynamic), ");
    }
    const scalar L = args.opt<scalar>("length");
    const scalar h = args.opt<scalar>("thickness");
    const scalar E = args.opt<scalar>("E");
    const scalar nu = args.opt<scalar>("nu");
    const scalar rho = quasiStatic ? 1 : args.opt<scalar>("rho");
    const scalar offset = args.opt<scalar>("offset");
    const scalar dt = args.opt<scalar>("deltaT");
    const scalar endTime = args.opt<scalar>("endTime");
    const scalarList gauges(args.opt<scalarList>("gauges"));
    if
    (
        L <= 0 || h <= 0 || h > L || E <= 0 || nu <= -1 || nu >= 0.5
     || rho <= 0 || dt <= 0 || endTime < dt
    )
    {
        FatalErrorInFunction
            << "need 0 < thickness <= length, E > 0, -1 < nu < 0.5, rho > 0"
            << " and 0 < deltaT <= endTime" << exit(FatalError);
    }
    for (const scalar s : gauges)
    {
        if (s - offset <= 0 || s - offset >= L)
        {
            FatalErrorInFunction
                << "gauge at s = " << s << " is off the panel (s from "
                << offset << " to " << offset + L << ')' << exit(FatalError);
        }
    }

    const dictionary noDict;
    const spaceTimeTable table(args.opt<fileName>("table"), noDict);

    const int ey = 4;
    const int ex = max(1, int(std::round(2*ey*L/h)));
    planeStrainPlate plate(L, h, ex, ey, E, nu, 0, 0, 0, false);

    OFstream os(args.opt<fileName>("output"));
    os  << "# Axial strain of a plane-strain cantilever (" << ex << " x " << ey
        << " nine-node elements, "
        << (quasiStatic ? "quasi-static: no inertia" : "Newmark average acceleration")
        << ", dt " << dt << " s) under p(s, t) of " << table.file() << nl
        << "# Time";
    for (const scalar s : gauges)
    {
        os  << "  loaded_" << s << "  other_" << s;
    }
    os  << nl;

    const label nSteps = label(std::round(endTime/dt));
    auto load = [&](const double x, const double t)
    {
        return table.value(x + offset, t);
    };
    auto observe = [&](const double t)
    {
        os  << t;
        for (const scalar s : gauges)
        {
            os  << ' ' << plate.strainXX(s - offset, 0)
                << ' ' << plate.strainXX(s - offset, -h);
        }
        os  << nl;
    };
    if (quasiStatic)
    {
        plate.quasiStatic(dt, nSteps, load, observe);
    }
    else
    {
        plate.integrate(rho, dt, nSteps, load, observe);
    }
    Info<< "Wrote " << os.name() << ": " << nSteps << " steps, "
        << gauges.size() << " gauges" << endl;
    return 0;
}


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
    argList::addOption("table", "file", "dynamic: p(s, t) on the top face");
    argList::addOption("offset", "m", "dynamic: s of the clamped face");
    argList::addOption("deltaT", "s", "dynamic: the time step");
    argList::addOption("endTime", "s", "dynamic: the end time");
    argList::addOption("gauges", "(s ...)", "dynamic: the gauges' s");
    argList::addOption("output", "file", "dynamic: the strains' file");
    argList::addBoolOption
    (
        "quasiStatic",
        "with -table: the static response at each time (no inertia; -rho"
        " not needed)"
    );

    argList args(argc, argv, false, false, false);

    if (args.found("table"))
    {
        return dynamicResponse(args);
    }

    require(args, {"length", "thickness", "E", "nu", "pressure"}, "");
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
