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

#include "structureModel.H"
#include "neighbourList.H"
#include "UIndirectList.H"
#include "Random.H"
#include "structureTangent.H"
#include "inputChecks.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(structureModel, 0);
    defineRunTimeSelectionTable(structureModel, dictionary);
}


// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * * //

void Foam::structureModel::findGhosts()
{
    if (!clampAtFace_)
    {
        return;
    }
    const neighbourList nbrs(X_, 1.1*ds_);
    DynamicList<label> ghost, near, far;
    forAll(X_, g)
    {
        if (!clamped_[g])
        {
            continue;
        }
        DynamicList<label> free;
        for (const label j : nbrs[g])
        {
            if (!clamped_[j])
            {
                free.append(j);
            }
        }
        if (free.empty())
        {
            continue;
        }
        if (free.size() > 1)
        {
            FatalIOErrorInFunction(dict_)
                << "clampAt face: the clamped particle at " << X_[g]
                << " touches " << free.size() << " free particles (at "
                << UIndirectList<vector2D>(X_, free) << "); a face clamp"
                << " needs a straight face between clamped and free"
                << " particles (use clampAt particles)" << exit(FatalIOError);
        }
        const label m1 = free[0];
        const vector2D beyond(2*X_[m1] - X_[g]);
        label m2 = -1;
        for (const label j : nbrs[m1])
        {
            if (!clamped_[j] && mag(X_[j] - beyond) < 1e-3*ds_)
            {
                m2 = j;
            }
        }
        if (m2 < 0)
        {
            FatalIOErrorInFunction(dict_)
                << "clampAt face: no free particle at " << beyond
                << ", two spacings across the face from the clamped"
                << " particle at " << X_[g] << " (the structure beyond a"
                << " face clamp must be two particles long on the lattice;"
                << " use clampAt particles)" << exit(FatalIOError);
        }
        ghost.append(g);
        near.append(m1);
        far.append(m2);
    }
    ghost_.transfer(ghost);
    ghostNear_.transfer(near);
    ghostFar_.transfer(far);
}


void Foam::structureModel::clampedInternalForces
(
    List<vector2D>& force,
    scalarList& torque
)
{
    if (ghost_.empty())
    {
        internalForces(force, torque);
        return;
    }

    // Quadratic extrapolation through the face: ghost at -ds/2, m1 at
    // ds/2, m2 at 3 ds/2, u(face) = 0
    const scalar a1 = -2, a2 = 1.0/3.0;

    // The ghosts exist only inside the evaluation: the clamped particles
    // keep the support's motion (walls attached to them, output, restart)
    const label nG = ghost_.size();
    List<vector2D> held(nG);
    scalarList heldTheta(nG);
    forAll(ghost_, k)
    {
        const label g = ghost_[k], m1 = ghostNear_[k], m2 = ghostFar_[k];
        held[k] = x_[g];
        heldTheta[k] = theta_[g];
        // the support's displacement is the ghost's own held one
        const vector2D c(x_[g] - X_[g]);
        x_[g] =
            x_[g]
          + a1*(x_[m1] - X_[m1] - c)
          + a2*(x_[m2] - X_[m2] - c);
        theta_[g] =
            theta_[g]
          + a1*(theta_[m1] - heldTheta[k])
          + a2*(theta_[m2] - heldTheta[k]);
    }

    internalForces(force, torque);

    forAll(ghost_, k)
    {
        const label g = ghost_[k], m1 = ghostNear_[k], m2 = ghostFar_[k];
        x_[g] = held[k];
        theta_[g] = heldTheta[k];
        force[m1] += a1*force[g];
        force[m2] += a2*force[g];
        torque[m1] += a1*torque[g];
        torque[m2] += a2*torque[g];
        force[g] *= 1 - a1 - a2;
        torque[g] *= 1 - a1 - a2;
    }
}


void Foam::structureModel::updateAcceleration()
{
    clampedInternalForces(a_, alpha_);
    if (stiffnessDamping_ > 0)
    {
        // (the stiffness damping's step takes K v from them)
        internalForce_ = a_;
        internalTorque_ = alpha_;
    }

    const scalar m = mass();
    const scalar I = rotationalInertia();

    // The support holds the clamped particles on their prescribed motion
    // (no acceleration, no rotation): its reaction is minus the internal,
    // external and gravity forces on them, its power that times their
    // velocity
    scalar power = 0;

    #pragma omp parallel for schedule(static) reduction(+:power)
    for (label i = 0; i < size(); ++i)
    {
        if (clamped_[i])
        {
            power -= (a_[i] + f_[i] + m*g_) & clampedVelocity_;
            a_[i] = Zero;
            alpha_[i] = 0;
        }
        else
        {
            a_[i] = (a_[i] + f_[i])/m + g_;
            alpha_[i] /= I;
        }
    }
    supportPower_ = power;
}


Foam::scalar Foam::structureModel::maxEigenfrequency() const
{
    // Power iteration on M^-1 K, K v from finite differences of the
    // internal forces about the reference state. Translations and
    // rotations are scaled by sqrt(m) and sqrt(I) so that the iterated
    // operator is symmetric.
    const label n = size();
    if (n == 0)
    {
        return 0;
    }
    const scalar sm = ::sqrt(mass());
    const scalar sI = ::sqrt(rotationalInertia());

    // The state is perturbed in place and restored at the end (the cached
    // result makes this a const query for the callers)
    structureModel& self = const_cast<structureModel&>(*this);
    const List<vector2D> x0(x_);
    const scalarList theta0(theta_);

    List<vector2D> u(n);
    scalarList r(n);
    Random rnd(1234);
    forAll(u, i)
    {
        const bool fixed = clamped_[i];
        u[i] =
            fixed
          ? vector2D::zero
          : vector2D
            (
                rnd.sample01<scalar>() - 0.5,
                rnd.sample01<scalar>() - 0.5
            );
        r[i] = fixed ? 0 : rnd.sample01<scalar>() - 0.5;
    }

    List<vector2D> F0(n), F1(n);
    scalarList T0(n), T1(n);
    self.x_ = X_;
    self.theta_ = 0;
    self.clampedInternalForces(F0, T0);

    scalar lambdaMax = 0;
    // Perturbation: displacements of at most 1e-6 spacings
    const scalar eps = 1e-6*ds_*sm;
    for (label iter = 0; iter < 200; ++iter)
    {
        scalar norm = 0;
        forAll(u, i)
        {
            norm += magSqr(u[i]) + sqr(r[i]);
        }
        norm = ::sqrt(norm);
        if (norm < VSMALL)
        {
            break;
        }
        forAll(u, i)
        {
            u[i] /= norm;
            r[i] /= norm;
            self.x_[i] = X_[i] + eps*u[i]/sm;
            self.theta_[i] = eps*r[i]/sI;
        }
        self.clampedInternalForces(F1, T1);

        scalar rayleigh = 0;
        forAll(u, i)
        {
            if (clamped_[i])
            {
                u[i] = Zero;
                r[i] = 0;
                continue;
            }
            const vector2D Ku(-(F1[i] - F0[i])/(eps*sm));
            const scalar Kr = -(T1[i] - T0[i])/(eps*sI);
            rayleigh += (Ku & u[i]) + Kr*r[i];
            u[i] = Ku;
            r[i] = Kr;
        }
        const scalar change = mag(rayleigh - lambdaMax);
        lambdaMax = rayleigh;
        if (iter > 20 && change < 1e-4*lambdaMax)
        {
            break;
        }
    }

    self.x_ = x0;
    self.theta_ = theta0;

    // The models keep strains of their last evaluation: evaluate the
    // restored state again so that no perturbed strain is left behind
    self.clampedInternalForces(F0, T0);

    return ::sqrt(max(lambdaMax, scalar(0)));
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::structureModel::structureModel
(
    const dictionary& dict,
    const UList<vector2D>& X,
    const UList<bool>& clamped,
    const scalar spacing
)
:
    dict_(dict),
    rho_(dict.get<scalar>("rho")),
    E_(dict.get<scalar>("E")),
    nu_(dict.get<scalar>("nu")),
    planeStrain_(dict.get<bool>("planeStrain")),
    lambda_(0),
    mu_(0),
    ds_(spacing),
    dt_(0),
    damping_(dict.getOrDefault<scalar>("damping", 0)),
    stiffnessDamping_(dict.getOrDefault<scalar>("stiffnessDamping", 0)),
    internalForce_(),
    internalTorque_(),
    g_(dict.getOrDefault<vector2D>("g", vector2D::zero)),
    X_(X),
    x_(X),
    v_(X.size(), Zero),
    a_(X.size(), Zero),
    theta_(X.size(), Zero),
    omega_(X.size(), Zero),
    alpha_(X.size(), Zero),
    f_(X.size(), Zero),
    clamped_(clamped),
    clampedVelocity_(Zero),
    clampAtFace_(false),
    time_(0),
    externalWork_(0),
    supportWork_(0),
    dampingLoss_(0),
    supportPower_(0),
    initialEnergy_(-1),
    dtMax_(0),
    integration_(integrationType::Verlet),
    rhoInf_(1),
    alphaM_(0),
    alphaF_(0),
    beta_(0.25),
    gamma_(0.5),
    aStep_(X.size(), Zero),
    alphaStep_(X.size(), Zero),
    stepAccelerations_(false),
    fStep_(X.size(), Zero),
    tangent_(),
    factorisedDeltaT_(0),
    nImplicitSteps_(0),
    nIterations_(0),
    nTangents_(0),
    nCutbacks_(0),
    nEvaluationsBefore_(0),
    savedStepAccelerations_(false)
{
    if (rho_ <= 0)
    {
        FatalIOErrorInFunction(dict)
            << "rho = " << rho_ << " must be positive" << exit(FatalIOError);
    }
    if (E_ <= 0)
    {
        FatalIOErrorInFunction(dict)
            << "E = " << E_ << " must be positive" << exit(FatalIOError);
    }
    if (nu_ <= -1 || nu_ >= 0.5)
    {
        FatalIOErrorInFunction(dict)
            << "nu = " << nu_ << " must lie in (-1, 0.5)"
            << exit(FatalIOError);
    }
    if (damping_ < 0)
    {
        FatalIOErrorInFunction(dict)
            << "damping = " << damping_ << " must not be negative"
            << exit(FatalIOError);
    }
    if (stiffnessDamping_ < 0)
    {
        FatalIOErrorInFunction(dict)
            << "stiffnessDamping = " << stiffnessDamping_
            << " must not be negative (a retardation time [s]; 0: none)"
            << exit(FatalIOError);
    }
    if (spacing <= 0)
    {
        FatalIOErrorInFunction(dict)
            << "structural particle spacing " << spacing
            << " must be positive" << exit(FatalIOError);
    }
    if (clamped.size() != X.size())
    {
        FatalErrorInFunction
            << clamped.size() << " clamped flags for " << X.size()
            << " particles" << exit(FatalError);
    }

    const word clampAt(dict.getOrDefault<word>("clampAt", "particles"));
    if (clampAt != "particles" && clampAt != "face")
    {
        FatalIOErrorInFunction(dict)
            << "clampAt " << clampAt << " is not valid: particles (the"
            << " clamped particles are held, with their strain energy) or"
            << " face (the support acts at the face between clamped and"
            << " free particles)" << exit(FatalIOError);
    }
    clampAtFace_ = (clampAt == "face");
    findGhosts();

    readTimeIntegration();

    mu_ = E_/(2*(1 + nu_));
    lambda_ = E_*nu_/((1 + nu_)*(1 - 2*nu_));
    if (!planeStrain_)
    {
        lambda_ = 2*lambda_*mu_/(lambda_ + 2*mu_);
    }
}


// * * * * * * * * * * * * * * * * Destructor  * * * * * * * * * * * * * * * //

Foam::structureModel::~structureModel()
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::structureModel::info(Ostream& os) const
{
    os  << type();
    if (implicit())
    {
        os  << ", timeIntegration generalisedAlpha (spectralRadius "
            << rhoInf_ << ")";
    }
}


Foam::label Foam::structureModel::nForceEvaluations() const
{
    return nEvaluationsBefore_ + (tangent_ ? tangent_->nEvaluations() : 0);
}


Foam::scalar Foam::structureModel::bendingModulus() const
{
    return 4*mu_*(lambda_ + mu_)/(lambda_ + 2*mu_);
}


Foam::scalar Foam::structureModel::waveSpeed() const
{
    return ::sqrt((lambda_ + 2*mu_)/rho_);
}


Foam::scalar Foam::structureModel::maxStableDeltaT() const
{
    // About the reference state, so computed once (an adjustable fluid
    // step resets the sub-steps often)
    if (dtMax_ <= 0)
    {
        const scalar w = maxEigenfrequency();
        const scalar zeta = stiffnessDamping_*w/2;
        dtMax_ = w > 0 ? 2/w*(::sqrt(1 + sqr(zeta)) - zeta) : GREAT;
    }
    return dtMax_;
}


void Foam::structureModel::setDeltaT(const scalar dt)
{
    if (implicit())
    {
        // Unconditionally stable
        if (!(dt > 0))
        {
            FatalIOErrorInFunction(dict_)
                << "Structural time step " << dt << " s must be positive"
                << exit(FatalIOError);
        }
        dt_ = dt;
        return;
    }
    const scalar dtMax = maxStableDeltaT();
    if (dt <= 0 || dt > 0.9*dtMax)
    {
        FatalIOErrorInFunction(dict_)
            << "Structural time step " << dt << " s is not in (0, "
            << 0.9*dtMax << "] s, the largest stable one for "
            << type() << " (0.9 x 2/omega_max; spacing " << ds_
            << " m, P-wave speed " << waveSpeed() << " m/s"
            << (
                   stiffnessDamping_ > 0
                 ? "; with stiffnessDamping, times sqrt(1 + zeta^2) - zeta,"
                   " zeta = beta omega_max/2"
                 : ""
               )
            << ")" << exit(FatalIOError);
    }
    dt_ = dt;
}


Foam::label Foam::structureModel::setSubSteps(const scalar fluidDeltaT)
{
    label n = 0;
    if (dict_.found("nSubSteps"))
    {
        n = dict_.get<label>("nSubSteps");
        if (n < 1)
        {
            FatalIOErrorInFunction(dict_)
                << "nSubSteps = " << n << " must be at least 1"
                << exit(FatalIOError);
        }
    }
    else if (dict_.found("deltaT"))
    {
        const scalar dt = dict_.get<scalar>("deltaT");
        n = max(label(std::ceil(fluidDeltaT/dt - 1e-6)), label(1));
    }
    else if (implicit())
    {
        n = 1;
    }
    else
    {
        FatalIOErrorInFunction(dict_)
            << "Give the structural step as deltaT [s] or as nSubSteps"
            << " per fluid step" << exit(FatalIOError);
    }
    setDeltaT(fluidDeltaT/n);
    return n;
}


namespace
{
    // One member of the state to its kept copy (save) or back (restore)
    template<class Type>
    void keep(const bool save, Type& live, Type& kept)
    {
        if (save)
        {
            kept = live;
        }
        else
        {
            live = kept;
        }
    }
}


void Foam::structureModel::transferState(const bool save)
{
    keep(save, x_, saved_.x);
    keep(save, v_, saved_.v);
    keep(save, f_, saved_.f);
    keep(save, theta_, saved_.theta);
    keep(save, omega_, saved_.omega);
    keep(save, clampedVelocity_, saved_.clampedVelocity);
    keep(save, time_, saved_.time);
    keep(save, externalWork_, saved_.externalWork);
    keep(save, supportWork_, saved_.supportWork);
    keep(save, dampingLoss_, saved_.dampingLoss);
    keep(save, supportPower_, saved_.supportPower);
    keep(save, initialEnergy_, saved_.initialEnergy);
    keep(save, aStep_, savedAStep_);
    keep(save, alphaStep_, savedAlphaStep_);
    keep(save, stepAccelerations_, savedStepAccelerations_);
    keep(save, fStep_, savedFStep_);
}


void Foam::structureModel::saveState()
{
    transferState(true);
}


void Foam::structureModel::restoreState()
{
    if (saved_.x.size() != x_.size())
    {
        FatalErrorInFunction
            << "No state was saved" << exit(FatalError);
    }
    transferState(false);
    restored();
}


void Foam::structureModel::startSubSteps()
{
    if (dt_ <= 0)
    {
        FatalErrorInFunction
            << "The structural time step is not set" << exit(FatalError);
    }
    startEnergyBalance();
}


void Foam::structureModel::subStep()
{
    if (implicit())
    {
        implicitStep();
        return;
    }
    const scalar dt = dt_;
    const scalar decay = ::exp(-damping_*dt);
    const scalar m = mass();
    const scalar I = rotationalInertia();

    // Work of the external forces and gravity, constant over the
    // step: (f + m g).dx, exact for the drift dx
    scalar work = 0;

    #pragma omp parallel for schedule(static) reduction(+:work)
    for (label i = 0; i < size(); ++i)
    {
        vector2D dx;
        if (clamped_[i])
        {
            v_[i] = clampedVelocity_;
            dx = dt*clampedVelocity_;
        }
        else
        {
            v_[i] += 0.5*dt*a_[i];
            dx = dt*v_[i];
            omega_[i] += 0.5*dt*alpha_[i];
            theta_[i] += dt*omega_[i];
        }
        x_[i] += dx;
        work += (f_[i] + m*g_) & dx;
    }
    time_ += dt;
    externalWork_ += work;

    const scalar powerBefore = supportPower_;
    updateAcceleration();
    supportWork_ += 0.5*dt*(powerBefore + supportPower_);

    scalar loss = 0;

    #pragma omp parallel for schedule(static) reduction(+:loss)
    for (label i = 0; i < size(); ++i)
    {
        if (!clamped_[i])
        {
            v_[i] += 0.5*dt*a_[i];
            omega_[i] += 0.5*dt*alpha_[i];
            if (damping_ > 0)
            {
                const scalar e =
                    0.5*m*magSqr(v_[i]) + 0.5*I*sqr(omega_[i]);
                v_[i] *= decay;
                omega_[i] *= decay;
                loss += e*(1 - sqr(decay));
            }
        }
    }
    dampingLoss_ += loss;
    if (stiffnessDamping_ > 0)
    {
        viscousStep(dt);
    }
}


void Foam::structureModel::advance(const label nSteps)
{
    startSubSteps();
    for (label step = 0; step < nSteps; ++step)
    {
        subStep();
    }
}


void Foam::structureModel::viscousStep(const scalar dt)
{
    // -beta K v from the internal forces a step beta along the velocities
    // (every particle, the clamped ones with the support's velocity, so
    // that a rigid motion gives none): F(x + beta v) - F(x)
    const scalar beta = stiffnessDamping_;
    const List<vector2D> x0(x_);
    const scalarList theta0(theta_);
    forAll(x_, i)
    {
        x_[i] += beta*v_[i];
        theta_[i] += beta*omega_[i];
    }
    List<vector2D> force(size());
    scalarList torque(size());
    clampedInternalForces(force, torque);
    x_ = x0;
    theta_ = theta0;

    // Each free particle takes the impulse J = dt F_d (and L = dt T_d);
    // the kinetic energy that takes out, -(J.v + |J|^2/(2m)) and its
    // rotational part, is the structure's loss (the dashpots' forces on
    // the clamped particles meet the support, whose motion feeds them
    // from outside: no part of the structure's energy)
    const scalar invM = 1/mass(), invI = 1/rotationalInertia();
    scalar loss = 0;

    #pragma omp parallel for schedule(static) reduction(+:loss)
    for (label i = 0; i < size(); ++i)
    {
        if (!clamped_[i])
        {
            const vector2D J(dt*(force[i] - internalForce_[i]));
            const scalar L = dt*(torque[i] - internalTorque_[i]);
            loss -=
                (J & v_[i]) + 0.5*invM*magSqr(J)
              + L*omega_[i] + 0.5*invI*sqr(L);
            v_[i] += invM*J;
            omega_[i] += invI*L;
        }
    }
    dampingLoss_ += loss;
}


void Foam::structureModel::readTimeIntegration()
{
    if (!dict_.found("timeIntegration"))
    {
        return;
    }
    const dictionary* tiPtr = dict_.findDict("timeIntegration");
    if (!tiPtr)
    {
        FatalIOErrorInFunction(dict_)
            << "Entry 'timeIntegration' must be a dictionary:"
            << " timeIntegration { type generalisedAlpha; spectralRadius"
            << " 0.8; } or { type Verlet; }" << exit(FatalIOError);
    }
    const dictionary& ti = *tiPtr;
    inputChecks::keywords(ti, {"type", "spectralRadius"}, "timeIntegration");
    const word type(ti.get<word>("type"));
    if (type == "Verlet")
    {
        if (ti.found("spectralRadius"))
        {
            FatalIOErrorInFunction(ti)
                << "Entry 'spectralRadius' belongs to timeIntegration"
                << " generalisedAlpha; Verlet has none" << exit(FatalIOError);
        }
        return;
    }
    if (type != "generalisedAlpha")
    {
        FatalIOErrorInFunction(ti)
            << "timeIntegration type " << type << " is not valid: Verlet"
            << " (explicit, sub-cycled; the default) or generalisedAlpha"
            << " (implicit, at the fluid's step)" << exit(FatalIOError);
    }
    integration_ = integrationType::generalisedAlpha;
    rhoInf_ = inputChecks::number<scalar>(ti, "spectralRadius", 0.8, "[0, 1]");
    if (stiffnessDamping_ > 0)
    {
        FatalIOErrorInFunction(dict_)
            << "Entry 'stiffnessDamping' belongs to the explicit Verlet"
            << " integration (its damping step would be unstable at the"
            << " implicit step); with timeIntegration generalisedAlpha the"
            << " spectralRadius takes out the high modes: remove"
            << " stiffnessDamping" << exit(FatalIOError);
    }
    alphaM_ = (2*rhoInf_ - 1)/(rhoInf_ + 1);
    alphaF_ = rhoInf_/(rhoInf_ + 1);
    gamma_ = 0.5 - alphaM_ + alphaF_;
    beta_ = 0.25*sqr(1 - alphaM_ + alphaF_);
}


void Foam::structureModel::forcesAt
(
    const UList<vector2D>& x,
    const UList<scalar>& theta,
    List<vector2D>& force,
    scalarList& torque
)
{
    const List<vector2D> x0(x_);
    const scalarList theta0(theta_);
    x_ = x;
    theta_ = theta;
    clampedInternalForces(force, torque);
    x_ = x0;
    theta_ = theta0;
}


void Foam::structureModel::setStepAccelerations
(
    const UList<vector2D>& a,
    const UList<scalar>& alpha,
    const UList<vector2D>& load
)
{
    aStep_ = a;
    alphaStep_ = alpha;
    fStep_ = load;
    stepAccelerations_ = true;
}


void Foam::structureModel::resetTangent()
{
    if (tangent_)
    {
        nEvaluationsBefore_ += tangent_->nEvaluations();
    }
    tangent_.reset();
}


void Foam::structureModel::implicitStep()
{
    implicitSteps(dt_, 0);
}


void Foam::structureModel::implicitSteps(const scalar dt, const label cuts)
{
    // A step whose Newton iterations do not converge is taken again as two
    // halves, down to 2^-maxCuts of the step (the load held over both)
    const label maxCuts = 4;
    if (newtonStep(dt, cuts == maxCuts))
    {
        return;
    }
    ++nCutbacks_;
    implicitSteps(0.5*dt, cuts + 1);
    implicitSteps(0.5*dt, cuts + 1);
}


bool Foam::structureModel::newtonStep(const scalar dt, const bool last)
{
    const scalar dt2 = sqr(dt);
    const label n = size();
    const scalar m = mass();
    const scalar I = rotationalInertia();

    const structureTangent::forceFunction forces
    (
        [this]
        (
            const UList<vector2D>& x,
            const UList<scalar>& theta,
            List<vector2D>& F,
            scalarList& T
        )
        {
            forcesAt(x, theta, F, T);
        }
    );
    const scalar cM = (1 - alphaM_)/(beta_*dt2), cK = 1 - alphaF_;
    if (!tangent_)
    {
        tangent_.reset(new structureTangent(X_, clamped_, ds_));
        tangent_->build(x_, theta_, forces);
        ++nTangents_;
        factorisedDeltaT_ = 0;
    }
    if (dt != factorisedDeltaT_)
    {
        tangent_->factorise(cM, cK, m, I);
        factorisedDeltaT_ = dt;
    }
    if (!stepAccelerations_)
    {
        // The first step starts from the equilibrium's accelerations, its
        // load held
        aStep_ = a_;
        alphaStep_ = alpha_;
        fStep_ = f_;
        stepAccelerations_ = true;
    }

    // The load at n + 1 - alpha_f: the held loads are the values at the
    // steps' middles, extrapolated linearly (with alpha_f = 1/2, the held
    // load itself; otherwise each step's impulse would lag the load by
    // (1/2 - alpha_f) dt, which a body in motion turns into work)
    List<vector2D> fA(n);
    forAll(fA, i)
    {
        fA[i] = f_[i] + (0.5 - alphaF_)*(f_[i] - fStep_[i]);
    }

    const List<vector2D> xn(x_), vn(v_);
    const scalarList thetan(theta_), omegan(omega_);

    // Predictor: the accelerations kept over the step (the clamped
    // particles on their motion)
    List<vector2D> x(n);
    scalarList theta(n);
    forAll(x, i)
    {
        if (clamped_[i])
        {
            x[i] = xn[i] + dt*clampedVelocity_;
            theta[i] = thetan[i];
        }
        else
        {
            x[i] = xn[i] + dt*vn[i] + 0.5*dt2*aStep_[i];
            theta[i] = thetan[i] + dt*omegan[i] + 0.5*dt2*alphaStep_[i];
        }
    }
    // Newmark: the accelerations at the step's end from its positions
    auto acceleration = [&](const label i)
    {
        return
            (x[i] - xn[i] - dt*vn[i] - (0.5 - beta_)*dt2*aStep_[i])
           /(beta_*dt2);
    };
    auto angularAcceleration = [&](const label i)
    {
        return
            (
                theta[i] - thetan[i] - dt*omegan[i]
              - (0.5 - beta_)*dt2*alphaStep_[i]
            )/(beta_*dt2);
    };

    // Newton's iterations on the balance at n + 1 - alpha_f, with the
    // tangent kept while the corrections shrink fast
    const scalar tolerance = 1e-10;
    const label maxIterations = 50;
    List<vector2D> F(n), rF(n), du;
    scalarList T(n), rT(n), dtheta;
    scalar lastCorrection = GREAT;
    for (label iter = 1; ; ++iter)
    {
        forAll(x_, i)
        {
            x_[i] = (1 - alphaF_)*x[i] + alphaF_*xn[i];
            theta_[i] = (1 - alphaF_)*theta[i] + alphaF_*thetan[i];
        }
        clampedInternalForces(F, T);
        forAll(rF, i)
        {
            if (clamped_[i])
            {
                rF[i] = Zero;
                rT[i] = 0;
            }
            else
            {
                rF[i] =
                    F[i] + fA[i] + m*g_
                  - m*((1 - alphaM_)*acceleration(i) + alphaM_*aStep_[i]);
                rT[i] =
                    T[i]
                  - I
                   *(
                        (1 - alphaM_)*angularAcceleration(i)
                      + alphaM_*alphaStep_[i]
                    );
            }
        }
        tangent_->solve(rF, rT, du, dtheta);
        scalar correction = 0;
        forAll(x, i)
        {
            x[i] += du[i];
            theta[i] += dtheta[i];
            correction = max(correction, max(mag(du[i])/ds_, mag(dtheta[i])));
        }
        ++nIterations_;
        if (debug)
        {
            Info<< "structureModel: step " << nImplicitSteps_ << " iteration "
                << iter << " correction " << correction << endl;
        }
        if (correction < tolerance)
        {
            break;
        }
        if (iter == maxIterations || !std::isfinite(correction))
        {
            if (!last)
            {
                // The step's start back, for its halves
                x_ = xn;
                theta_ = thetan;
                return false;
            }
            FatalErrorInFunction
                << "The structure's implicit step at time " << time_ + dt
                << " s did not converge in " << iter << " Newton iterations"
                << ", nor in steps of " << dt << " s (last correction "
                << correction << " spacings, " << nTangents_
                << " tangents): a step too long for the structure's motion"
                << " (deltaT or nSubSteps in constant/structureProperties)"
                << exit(FatalError);
        }
        if (correction > lastCorrection)
        {
            // Diverging: the iterate is no configuration to take a tangent
            // at; the step starts again from its predictor with the
            // tangent of its start
            tangent_->build(xn, thetan, forces);
            tangent_->factorise(cM, cK, m, I);
            ++nTangents_;
            forAll(x, i)
            {
                if (!clamped_[i])
                {
                    x[i] = xn[i] + dt*vn[i] + 0.5*dt2*aStep_[i];
                    theta[i] =
                        thetan[i] + dt*omegan[i] + 0.5*dt2*alphaStep_[i];
                }
            }
            correction = GREAT;
        }
        else if (correction > 0.5*lastCorrection)
        {
            // Slow: the tangent of the configuration reached
            const List<vector2D> xMid(x_);
            const scalarList thetaMid(theta_);
            tangent_->build(xMid, thetaMid, forces);
            tangent_->factorise(cM, cK, m, I);
            ++nTangents_;
        }
        lastCorrection = correction;
    }

    // The step's end: velocities and accelerations (Newmark), the work of
    // the loads held over it
    scalar work = 0;
    forAll(x, i)
    {
        if (clamped_[i])
        {
            v_[i] = clampedVelocity_;
        }
        else
        {
            const vector2D a1(acceleration(i));
            const scalar alpha1 = angularAcceleration(i);
            v_[i] = vn[i] + dt*((1 - gamma_)*aStep_[i] + gamma_*a1);
            omega_[i] =
                omegan[i] + dt*((1 - gamma_)*alphaStep_[i] + gamma_*alpha1);
            aStep_[i] = a1;
            alphaStep_[i] = alpha1;
        }
        work += (f_[i] + m*g_) & (x[i] - xn[i]);
    }
    x_ = x;
    theta_ = theta;
    fStep_ = f_;
    time_ += dt;
    externalWork_ += work;
    ++nImplicitSteps_;

    // The forces of the step's end: the strains the output reads, the
    // support's power
    const scalar powerBefore = supportPower_;
    updateAcceleration();
    supportWork_ += 0.5*dt*(powerBefore + supportPower_);

    if (damping_ > 0)
    {
        const scalar decay = ::exp(-damping_*dt);
        scalar loss = 0;
        forAll(v_, i)
        {
            if (!clamped_[i])
            {
                loss +=
                    (0.5*m*magSqr(v_[i]) + 0.5*I*sqr(omega_[i]))
                   *(1 - sqr(decay));
                v_[i] *= decay;
                omega_[i] *= decay;
            }
        }
        dampingLoss_ += loss;
    }
    return true;
}


Foam::scalar Foam::structureModel::axialStrain
(
    const label i,
    const vector2D& t,
    const vector2D&,
    const scalar
) const
{
    const symmTensor2D e(strain(i));
    return t & (e & t);
}


Foam::scalar Foam::structureModel::kineticEnergy() const
{
    const scalar m = mass();
    const scalar I = rotationalInertia();
    scalar e = 0;
    forAll(v_, i)
    {
        e += 0.5*m*magSqr(v_[i]) + 0.5*I*sqr(omega_[i]);
    }
    return e;
}


Foam::vector2D Foam::structureModel::totalExternalForce() const
{
    vector2D F(Zero);
    forAll(f_, i)
    {
        F += f_[i];
    }
    return F;
}


// ************************************************************************* //
