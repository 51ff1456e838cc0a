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

#include "totalLagrangianSolid.H"
#include "neighbourList.H"
#include "mathematicalConstants.H"
#include "error.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::totalLagrangianSolid::dWdr(const scalar r) const
{
    const scalar q = r/h_;
    if (q >= 2)
    {
        return 0;
    }
    const scalar alpha = 7/(4*constant::mathematical::pi*sqr(h_));
    const scalar s = 1 - 0.5*q;
    return alpha*(-5*q)*s*s*s/h_;
}


void Foam::totalLagrangianSolid::updateStress()
{
    const scalar V = sqr(props_.spacing);
    const tensor2D I(tensor2D::I);

    #pragma omp parallel for schedule(static)
    for (label i = 0; i < size(); ++i)
    {
        tensor2D sum(tensor2D::zero);
        for (label k = offsets_[i]; k < offsets_[i + 1]; ++k)
        {
            sum += V*((x_[nbr_[k]] - x_[i])*gradW_[k]);
        }
        const tensor2D F(sum & B_[i]);
        const tensor2D E(0.5*((F.T() & F) - I));
        const tensor2D S(lambda_*tr(E)*I + 2*mu_*E);
        F_[i] = F;
        P_[i] = F & S;
    }
}


void Foam::totalLagrangianSolid::updateAcceleration()
{
    const scalar V = sqr(props_.spacing);
    const scalar m = mass();

    #pragma omp parallel for schedule(static)
    for (label i = 0; i < size(); ++i)
    {
        if (clamped_[i])
        {
            a_[i] = Zero;
            continue;
        }
        const tensor2D PBi(P_[i] & B_[i].T());
        vector2D sum(Zero);
        for (label k = offsets_[i]; k < offsets_[i + 1]; ++k)
        {
            const label j = nbr_[k];
            sum += (PBi + (P_[j] & B_[j].T())) & gradW_[k];
        }
        a_[i] = (V/props_.rho)*sum + props_.g + f_[i]/m;
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::totalLagrangianSolid::totalLagrangianSolid
(
    const properties& props,
    const UList<vector2D>& X,
    const UList<bool>& clamped
)
:
    props_(props),
    lambda_(0),
    mu_(0),
    h_(1.3*props.spacing),
    X_(X),
    x_(X),
    v_(X.size(), Zero),
    a_(X.size(), Zero),
    f_(X.size(), Zero),
    clamped_(clamped),
    B_(X.size()),
    F_(X.size(), tensor2D::I),
    P_(X.size(), tensor2D::zero)
{
    const scalar E = props_.E;
    const scalar nu = props_.nu;
    mu_ = E/(2*(1 + nu));
    lambda_ = E*nu/((1 + nu)*(1 - 2*nu));
    if (!props_.planeStrain)
    {
        lambda_ = 2*lambda_*mu_/(lambda_ + 2*mu_);
    }

    // Reference neighbours and kernel gradients, fixed from now on
    const neighbourList nbrs(X_, 2*h_);
    offsets_ = nbrs.offsets();
    nbr_ = nbrs.neighbours();
    gradW_.setSize(nbr_.size());
    const scalar V = sqr(props_.spacing);

    forAll(X_, i)
    {
        tensor2D A(tensor2D::zero);
        for (label k = offsets_[i]; k < offsets_[i + 1]; ++k)
        {
            const vector2D d(X_[i] - X_[nbr_[k]]);
            const scalar r = mag(d);
            gradW_[k] = (dWdr(r)/r)*d;
            A += V*((X_[nbr_[k]] - X_[i])*gradW_[k]);
        }
        if (mag(det(A)) < SMALL)
        {
            FatalErrorInFunction
                << "Structural particle " << i << " at " << X_[i]
                << " has too few neighbours for the correction matrix"
                << exit(FatalError);
        }
        B_[i] = inv(A);
    }

    if (props_.dt > maxStableDeltaT())
    {
        FatalErrorInFunction
            << "Structural time step " << props_.dt << " s is above the"
            << " largest stable one, " << maxStableDeltaT() << " s"
            << " (0.6 h/c, c = sqrt((lambda + 2 mu)/rho) = "
            << ::sqrt((lambda_ + 2*mu_)/props_.rho) << " m/s, h = " << h_
            << " m)" << exit(FatalError);
    }

    updateStress();
    updateAcceleration();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::totalLagrangianSolid::maxStableDeltaT() const
{
    return 0.6*h_/::sqrt((lambda_ + 2*mu_)/props_.rho);
}


void Foam::totalLagrangianSolid::advance(const label nSteps)
{
    const scalar dt = props_.dt;
    for (label step = 0; step < nSteps; ++step)
    {
        #pragma omp parallel for schedule(static)
        for (label i = 0; i < size(); ++i)
        {
            if (!clamped_[i])
            {
                v_[i] += 0.5*dt*a_[i];
                x_[i] += dt*v_[i];
            }
        }
        updateStress();
        updateAcceleration();

        #pragma omp parallel for schedule(static)
        for (label i = 0; i < size(); ++i)
        {
            if (!clamped_[i])
            {
                v_[i] += 0.5*dt*a_[i];
            }
        }
    }
}


void Foam::totalLagrangianSolid::evaluate()
{
    updateStress();
    updateAcceleration();
}


Foam::tensor2D Foam::totalLagrangianSolid::greenStrain(const label i) const
{
    return 0.5*((F_[i].T() & F_[i]) - tensor2D::I);
}


Foam::scalar Foam::totalLagrangianSolid::kineticEnergy() const
{
    scalar e = 0;
    forAll(v_, i)
    {
        e += 0.5*mass()*magSqr(v_[i]);
    }
    return e;
}


Foam::scalar Foam::totalLagrangianSolid::strainEnergy() const
{
    const scalar V = sqr(props_.spacing);
    scalar e = 0;
    forAll(F_, i)
    {
        const tensor2D E(greenStrain(i));
        e += V*(0.5*lambda_*sqr(tr(E)) + mu_*(E && E));
    }
    return e;
}


// ************************************************************************* //
