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
    Test-mpsDecomposition

Description
    The particles' decomposition (mpsDecomposition) on a decomposed case,
    run with mpirun -np N ... -parallel: every rank generates the case's
    particles (system/particleDict; all kinds), keeps a scrambled share
    (id modulo N), distributes them to their owners and adds halos; then
    the number density of every owned particle, summed over its local
    neighbours (owned and halo), must equal the one summed over the whole
    cloud, and its neighbour count too. Repeated after every particle has
    moved by up to 0.9 l0 (a smooth field), so that particles change rank
    (those that leave the mesh are removed, as the solver does).
    Then a pressure-like system over the fluid and wall particles (the MPS
    Laplacian's weights, a mass term n0/10 for a unique answer, the other
    kinds as p = 0 neighbours), numbered by rank with the halos' global
    rows from updateHalos, solved by BoomerAMG across the ranks, must give
    the serial solution to within the solver's tolerance.
    Prints "passed" or what failed; the exit status says the same.
    -haloWidth <factor> sets the halo width to that many kernel radii
    (default 1): below 1 the check must fail (the case test shows it does).

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

using namespace Foam;

// Number density (original kernel re/r - 1) and neighbour count of each
// point of x, over every other point of x
void numberDensity
(
    const UList<vector2D>& x,
    const scalar re,
    scalarList& n,
    labelList& count
)
{
    const neighbourList nbrs(x, re);
    n.setSize(x.size());
    count.setSize(x.size());
    forAll(x, i)
    {
        scalar s = 0;
        for (const label j : nbrs[i])
        {
            s += re/mag(x[j] - x[i]) - 1;
        }
        n[i] = s;
        count[i] = nbrs[i].size();
    }
}


// A smooth displacement of up to 0.9 l0, the same function on every rank
vector2D displacement(const vector2D& x, const scalar l0)
{
    return 0.9*l0*vector2D
    (
        ::sin(7.3*x.y() + 0.4),
        ::cos(5.1*x.x() - 0.2)
    );
}


// Compare the owned particles of local with the reference (by id);
// returns the number of failures on this rank
label check
(
    const word& stage,
    const mpsCloud& full,
    const mpsCloud& local,
    const mpsDecomposition& decomposition,
    const scalar re,
    const scalar n0
)
{
    scalarList nRef, n;
    labelList countRef, count;
    numberDensity(full.x(), re, nRef, countRef);
    numberDensity(local.x(), re, n, count);

    label nOwned = 0, nHalo = 0, wrongOwner = 0, wrongCount = 0;
    label nReplicated = 0, nReplicatedFull = 0, wrongReplicated = 0;
    for (const particleKind k : full.kind())
    {
        nReplicatedFull += mpsDecomposition::replicated(k);
    }
    scalar maxError = 0;
    forAll(local.x(), i)
    {
        const bool replicated =
            mpsDecomposition::replicated(local.kind()[i]);
        if (local.halo()[i])
        {
            ++nHalo;
            wrongReplicated += replicated;
            continue;
        }
        if (replicated)
        {
            // (the structure reads no neighbour sums of the fluid's: its
            // particles away from this rank's cells have no halos near)
            ++nReplicated;
            continue;
        }
        ++nOwned;
        if (decomposition.owner(local.x()[i]) != Pstream::myProcNo())
        {
            ++wrongOwner;
        }
        const label r = full.index(local.id()[i]);
        maxError = max(maxError, mag(n[i] - nRef[r])/n0);
        if (count[i] != countRef[r])
        {
            ++wrongCount;
        }
    }
    const label nHaloMine = nHalo;
    reduce(nOwned, sumOp<label>());
    reduce(nHalo, sumOp<label>());
    reduce(wrongOwner, sumOp<label>());
    reduce(wrongCount, sumOp<label>());
    reduce(maxError, maxOp<scalar>());

    Info<< stage << ": " << Pstream::nProcs() << " ranks, " << nOwned
        << " owned of " << full.size() << ", " << nHalo << " halos"
        << " (this rank " << nHaloMine << "); max |n - n_serial|/n0 "
        << maxError << ", " << wrongCount << " neighbour counts differ, "
        << wrongOwner << " particles on the wrong rank" << endl;

    label failures = 0;
    if (nOwned != full.size() - nReplicatedFull)
    {
        Info<< "FAILED: " << nOwned << " particles owned, the cloud has "
            << full.size() - nReplicatedFull << " not replicated" << endl;
        ++failures;
    }
    // Every rank holds every replicated particle (the structure's), none
    // of them as a halo
    label badRanks = (nReplicated != nReplicatedFull || wrongReplicated);
    reduce(badRanks, sumOp<label>());
    if (badRanks)
    {
        Info<< "FAILED: " << badRanks << " ranks do not hold the "
            << nReplicatedFull << " structure particles, or hold them as"
            << " halos" << endl;
        ++failures;
    }
    if (wrongOwner || wrongCount)
    {
        Info<< "FAILED: particles on the wrong rank or with other"
            << " neighbours than in serial" << endl;
        ++failures;
    }
    if (maxError > 1e-12)
    {
        Info<< "FAILED: number density differs from the serial sum by more"
            << " than round-off (1e-12 n0)" << endl;
        ++failures;
    }
    if (Pstream::parRun() && Pstream::nProcs() > 1 && !nHalo)
    {
        Info<< "FAILED: no halos on " << Pstream::nProcs() << " ranks"
            << endl;
        ++failures;
    }
    return failures;
}


// The system over the ranks against the serial one; returns failures
label checkPressure
(
    const mpsCloud& full,
    const mpsCloud& local,
    const mpsDecomposition& decomposition,
    const scalar re,
    const scalar n0
)
{
    auto unknown = [](const particleKind k)
    {
        return k == particleKind::fluid || k == particleKind::wall;
    };
    dictionary dict;
    dict.add
    (
        "pressureSolver",
        dictionary(IStringStream
        (
            "type BoomerAMG; tolerance 1e-10; maxIter 200;"
        )())
    );

    // Serial, on every rank alone
    labelList rowFull(full.size(), -1);
    label nFull = 0;
    forAll(rowFull, i)
    {
        if (unknown(full.kind()[i]))
        {
            rowFull[i] = nFull++;
        }
    }
    ppeMatrix A;
    Eigen::VectorXd b;
    assemble
    (
        full, neighbourList(full.x(), re), rowFull, 0, nFull, nFull, re,
        0.1*n0, A, b
    );
    Eigen::VectorXd pRef = Eigen::VectorXd::Zero(nFull);
    autoPtr<pressureSolver> serial(pressureSolver::New(dict));
    serial->solve(A, b, pRef);

    // Across the ranks: owned rows numbered rank by rank, halos' rows
    // from their owners
    labelList row;
    const globalIndex rows(numberRows(local, decomposition, row));
    const label nMine = rows.localSize();
    assemble
    (
        local, neighbourList(local.x(), re), row,
        rows.offset(Pstream::myProcNo()), nMine, rows.size(), re, 0.1*n0,
        A, b
    );
    Eigen::VectorXd p = Eigen::VectorXd::Zero(nMine);
    autoPtr<pressureSolver> parallel(pressureSolver::New(dict));
    const pressureSolver::performance perf =
        parallel->solve(A, b, p, rows.offset(Pstream::myProcNo()));

    scalar maxError = 0;
    forAll(row, i)
    {
        if (row[i] >= 0 && !local.halo()[i])
        {
            const scalar ref = pRef[rowFull[full.index(local.id()[i])]];
            const label r = row[i] - rows.offset(Pstream::myProcNo());
            maxError = max(maxError, mag(p[r] - ref));
        }
    }
    reduce(maxError, maxOp<scalar>());
    const scalar scale = pRef.cwiseAbs().maxCoeff();
    Info<< "pressure: " << rows.size() << " unknowns on "
        << Pstream::nProcs() << " ranks (" << perf.iterations
        << " iterations, residual " << perf.residual << "); max |p - p_serial|"
        << "/max |p_serial| " << maxError/scale << endl;
    if (rows.size() != nFull || !perf.converged || !(maxError <= 1e-7*scale))
    {
        Info<< "FAILED: the system across the ranks is not the serial one"
            << " (" << rows.size() << " against " << nFull << " unknowns;"
            << " difference above 1e-7 of the largest value)" << endl;
        return 1;
    }
    return 0;
}


int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Checks the particles' decomposition (ownership, migration, halos)"
        " against the serial number density"
    );
    argList::addOption
    (
        "haloWidth",
        "factor",
        "halo width in kernel radii (default 1; below 1 must fail)"
    );

    #include "setRootCase.H"
    #include "createTime.H"
    #include "createPolyMesh.H"

    const IOdictionary mpsProperties
    (
        IOobject("mpsProperties", runTime.constant(), mesh,
            IOobject::MUST_READ, IOobject::NO_WRITE)
    );
    const IOdictionary structureProperties
    (
        IOobject("structureProperties", runTime.constant(), mesh,
            IOobject::READ_IF_PRESENT, IOobject::NO_WRITE),
        dictionary()
    );
    const IOdictionary particleDict
    (
        IOobject("particleDict", runTime.system(), mesh,
            IOobject::MUST_READ, IOobject::NO_WRITE)
    );
    const scalar l0 = mpsProperties.get<scalar>("l0");
    const scalar re = 2.1*l0;

    // Every rank generates the whole cloud (the reference) in the whole
    // mesh's bounds
    const boundBox bounds(mesh.points(), true);
    mpsCloud full;
    particleGenerator
    (
        particleDict, l0, mpsStructure::spacing(structureProperties, l0)
    ).generate(full, bounds);

    scalarList nRef;
    labelList countRef;
    numberDensity(full.x(), re, nRef, countRef);
    const scalar n0 = max(nRef);

    // A scrambled share to start from: every particle somewhere, mostly
    // on the wrong rank
    mpsCloud local(full);
    {
        boolList keep(local.size());
        forAll(keep, i)
        {
            // (the replicated kinds, the structure's, everywhere)
            keep[i] =
                mpsDecomposition::replicated(local.kind()[i])
             || (local.id()[i] % Pstream::nProcs() == Pstream::myProcNo());
        }
        local.subset(keep);
    }

    mpsDecomposition decomposition
    (
        mesh, args.getOrDefault<scalar>("haloWidth", 1)*re
    );

    label failures = 0;
    label nSent = decomposition.sendToOwners(local);
    reduce(nSent, sumOp<label>());
    Info<< "distributed: " << nSent << " particles moved rank" << endl;
    decomposition.addHalos(local);
    failures += check("generated", full, local, decomposition, re, n0);

    // Move every particle (the same function of position everywhere);
    // those that leave the mesh go, as the solver removes them
    mpsDecomposition::removeHalos(local);
    for (mpsCloud* c : {&full, &local})
    {
        UList<vector2D>& x = c->x();
        boolList keep(x.size());
        forAll(x, i)
        {
            x[i] += displacement(x[i], l0);
            keep[i] = (decomposition.owner(x[i]) >= 0);
        }
        c->subset(keep);
    }
    nSent = decomposition.sendToOwners(local);
    reduce(nSent, sumOp<label>());
    Info<< "moved: " << nSent << " particles changed rank" << endl;
    if (Pstream::parRun() && Pstream::nProcs() > 1 && !nSent)
    {
        Info<< "FAILED: no particle changed rank after the move" << endl;
        ++failures;
    }
    decomposition.addHalos(local);
    failures += check("moved", full, local, decomposition, re, n0);
    failures += checkPressure(full, local, decomposition, re, n0);

    Info<< (failures ? "FAILED" : "passed") << nl << endl;
    return failures ? 1 : 0;
}


// ************************************************************************* //
