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
    benchStructure

Description
    Benchmark of the elastic particle structure (structureModel): the two
    panels of the elastic wedge (aluminium, 300 mm x 2 mm each, 30 deg
    deadrise, clamped over 4 spacings at the keel) with n particles across
    the thickness, under a uniform pressure of 50 kPa on the wet faces.
    Prints the particle count, the largest stable structural step against
    the paper's 2e-7 s, particle-sub-steps per second, and the wall time
    of 150,000 sub-steps and of 0.03 s at 0.9 of the stable step.

    Usage: benchStructure [-model rotatingParticles] [-across "(2 5)"]
                          [-steps 2000] [-stiffnessDamping 0]

    -stiffnessDamping beta: the structure's Kelvin-Voigt damping [s] (a
    second evaluation of the internal forces per sub-step; its stable
    step is smaller, and the step follows it).

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "clockValue.H"
#include "structureModel.H"
#include "IStringStream.H"
#include "DynamicList.H"
#include "mathematicalConstants.H"

using namespace Foam;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::noBanner();
    argList::noParallel();
    argList::addOption("across", "list", "particles across 2 mm, default (2 5)");
    argList::addOption("steps", "n", "sub-steps to time, default 2000");
    argList::addOption
    (
        "model", "word", "structure model, default rotatingParticles"
    );
    argList::addOption
    (
        "stiffnessDamping", "s", "Kelvin-Voigt retardation time, default 0"
    );
    argList args(argc, argv, false, false);

    const labelList acrossList
    (
        args.getOrDefault<labelList>("across", labelList({2, 5}))
    );
    const label nSteps = args.getOrDefault<label>("steps", 2000);
    const word model = args.getOrDefault<word>("model", "rotatingParticles");
    const scalar damping = args.getOrDefault<scalar>("stiffnessDamping", 0);

    const scalar L = 0.3, H = 0.002, beta = 30*constant::mathematical::pi/180;
    const scalar E = 68e9, nu = 0.3, rho = 2700, load = 50e3;

    for (const label n : acrossList)
    {
        const scalar ds = H/n;
        const label nx = label(std::round(L/ds));
        DynamicList<vector2D> X;
        DynamicList<bool> clamped;
        DynamicList<bool> wet;
        for (const scalar side : {1.0, -1.0})
        {
            const vector2D t(side*::cos(beta), ::sin(beta));
            const vector2D nrm(-side*t.y(), side*t.x());    // inwards (dry)
            for (label i = 0; i < nx; ++i)
            {
                for (label j = 0; j < n; ++j)
                {
                    X.append(((i + 0.5)*ds)*t + ((j + 0.5)*ds)*nrm);
                    clamped.append(i < 4);
                    wet.append(j == 0);
                }
            }
        }

        IStringStream is
        (
            "structureModel { type " + model + "; } rho 2700; E 68e9; nu 0.3;"
            " planeStrain yes; stiffnessDamping " + Foam::name(damping)
          + ";"
        );
        autoPtr<structureModel> solidPtr
        (
            structureModel::New(dictionary(is), X, clamped, ds)
        );
        structureModel& solid = solidPtr();
        const scalar dtMax = solid.maxStableDeltaT();
        solid.setDeltaT(0.9*dtMax);

        forAll(X, i)
        {
            if (wet[i])
            {
                // Pressure on the wet face: force per unit depth ds*p,
                // pushing the panel inwards (towards the dry side)
                const scalar side = (X[i].x() > 0 ? 1.0 : -1.0);
                const vector2D t(side*::cos(beta), ::sin(beta));
                const vector2D nrm(-side*t.y(), side*t.x());
                solid.externalForce()[i] = (load*ds)*nrm;
            }
        }

        solid.advance(10);      // warm up
        clockValue clock(true);
        solid.advance(nSteps);
        const scalar t = clock.elapsed();
        const scalar rate = scalar(solid.size())*nSteps/t;
        const scalar stepsFor30ms = 0.03/solid.deltaT();

        Info<< model << " across=" << n << ": " << solid.size()
            << " particles, largest stable step " << dtMax
            << " s (paper: 2e-07 s)" << nl
            << model << " across=" << n << ": " << rate
            << " particle-sub-steps/s; 150000 sub-steps: "
            << 150000*t/nSteps << " s; 0.03 s at dt = " << solid.deltaT()
            << " s is " << stepsFor30ms << " sub-steps, "
            << stepsFor30ms*t/nSteps << " s wall time" << endl;
    }

    return 0;
}


// ************************************************************************* //
