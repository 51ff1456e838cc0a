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

    Parallel: decomposePar (system/decomposeParDict: the background mesh's
    decomposition, method simple, hierarchical or manual), then
    mpirun -np N mpsFsiFoam -parallel, then reconstructPar. Every rank
    generates the particles and keeps those in its cells; the fluid's
    particles, wall and dummy ones move between ranks and are exchanged as
    halos (mpsDecomposition); the pressure is solved across the ranks
    (pressureSolver BoomerAMG); the structure is replicated on every rank,
    under the interface forces summed over the ranks. Each rank writes
    processor<N>/<time>/lagrangian/<cloud>; a restart (startFrom
    latestTime) reads them back.

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "mpsCloud.H"
#include "mpsKernel.H"
#include "particleGenerator.H"
#include "mpsCloudOutput.H"
#include "lagrangianCloudReader.H"
#include "mpsFluid.H"
#include "mpsDecomposition.H"
#include "mpsState.H"
#include "mpsStructure.H"
#include "couplingScheme.H"
#include "clockValue.H"
#include "inputChecks.H"
#include "IFstream.H"
#include "wideVectors.H"
#include <fenv.h>
#include <cstring>
#include <cerrno>
#include <fstream>
#include <sstream>
#include <omp.h>

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Hydroelastic slamming (elastic wedge entry) with an improved MPS"
        " method: particle fluid, particle structure, sub-cycled coupling."
    );
    setEnv("FOAM_SIGFPE", "false", true);

    #include "setRootCaseLists.H"
    #include "checkDecomposeParDict.H"
    #include "checkControlDict.H"
    #include "checkLatestTime.H"
    #include "createTime.H"
    #include "checkStartTime.H"
    #include "checkWritable.H"

    // The solver checks every step for values that are not finite and stops
    // with a message naming the step: floating-point traps would abort it
    // earlier, without saying where (OpenFOAM's own trapping is kept off
    // too, FOAM_SIGFPE, before the argList reads it)
    fedisableexcept(FE_DIVBYZERO | FE_INVALID | FE_OVERFLOW);
    Info<< "Floating-point traps: off (every step is checked for values"
        << " that are not finite)" << nl
        << "OpenMP threads: " << omp_get_max_threads() << nl
        << "Vector loops: the fluid step's rows (neighbours, viscosity,"
        << " kernel, shift) on "
        << (wideVectors() ? "AVX-512" : "x86-64")
        << " (MPSFSIFOAM_WIDE_VECTORS=0: x86-64's; the same numbers)" << nl
        << endl;

    #include "createMesh.H"
    #include "createFields.H"
    #include "reportParticles.H"
    #include "createSettings.H"
    #include "readTimeControls.H"

    Info<< "Starting time loop" << nl << endl;

    while (runTime.run())
    {
        #include "checkFunctionObjects.H"
        #include "writeStartTime.H"

        ++runTime;
        ++stepi;
        const scalar dt = runTime.deltaTValue();

        // The step: the fluid's, and the structure's sub-steps under the
        // wall pressures, as the coupling scheme orders them (explicit:
        // fluid first, then the structure, which moves the walls; implicit:
        // the pressure and the structure iterated within the step)
        const mpsFluid::stepInfo& info = coupling->evolve(runTime.value(), dt);
        #include "checkFluidStep.H"

        runTime.write();
        if (runTime.writeTime())
        {
            // (under -parallel each rank writes the particles in its cells)
            cloud.localise();
            output.write(cloud);
            fluid.restartPoint();
            lastWritten = runTime.timeName();
        }

        #include "reportStep.H"
        #include "setDeltaT.H"
    }

    #include "writeStartTime.H"
    #include "reportRun.H"

    runTime.printExecutionTime(Info);

    Info<< "End\n" << endl;

    return 0;
}


// ************************************************************************* //
