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
    Test-mpsParallelFluid

Description
    The fluid step across ranks (mpsFluid with an mpsDecomposition) against
    the serial step, on a decomposed case without a structure, run with
    mpirun -np N ... -parallel: every rank generates the case's particles
    and steps the whole cloud alone (the reference) and its own share with
    halos, from the same start, for -steps steps of the controlDict's
    deltaT. Every -every steps it compares each owned particle with the
    same particle of the reference: positions (in l0), velocities (in the
    largest speed), pressures (in the largest pressure); with -tolerance
    (default 1e-9) on all three. Prints "passed" or what failed.

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "Time.H"
#include "polyMesh.H"
#include "IOdictionary.H"
#include "mpsCloud.H"
#include "mpsFluid.H"
#include "mpsDecomposition.H"
#include "particleGenerator.H"
#include "StringStream.H"

using namespace Foam;

// The same particles, each kind in reverse order: the step's sums over
// neighbours then run in another order, round-off apart
mpsCloud reversedCopy(const mpsCloud& cloud)
{
    labelList order(cloud.size());
    forAll(order, k)
    {
        order[k] = cloud.size() - 1 - k;
    }
    OStringStream os;
    cloud.send(order, os);
    IStringStream is(os.str());
    mpsCloud copy;
    copy.receive(is);
    return copy;
}

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Checks the fluid step across ranks against the serial step"
    );
    argList::addOption("steps", "n", "steps (default 40)");
    argList::addOption("every", "n", "compare every n steps (default 10)");
    argList::addOption("tolerance", "e", "largest difference (default 1e-9)");
    argList::addBoolOption
    (
        "reversed",
        "compare with the serial step on the same particles in reverse"
        " order instead (how fast the step itself amplifies round-off)"
    );

    #include "setRootCase.H"
    #include "createTime.H"
    #include "createPolyMesh.H"

    const label nSteps = args.getOrDefault<label>("steps", 40);
    const label every = args.getOrDefault<label>("every", 10);
    const scalar tolerance = args.getOrDefault<scalar>("tolerance", 1e-9);

    const IOdictionary mpsProperties
    (
        IOobject("mpsProperties", runTime.constant(), mesh,
            IOobject::MUST_READ, IOobject::NO_WRITE)
    );
    const IOdictionary particleDict
    (
        IOobject("particleDict", runTime.system(), mesh,
            IOobject::MUST_READ, IOobject::NO_WRITE)
    );
    const scalar dt = runTime.deltaTValue();

    const boundBox bounds(mesh.points(), true);
    mpsCloud full;
    mpsFluid serial(full, mpsProperties, bounds);
    const scalar l0 = serial.l0();
    particleGenerator(particleDict, l0, l0).generate(full, bounds);
    if (full.count(particleKind::structure))
    {
        FatalErrorInFunction
            << "The case has a structure: this test steps the fluid alone"
            << exit(FatalError);
    }

    const bool reversed = args.found("reversed");
    mpsCloud local(reversed ? reversedCopy(full) : mpsCloud(full));
    mpsFluid parallel(local, mpsProperties, bounds);
    mpsDecomposition decomposition
    (
        mesh, parallel.haloRadius() + l0
    );
    if (!reversed)
    {
        // This rank's share
        boolList keep(local.size());
        forAll(keep, i)
        {
            keep[i] =
                decomposition.owner(local.x()[i]) == Pstream::myProcNo();
        }
        local.subset(keep);
        local.setDistribution(decomposition);
    }

    serial.evaluate();
    parallel.evaluate();

    label failures = 0;
    for (label step = 1; step <= nSteps; ++step)
    {
        serial.step(dt);
        parallel.step(dt);

        if (step % every && step != nSteps)
        {
            continue;
        }

        scalar maxU = 0, maxP = 0;
        forAll(full.x(), i)
        {
            maxU = max(maxU, mag(full.U()[i]));
            maxP = max(maxP, mag(full.p()[i]));
        }
        scalar dx = 0, dU = 0, dp = 0;
        label nOwned = 0, missing = 0;
        forAll(local.x(), i)
        {
            if (local.halo()[i])
            {
                continue;
            }
            ++nOwned;
            const label r = full.index(local.id()[i]);
            if (r < 0)
            {
                ++missing;
                continue;
            }
            dx = max(dx, mag(local.x()[i] - full.x()[r])/l0);
            dU = max(dU, mag(local.U()[i] - full.U()[r])/max(maxU, VSMALL));
            dp = max(dp, mag(local.p()[i] - full.p()[r])/max(maxP, VSMALL));
        }
        reduce(nOwned, sumOp<label>());
        reduce(missing, sumOp<label>());
        reduce(dx, maxOp<scalar>());
        reduce(dU, maxOp<scalar>());
        reduce(dp, maxOp<scalar>());
        Info<< "step " << step << " (t = " << step*dt << " s): "
            << nOwned << " owned of " << full.size() << " on "
            << Pstream::nProcs() << " ranks; max |x - x_serial|/l0 " << dx
            << ", |u - u_serial|/max|u| " << dU
            << ", |p - p_serial|/max|p| " << dp
            << " (PPE iterations " << serial.info().ppeIterations
            << " serial, "
            << parallel.info().ppeIterations << " parallel)" << endl;
        if (nOwned != full.size() || missing)
        {
            Info<< "FAILED: " << nOwned << " particles owned ("
                << missing << " not in the serial cloud), "
                << full.size() << " in the serial cloud" << endl;
            ++failures;
        }
        if (!(dx <= tolerance && dU <= tolerance && dp <= tolerance))
        {
            Info<< "FAILED: the parallel step differs from the serial one"
                << " by more than " << tolerance << endl;
            ++failures;
        }
    }

    Info<< (failures ? "FAILED" : "passed") << nl << endl;
    return failures ? 1 : 0;
}


// ************************************************************************* //
