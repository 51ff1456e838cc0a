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

#include "mpsFluid.H"
#include "globalIndex.H"
#include "Map.H"
#include "clockValue.H"
#include "inputChecks.H"
#include <omp.h>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::Enum<Foam::mpsFluid::sourceType> Foam::mpsFluid::sourceTypeNames
({
    { sourceType::numberDensity, "numberDensity" },
    { sourceType::mixed, "mixed" },
    { sourceType::higherOrder, "higherOrder" },
    { sourceType::errorCompensating, "errorCompensating" },
});

const Foam::Enum<Foam::mpsFluid::surfaceConditionType>
Foam::mpsFluid::surfaceConditionTypeNames
({
    { surfaceConditionType::flagged, "flagged" },
    { surfaceConditionType::continuous, "continuous" },
    { surfaceConditionType::extrapolated, "extrapolated" },
    { surfaceConditionType::continuousWalls, "continuousWalls" },
});

const Foam::Enum<Foam::mpsFluid::compressibilityFormType>
Foam::mpsFluid::compressibilityFormTypeNames
({
    { compressibilityFormType::absolute, "absolute" },
    { compressibilityFormType::rate, "rate" },
});


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

const Foam::dictionary& Foam::mpsFluid::checkEntries(const dictionary& dict)
{
    inputChecks::keywords
    (
        dict,
        {
            "rho", "nu", "g", "l0", "kernel", "re", "ppe", "freeSurface",
            "collision", "pressureSolver", "pressureGradient", "shifting"
        },
        "constant/mpsProperties"
    );
    inputChecks::values(dict, {"rho", "nu", "g", "l0"});
    inputChecks::keywords
    (
        inputChecks::subDict(dict, "re"),
        {"numberDensity", "gradient", "laplacian", "viscosity"},
        "re"
    );
    if (const dictionary* ppe = inputChecks::optionalDict(dict, "ppe"))
    {
        inputChecks::keywords
        (
            *ppe,
            {
                "source", "surfaceCondition", "relaxation", "relaxationTime",
                "compressibility", "compressibilityForm", "fillVoids",
                "clampNegative"
            },
            "ppe"
        );
    }
    return dict;
}


Foam::scalar Foam::mpsFluid::readPositive
(
    const dictionary& dict,
    const word& key
)
{
    const scalar value = dict.get<scalar>(key);
    if (!(value > 0))
    {
        FatalIOErrorInFunction(dict)
            << "Entry '" << key << "' must be positive, got " << value
            << exit(FatalIOError);
    }
    return value;
}


Foam::label Foam::mpsFluid::nActive() const
{
    // The cloud holds the kinds in order, the structure's last
    return cloud_.end(particleKind::dummy);
}


void Foam::mpsFluid::updateNeighbours()
{
    const scalar radius = max(kN_->re(), max(kG_->re(), kL_->re()));
    nbrs_.build(cloud_.x(), radius, nActive());

    const UList<vector2D>& x = cloud_.x();
    const labelList& offsets = nbrs_.offsets();
    const labelList& nbr = nbrs_.neighbours();
    const label nPairs = nbrs_.nPairs();
    wN_.setSize(nPairs);
    wG_.setSize(nPairs);
    wL_.setSize(nPairs);

    // The three weights are one when the kernels are (the usual case):
    // computed once
    auto same = [this](const mpsKernel& k)
    {
        return k.type() == kN_->type() && k.re() == kN_->re();
    };
    const bool sameG = same(kG_()), sameL = same(kL_());

    #pragma omp parallel for schedule(static)
    for (label i = 0; i < cloud_.size(); ++i)
    {
        for (label k = offsets[i]; k < offsets[i + 1]; ++k)
        {
            const scalar r = max(mag(x[nbr[k]] - x[i]), minR_);
            const scalar w = kN_->w(r);
            wN_[k] = w;
            wG_[k] = sameG ? w : kG_->w(r);
            wL_[k] = sameL ? w : kL_->w(r);
        }
    }
}


void Foam::mpsFluid::updateNumberDensity()
{
    UList<scalar>& n = cloud_.n();
    const labelList& offsets = nbrs_.offsets();

    #pragma omp parallel for schedule(static)
    for (label i = 0; i < cloud_.size(); ++i)
    {
        scalar ni = 0;
        for (label k = offsets[i]; k < offsets[i + 1]; ++k)
        {
            ni += wN_[k];
        }
        n[i] = ni;
    }
    syncHalos(n);
}


void Foam::mpsFluid::predict(const scalar dt)
{
    UList<vector2D>& x = cloud_.x();
    UList<vector2D>& U = cloud_.U();
    const UList<particleKind>& kind = cloud_.kind();

    // Viscous acceleration from the velocities at the start of the step
    List<vector2D> acc;
    viscousAcceleration(acc);

    #pragma omp parallel for schedule(static)
    for (label i = 0; i < cloud_.size(); ++i)
    {
        if (kind[i] == particleKind::fluid)
        {
            U[i] += dt*(acc[i] + g_);
            x[i] += dt*U[i];
        }
    }
    // (the halos' u*, x* are refreshed after the collisions: those read
    // only pairs closer than l0, whose halo lies within the halo width
    // less one viscosity radius of the border, its neighbourhood whole)
}


Foam::label Foam::mpsFluid::setUnknowns()
{
    const UList<particleKind>& kind = cloud_.kind();
    UList<scalar>& p = cloud_.p();
    const label nPart = cloud_.size();

    // Unknowns: every fluid and wall particle; with the flagged condition
    // a surface particle's row is p_i = 0 (scaled like an interior row), so
    // that the matrix keeps its size while particles reach or leave the
    // surface (a multigrid hierarchy can then serve several steps)
    // (under -parallel this rank's particles only, numbered after the
    // rows of the ranks before it; the halos' rows are their owners')
    unknown_.setSize(nPart);
    label nUnknowns = 0;
    label nSolved = 0;
    for (label i = 0; i < nPart; ++i)
    {
        const bool inPPE =
            (kind[i] == particleKind::fluid || kind[i] == particleKind::wall);
        const bool zero = zeroRow(i);
        unknown_[i] = (inPPE && owned(i)) ? nUnknowns++ : -1;
        if (!inPPE || zero)
        {
            p[i] = 0;
        }
        nSolved += (inPPE && !zero && owned(i));
    }
    info_.nUnknowns = nSolved;

    rowStart_ = 0;
    nGlobalRows_ = nUnknowns;
    if (decomposition_)
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
        syncHalos(unknown_);
    }

    return nUnknowns;
}


void Foam::mpsFluid::assemblePressure
(
    const scalar dt,
    ppeMatrix& A,
    Eigen::VectorXd& b,
    Eigen::VectorXd& sol
) const
{
    const UList<vector2D>& x = cloud_.x();
    const UList<vector2D>& U = cloud_.U();
    const UList<scalar>& n = cloud_.n();
    // continuous and extrapolated (continuousWalls: the walls): no row is
    // set to zero, the missing lattice sites are air (airSites(i))
    // The pressure the missing lattice sites carry, relative to p_i: 0
    // (continuous) or the mirror image -p_i (extrapolated), so that the
    // missing weight counts once or twice on the diagonal
    const scalar airFactor =
        surfaceCondition_ == surfaceConditionType::extrapolated ? 2 : 1;
    const UList<particleKind>& kind = cloud_.kind();
    const UList<scalar>& p = cloud_.p();
    const labelList& offsets = nbrs_.offsets();
    const labelList& nbr = nbrs_.neighbours();
    const label nPart = cloud_.size();
    const label nUnknowns = A.rows();

    // Rows: -<lap p>_i + (alpha rho/dt^2) p_i = -RHS_i (positive definite)
    const scalar lapCoeff = 2*2/(lambdaL_*n0L_);
    const scalar divCoeff = 2/n0N_;
    const scalar kappa = compressibility_*rho_/sqr(dt);

    // Weak compressibility: the particles' density follows the pressure,
    // n = n0 (1 + alpha p). absolute (Ikeda et al.): the source's density
    // is measured from n0 with the new pressure, kappa p on the diagonal.
    // rate: the divergence term is the rate of the density, kappa (p - p_old)
    // (a fluid of sound speed 1/sqrt(alpha rho)), the relaxation's density
    // error is measured from n0 (1 + alpha p): gamma kappa p; the numberDensity
    // source has no rate term, so it stays absolute
    const bool rate = rateForm();
    const scalar oldComp = rate ? kappa : 0;

    // The matrix is written straight into compressed rows, in parallel:
    // row sizes first, then each row filled (sorted by column) on its own
    auto coupled = [&](const label j)
    {
        return
            kind[j] != particleKind::dummy
         && unknown_[j] >= 0 && !zeroRow(j);
    };
    // (rows: this rank's, from rowStart_; columns: global row numbers)
    ppeMatrix::StorageIndex* outer = A.outerIndexPtr();
    outer[0] = 0;
    for (label i = 0; i < nPart; ++i)
    {
        if (unknown_[i] < 0 || !owned(i))
        {
            continue;
        }
        const label row = unknown_[i] - rowStart_;
        label nnz = 1;
        if (!zeroRow(i))
        {
            for (label k = offsets[i]; k < offsets[i + 1]; ++k)
            {
                nnz += coupled(nbr[k]);
            }
        }
        outer[row + 1] = outer[row] + nnz;
    }
    A.resizeNonZeros(outer[nUnknowns]);
    ppeMatrix::StorageIndex* cols = A.innerIndexPtr();
    double* vals = A.valuePtr();

    // A typical diagonal, for the rows of surface particles
    const scalar surfaceDiag = lapCoeff*n0L_;

    #pragma omp parallel for schedule(static)
    for (label i = 0; i < nPart; ++i)
    {
        if (unknown_[i] < 0 || !owned(i))
        {
            continue;
        }
        const label row = unknown_[i] - rowStart_;
        const label start = outer[row];
        if (zeroRow(i))
        {
            cols[start] = unknown_[i];
            vals[start] = surfaceDiag;
            b[row] = 0;
            sol[row] = 0;
            continue;
        }

        const bool air = airSites(i);
        scalar diag = 0;
        scalar div = 0;
        scalar nL = 0;
        label e = start;
        for (label k = offsets[i]; k < offsets[i + 1]; ++k)
        {
            const label j = nbr[k];
            nL += wL_[k];
            if (kind[j] == particleKind::dummy)
            {
                continue;
            }
            const scalar a = lapCoeff*wL_[k];
            diag += a;
            if (coupled(j))
            {
                cols[e] = unknown_[j];
                vals[e] = -a;
                ++e;
            }
            if (source_ == sourceType::mixed)
            {
                // (a velocity divergence: the mixed source's)
                const vector2D r(x[j] - x[i]);
                div += ((U[j] - U[i]) & r)*wN_[k]/max(magSqr(r), minR2_);
            }
        }
        if (air)
        {
            // The lattice sites missing around i are air at p = 0: the
            // Laplacian's weight they would carry, n0 - sum_j w_ij (dummies
            // count as present: they close the wall side), joins the
            // diagonal, and varies continuously as neighbours come and go
            diag += airFactor*lapCoeff*max(n0L_ - nL, scalar(0));
        }

        // The source, and the coefficient gamma of its density error
        const rowSource s(source(i, divCoeff*div, dt, air));
        diag += rate ? (1 + s.gamma)*kappa : kappa;
        b[row] = -s.rhs + oldComp*p[i];
        sol[row] = p[i];

        cols[e] = unknown_[i];
        vals[e] = diag;
        ++e;

        // Columns in increasing order within the row (insertion sort: a
        // row has a dozen entries)
        for (label m = start + 1; m < e; ++m)
        {
            const ppeMatrix::StorageIndex c = cols[m];
            const double v = vals[m];
            label l = m - 1;
            while (l >= start && cols[l] > c)
            {
                cols[l + 1] = cols[l];
                vals[l + 1] = vals[l];
                --l;
            }
            cols[l + 1] = c;
            vals[l + 1] = v;
        }

    }

}


Foam::mpsFluid::rowSource Foam::mpsFluid::source
(
    const label i,
    const scalar divergence,
    const scalar dt,
    const bool airSites
) const
{
    const scalar n = cloud_.n()[i];

    // The density error (n - n0)/n0; with the continuous and extrapolated
    // conditions compression only (n* > n0), since a deficit of neighbours
    // there is the surface's, not a rarefaction
    scalar error = (n - n0N_)/n0N_;
    if (airSites)
    {
        error = max(error, scalar(0));
    }
    const scalar densitySource = -rho_/sqr(dt)*error;

    // With fillVoids, neighbours that approach a particle short of
    // neighbours (n < n0) fill its void before they compress the water:
    // the compression rate the source corrects is what exceeds the rate
    // that fills the deficit (n0 - n)/n0 within the step (the rows whose
    // missing sites are air: under continuousWalls the walls')
    const scalar deficit =
        (fillVoids_ && airSites) ? max(n0N_ - n, scalar(0))/n0N_ : 0;

    // The fixed relaxation, or dt/relaxationTime (a share of the error per
    // unit time, at most all of it in one step)
    const scalar relaxation =
        relaxationTime_ > 0 ? min(dt/relaxationTime_, scalar(1)) : relaxation_;

    rowSource s;
    switch (source_)
    {
        case sourceType::numberDensity:
        {
            s.rhs = densitySource;
            s.gamma = 1;
            break;
        }
        case sourceType::mixed:
        {
            scalar div = divergence;
            if (div < 0)
            {
                div = min(div + deficit/dt, scalar(0));
            }
            s.rhs = rho_/dt*div + relaxation*densitySource;
            s.gamma = relaxation;
            break;
        }
        case sourceType::higherOrder:
        case sourceType::errorCompensating:
        {
            // (1/n0) Dn_i/Dt: positive for a compression
            scalar nRate =
                numberDensityRate(cloud_, nbrs_, kN_(), i, minR_)/n0N_;
            if (nRate > 0)
            {
                nRate = max(nRate - deficit/dt, scalar(0));
            }
            if (source_ == sourceType::higherOrder)
            {
                s.rhs = -rho_/dt*nRate + relaxation*densitySource;
                s.gamma = relaxation;
            }
            else
            {
                // Khayyer & Gotoh (2011): the rate term scaled up by the
                // density error's size, and the density error corrected
                // with the coefficient |dt (1/n0) Dn/Dt|, so that both
                // parts scale as 1/dt, as the rate term does; the fixed
                // relaxation beside it (0 for the paper's form)
                const scalar gamma = relaxation + mag(dt*nRate);
                s.rhs =
                    -(1 + mag(error))*rho_/dt*nRate + gamma*densitySource;
                s.gamma = gamma;
            }
            break;
        }
    }
    return s;
}


Foam::scalar Foam::mpsFluid::numberDensityRate
(
    const mpsCloud& cloud,
    const neighbourList& nbrs,
    const mpsKernel& kernel,
    const label i,
    const scalar minR
)
{
    const UList<vector2D>& x = cloud.x();
    const UList<vector2D>& U = cloud.U();
    const labelList& offsets = nbrs.offsets();
    const labelList& nbr = nbrs.neighbours();

    // Dn_i/Dt = sum_j dw/dr(r_ij) (r_ij . u_ij)/r_ij over every neighbour
    // (dummies included, as in n_i)
    scalar rate = 0;
    for (label kk = offsets[i]; kk < offsets[i + 1]; ++kk)
    {
        const label j = nbr[kk];
        const vector2D r(x[j] - x[i]);
        const scalar d = max(mag(r), minR);
        rate += kernel.dwdr(d)*((U[j] - U[i]) & r)/d;
    }
    return rate;
}


const Foam::labelList& Foam::mpsFluid::pressureSystem
(
    const scalar dt,
    ppeMatrix& A,
    Eigen::VectorXd& b,
    Eigen::VectorXd& sol
)
{
    const label nUnknowns = setUnknowns();
    A.resize(nUnknowns, nGlobalRows_);
    b.resize(nUnknowns);
    sol.resize(nUnknowns);
    assemblePressure(dt, A, b, sol);
    return unknown_;
}


void Foam::mpsFluid::solvePressure(const scalar dt)
{
    Eigen::VectorXd b;
    Eigen::VectorXd sol;
    ppeMatrix A;
    pressureSystem(dt, A, b, sol);

    // The relative residual |b - A p|/|b| of the last step's pressure (the
    // log's initial residual; the solvers' final one is the same measure)
    if (decomposition_)
    {
        info_.ppeInitialResidual = parallelResidual(A, b, sol);
    }
    else
    {
        const scalar bNorm = b.norm();
        info_.ppeInitialResidual =
            bNorm > 0 ? (b - A*sol).norm()/bNorm : scalar(0);
    }

    clockValue solveClock(true);
    const pressureSolver::performance perf =
        decomposition_
      ? solver_->solve(A, b, sol, rowStart_)
      : solver_->solve(A, b, sol);
    lastSolveTime_ = solveClock.elapsed();
    info_.ppeIterations = perf.iterations;
    info_.totalPpeIterations += perf.iterations;
    info_.ppeResidual = perf.residual;
    info_.ppeConverged = perf.converged;


    // The solution to the particles (negative pressures clamped to zero
    // where ppe.clampNegative says so); flagged surface particles keep p = 0
    UList<scalar>& p = cloud_.p();
    const label nPart = cloud_.size();
    for (label i = 0; i < nPart; ++i)
    {
        const label row = unknown_[i] - rowStart_;
        if (unknown_[i] >= 0 && owned(i) && !zeroRow(i))
        {
            p[i] = (clampNegative_ && sol[row] < 0) ? 0 : sol[row];
        }
    }
    syncHalos(p);
}


void Foam::mpsFluid::correct(const scalar dt)
{
    UList<vector2D>& x = cloud_.x();
    UList<vector2D>& U = cloud_.U();
    const UList<particleKind>& kind = cloud_.kind();
    const label n = cloud_.size();

    gradient_->gradient(cloud_, nbrs_, wG_, n0G_, minR2_, cloud_.p(), gradP_);
    syncHalos(gradP_);

    scalar maxSpeed2 = 0;

    #pragma omp parallel for schedule(static) reduction(max:maxSpeed2)
    for (label i = 0; i < n; ++i)
    {
        if (kind[i] == particleKind::fluid)
        {
            const vector2D dU(-(dt/rho_)*gradP_[i]);
            U[i] += dU;
            x[i] += dt*dU;
            maxSpeed2 = max(maxSpeed2, magSqr(U[i]));
        }
    }
    syncHalos(U);
    syncHalos(x);
    reduceRanks(maxSpeed2, maxOp<scalar>());
    info_.maxSpeed = ::sqrt(maxSpeed2);
}


Foam::label Foam::mpsFluid::removeOutside()
{
    const UList<vector2D>& x = cloud_.x();
    const UList<particleKind>& kind = cloud_.kind();
    List<bool> keep(cloud_.size(), true);
    label nOut = 0;
    forAll(x, i)
    {
        if
        (
            kind[i] == particleKind::fluid
         && owned(i)
         && (
                x[i].x() < domain_.min().x() || x[i].x() > domain_.max().x()
             || x[i].y() < domain_.min().y() || x[i].y() > domain_.max().y()
            )
        )
        {
            keep[i] = false;
            ++nOut;
        }
    }
    if (nOut)
    {
        cloud_.subset(keep);
    }
    return nOut;
}


bool Foam::mpsFluid::allFinite() const
{
    const UList<vector2D>& x = cloud_.x();
    const UList<vector2D>& U = cloud_.U();
    const UList<scalar>& p = cloud_.p();
    bool finite = true;

    #pragma omp parallel for schedule(static) reduction(&&:finite)
    for (label i = 0; i < cloud_.size(); ++i)
    {
        finite = finite
            && std::isfinite(x[i].x()) && std::isfinite(x[i].y())
            && std::isfinite(U[i].x()) && std::isfinite(U[i].y())
            && std::isfinite(p[i]);
    }
    reduceRanks(finite, andOp<bool>());
    return finite;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::mpsFluid::mpsFluid
(
    mpsCloud& cloud,
    const dictionary& dict,
    const boundBox& domain
)
:
    cloud_(cloud),
    rho_(readPositive(checkEntries(dict), "rho")),
    nu_(dict.get<scalar>("nu")),
    g_(Zero),
    l0_(readPositive(dict, "l0")),
    minR_(1e-3*l0_),
    minR2_(sqr(minR_)),
    source_(sourceType::mixed),
    surfaceCondition_(surfaceConditionType::flagged),
    relaxation_(0.05),
    relaxationTime_(0),
    compressibility_(0),
    compressibilityForm_(compressibilityFormType::absolute),
    fillVoids_(false),
    clampNegative_(true),
    domain_(domain),
    lastSolveTime_(0),
    decomposition_(nullptr),
    exchangeTime_(0),
    rowStart_(0),
    nGlobalRows_(0)
{
    if (nu_ < 0)
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'nu' (kinematic viscosity) must not be negative, got "
            << nu_ << exit(FatalIOError);
    }
    const vector g(dict.get<vector>("g"));
    g_ = vector2D(g.x(), g.y());

    const dictionary& reDict = dict.subDict("re");
    auto radius = [&](const word& key)
    {
        // A radius beyond 10 l0 is no MPS kernel (2 to 4 l0 are usual),
        // and its lattice sums would run over (2 re/l0)^2 sites
        inputChecks::value(reDict, key);
        const scalar re = reDict.get<scalar>(key);
        if (!(re > 1 && re <= 10))
        {
            FatalIOErrorInFunction(reDict)
                << "Entry '" << key << "' (radius in units of l0) must lie"
                << " in (1, 10], got " << re << exit(FatalIOError);
        }
        return re*l0_;
    };
    kN_ = mpsKernel::New(dict, radius("numberDensity"));
    kG_ = mpsKernel::New(dict, radius("gradient"));
    kL_ = mpsKernel::New(dict, radius("laplacian"));
    kV_ = mpsKernel::New(dict, radius("viscosity"));

    n0N_ = kN_->latticeNumberDensity(l0_);
    n0G_ = kG_->latticeNumberDensity(l0_);
    n0L_ = kL_->latticeNumberDensity(l0_);
    lambdaL_ = kL_->latticeLambda(l0_);
    n0V_ = kV_->latticeNumberDensity(l0_);
    lambdaV_ = kV_->latticeLambda(l0_);
    F0_ = kN_->latticeSurfaceAsymmetry(l0_);

    if (const dictionary* ppePtr = dict.findDict("ppe"))
    {
        const dictionary& ppe = *ppePtr;
        source_ = sourceTypeNames.getOrDefault("source", ppe, source_);
        surfaceCondition_ = surfaceConditionTypeNames.getOrDefault
        (
            "surfaceCondition", ppe, surfaceCondition_
        );
        relaxation_ = ppe.getOrDefault<scalar>("relaxation", relaxation_);
        if (ppe.found("relaxationTime"))
        {
            relaxationTime_ = ppe.get<scalar>("relaxationTime");
            if (ppe.found("relaxation"))
            {
                FatalIOErrorInFunction(ppe)
                    << "Entries 'relaxation' and 'relaxationTime': the one"
                    << " stands in place of the other, give one of them"
                    << exit(FatalIOError);
            }
            if (!(relaxationTime_ > 0))
            {
                FatalIOErrorInFunction(ppe)
                    << "Entry 'relaxationTime' [s] must be positive, got "
                    << relaxationTime_ << exit(FatalIOError);
            }
        }
        compressibility_ =
            ppe.getOrDefault<scalar>("compressibility", compressibility_);
        compressibilityForm_ = compressibilityFormTypeNames.getOrDefault
        (
            "compressibilityForm", ppe, compressibilityForm_
        );
        clampNegative_ = ppe.getOrDefault<bool>("clampNegative", true);
        fillVoids_ = ppe.getOrDefault<bool>("fillVoids", false);
        if (fillVoids_ && surfaceCondition_ == surfaceConditionType::flagged)
        {
            FatalIOErrorInFunction(ppe)
                << "Entry 'fillVoids' needs surfaceCondition continuous,"
                << " extrapolated or continuousWalls (flagged sets the"
                << " particles short of neighbours to p = 0)"
                << exit(FatalIOError);
        }
        if (relaxationTime_ > 0 && source_ == sourceType::numberDensity)
        {
            FatalIOErrorInFunction(ppe)
                << "Entry 'relaxationTime' applies to the sources mixed,"
                << " higherOrder and errorCompensating, not to "
                << sourceTypeNames[source_] << exit(FatalIOError);
        }
        const bool dynamicRelaxation =
            source_ == sourceType::errorCompensating || relaxationTime_ > 0;
        if
        (
            dynamicRelaxation
         && compressibility_ > 0
         && !rateForm()
        )
        {
            FatalIOErrorInFunction(ppe)
                << "Entry 'source " << sourceTypeNames[source_] << "'"
                << (relaxationTime_ > 0 ? " with 'relaxationTime'" : "")
                << " and 'compressibility' " << compressibility_
                << " need 'compressibilityForm rate' (absolute: the"
                << " equation of state would take the density term's"
                << " coefficient, which changes with the step or from"
                << " particle to particle), or compressibility 0"
                << exit(FatalIOError);
        }
        if (relaxation_ < 0 || relaxation_ > 1 || compressibility_ < 0)
        {
            FatalIOErrorInFunction(ppe)
                << "Entries 'relaxation' (0 to 1, got " << relaxation_
                << ") and 'compressibility' (not negative, got "
                << compressibility_ << ") are out of range"
                << exit(FatalIOError);
        }
    }

    Info<< "Pressure equation: source " << sourceTypeNames[source_]
        << ", surfaceCondition " << surfaceConditionTypeNames[surfaceCondition_];
    if (source_ != sourceType::numberDensity)
    {
        if (relaxationTime_ > 0)
        {
            Info<< ", relaxationTime " << relaxationTime_ << " s";
        }
        else
        {
            Info<< ", relaxation " << relaxation_;
        }
    }
    if (compressibility_ > 0)
    {
        Info<< ", compressibility " << compressibility_ << " 1/Pa ("
            << compressibilityFormTypeNames
               [
                   rateForm()
                 ? compressibilityFormType::rate
                 : compressibilityFormType::absolute
               ]
            << "): sound speed " << soundSpeed() << " m/s" << nl;
    }
    else
    {
        Info<< ", incompressible (compressibility 0)" << nl;
    }

    freeSurface_ = freeSurfaceModel::New(dict, l0_);
    collision_ = collisionModel::New(dict);
    shifting_ = particleShifting::New(dict);
    gradient_ = pressureGradient::New(dict);
    solver_ = pressureSolver::New(dict);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::mpsFluid::viscousAcceleration(List<vector2D>& acc)
{
    const UList<vector2D>& x = cloud_.x();
    const UList<vector2D>& U = cloud_.U();
    const UList<particleKind>& kind = cloud_.kind();
    const label n = cloud_.size();

    nbrsV_.build(x, kV_->re(), nActive());
    const labelList& offsets = nbrsV_.offsets();
    const labelList& nbr = nbrsV_.neighbours();
    const scalar coeff = nu_*2*2/(lambdaV_*n0V_);

    acc.setSize(n);

    #pragma omp parallel for schedule(static)
    for (label i = 0; i < n; ++i)
    {
        vector2D lapU(Zero);
        if (kind[i] == particleKind::fluid && nu_ > 0)
        {
            for (label k = offsets[i]; k < offsets[i + 1]; ++k)
            {
                const label j = nbr[k];
                lapU += kV_->w(max(mag(x[j] - x[i]), minR_))*(U[j] - U[i]);
            }
        }
        acc[i] = coeff*lapU;
    }
}


void Foam::mpsFluid::evaluate()
{
    updateNeighbours();
    updateNumberDensity();
    freeSurface_->identify
    (
        cloud_, nbrs_, wN_, n0N_, F0_, cloud_.surface()
    );
    syncHalos(cloud_.surface());
}


Foam::scalar Foam::mpsFluid::soundSpeed() const
{
    if (!(compressibility_ > 0))
    {
        return 0;
    }
    // At rest (no divergence) and uniform n the rows read kappa p = gamma
    // (rho/dt^2)(n - n0)/n0 (absolute), or, steady (p = p_old), gamma kappa
    // p = gamma (rho/dt^2)(n - n0)/n0 (rate), kappa = alpha rho/dt^2
    const scalar gamma =
        (source_ == sourceType::numberDensity || rateForm()) ? 1 : relaxation_;
    return sqrt(gamma/(compressibility_*rho_));
}


Foam::scalar Foam::mpsFluid::interactionRadius() const
{
    return max(max(kN_->re(), kG_->re()), max(kL_->re(), kV_->re()));
}


void Foam::mpsFluid::setDecomposition(mpsDecomposition& decomposition)
{
    decomposition_ = &decomposition;
    redistribute();
}


void Foam::mpsFluid::redistribute()
{
    if (decomposition_)
    {
        const clockValue clock(true);
        mpsDecomposition::removeHalos(cloud_);
        decomposition_->distribute(cloud_);
        decomposition_->addHalos(cloud_);
        exchangeTime_ += clock.elapsed();
    }
}


void Foam::mpsFluid::rebuildPairs()
{
    redistribute();
    updateNeighbours();
    gradient_->gradient
    (
        cloud_, nbrs_, wG_, n0G_, minR2_, cloud_.p(), gradP_
    );
    syncHalos(gradP_);
}


void Foam::mpsFluid::localise()
{
    if (decomposition_)
    {
        // The pairs and gradients that fluidPressureAt reads follow the
        // particles to their ranks
        rebuildPairs();
    }
}


Foam::scalar Foam::mpsFluid::parallelResidual
(
    const ppeMatrix& A,
    const Eigen::VectorXd& b,
    const Eigen::VectorXd& sol
) const
{
    // |b - A p|/|b| over the ranks: the columns of other ranks' rows take
    // the pressures of the halos (zeroed where the owner zeroed them)
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


const Foam::mpsFluid::stepInfo& Foam::mpsFluid::step(const scalar dt)
{
    if (beginStep(dt))
    {
        solveStepPressure(dt);
        endStep(dt);
    }
    return info_;
}


bool Foam::mpsFluid::beginStep(const scalar dt)
{
    // (a rank without fluid still takes part in the step's exchanges)
    label nFluid = cloud_.count(particleKind::fluid);
    reduceRanks(nFluid, sumOp<label>());
    if (!nFluid)
    {
        // A structure alone: nothing to do
        return false;
    }

    clockValue clock(true);
    auto lap = [&clock](scalar& t)
    {
        t += clock.elapsed();
        clock.update();
    };

    ++info_.nSteps;
    redistribute();
    predict(dt);
    lap(info_.timeRest);

    info_.nCollisions = collision_->correct
    (
        cloud_, nbrsV_, l0_, dt, cloud_.x(), cloud_.U()
    );
    syncHalos(cloud_.U());
    syncHalos(cloud_.x());
    info_.finite = allFinite();
    if (!info_.finite)
    {
        // Nothing more can be computed from non-finite positions
        return false;
    }
    // (counts of the step are those of all ranks)
    reduceRanks(info_.nCollisions, sumOp<label>());
    info_.nRemoved = removeOutside();
    reduceRanks(info_.nRemoved, sumOp<label>());
    info_.totalRemoved += info_.nRemoved;
    if (decomposition_ && info_.nRemoved > 0)
    {
        // Halos of particles removed on their rank would refresh no more
        redistribute();
    }
    lap(info_.timeRest);

    updateNeighbours();
    lap(info_.timeNeighbours);

    updateNumberDensity();
    freeSurface_->identify
    (
        cloud_, nbrs_, wN_, n0N_, F0_, cloud_.surface()
    );
    syncHalos(cloud_.surface());
    info_.nSurface = 0;
    forAll(cloud_.surface(), i)
    {
        info_.nSurface += (cloud_.surface()[i] && owned(i));
    }
    reduceRanks(info_.nSurface, sumOp<label>());
    lap(info_.timeRest);
    return true;
}


void Foam::mpsFluid::solveStepPressure(const scalar dt)
{
    // Assembly and solve: the solve's own time is measured inside
    clockValue clock(true);
    solvePressure(dt);
    info_.timeAssembly += clock.elapsed() - lastSolveTime_;
    info_.timeSolve += lastSolveTime_;
}


const Foam::mpsFluid::stepInfo& Foam::mpsFluid::endStep(const scalar dt)
{
    clockValue clock(true);
    correct(dt);
    info_.finite = allFinite() && std::isfinite(info_.ppeResidual);
    label nLeft = removeOutside();
    reduceRanks(nLeft, sumOp<label>());
    info_.nRemoved += nLeft;
    info_.totalRemoved += nLeft;
    if (nLeft > 0)
    {
        // The pairs and gradients that fluidPressureAt reads belong to
        // the particles before the removal: rebuilt for those that remain
        rebuildPairs();
    }
    info_.maxShift = shifting_->shift(cloud_, nbrs_, l0_, kN_->re(), dt);
    syncHalos(cloud_.x());
    syncHalos(cloud_.U());
    reduceRanks(info_.maxShift, maxOp<scalar>());
    info_.timeRest += clock.elapsed();
    info_.timeExchange = exchangeTime_;

    return info_;
}


Foam::scalar Foam::mpsFluid::fluidPressureAt(const label i) const
{
    if (gradP_.size() != cloud_.size())
    {
        return 0;   // before the first step
    }
    return pressureGradient::extrapolate
    (
        cloud_, nbrs_, kG_(), i, cloud_.p(), gradP_
    );
}


// ************************************************************************* //
