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

#include "pressureEquation.H"
#include "globalIndex.H"
#include "Map.H"
#include "clockValue.H"
#include "inputChecks.H"
#include "rowChunks.H"

#include <algorithm>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::Enum<Foam::pressureEquation::compressibilityFormType>
Foam::pressureEquation::compressibilityFormTypeNames
({
    { compressibilityFormType::absolute, "absolute" },
    { compressibilityFormType::rate, "rate" },
});


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::pressureEquation::read(const dictionary& ppe)
{
    wordList valid
    {
        "source", "surfaceCondition", "wallCondition", "compressibility",
        "compressibilityForm", "clampNegative"
    };
    valid.append(source_->entries());
    valid.append(surface_->entries());
    valid.append(walls_->entries());
    inputChecks::keywords(ppe, valid, "ppe");

    compressibility_ = ppe.getOrDefault<scalar>("compressibility", 0);
    if (compressibility_ < 0)
    {
        FatalIOErrorInFunction(ppe)
            << "Entry 'compressibility' [1/Pa] must not be negative, got "
            << compressibility_ << exit(FatalIOError);
    }
    const compressibilityFormType form =
        inputChecks::choice
        (
            ppe,
            "compressibilityForm",
            compressibilityFormTypeNames,
            compressibilityFormType::absolute
        );
    rateForm_ = form == compressibilityFormType::rate && source_->hasRate();
    clampNegative_ = ppe.getOrDefault<bool>("clampNegative", true);

    if (source_->variableGamma() && compressibility_ > 0 && !rateForm_)
    {
        FatalIOErrorInFunction(ppe)
            << "Entry 'source " << source_->type() << "'"
            << (ppe.found("relaxationTime") ? " with 'relaxationTime'" : "")
            << " and 'compressibility' " << compressibility_
            << " need 'compressibilityForm rate' (absolute: the"
            << " equation of state would take the density term's"
            << " coefficient, which changes with the step or from"
            << " particle to particle), or compressibility 0"
            << exit(FatalIOError);
    }
}


Foam::label Foam::pressureEquation::setUnknowns()
{
    const UList<particleKind>& kind = cloud_.kind();
    UList<scalar>& p = cloud_.p();
    const label nPart = cloud_.size();

    // Rows: every fluid and wall particle; a zero row p_i = 0 (scaled like
    // an interior row) keeps its place, so that the matrix keeps its size
    // while particles reach or leave the surface (a multigrid hierarchy
    // can then serve several steps). Under -parallel this rank's
    // particles only, numbered after the rows of the ranks before it; the
    // halos' rows are their owners'
    zeroRow_.setSize(nPart);
    airSites_.setSize(nPart);
    unknown_.setSize(nPart);
    const bool wallRows = walls_->wallRows();
    label nSolved = 0;
    #pragma omp parallel for schedule(static) reduction(+:nSolved)
    for (label i = 0; i < nPart; ++i)
    {
        const bool inPPE =
            kind[i] == particleKind::fluid
         || (kind[i] == particleKind::wall && wallRows);
        zeroRow_[i] = surface_->zeroRow(cloud_, i);
        airSites_[i] = surface_->airSites(cloud_, i);
        unknown_[i] = (inPPE && owned(i));
        if (!inPPE || zeroRow_[i])
        {
            p[i] = 0;
        }
        nSolved += (inPPE && !zeroRow_[i] && owned(i));
    }
    nSolved_ = nSolved;

    // The rows numbered in the particles' order
    label nUnknowns = 0;
    for (label i = 0; i < nPart; ++i)
    {
        unknown_[i] = unknown_[i] ? nUnknowns++ : -1;
    }

    rowStart_ = 0;
    nGlobalRows_ = nUnknowns;
    if (cloud_.distribution())
    {
        const globalIndex rows(nUnknowns);
        rowStart_ = rows.offset(Pstream::myProcNo());
        nGlobalRows_ = rows.size();
        for (label& row : unknown_)
        {
            if (row >= 0)
            {
                row += rowStart_;
            }
        }
        cloud_.syncHalos(unknown_);
    }

    return nUnknowns;
}


Foam::label Foam::pressureEquation::wallCouplingColumns
(
    const label i,
    const scalar lapCoeff,
    const labelList& column
) const
{
    const labelList& offsets = laplacian_.pairs.offsets();
    const labelList& nbr = laplacian_.pairs.neighbours();

    // The wall condition's couplings, on the columns of the fluid rows
    // (a fluid particle that is no row, or a zero row, has p = 0), merged
    // by column
    ppeWallCondition::couplingList& c = wallCouplings_[i];
    walls_->couplings(laplacian_, i, lapCoeff, c);
    std::vector<std::pair<label, scalar>>& e = c.entries;
    label n = 0;
    for (const auto& fe : e)
    {
        const label col = column[fe.first];
        if (col >= 0)
        {
            e[n++] = {col, fe.second};
        }
    }
    e.resize(n);
    std::sort(e.begin(), e.end());
    n = 0;
    for (label m = 0; m < label(e.size()); ++m)
    {
        if (n > 0 && e[n - 1].first == e[m].first)
        {
            e[n - 1].second += e[m].second;
        }
        else
        {
            e[n++] = e[m];
        }
    }
    e.resize(n);

    // The columns that are neither the diagonal nor a neighbour's
    label extra = 0;
    for (const auto& ce : e)
    {
        bool found = (ce.first == unknown_[i]);
        for (label k = offsets[i]; !found && k < offsets[i + 1]; ++k)
        {
            found = (column[nbr[k]] == ce.first);
        }
        extra += !found;
    }
    return extra;
}


void Foam::pressureEquation::assemble
(
    const scalar dt,
    ppeMatrix& A,
    Eigen::VectorXd& b,
    Eigen::VectorXd& sol
) const
{
    const UList<particleKind>& kind = cloud_.kind();
    const UList<scalar>& p = cloud_.p();
    const labelList& offsets = laplacian_.pairs.offsets();
    const labelList& nbr = laplacian_.pairs.neighbours();
    const UList<scalar>& wL = laplacian_.w;
    const scalar n0L = laplacian_.n0;
    const label nPart = cloud_.size();
    const label nUnknowns = A.rows();

    // Rows: -<lap p>_i + (alpha rho/dt^2) p_i = -RHS_i (positive definite)
    const scalar lapCoeff = 2*2/(laplacian_.lambda*n0L);
    const scalar kappa = compressibility_*rho_/sqr(dt);
    const scalar airWeight = surface_->airWeight();
    const bool wallRows = walls_->wallRows();
    if (!wallRows)
    {
        wallCouplings_.setSize(nPart);
    }

    // Weak compressibility: absolute, kappa p on the diagonal; rate, the
    // divergence term is the rate of the density, kappa (p - p_old), and
    // the density error is measured from n0 (1 + alpha p): gamma kappa p
    const scalar oldComp = rateForm_ ? kappa : 0;

    // The matrix is written straight into compressed rows, in parallel:
    // row sizes first, then each row filled (sorted by column) on its own
    // (rows: this rank's, from rowStart_; columns: global row numbers)
    // Each particle as a neighbour, read once a pair: its column where it
    // is coupled (a row, not a zero row), -1 where it is not, -2 for a
    // dummy (its weight is left out of the diagonal)
    labelList column(nPart);
    #pragma omp parallel for schedule(static)
    for (label j = 0; j < nPart; ++j)
    {
        column[j] =
            kind[j] == particleKind::dummy ? -2
          : (unknown_[j] >= 0 && !zeroRow_[j]) ? unknown_[j]
          : -1;
    }
    ppeMatrix::StorageIndex* outer = A.outerIndexPtr();
    outer[0] = 0;

    rowChunks rows(nPart);
    #pragma omp parallel
    rows.forEach([&](const label i)
    {
        if (unknown_[i] < 0 || !owned(i))
        {
            return;
        }
        label nnz = 1;
        if (!zeroRow_[i])
        {
            for (label k = offsets[i]; k < offsets[i + 1]; ++k)
            {
                nnz += (column[nbr[k]] >= 0);
            }
            if (!wallRows)
            {
                nnz += wallCouplingColumns(i, lapCoeff, column);
            }
        }
        outer[unknown_[i] - rowStart_ + 1] = nnz;
    });
    for (label row = 0; row < nUnknowns; ++row)
    {
        outer[row + 1] += outer[row];
    }
    A.resizeNonZeros(outer[nUnknowns]);
    ppeMatrix::StorageIndex* cols = A.innerIndexPtr();
    double* vals = A.valuePtr();

    // A typical diagonal, for the zero rows
    const scalar surfaceDiag = lapCoeff*n0L;

    rowChunks rowsFilled(nPart);
    #pragma omp parallel
    rowsFilled.forEach([&](const label i)
    {
        if (unknown_[i] < 0 || !owned(i))
        {
            return;
        }
        const label row = unknown_[i] - rowStart_;
        const label start = outer[row];
        if (zeroRow_[i])
        {
            cols[start] = unknown_[i];
            vals[start] = surfaceDiag;
            b[row] = 0;
            sol[row] = 0;
            return;
        }

        // (the matrix's arrays through locals: the compiler then knows
        // that writing an entry changes no pointer)
        ppeMatrix::StorageIndex* const C = cols;
        double* const V = vals;
        const label diagCol = unknown_[i];

        // The row's entries in the neighbours' order, the diagonal's place
        // kept before the first larger column (the columns follow the
        // particles' order: the row is then sorted as it is written)
        scalar diag = 0;
        scalar nL = 0;
        label e = start;
        label diagAt = -1;
        for (label k = offsets[i]; k < offsets[i + 1]; ++k)
        {
            const label c = column[nbr[k]];
            nL += wL[k];
            if (c == -2)
            {
                continue;
            }
            const scalar a = lapCoeff*wL[k];
            diag += a;
            if (c >= 0)
            {
                if (diagAt < 0 && c > diagCol)
                {
                    diagAt = e++;
                }
                C[e] = c;
                V[e] = -a;
                ++e;
            }
        }
        if (diagAt < 0)
        {
            diagAt = e++;
        }
        scalar bWalls = 0;
        if (!wallRows)
        {
            // The couplings through the walls: on the diagonal, on a
            // neighbour's column or on a column of their own
            const ppeWallCondition::couplingList& cw = wallCouplings_[i];
            bWalls = cw.rhs;
            for (const auto& ce : cw.entries)
            {
                if (ce.first == diagCol)
                {
                    diag += ce.second;
                    continue;
                }
                label at = -1;
                for (label m = start; m < e && at < 0; ++m)
                {
                    if (m != diagAt && C[m] == ce.first)
                    {
                        at = m;
                    }
                }
                if (at >= 0)
                {
                    V[at] += ce.second;
                }
                else
                {
                    C[e] = ce.first;
                    V[e] = ce.second;
                    ++e;
                }
            }
        }
        if (airSites_[i])
        {
            // The missing sites' weight n0 - sum_j w_ij (dummies count as
            // present) joins the diagonal
            diag += airWeight*lapCoeff*max(n0L - nL, scalar(0));
        }

        const ppeSource::row s(source_->source(i, dt, airSites_[i]));
        diag += rateForm_ ? (1 + s.gamma)*kappa : kappa;
        b[row] = -s.rhs + oldComp*p[i] + bWalls;
        sol[row] = p[i];

        C[diagAt] = diagCol;
        V[diagAt] = diag;

        // Columns in increasing order within the row, where they were not
        // (insertion sort: a row has a few dozen entries; under -parallel
        // other ranks' columns may come in another order)
        for (label m = start + 1; m < e; ++m)
        {
            const ppeMatrix::StorageIndex c = C[m];
            if (!(C[m - 1] > c))
            {
                continue;
            }
            const double v = V[m];
            label l = m - 1;
            while (l >= start && C[l] > c)
            {
                C[l + 1] = C[l];
                V[l + 1] = V[l];
                --l;
            }
            C[l + 1] = c;
            V[l + 1] = v;
        }
    });
}


Foam::scalar Foam::pressureEquation::residual
(
    const ppeMatrix& A,
    const Eigen::VectorXd& b,
    const Eigen::VectorXd& sol
) const
{
    if (!cloud_.distribution())
    {
        // (the diagonal PCG gives it itself: this serves the other
        // solvers)
        const scalar bNorm = b.norm();
        return bNorm > 0 ? (b - A*sol).norm()/bNorm : scalar(0);
    }

    // Over the ranks: the columns of other ranks' rows take the pressures
    // of the halos (zeroed where the owner zeroed them)
    Map<scalar> haloP;
    const UList<scalar>& p = cloud_.p();
    forAll(unknown_, i)
    {
        if (unknown_[i] >= 0 && !owned(i))
        {
            haloP.set(unknown_[i], p[i]);
        }
    }
    scalar r2 = 0, b2 = 0;
    for (label row = 0; row < A.rows(); ++row)
    {
        scalar Ap = 0;
        for
        (
            label k = A.outerIndexPtr()[row];
            k < A.outerIndexPtr()[row + 1];
            ++k
        )
        {
            const label col = A.innerIndexPtr()[k];
            const label local = col - rowStart_;
            Ap += A.valuePtr()[k]
               *(
                    (local >= 0 && local < sol.size())
                  ? sol[local] : haloP.lookup(col, 0)
                );
        }
        r2 += sqr(b[row] - Ap);
        b2 += sqr(b[row]);
    }
    reduce(r2, sumOp<scalar>());
    reduce(b2, sumOp<scalar>());
    return b2 > 0 ? ::sqrt(r2/b2) : scalar(0);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::pressureEquation::pressureEquation
(
    mpsCloud& cloud,
    const dictionary& mpsProperties,
    const kernelPairs& number,
    const kernelPairs& laplacian,
    const scalar rho,
    const vector2D& g
)
:
    cloud_(cloud),
    number_(number),
    laplacian_(laplacian),
    rho_(rho),
    g_(g),
    compressibility_(0),
    rateForm_(false),
    clampNegative_(true),
    rowStart_(0),
    nGlobalRows_(0),
    nSolved_(0),
    initialResidual_(0),
    assemblyTime_(0),
    solveTime_(0),
    clampReported_(false)
{
    const dictionary* ppePtr = inputChecks::optionalDict(mpsProperties, "ppe");
    const dictionary ppe(ppePtr ? *ppePtr : dictionary());

    source_ = ppeSource::New(ppe, number_, rho_);
    surface_ = ppeSurfaceCondition::New(ppe);
    walls_ = ppeWallCondition::New(ppe);
    read(ppe);

    Info<< "Pressure equation: ";
    info(Info);
    Info<< nl;

    solver_ = pressureSolver::New(mpsProperties);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::pressureEquation::info(Ostream& os) const
{
    os  << "source " << source_->type()
        << ", surfaceCondition " << surface_->type() << ", wallCondition ";
    walls_->info(os);
    source_->writeRelaxation(os);
    if (source_->fillVoids())
    {
        os  << ", fillVoids";
    }
    if (compressibility_ > 0)
    {
        os  << ", compressibility " << compressibility_ << " 1/Pa ("
            << compressibilityFormTypeNames
               [
                   rateForm_
                 ? compressibilityFormType::rate
                 : compressibilityFormType::absolute
               ]
            << "): sound speed " << soundSpeed() << " m/s";
    }
    else
    {
        os  << ", incompressible (compressibility 0)";
    }
    if (!clampNegative_)
    {
        os  << ", negative pressures kept";
    }
}


Foam::scalar Foam::pressureEquation::soundSpeed() const
{
    if (!(compressibility_ > 0))
    {
        return 0;
    }
    // At rest (no divergence) and uniform n the rows read kappa p = gamma
    // (rho/dt^2)(n - n0)/n0 (absolute), or, steady (p = p_old), gamma kappa
    // p = gamma (rho/dt^2)(n - n0)/n0 (rate), kappa = alpha rho/dt^2
    const scalar gamma = rateForm_ ? 1 : source_->restGamma();
    return sqrt(gamma/(compressibility_*rho_));
}


const Foam::labelList& Foam::pressureEquation::system
(
    const scalar dt,
    ppeMatrix& A,
    Eigen::VectorXd& b,
    Eigen::VectorXd& sol
)
{
    if (beforeAssembly_)
    {
        beforeAssembly_();
    }
    const label nUnknowns = setUnknowns();
    walls_->update(laplacian_, rho_, g_, dt);
    A.resize(nUnknowns, nGlobalRows_);
    b.resize(nUnknowns);
    sol.resize(nUnknowns);
    assemble(dt, A, b, sol);
    return unknown_;
}


void Foam::pressureEquation::solve(const scalar dt)
{
    if
    (
        !clampReported_
     && source_->relaxationTime() > 0
     && dt > source_->relaxationTime()
    )
    {
        // (an adjusted step grown past relaxationTime: said once)
        WarningInFunction
            << "The time step " << dt << " s exceeds ppe.relaxationTime "
            << source_->relaxationTime() << " s: the relaxation"
            << " dt/relaxationTime is clamped to 1 from here on (the whole"
            << " density error corrected each step)" << endl;
        clampReported_ = true;
    }
    const clockValue clock(true);
    ppeMatrix& A = A_;
    Eigen::VectorXd& b = b_;
    Eigen::VectorXd& sol = sol_;
    system(dt, A, b, sol);

    // The initial guess kept for its residual, where the solver does not
    // give it
    guess_ = sol;

    const clockValue solveClock(true);
    performance_ =
        cloud_.distribution()
      ? solver_->solve(A, b, sol, rowStart_)
      : solver_->solve(A, b, sol);
    solveTime_ = solveClock.elapsed();

    // The relative residual of the last step's pressure (the log's initial
    // residual; the solvers' final one is the same measure)
    initialResidual_ =
        (performance_.initialResidual >= 0 && !cloud_.distribution())
      ? performance_.initialResidual
      : residual(A, b, guess_);

    // The solution to the particles (negative pressures clamped to zero
    // where clampNegative says so); zero rows keep p = 0
    UList<scalar>& p = cloud_.p();
    const label nPart = cloud_.size();
    #pragma omp parallel for schedule(static)
    for (label i = 0; i < nPart; ++i)
    {
        const label row = unknown_[i] - rowStart_;
        if (unknown_[i] >= 0 && owned(i) && !zeroRow_[i])
        {
            p[i] = (clampNegative_ && sol[row] < 0) ? 0 : sol[row];
        }
    }
    cloud_.syncHalos(p);
    if (!walls_->wallRows())
    {
        wallPressures(p);
        cloud_.syncHalos(p);
    }
    assemblyTime_ = clock.elapsed() - solveTime_;
}


// ************************************************************************* //
