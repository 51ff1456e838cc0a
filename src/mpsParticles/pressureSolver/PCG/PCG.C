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
#include <Eigen/IterativeLinearSolvers>

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

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::pressureSolvers::PCG::PCG(const dictionary& dict)
:
    pressureSolver(dict),
    preconditioner_
    (
        preconditionerNames.getOrDefault
        (
            "preconditioner",
            dict,
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
        Eigen::ConjugateGradient
        <
            ppeMatrix,
            Eigen::Lower|Eigen::Upper,
            Eigen::DiagonalPreconditioner<double>
        > cg;
        return solveWith(cg, A, b, p, tolerance_, maxIter_);
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
