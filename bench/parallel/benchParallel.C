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
    benchParallel

Description
    The parallel building blocks of an MPS step on a case's particles, timed
    on each rank (mpirun -np N benchParallel -parallel, or serial): per
    repetition, every particle moves a little, then
      exchange   removeHalos, sendToOwners, addHalos (mpsDecomposition)
      neighbours the neighbour list over owned and halo particles
      rows       global row numbers, the halos' through updateHalos
      assembly   a pressure-like system (the MPS Laplacian's weights and a
                 mass term) over the fluid and wall particles
      solve      BoomerAMG (PCG, tolerance 1e-8) across the ranks
      refresh    the solution to the halos (updateHalos)
    Prints per item the slowest rank's time, the best of the repetitions
    (after a first one not counted), the particles and halos per rank, and
    the solve's iterations. The multigrid hierarchy is rebuilt every solve
    (reuse 1), so that one rank and several pay the same setup.

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "Time.H"
#include "polyMesh.H"
#include "IOdictionary.H"
#include "mpsCloud.H"
#include "mpsDecomposition.H"
#include "neighbourList.H"
#include "particleGenerator.H"
#include "mpsStructure.H"
#include "laplacianSystem.H"
#include "clockValue.H"
#include <omp.h>

using namespace Foam;

int main(int argc, char *argv[])
{
    argList::addNote("Times the parallel building blocks of an MPS step");
    argList::addOption("repeat", "n", "repetitions (default 5)");

    #include "setRootCase.H"
    #include "createTime.H"
    #include "createPolyMesh.H"

    const label nRepeat = args.getOrDefault<label>("repeat", 5);
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
    const scalar l0 = mpsProperties.get<scalar>("l0");
    const scalar re = 2.1*l0;

    const boundBox bounds(mesh.points(), true);
    mpsCloud cloud;
    particleGenerator(particleDict, l0, l0).generate(cloud, bounds);
    const label nTotal = cloud.size();

    mpsDecomposition decomposition(mesh, re + 0.5*l0);
    {
        boolList keep(cloud.size());
        forAll(keep, i)
        {
            const label owner = decomposition.owner(cloud.x()[i]);
            keep[i] = (owner == Pstream::myProcNo() || owner < 0);
        }
        cloud.subset(keep);
    }

    dictionary dict;
    dict.add
    (
        "pressureSolver",
        dictionary
        (
            IStringStream
            (
                "type BoomerAMG; tolerance 1e-8; maxIter 200; reuse 1;"
            )()
        )
    );
    autoPtr<pressureSolver> solver(pressureSolver::New(dict));

    enum { tExchange, tNeighbours, tRows, tAssembly, tSolve, tRefresh, nItems };
    const char* names[nItems] =
        {"exchange", "neighbours", "rows", "assembly", "solve", "refresh"};
    scalarList t(nItems, GREAT);
    label iterations = 0, nHalo = 0;
    neighbourList nbrs;

    for (label rep = 0; rep <= nRepeat; ++rep)
    {
        scalarList tRep(nItems, Zero);
        clockValue clock(true);
        auto lap = [&](const label item)
        {
            tRep[item] += clock.elapsed();
            clock.update();
        };

        // A small smooth motion, then the particles to their owners
        mpsDecomposition::removeHalos(cloud);
        UList<vector2D>& x = cloud.x();
        forAll(x, i)
        {
            if (cloud.kind()[i] == particleKind::fluid)
            {
                x[i] += 0.05*l0*vector2D
                (
                    ::sin(40*x[i].y() + rep), ::cos(30*x[i].x() - rep)
                );
            }
        }
        decomposition.sendToOwners(cloud);
        nHalo = decomposition.addHalos(cloud);
        lap(tExchange);

        nbrs.build(cloud.x(), re);
        lap(tNeighbours);

        labelList row;
        const globalIndex rows(numberRows(cloud, decomposition, row));
        const label nMine = rows.localSize();
        const label rowStart = rows.offset(Pstream::myProcNo());
        lap(tRows);

        ppeMatrix A;
        Eigen::VectorXd b;
        assemble
        (
            cloud, nbrs, row, rowStart, nMine, rows.size(), re, 0.01*6.5,
            A, b
        );
        lap(tAssembly);

        Eigen::VectorXd p = Eigen::VectorXd::Zero(nMine);
        const pressureSolver::performance perf =
            solver->solve(A, b, p, rowStart);
        lap(tSolve);

        scalarList pAll(cloud.size(), Zero);
        forAll(row, i)
        {
            if (row[i] >= 0 && !cloud.halo()[i])
            {
                pAll[i] = p[row[i] - rowStart];
            }
        }
        decomposition.updateHalos(cloud, pAll);
        lap(tRefresh);

        if (rep > 0)
        {
            // (the first repetition builds the hierarchy: not counted)
            forAll(t, item)
            {
                reduce(tRep[item], maxOp<scalar>());
                t[item] = min(t[item], tRep[item]);
            }
            iterations += perf.iterations;
        }
    }

    label nOwned = cloud.size() - nHalo;
    label maxOwned = nOwned, maxHalo = nHalo;
    reduce(maxOwned, maxOp<label>());
    reduce(maxHalo, maxOp<label>());
    scalar total = 0;
    Info<< "benchParallel: " << nTotal << " particles, "
        << Pstream::nProcs() << " rank(s) x " << omp_get_max_threads()
        << " thread(s); per rank at most " << maxOwned << " owned, "
        << maxHalo << " halos; " << scalar(iterations)/nRepeat
        << " PCG iterations a solve" << nl;
    for (label item = 0; item < nItems; ++item)
    {
        const scalar ti = t[item];
        total += ti;
        Info<< "    " << names[item] << ": " << 1e3*ti << " ms" << nl;
    }
    Info<< "    total: " << 1e3*total << " ms a repetition" << nl << endl;
    return 0;
}


// ************************************************************************* //
