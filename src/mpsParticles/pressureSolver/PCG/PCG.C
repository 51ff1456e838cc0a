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

\*---------------------------------------------------------------------------*/

#include "PCG.H"
#include "hypreSystem.H"
#include "Pstream.H"
#include "addToRunTimeSelectionTable.H"
#include "inputChecks.H"
#include "rowChunks.H"
#include <Eigen/IterativeLinearSolvers>
#include <algorithm>
#include <limits>
#include <vector>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace pressureSolvers
{
    defineTypeNameAndDebug(PCG, 0);
    addToRunTimeSelectionTable(pressureSolver, PCG, dictionary);
}
}

const Foam::Enum<Foam::pressureSolvers::PCG::preconditionerType>
Foam::pressureSolvers::PCG::preconditionerNames
({
    { preconditionerType::diagonal, "diagonal" },
    { preconditionerType::incompleteCholesky, "incompleteCholesky" },
});


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

template<class Solver>
Foam::pressureSolver::performance solveWith
(
    Solver& solver,
    const Foam::ppeMatrix& A,
    const Eigen::VectorXd& b,
    Eigen::VectorXd& p,
    const Foam::scalar tolerance,
    const Foam::label maxIter
)
{
    solver.setTolerance(tolerance);
    solver.setMaxIterations(maxIter);
    solver.compute(A);
    p = solver.solveWithGuess(b, p);

    Foam::pressureSolver::performance perf;
    perf.iterations = solver.iterations();
    perf.residual = solver.error();
    perf.converged = (solver.info() == Eigen::Success);
    return perf;
}

// The diagonal PCG on the OpenMP threads, the iteration of Eigen's
// ConjugateGradient (the same stopping test, residual and iteration count)
// with its vector updates and inner products fused into three passes an
// iteration: q = A p with p.q; x, r, z = D^-1 r with r.r and r.z; p. The
// sums run over fixed blocks of rows, each summed in order, the blocks'
// sums then added in order: the same result on any number of threads.
// The products' blocks go to the threads as rowChunks hands them out (each
// thread its own range first, then the other's that it reaches: the rows'
// lengths differ), which leaves the sums as they are.
Foam::pressureSolver::performance diagonalPCG
(
    const Foam::ppeMatrix& A,
    const Eigen::VectorXd& b,
    Eigen::VectorXd& x,
    const Foam::scalar tolerance,
    const Foam::label maxIter,
    std::vector<Foam::scalar>& work
)
{
    using Foam::label;
    using Foam::scalar;

    const label n = A.rows();
    const auto* outer = A.outerIndexPtr();
    const auto* inner = A.innerIndexPtr();
    const scalar* val = A.valuePtr();

    constexpr label blockSize = 1024;
    const label nBlocks = (n + blockSize - 1)/blockSize;
    std::vector<scalar> sum1(nBlocks), sum2(nBlocks);
    auto total = [nBlocks](const std::vector<scalar>& s)
    {
        scalar t = 0;
        for (label k = 0; k < nBlocks; ++k)
        {
            t += s[k];
        }
        return t;
    };

    // The products' blocks: each thread its own range of them first (the
    // rows of the particles it takes in the fluid step's loops, as the
    // static schedule's vector loops), then helps with the other's
    auto forBlocks = [n](const auto& body)
    {
        Foam::rowChunks blocks(n, blockSize);
        #pragma omp parallel
        blocks.forEachChunk
        (
            [&body](const label first, const label last)
            {
                body(first/blockSize, first, last);
            }
        );
    };

    // The vectors in the solver's room, kept between solves (each element
    // written before it is read: nothing to clear)
    if (label(work.size()) < 5*n)
    {
        work.resize(5*n);
    }
    scalar* const invD = work.data();
    scalar* const r = invD + n;
    scalar* const z = r + n;
    scalar* const p = z + n;
    scalar* const q = p + n;

    // Jacobi's inverse diagonal (1 where the diagonal is zero, as Eigen's),
    // r = b - A x
    forBlocks([&](const label blk, const label first, const label last)
    {
        scalar rr = 0, bb = 0;
        for (label i = first; i < last; ++i)
        {
            scalar d = 0, Ax = 0;
            for (label k = outer[i]; k < outer[i + 1]; ++k)
            {
                Ax += val[k]*x[inner[k]];
                if (inner[k] == i)
                {
                    d = val[k];
                }
            }
            invD[i] = d != 0 ? 1/d : 1;
            r[i] = b[i] - Ax;
            rr += r[i]*r[i];
            bb += b[i]*b[i];
        }
        sum1[blk] = rr;
        sum2[blk] = bb;
    });

    Foam::pressureSolver::performance perf;
    const scalar bNorm2 = total(sum2);
    if (bNorm2 == 0)
    {
        x.setZero();
        perf.converged = true;
        perf.initialResidual = 0;
        return perf;
    }
    const scalar threshold =
        std::max(Foam::sqr(tolerance)*bNorm2, std::numeric_limits<scalar>::min());
    scalar rNorm2 = total(sum1);
    perf.initialResidual = std::sqrt(rNorm2/bNorm2);

    label iter = 0;
    if (rNorm2 >= threshold)
    {
        #pragma omp parallel for schedule(static)
        for (label blk = 0; blk < nBlocks; ++blk)
        {
            scalar rz = 0;
            for (label i = blk*blockSize; i < std::min(n, (blk + 1)*blockSize); ++i)
            {
                p[i] = invD[i]*r[i];
                rz += r[i]*p[i];
            }
            sum1[blk] = rz;
        }
        scalar rz = total(sum1);

        while (iter < maxIter)
        {
            forBlocks([&](const label blk, const label first, const label last)
            {
                scalar pq = 0;
                for (label i = first; i < last; ++i)
                {
                    scalar Ap = 0;
                    for (label k = outer[i]; k < outer[i + 1]; ++k)
                    {
                        Ap += val[k]*p[inner[k]];
                    }
                    q[i] = Ap;
                    pq += p[i]*Ap;
                }
                sum1[blk] = pq;
            });
            const scalar alpha = rz/total(sum1);

            #pragma omp parallel for schedule(static)
            for (label blk = 0; blk < nBlocks; ++blk)
            {
                scalar rr = 0, rzNew = 0;
                for (label i = blk*blockSize; i < std::min(n, (blk + 1)*blockSize); ++i)
                {
                    x[i] += alpha*p[i];
                    r[i] -= alpha*q[i];
                    z[i] = invD[i]*r[i];
                    rr += r[i]*r[i];
                    rzNew += r[i]*z[i];
                }
                sum1[blk] = rr;
                sum2[blk] = rzNew;
            }
            rNorm2 = total(sum1);
            if (rNorm2 < threshold)
            {
                break;
            }
            const scalar rzOld = rz;
            rz = total(sum2);
            const scalar beta = rz/rzOld;

            #pragma omp parallel for schedule(static)
            for (label i = 0; i < n; ++i)
            {
                p[i] = z[i] + beta*p[i];
            }
            ++iter;
        }
    }

    perf.iterations = iter;
    perf.residual = std::sqrt(rNorm2/bNorm2);
    perf.converged = perf.residual <= tolerance;
    return perf;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::pressureSolvers::PCG::PCG(const dictionary& dict)
:
    pressureSolver(dict),
    preconditioner_
    (
        inputChecks::choice
        (
            dict,
            "preconditioner",
            preconditionerNames,
            preconditionerType::diagonal
        )
    )
{
    inputChecks::keywords
    (
        dict,
        {"type", "tolerance", "maxIter", "preconditioner"},
        "pressureSolver PCG"
    );
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::pressureSolver::performance Foam::pressureSolvers::PCG::solve
(
    const ppeMatrix& A,
    const Eigen::VectorXd& b,
    Eigen::VectorXd& p
)
{
    if (b.size() == 0)
    {
        return performance();
    }

    if (preconditioner_ == preconditionerType::diagonal)
    {
        return diagonalPCG(A, b, p, tolerance_, maxIter_, work_);
    }

    Eigen::ConjugateGradient
    <
        ppeMatrix,
        Eigen::Lower|Eigen::Upper,
        Eigen::IncompleteCholesky<double, Eigen::Lower>
    > cg;
    return solveWith(cg, A, b, p, tolerance_, maxIter_);
}


Foam::pressureSolver::performance Foam::pressureSolvers::PCG::solve
(
    const ppeMatrix& A,
    const Eigen::VectorXd& b,
    Eigen::VectorXd& p,
    const label rowStart
)
{
    if (!Pstream::parRun() || Pstream::nProcs() == 1)
    {
        return solve(A, b, p);
    }
    if (preconditioner_ != preconditionerType::diagonal)
    {
        FatalIOErrorInFunction(dict_)
            << "pressureSolver PCG with preconditioner "
            << preconditionerNames[preconditioner_]
            << " solves on one rank; under -parallel use preconditioner "
            << "diagonal, or type BoomerAMG" << exit(FatalIOError);
    }

    label nGlobal = A.rows();
    reduce(nGlobal, sumOp<label>());
    if (nGlobal == 0)
    {
        return performance();
    }

    hypreSystem::initialise();
    hypreSystem sys(A, b, p, rowStart, true);
    return sys.pcg
    (
        reinterpret_cast<HYPRE_PtrToSolverFcn>(HYPRE_ParCSRDiagScale),
        reinterpret_cast<HYPRE_PtrToSolverFcn>(HYPRE_ParCSRDiagScaleSetup),
        nullptr,
        tolerance_,
        maxIter_,
        p
    );
}


void Foam::pressureSolvers::PCG::info(Ostream& os) const
{
    os  << type() << " (tolerance " << tolerance_ << ", maxIter "
        << maxIter_ << ')';
}


// ************************************************************************* //
