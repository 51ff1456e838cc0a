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
#include "Random.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(structureModel, 0);
    defineRunTimeSelectionTable(structureModel, dictionary);
}


// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * * //

void Foam::structureModel::updateAcceleration()
{
    internalForces(a_, alpha_);

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
    internalForces(F0, T0);

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
        internalForces(F1, T1);

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
    internalForces(F0, T0);

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
    time_(0),
    externalWork_(0),
    supportWork_(0),
    dampingLoss_(0),
    supportPower_(0),
    initialEnergy_(-1),
    dtMax_(0)
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

    mu_ = E_/(2*(1 + nu_));
    lambda_ = E_*nu_/((1 + nu_)*(1 - 2*nu_));
    if (!planeStrain_)
    {
        lambda_ = 2*lambda_*mu_/(lambda_ + 2*mu_);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

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
        dtMax_ = w > 0 ? 2/w : GREAT;
    }
    return dtMax_;
}


void Foam::structureModel::setDeltaT(const scalar dt)
{
    const scalar dtMax = maxStableDeltaT();
    if (dt <= 0 || dt > 0.9*dtMax)
    {
        FatalIOErrorInFunction(dict_)
            << "Structural time step " << dt << " s is not in (0, "
            << 0.9*dtMax << "] s, the largest stable one for "
            << type() << " (0.9 x 2/omega_max; spacing " << ds_
            << " m, P-wave speed " << waveSpeed() << " m/s)"
            << exit(FatalIOError);
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
    else
    {
        FatalIOErrorInFunction(dict_)
            << "Give the structural step as deltaT [s] or as nSubSteps"
            << " per fluid step" << exit(FatalIOError);
    }
    setDeltaT(fluidDeltaT/n);
    return n;
}


void Foam::structureModel::advance(const label nSteps)
{
    if (dt_ <= 0)
    {
        FatalErrorInFunction
            << "The structural time step is not set" << exit(FatalError);
    }
    const scalar dt = dt_;
    const scalar decay = ::exp(-damping_*dt);
    const scalar m = mass();
    const scalar I = rotationalInertia();
    startEnergyBalance();

    for (label step = 0; step < nSteps; ++step)
    {
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
    }
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
