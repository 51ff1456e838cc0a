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
    wedgeSimilarity

Description
    The reference of the rigid limit of slamming: the exact similarity
    solution of a rigid wedge entering calm water at a constant speed V,
    without gravity (Dobrovol'skaya 1969; Zhao & Faltinsen 1993), by
    boundary elements marched to the self-similar state
    (similarityWedge.H). For each deadrise angle it writes a row of

        F/(rho V^3 t)   the vertical force on the wedge (both faces)
        CpMax           the largest pressure coefficient p/(rho V^2/2)
        xMax, zMax      where it is: its distance from the symmetry line and
                        its height above the undisturbed surface, over V t
        CF/Wagner       F/(rho V^3 t) over Wagner's pi^3/(4 tan^2 b)

    and, with -profiles, the pressure along a face and the free surface
    (profile_<deadrise>.dat: xi = x/(V t), eta = y/(V t), Cp).

    The elements near the spray root are alpha times their distance from
    the boundary facing them, never shorter than hMin c_w (Wagner's
    half-width c_w = pi/(2 tan b)); hMin defaults to a fifth of Wagner's
    jet thickness, tan^2(b)/(10 pi), within 0.002 to 0.01 (0.0042 at 20
    deg). A row takes seconds at 45 deg, a minute at 20 deg and a quarter
    of an hour at 10 deg.

Usage
    wedgeSimilarity [-deadrise '(10 20 30 45)'] [-output file]
        [-profiles dir] [-hMin 0.01] [-alpha 0.2] [-growth 1.1]
        [-farRadius 20] [-tauEnd 3] [-cfl 0.3] [-cutThickness 1]

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "OFstream.H"
#include "OSspecific.H"
#include "clockTime.H"
#include "scalarList.H"
#include "unitConversion.H"
#include "mathematicalConstants.H"
#include "similarityWedge.H"

#include <sstream>

using namespace Foam;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

//- Write a file under a temporary name and rename it: a kill leaves the
//  earlier file or the whole new one
template<class Writer>
void writeAtomic(const fileName& name, const Writer& write)
{
    const fileName tmp(name + ".tmp");
    {
        OFstream os(tmp);
        if (!os.good())
        {
            FatalErrorInFunction
                << "cannot write " << tmp << exit(FatalError);
        }
        write(os);
    }
    Foam::mv(tmp, name);
}


//- A control from the command line, checked against its valid range
scalar option
(
    const argList& args, const word& name, const scalar deflt,
    const scalar lower, const scalar upper, const char* valid
)
{
    const scalar v = args.getOrDefault<scalar>(name, deflt);
    if (!(v >= lower && v <= upper))
    {
        FatalErrorInFunction
            << "-" << name << " " << v << ": valid is " << valid
            << exit(FatalError);
    }
    return v;
}


int main(int argc, char *argv[])
{
    argList::addNote
    (
        "The similarity solution of a rigid wedge entering calm water at a"
        " constant speed (boundary elements): F/(rho V^3 t), the peak"
        " pressure and where it is, for each deadrise angle"
    );
    argList::noParallel();
    argList::noBanner();
    argList::addOption("deadrise", "(deg ...)", "default (10 20 30 45)");
    argList::addOption("output", "file", "default wedgeSimilarity.dat");
    argList::addOption("profiles", "dir", "write profile_<deadrise>.dat there");
    argList::addOption
    (
        "hMin", "value",
        "shortest element over c_w (default tan^2(b)/(10 pi), 0.002 to 0.01)"
    );
    argList::addOption
    (
        "alpha", "value",
        "element length over its distance from the facing boundary (0.2)"
    );
    argList::addOption("growth", "value", "largest ratio of neighbouring elements (1.1)");
    argList::addOption("farRadius", "value", "far boundary's radius over c_w (20)");
    argList::addOption("tauEnd", "value", "pseudo-time ln(t/t0) marched (3)");
    argList::addOption("cfl", "value", "step over an element's passage time (0.3)");
    argList::addOption("cutThickness", "value", "jet cut where thinner, over hMin (1)");

    argList args(argc, argv, false, false, false);

    const scalarList deadrise
    (
        args.getOrDefault<scalarList>("deadrise", scalarList({10, 20, 30, 45}))
    );
    const fileName output
    (
        args.getOrDefault<fileName>("output", "wedgeSimilarity.dat")
    );

    similarityWedge::controls c;
    c.alpha = option(args, "alpha", c.alpha, 1e-3, 1, "0 < alpha <= 1");
    c.growth = option(args, "growth", c.growth, 1, 2, "1 <= growth <= 2");
    c.farRadius =
        option(args, "farRadius", c.farRadius, 4, 1000, "4 <= farRadius <= 1000");
    c.tauEnd = option(args, "tauEnd", c.tauEnd, 0.01, 20, "0 < tauEnd <= 20");
    c.cfl = option(args, "cfl", c.cfl, 1e-3, 1, "0 < cfl <= 1");
    c.cutThickness =
        option(args, "cutThickness", c.cutThickness, 0.1, 10, "0.1 <= cutThickness <= 10");

    forAll(deadrise, i)
    {
        if (!(deadrise[i] >= 5 && deadrise[i] <= 60))
        {
            FatalErrorInFunction
                << "-deadrise: " << deadrise[i] << " deg; valid are angles"
                << " from 5 to 60 deg" << exit(FatalError);
        }
    }

    if (args.found("profiles")) mkDir(args.get<fileName>("profiles"));

    const clockTime clock;
    List<similarityWedge::state> rows(deadrise.size());
    scalarList hMins(deadrise.size());
    forAll(deadrise, i)
    {
        const scalar tanb = std::tan(degToRad(deadrise[i]));
        c.hMin = option
        (
            args, "hMin",
            min(0.01, max(0.002, sqr(tanb)/(10*constant::mathematical::pi))),
            1e-4, 0.1, "1e-4 <= hMin <= 0.1"
        );
        hMins[i] = c.hMin;

        Info<< "Deadrise " << deadrise[i] << " deg (hMin " << c.hMin
            << " c_w):" << endl;
        similarityWedge wedge(deadrise[i], c);
        const scalar started = clock.elapsedTime();
        try
        {
            rows[i] = wedge.march
            (
                [&](const similarityWedge::state& s)
                {
                    Info<< "    tau " << s.tau << "  F/(rho V^3 t) " << s.CF
                        << "  CpMax " << s.CpMax << "  zMax " << s.zMax
                        << "  (" << s.body.size() + s.surface.size()
                        << " nodes on the face and the surface, "
                        << clock.elapsedTime() - started << " s)" << endl;
                },
                0.5
            );
        }
        catch (const std::exception& e)
        {
            FatalErrorInFunction
                << "deadrise " << deadrise[i] << " deg: " << e.what()
                << "; nothing written" << exit(FatalError);
        }
        const similarityWedge::state& s = rows[i];
        Info<< "    F/(rho V^3 t) " << s.CF << ", CpMax " << s.CpMax
            << " at xi " << s.xMax << ", eta " << s.zMax << nl << endl;

        if (args.found("profiles"))
        {
            const fileName dir(args.get<fileName>("profiles"));
            std::ostringstream name;
            name << "profile_" << deadrise[i] << ".dat";
            writeAtomic
            (
                dir/name.str(),
                [&](OFstream& os)
                {
                    os  << "# The similarity solution at deadrise "
                        << deadrise[i] << " deg (wedgeSimilarity)" << nl
                        << "# xi = x/(V t), eta = y/(V t), Cp = p/(rho V^2/2)"
                        << nl << "# face: xi eta Cp" << nl;
                    for (size_t k = 0; k < s.body.size(); ++k)
                    {
                        os  << s.body[k].x() << ' ' << s.body[k].y() << ' '
                            << s.Cp[k] << nl;
                    }
                    os  << nl << nl << "# free surface: xi eta" << nl;
                    for (const auto& X : s.surface)
                    {
                        if (X.x() > 10*wedge.cw()) break;
                        os  << X.x() << ' ' << X.y() << nl;
                    }
                }
            );
        }
    }

    writeAtomic
    (
        output,
        [&](OFstream& os)
        {
            os  << "# The similarity solution of a rigid wedge entering calm"
                << " water at a constant speed V, no gravity" << nl
                << "# (Dobrovol'skaya 1969), by boundary elements: "
                << "wedgeSimilarity";
            for (int a = 1; a < argc; ++a) os << ' ' << argv[a];
            os  << nl
                << "# CF = F/(rho V^3 t), the vertical force on both faces;"
                << " CpMax = max p/(rho V^2/2)" << nl
                << "# at xMax/(V t) from the symmetry line, zMax/(V t) above"
                << " the undisturbed surface; Wagner's CF = pi^3/(4 tan^2 b)"
                << nl
                << "# deadrise[deg] CF CpMax xMax zMax CF/Wagner hMin" << nl;
            forAll(rows, i)
            {
                const similarityWedge::state& s = rows[i];
                const scalar tanb = std::tan(degToRad(deadrise[i]));
                const scalar wagner =
                    pow3(constant::mathematical::pi)/(4*sqr(tanb));
                os  << deadrise[i] << ' ' << s.CF << ' ' << s.CpMax << ' '
                    << s.xMax << ' ' << s.zMax << ' ' << s.CF/wagner << ' '
                    << hMins[i] << nl;
            }
        }
    );
    Info<< "Wrote " << output << " (" << clock.elapsedTime() << " s)" << endl;

    return 0;
}


// ************************************************************************* //
