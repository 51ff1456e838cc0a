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
    mpsFsiFoam

Group
    grpLagrangianSolvers

Description
    Hydroelastic slamming of an elastic wedge entering calm water, solved by
    an improved Moving Particle Semi-implicit (MPS) method: incompressible
    fluid with wall and dummy particles, an elastic particle structure with
    its own spacing and sub-cycled time step, coupled at the interface of
    wall particles and the structure's interface layer.

    Reads system/controlDict, system/particleDict, constant/mpsProperties and
    (where present) constant/structureProperties; builds the particles (or
    reads them back at the start time of a restart) and advances the fluid
    with the semi-implicit MPS step (mpsFluid). Writes at write times the
    lagrangian clouds fluid, wall and structure, and VTK/<cloud>_<n>.vtp with
    VTK/<cloud>.pvd. A step whose pressure or velocity is not finite stops
    the run with a message; the last written time stays as it was.

    controlDict: the usual time controls; adjustTimeStep (default no) with
    maxCo (default 0.2, Courant number |u| dt/l0) and maxDeltaT.

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "mpsCloud.H"
#include "mpsKernel.H"
#include "particleGenerator.H"
#include "mpsCloudOutput.H"
#include "lagrangianCloudReader.H"
#include "mpsFluid.H"
#include "mpsState.H"
#include "mpsStructure.H"
#include "fluidStructureInterface.H"
#include "clockValue.H"
#include <fenv.h>

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Hydroelastic slamming (elastic wedge entry) with an improved MPS"
        " method: particle fluid, particle structure, sub-cycled coupling."
    );
    argList::noParallel();

    #include "setRootCaseLists.H"
    #include "createTime.H"

    // The solver checks every step for values that are not finite and stops
    // with a message naming the step: floating-point traps would abort it
    // earlier, without saying where
    fedisableexcept(FE_DIVBYZERO | FE_INVALID | FE_OVERFLOW);
    Info<< "Floating-point traps off: every step is checked for values that"
        << " are not finite" << nl << endl;

    #include "createMesh.H"
    #include "createFields.H"
    #include "reportParticles.H"

    mpsCloudOutput output(mesh);

    if (restart)
    {
        Info<< "Continuing from time " << runTime.timeName() << nl << endl;
    }
    // The start time is written once the function objects are built (at
    // the first runTime.run()), so that one with bad input stops the run
    // before anything of an earlier run is overwritten
    bool writeStart = !restart;

    const bool adjustTimeStep =
        runTime.controlDict().getOrDefault("adjustTimeStep", false);
    const scalar maxCo = runTime.controlDict().getOrDefault<scalar>("maxCo", 0.2);
    const scalar maxDeltaT =
        runTime.controlDict().getOrDefault<scalar>("maxDeltaT", GREAT);

    Info<< "Starting time loop" << nl << endl;

    clockValue wallClock(true);
    label stepi = 0;
    scalar couplingTime = 0;
    word lastWritten(runTime.timeName());

    while (runTime.run())
    {
        if (writeStart)
        {
            Info<< "Writing time " << runTime.timeName() << nl << endl;
            output.write(cloud, &structure);
            writeStart = false;
        }

        ++runTime;
        ++stepi;
        const scalar dt = runTime.deltaTValue();

        // Fluid first (when the case has fluid), then the structure,
        // sub-cycled over the fluid step
        const label nFluidBefore = cloud.count(particleKind::fluid);
        const mpsFluid::stepInfo& info =
            nFluidBefore ? fluid.step(dt) : fluid.info();

        if (nFluidBefore)
        {
            #include "checkDivergence.H"
        }

        // Wall pressures to forces on the interface layer; the structure
        // sub-cycled under them; the attached walls follow it and bound
        // the fluid at the next step
        clockValue couplingClock(true);
        coupling.transferPressure();
        couplingTime += couplingClock.elapsed();
        structure.advance(runTime.value(), dt);
        couplingClock.update();
        coupling.moveWalls();
        couplingTime += couplingClock.elapsed();

        if (nFluidBefore && !info.ppeConverged)
        {
            WarningInFunction
                << "Time " << runTime.timeName() << ", step " << stepi
                << ": the pressure solver did not reach its tolerance "
                << fluid.solver().tolerance() << " in " << info.ppeIterations
                << " iterations (relative residual " << info.ppeResidual
                << ")" << endl;
        }

        const scalar Co = info.maxSpeed*dt/fluid.l0();

        runTime.write();
        if (runTime.writeTime())
        {
            output.write(cloud, &structure);
            lastWritten = runTime.timeName();
        }

        if (runTime.writeTime() || stepi % 100 == 0)
        {
            Info<< "Time = " << runTime.timeName()
                << "  step " << stepi
                << "  PPE " << info.ppeIterations << " it, residual "
                << info.ppeResidual
                << "  surface " << info.nSurface
                << "  Co " << Co;
            if (structure.active())
            {
                Info<< "  structure " << structure.nSubSteps()
                    << " sub-steps";
            }
            Info<< "  wall " << wallClock.elapsed() << " s"
                << (runTime.writeTime() ? "  (written)" : "") << endl;
        }

        if (adjustTimeStep)
        {
            const scalar dtCo =
                info.maxSpeed > SMALL ? maxCo*fluid.l0()/info.maxSpeed : GREAT;
            runTime.setDeltaT(min(min(dtCo, 1.2*dt), maxDeltaT));
        }
    }

    if (writeStart)
    {
        // endTime = startTime: nothing to run, only the particles to write
        Info<< "Writing time " << runTime.timeName() << nl << endl;
        output.write(cloud, &structure);
    }

    const mpsFluid::stepInfo& info = fluid.info();
    const label nSteps = max(info.nSteps, label(1));
    Info<< nl << "Fluid steps: " << info.nSteps
        << ", mean PPE iterations " << scalar(info.totalPpeIterations)/nSteps
        << nl
        << "Time split [s]: neighbours " << info.timeNeighbours
        << ", PPE assembly " << info.timeAssembly
        << ", PPE solve " << info.timeSolve
        << ", rest " << info.timeRest << nl;
    if (structure.active())
    {
        Info<< "Structure sub-steps: " << structure.totalSubSteps()
            << ", time " << structure.wallTime() << " s" << nl;
    }
    if (coupling.active())
    {
        Info<< "Coupling time " << couplingTime << " s" << nl
            << "Force balance: largest |sum of the structural forces -"
            << " fluid force| " << coupling.maxImbalance() << " N/m" << nl;
    }

    runTime.printExecutionTime(Info);

    Info<< "End\n" << endl;

    return 0;
}


// ************************************************************************* //
