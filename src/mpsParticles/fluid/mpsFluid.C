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
#include "clockValue.H"
#include "inputChecks.H"
#include "rowChunks.H"
#include "wideVectors.H"

#include <vector>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::Enum<Foam::mpsFluid::wallPositionsType>
Foam::mpsFluid::wallPositionsTypeNames
({
    {wallPositionsType::lagged, "lagged"},
    {wallPositionsType::predicted, "predicted"},
});

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

const Foam::dictionary& Foam::mpsFluid::checkEntries(const dictionary& dict)
{
    inputChecks::keywords
    (
        dict,
        {
            "rho", "nu", "g", "l0", "kernel", "re", "ppe", "freeSurface",
            "collision", "pressureSolver", "pressureGradient", "shifting",
            "neighbourSkin", "wallPositions"
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
    return dict;
}


bool Foam::mpsFluid::sameKernel(const mpsKernel& a, const mpsKernel& b)
{
    return a.type() == b.type() && a.re() == b.re();
}


Foam::vector2D Foam::mpsFluid::readGravity(const dictionary& dict)
{
    const vector g(dict.get<vector>("g"));
    return vector2D(g.x(), g.y());
}


Foam::autoPtr<Foam::mpsKernel> Foam::mpsFluid::newKernel
(
    const dictionary& dict,
    const word& key,
    const scalar l0
)
{
    // A radius beyond 10 l0 is no MPS kernel (2 to 4 l0 are usual), and its
    // lattice sums would run over (2 re/l0)^2 sites
    const dictionary& reDict = dict.subDict("re");
    inputChecks::value(reDict, key);
    const scalar re = reDict.get<scalar>(key);
    if (!(re > 1 && re <= 10))
    {
        FatalIOErrorInFunction(reDict)
            << "Entry '" << key << "' (radius in units of l0) must lie"
            << " in (1, 10], got " << re << exit(FatalIOError);
    }
    return mpsKernel::New(dict, re*l0);
}


Foam::label Foam::mpsFluid::nActive() const
{
    // The cloud holds the kinds in order, the structure's last
    return cloud_.end(particleKind::dummy);
}


MPS_ALWAYS_INLINE Foam::label Foam::mpsFluid::separations
(
    const label i,
    rowTerms& row
) const
{
    const UList<vector2D>& x = cloud_.x();
    const label k0 = nbrs_.offsets()[i];
    const label nk = nbrs_.offsets()[i + 1] - k0;
    const labelList& nbr = nbrs_.neighbours();
    row.fit(nk);
    vector2D* d = row.d.data();
    scalar* r = row.r.data();
    for (label l = 0; l < nk; ++l)
    {
        d[l] = x[i] - x[nbr[k0 + l]];
    }
    // (the square roots apart, in vector registers: mag's, in its order)
    #pragma omp simd
    for (label l = 0; l < nk; ++l)
    {
        r[l] = ::sqrt(d[l].x()*d[l].x() + d[l].y()*d[l].y());
    }
    return nk;
}


MPS_ALWAYS_INLINE void Foam::mpsFluid::neighbourRow
(
    const label i,
    rowTerms& row
)
{
    const labelList& nbr = nbrs_.neighbours();
    const UList<particleKind>& kind = cloud_.kind();
    const UList<vector2D>& U = cloud_.U();

    const label k0 = nbrs_.offsets()[i], nk = separations(i, row);
    const vector2D* d = row.d.data();
    const scalar* r = row.r.data();
    scalar* a = row.a.data();
    scalar* g = row.g.data();
    scalar* wN = wN_.data() + k0;

    // Distances first (in wN_), then the kernel over the row
    for (label l = 0; l < nk; ++l)
    {
        wN[l] = max(r[l], minR_);
    }
    if (!sameG_ || !sameL_)
    {
        for (label l = 0; l < nk; ++l)
        {
            if (!sameG_)
            {
                wG_[k0 + l] = kG_->w(wN[l]);
            }
            if (!sameL_)
            {
                wL_[k0 + l] = kL_->w(wN[l]);
            }
        }
    }
    kN_->weights(wN, nk, wN, g);

    // The number density and (fluid, walls) the asymmetry vector and the
    // rate, each summed in the row's order, in one loop (their sums'
    // chains of additions overlap)
    const bool inPPE =
        kind[i] == particleKind::fluid || kind[i] == particleKind::wall;
    for (label l = 0; l < nk; ++l)
    {
        a[l] = wN[l]/max(r[l], SMALL);
    }
    scalar ni = 0, rate = 0;
    vector2D F(Zero);
    for (label l = 0; l < nk; ++l)
    {
        ni += wN[l];
        if (inPPE)
        {
            const label j = nbr[k0 + l];
            // (x_j - x_i = -d exactly)
            rate += g[l]*((U[j] - U[i]) & (-d[l]));
            if (kind[j] != particleKind::dummy)
            {
                F += a[l]*d[l];
            }
        }
    }
    rateN_[i] = rate;
    rateU_[i] = U[i];
    rowSumN_[i] = ni;
    asymmetryN_[i] = F;
}


MPS_WIDE_VECTORS void Foam::mpsFluid::neighbourRowWide
(
    const label i,
    rowTerms& row
)
{
    neighbourRow(i, row);
}


void Foam::mpsFluid::neighbourRowPlain(const label i, rowTerms& row)
{
    neighbourRow(i, row);
}


void Foam::mpsFluid::updateNeighbours()
{
    const scalar radius = max(kN_->re(), max(kG_->re(), kL_->re()));
    search_.find(cloud_.x(), nActive(), cloud_.revision(), radius, nbrs_);

    const label nPairs = nbrs_.nPairs();
    wN_.setSize(nPairs);
    if (!sameG_)
    {
        wG_.setSize(nPairs);
    }
    if (!sameL_)
    {
        wL_.setSize(nPairs);
    }

    rowSumN_.setSize(cloud_.size());
    asymmetryN_.setSize(cloud_.size());
    rateN_.setSize(cloud_.size());
    rateU_.setSize(cloud_.size());

    // Each row on the AVX-512 path where the processor has it, else on
    // the x86-64 one (bitwise the same numbers: wideVectors.H)
    const bool wide = wideVectors();
    rowChunks rows(cloud_.size());
    #pragma omp parallel
    {
        // A row's separations, distances and (dw/dr)/r, kept for the sums
        rowTerms row;
        rows.forEach([&](const label i)
        {
            if (wide)
            {
                neighbourRowWide(i, row);
            }
            else
            {
                neighbourRowPlain(i, row);
            }
        });
    }
}


void Foam::mpsFluid::updateNumberDensity()
{
    UList<scalar>& n = cloud_.n();

    #pragma omp parallel for schedule(static)
    for (label i = 0; i < cloud_.size(); ++i)
    {
        n[i] = rowSumN_[i];
    }
    syncHalos(n);
}


void Foam::mpsFluid::rateSums()
{
    const UList<vector2D>& U = cloud_.U();
    bool same = (rateU_.size() == U.size());
    if (same)
    {
        #pragma omp parallel for schedule(static) reduction(&&:same)
        for (label i = 0; i < U.size(); ++i)
        {
            same = same && (rateU_[i] == U[i]);
        }
    }
    if (same)
    {
        return;
    }

    // As updateNeighbours sums it
    const UList<particleKind>& kind = cloud_.kind();
    const labelList& nbr = nbrs_.neighbours();
    rateN_.setSize(U.size());
    rateU_ = U;

    rowChunks rows(U.size());
    #pragma omp parallel
    {
        rowTerms row;

        rows.forEach([&](const label i)
        {
            scalar rate = 0;
            if (kind[i] == particleKind::fluid || kind[i] == particleKind::wall)
            {
                const label k0 = nbrs_.offsets()[i];
                const label nk = separations(i, row);
                for (label l = 0; l < nk; ++l)
                {
                    row.a[l] = max(row.r[l], minR_);
                }
                kN_->weights(row.a.data(), nk, row.a.data(), row.g.data());
                for (label l = 0; l < nk; ++l)
                {
                    rate += row.g[l]*((U[nbr[k0 + l]] - U[i]) & (-row.d[l]));
                }
            }
            rateN_[i] = rate;
        });
    }
}


void Foam::mpsFluid::predict(const scalar dt, const neighbourList& pairs)
{
    UList<vector2D>& x = cloud_.x();
    UList<vector2D>& U = cloud_.U();
    const UList<particleKind>& kind = cloud_.kind();

    // Viscous acceleration from the velocities at the start of the step
    List<vector2D> acc;
    viscousAcceleration(pairs, acc);

    const bool moveWalls = wallPositions_ == wallPositionsType::predicted;

    #pragma omp parallel for schedule(static)
    for (label i = 0; i < cloud_.size(); ++i)
    {
        if (kind[i] == particleKind::fluid)
        {
            U[i] += dt*(acc[i] + g_);
            x[i] += dt*U[i];
        }
        else if (moveWalls)
        {
            // Walls and dummies at the step's end with the water's x*
            // (the coupling then puts them where the structure went)
            x[i] += dt*U[i];
        }
    }
    // (the halos' u*, x* are refreshed after the collisions: those read
    // only pairs closer than l0, whose halo lies within the halo width
    // less one viscosity radius of the border, its neighbourhood whole)
}


void Foam::mpsFluid::correct(const scalar dt)
{
    UList<vector2D>& x = cloud_.x();
    UList<vector2D>& U = cloud_.U();
    const UList<particleKind>& kind = cloud_.kind();
    const label n = cloud_.size();

    gradient_->gradient(pairsG_, cloud_.p(), gradP_);
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


void Foam::mpsFluid::collide(const neighbourList& pairs, const scalar dt)
{
    label nPairs =
        collision_->correct(cloud_, pairs, l0_, dt, cloud_.x(), cloud_.U());
    syncHalos(cloud_.U());
    syncHalos(cloud_.x());
    reduceRanks(nPairs, sumOp<label>());
    info_.nCollisions += nPairs;
}


Foam::label Foam::mpsFluid::removeOutside()
{
    const UList<vector2D>& x = cloud_.x();
    const UList<particleKind>& kind = cloud_.kind();
    const vector2D lo(domain_.min().x(), domain_.min().y());
    const vector2D hi(domain_.max().x(), domain_.max().y());
    auto outside = [&](const label i)
    {
        return
            kind[i] == particleKind::fluid
         && owned(i)
         && (
                x[i].x() < lo.x() || x[i].x() > hi.x()
             || x[i].y() < lo.y() || x[i].y() > hi.y()
            );
    };

    // Counted on the threads; the cloud is subset only when one left
    label nOut = 0;
    #pragma omp parallel for schedule(static) reduction(+:nOut)
    for (label i = 0; i < cloud_.size(); ++i)
    {
        nOut += outside(i);
    }
    if (nOut)
    {
        List<bool> keep(cloud_.size());
        forAll(keep, i)
        {
            keep[i] = !outside(i);
        }
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
    rho_(inputChecks::number<scalar>(checkEntries(dict), "rho", "> 0")),
    nu_(dict.get<scalar>("nu")),
    g_(readGravity(dict)),
    l0_(inputChecks::number<scalar>(dict, "l0", "> 0")),
    minR_(1e-3*l0_),
    kN_(newKernel(dict, "numberDensity", l0_)),
    kG_(newKernel(dict, "gradient", l0_)),
    kL_(newKernel(dict, "laplacian", l0_)),
    kV_(newKernel(dict, "viscosity", l0_)),
    n0N_(kN_->latticeNumberDensity(l0_)),
    n0G_(kG_->latticeNumberDensity(l0_)),
    n0L_(kL_->latticeNumberDensity(l0_)),
    lambdaL_(kL_->latticeLambda(l0_)),
    n0V_(kV_->latticeNumberDensity(l0_)),
    lambdaV_(kV_->latticeLambda(l0_)),
    F0_(kN_->latticeSurfaceAsymmetry(l0_)),
    wallPositions_
    (
        inputChecks::choice
        (
            dict,
            "wallPositions",
            wallPositionsTypeNames,
            wallPositionsType::lagged
        )
    ),
    search_(interactionRadius(), inputChecks::number<scalar>(dict, "neighbourSkin", 0.3, "[0, 2]")*l0_),
    sameG_(sameKernel(kG_(), kN_())),
    sameL_(sameKernel(kL_(), kN_())),
    pairsN_
    {
        cloud_, nbrs_, wN_, kN_(), n0N_, kN_->latticeLambda(l0_), minR_,
        &rateN_, &asymmetryN_
    },
    pairsG_
    {
        cloud_, nbrs_, sameG_ ? wN_ : wG_, kG_(), n0G_,
        kG_->latticeLambda(l0_), minR_
    },
    pairsL_{cloud_, nbrs_, sameL_ ? wN_ : wL_, kL_(), n0L_, lambdaL_, minR_},
    ppe_(cloud_, dict, pairsN_, pairsL_, rho_, g_),
    freeSurface_(freeSurfaceModel::New(dict, l0_)),
    collision_(collisionModel::New(dict)),
    shifting_(particleShifting::New(dict)),
    gradient_(pressureGradient::New(dict)),
    domain_(domain),
    exchangeTime_(0),
    pStepStart_(),
    pressureSolved_(false)
{
    if (nu_ < 0)
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'nu' (kinematic viscosity) must not be negative, got "
            << nu_ << exit(FatalIOError);
    }

    // When the cloud moves particles between ranks (before a write), the
    // pairs and gradients that fluidPressureAt reads follow them
    cloud_.onLocalise([this]() { rebuildPairs(); });

    // The PPE's source reads the number density's rate: summed with the
    // weights, again where the velocities changed since (a scheme that
    // sets the walls' velocities between solves)
    ppe_.beforeAssembly([this]() { rateSums(); });
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::mpsFluid::viscousAcceleration(List<vector2D>& acc)
{
    viscousAcceleration
    (
        search_.candidates(cloud_.x(), nActive(), cloud_.revision()), acc
    );
}


MPS_ALWAYS_INLINE Foam::vector2D Foam::mpsFluid::viscousSum
(
    const neighbourList& pairs,
    const label i,
    rowTerms& row
) const
{
    const UList<vector2D>& x = cloud_.x();
    const UList<vector2D>& U = cloud_.U();
    const label k0 = pairs.offsets()[i];
    const label nk = pairs.offsets()[i + 1] - k0;
    const label* nbr = pairs.neighbours().cdata() + k0;
    const scalar reV2 = sqr(kV_->re());
    row.fit(nk);
    label* J = row.J.data();
    scalar* w = row.r.data();

    // The pairs within the kernel's radius gathered (those beyond it weigh
    // zero: leaving them out leaves the sum as it is), each candidate
    // written and kept where it is close enough (no branch: one near the
    // radius is as likely in as out), the square roots apart, in vector
    // registers, the weights at once (the kernel's vectorised values),
    // then the sum in the row's order
    label m = 0;
    for (label l = 0; l < nk; ++l)
    {
        const label j = nbr[l];
        const scalar r2 = magSqr(x[j] - x[i]);
        J[m] = j;
        w[m] = r2;
        m += (r2 < reV2);
    }
    #pragma omp simd
    for (label l = 0; l < m; ++l)
    {
        w[l] = max(::sqrt(w[l]), minR_);
    }
    kV_->values(w, m, w);
    vector2D lapU(Zero);
    for (label l = 0; l < m; ++l)
    {
        lapU += w[l]*(U[J[l]] - U[i]);
    }
    return lapU;
}


MPS_WIDE_VECTORS Foam::vector2D Foam::mpsFluid::viscousSumWide
(
    const neighbourList& pairs,
    const label i,
    rowTerms& row
) const
{
    return viscousSum(pairs, i, row);
}


Foam::vector2D Foam::mpsFluid::viscousSumPlain
(
    const neighbourList& pairs,
    const label i,
    rowTerms& row
) const
{
    return viscousSum(pairs, i, row);
}


void Foam::mpsFluid::viscousAcceleration
(
    const neighbourList& pairs,
    List<vector2D>& acc
) const
{
    const UList<particleKind>& kind = cloud_.kind();
    const label n = cloud_.size();
    const scalar coeff = nu_*2*2/(lambdaV_*n0V_);
    acc.setSize(n);

    // (each row on the AVX-512 path where the processor has it: the same
    // numbers, wideVectors.H)
    const bool wide = wideVectors();
    rowChunks rows(n);
    #pragma omp parallel
    {
        rowTerms row;
        rows.forEach([&](const label i)
        {
            vector2D lapU(Zero);
            if (kind[i] == particleKind::fluid && nu_ > 0)
            {
                lapU =
                    wide
                  ? viscousSumWide(pairs, i, row)
                  : viscousSumPlain(pairs, i, row);
            }
            acc[i] = coeff*lapU;
        });
    }
}


void Foam::mpsFluid::evaluate()
{
    updateNeighbours();
    updateNumberDensity();
    freeSurface_->identify(pairsN_, F0_, cloud_.surface());
    syncHalos(cloud_.surface());
}


Foam::scalar Foam::mpsFluid::interactionRadius() const
{
    return max(max(kN_->re(), kG_->re()), max(kL_->re(), kV_->re()));
}


Foam::scalar Foam::mpsFluid::haloRadius() const
{
    return
        interactionRadius()
      + (ppe_.wallCondition().wallRows() ? 0 : kL_->re());
}


void Foam::mpsFluid::info(Ostream& os) const
{
    os  << "Fluid step:" << nl
        << "    kernel " << kN_->type() << ", radii [l0]: numberDensity "
        << kN_->re()/l0_ << ", gradient " << kG_->re()/l0_ << ", laplacian "
        << kL_->re()/l0_ << ", viscosity " << kV_->re()/l0_
        << ", neighbour skin " << search_.skin()/l0_
        << ", wallPositions " << wallPositionsTypeNames[wallPositions_] << nl
        << "    freeSurface ";
    freeSurface_->info(os);
    os  << nl << "    collision ";
    collision_->info(os);
    os  << nl << "    pressureGradient ";
    gradient_->info(os);
    os  << nl << "    shifting ";
    shifting_->info(os);
    os  << nl << "    ppe ";
    ppe_.info(os);
    os  << nl << "    pressureSolver ";
    ppe_.solver().info(os);
    os  << nl << endl;
}


void Foam::mpsFluid::redistribute()
{
    if (cloud_.distribution())
    {
        const clockValue clock(true);
        cloud_.distribute();
        exchangeTime_ += clock.elapsed();
    }
}


void Foam::mpsFluid::rebuildPairs()
{
    updateNeighbours();
    gradient_->gradient(pairsG_, cloud_.p(), gradP_);
    syncHalos(gradP_);
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
    pressureSolved_ = false;
    redistribute();
    // The search's candidates at x^k: the viscosity sums over them, and
    // the collisions find their pairs, closer than l0 at x*, among them
    // (no search at x*, which may not be finite)
    const neighbourList& candidates =
        search_.candidates(cloud_.x(), nActive(), cloud_.revision());
    predict(dt, candidates);
    lap(info_.timeRest);

    info_.nCollisions = 0;
    if (collision_->stage() == collisionModel::stageType::predicted)
    {
        collide(candidates, dt);
    }
    info_.finite = allFinite();
    if (!info_.finite)
    {
        // Nothing more can be computed from non-finite positions
        return false;
    }
    // (counts of the step are those of all ranks)
    info_.nRemoved = removeOutside();
    reduceRanks(info_.nRemoved, sumOp<label>());
    info_.totalRemoved += info_.nRemoved;
    if (cloud_.distribution() && info_.nRemoved > 0)
    {
        // Halos of particles removed on their rank would refresh no more
        redistribute();
    }
    lap(info_.timeRest);

    updateNeighbours();
    lap(info_.timeNeighbours);

    updateNumberDensity();
    freeSurface_->identify(pairsN_, F0_, cloud_.surface());
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
    if (pressureSolved_)
    {
        cloud_.p().deepCopy(pStepStart_);
    }
    else
    {
        pStepStart_ = cloud_.p();
        pressureSolved_ = true;
    }
    ppe_.solve(dt);
    const pressureSolver::performance& perf = ppe_.performance();
    info_.nUnknowns = ppe_.nSolved();
    info_.ppeInitialResidual = ppe_.initialResidual();
    info_.ppeIterations = perf.iterations;
    info_.totalPpeIterations += perf.iterations;
    info_.ppeResidual = perf.residual;
    info_.ppeConverged = perf.converged;
    info_.timeAssembly += ppe_.assemblyTime();
    info_.timeSolve += ppe_.solveTime();
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
        // (the halos of removed particles with them)
        redistribute();
        rebuildPairs();
    }
    if (collision_->stage() == collisionModel::stageType::corrected)
    {
        // The pairs at x*, within the largest kernel radius: those closer
        // than the collision distance at x^{k+1} among them
        collide(nbrs_, dt);
    }
    info_.maxShift = shifting_->shift(cloud_, nbrs_, l0_, kN_->re(), dt);
    syncHalos(cloud_.x());
    syncHalos(cloud_.U());
    reduceRanks(info_.maxShift, maxOp<scalar>());
    info_.timeRest += clock.elapsed();
    info_.timeExchange = exchangeTime_;
    info_.nSearches = search_.nSearches();
    info_.nSearchBuilds = search_.nBuilds();

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
