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
    (where present) constant/structureProperties; builds the particles,
    reports them and writes the start time as lagrangian clouds fluid, wall
    and structure, and as VTK/<cloud>_<n>.vtp with VTK/<cloud>.pvd.

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "mpsCloud.H"
#include "mpsKernel.H"
#include "particleGenerator.H"
#include "neighbourList.H"
#include "mpsCloudOutput.H"

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
    #include "createMesh.H"
    #include "createFields.H"

    // Number density of every particle with the number-density kernel
    {
        const neighbourList nbrs(cloud.x(), kernel->re());
        UList<scalar>& n = cloud.n();
        const UList<vector2D>& x = cloud.x();

        #pragma omp parallel for schedule(static)
        for (label i = 0; i < cloud.size(); ++i)
        {
            scalar ni = 0;
            for (const label j : nbrs[i])
            {
                ni += kernel->w(mag(x[j] - x[i]));
            }
            n[i] = ni;
        }
    }

    Info<< "Particles:" << nl;
    for (const word& kindName : particleKindNames.names())
    {
        Info<< "    " << kindName << ": "
            << cloud.count(particleKindNames[kindName]) << nl;
    }
    Info<< "    total: " << cloud.size() << nl
        << "Regions:" << nl;
    {
        labelList regionCount(cloud.regionNames().size(), Zero);
        for (const label r : cloud.region())
        {
            ++regionCount[r];
        }
        forAll(regionCount, r)
        {
            Info<< "    " << cloud.regionNames()[r] << ": "
                << regionCount[r] << nl;
        }
    }

    const scalar n0 = kernel->latticeNumberDensity(l0);
    const scalar lambda0 = kernel->latticeLambda(l0);
    scalar nMax = 0;
    forAll(cloud.kind(), i)
    {
        if (cloud.kind()[i] == particleKind::fluid)
        {
            nMax = max(nMax, cloud.n()[i]);
        }
    }
    Info<< "Kernel " << kernel->type() << ", re = " << kernel->re()
        << " (" << kernel->re()/l0 << " l0)" << nl
        << "    n0 = " << n0 << nl
        << "    lambda0 = " << lambda0 << " (" << lambda0/sqr(l0)
        << " l0^2)" << nl
        << "    largest fluid number density = " << nMax
        << " (n/n0 = " << nMax/n0 << ")" << nl << endl;

    Info<< "Writing time " << runTime.timeName() << endl;
    mpsCloudOutput output(mesh);
    output.write(cloud);

    Info<< "The fluid and structure physics come in later versions:"
        << " this run wrote the initial particles only." << nl;

    runTime.printExecutionTime(Info);

    Info<< "End\n" << endl;

    return 0;
}


// ************************************************************************* //
