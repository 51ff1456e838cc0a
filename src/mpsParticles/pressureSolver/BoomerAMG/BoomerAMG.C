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

#include "BoomerAMG.H"
#include "hypreSystem.H"
#include "addToRunTimeSelectionTable.H"
#include "inputChecks.H"
#include "Pstream.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace pressureSolvers
{
    defineTypeNameAndDebug(BoomerAMG, 0);
    addToRunTimeSelectionTable(pressureSolver, BoomerAMG, dictionary);
}
}


// * * * * * * * * * * * * * * * Private Classes * * * * * * * * * * * * * * //

struct Foam::pressureSolvers::BoomerAMG::hierarchy
{
    //- The matrix the hierarchy was built on (the hierarchy refers to it)
    HYPRE_IJMatrix A = nullptr;

    //- The multigrid
    HYPRE_Solver amg = nullptr;

    //- Its number of rows
    HYPRE_BigInt n = 0;

    //- Solves it has served
    label age = 0;

    void clear()
    {
        if (amg)
        {
            HYPRE_BoomerAMGDestroy(amg);
            amg = nullptr;
        }
        if (A)
        {
            HYPRE_IJMatrixDestroy(A);
            A = nullptr;
        }
        n = 0;
        age = 0;
    }

    ~hierarchy()
    {
        clear();
    }
};


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- Preconditioner setup that keeps the existing hierarchy
HYPRE_Int keepHierarchy(HYPRE_Solver, HYPRE_Matrix, HYPRE_Vector, HYPRE_Vector)
{
    return 0;
}

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::pressureSolvers::BoomerAMG::BoomerAMG(const dictionary& dict)
:
    pressureSolver(dict),
    strongThreshold_
    (
        inputChecks::number<scalar>(dict, "strongThreshold", 0.25, "(0, 1)")
    ),
    reuse_(inputChecks::number<label>(dict, "reuse", 10, ">= 1")),
    hierarchy_(new hierarchy)
{
    inputChecks::keywords
    (
        dict,
        {"type", "tolerance", "maxIter", "strongThreshold", "reuse"},
        "pressureSolver BoomerAMG"
    );
    hypreSystem::initialise();
}


// * * * * * * * * * * * * * * * * Destructor  * * * * * * * * * * * * * * //

Foam::pressureSolvers::BoomerAMG::~BoomerAMG()
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::pressureSolver::performance Foam::pressureSolvers::BoomerAMG::solve
(
    const ppeMatrix& A,
    const Eigen::VectorXd& b,
    Eigen::VectorXd& p
)
{
    return solve(A, b, p, 0, false);
}


Foam::pressureSolver::performance Foam::pressureSolvers::BoomerAMG::solve
(
    const ppeMatrix& A,
    const Eigen::VectorXd& b,
    Eigen::VectorXd& p,
    const label rowStart
)
{
    return solve(A, b, p, rowStart, Pstream::parRun() && Pstream::nProcs() > 1);
}


Foam::pressureSolver::performance Foam::pressureSolvers::BoomerAMG::solve
(
    const ppeMatrix& A,
    const Eigen::VectorXd& b,
    Eigen::VectorXd& p,
    const label rowStart,
    const bool parallel
)
{
    const HYPRE_BigInt n = A.rows();
    label nGlobal = n;
    if (parallel)
    {
        reduce(nGlobal, sumOp<label>());
    }
    if (nGlobal == 0)
    {
        return performance();
    }

    hypreSystem sys(A, b, p, rowStart, parallel);

    // The multigrid: built on this matrix, or kept from an earlier one
    hierarchy& h = *hierarchy_;
    // (the setup is collective: a rank that needs a new one rebuilds all)
    bool rebuild = (!h.amg || h.n != n || h.age >= reuse_);
    if (parallel)
    {
        reduce(rebuild, orOp<bool>());
    }
    if (rebuild)
    {
        h.clear();
        HYPRE_BoomerAMGCreate(&h.amg);
        HYPRE_BoomerAMGSetPrintLevel(h.amg, 0);
        HYPRE_BoomerAMGSetCoarsenType(h.amg, 10);       // HMIS
        HYPRE_BoomerAMGSetInterpType(h.amg, 6);         // extended+i
        HYPRE_BoomerAMGSetPMaxElmts(h.amg, 4);
        HYPRE_BoomerAMGSetStrongThreshold(h.amg, strongThreshold_);
        HYPRE_BoomerAMGSetRelaxType(h.amg, 6);          // hybrid sym. GS
        HYPRE_BoomerAMGSetNumSweeps(h.amg, 1);
        HYPRE_BoomerAMGSetMaxIter(h.amg, 1);
        HYPRE_BoomerAMGSetTol(h.amg, 0);
        HYPRE_BoomerAMGSetup(h.amg, sys.A(), sys.b(), sys.x());
        // (the hierarchy keeps the matrix it was built on)
        h.A = sys.release();
        h.n = n;
    }
    ++h.age;

    // PCG on this matrix, preconditioned by the hierarchy
    return sys.pcg
    (
        reinterpret_cast<HYPRE_PtrToSolverFcn>(HYPRE_BoomerAMGSolve),
        reinterpret_cast<HYPRE_PtrToSolverFcn>(keepHierarchy),
        h.amg,
        tolerance_,
        maxIter_,
        p
    );
}


void Foam::pressureSolvers::BoomerAMG::restartPoint()
{
    hierarchy_->clear();
}


void Foam::pressureSolvers::BoomerAMG::info(Ostream& os) const
{
    os  << type() << " (tolerance " << tolerance_ << ", maxIter "
        << maxIter_ << ", strongThreshold " << strongThreshold_
        << ", reuse " << reuse_ << ')';
}


// ************************************************************************* //
