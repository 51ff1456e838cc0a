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

#include "rigid.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace structureModels
{
    defineTypeNameAndDebug(rigid, 0);
    addToRunTimeSelectionTable(structureModel, rigid, dictionary);
}
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::structureModels::rigid::internalForces
(
    List<vector2D>& force,
    scalarList& torque
) const
{
    force = Zero;
    torque = Zero;
}


void Foam::structureModels::rigid::updateAcceleration()
{
    if (prescribed_)
    {
        ac_ = Zero;
        alphaC_ = 0;
        return;
    }
    vector2D F(Zero);
    scalar T = 0;
    forAll(f_, i)
    {
        const vector2D r(x_[i] - xc_);
        F += f_[i];
        T += r.x()*f_[i].y() - r.y()*f_[i].x();
    }
    ac_ = F/M_ + g_;
    alphaC_ = T/J_;
}


void Foam::structureModels::rigid::place()
{
    const scalar c = ::cos(phi_);
    const scalar s = ::sin(phi_);
    forAll(X_, i)
    {
        const vector2D R(X_[i] - Xc_);
        const vector2D r(c*R.x() - s*R.y(), s*R.x() + c*R.y());
        x_[i] = xc_ + r;
        v_[i] = vc_ + Omega_*vector2D(-r.y(), r.x());
        theta_[i] = phi_;
        omega_[i] = Omega_;
        a_[i] = ac_;
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::structureModels::rigid::rigid
(
    const dictionary& dict,
    const UList<vector2D>& X,
    const UList<bool>& clamped,
    const scalar spacing
)
:
    structureModel(dict, X, clamped, spacing),
    Xc_(Zero),
    xc_(Zero),
    vc_(Zero),
    ac_(Zero),
    phi_(0),
    Omega_(0),
    alphaC_(0),
    M_(mass()*X.size()),
    J_(0),
    prescribed_(false)
{
    if (clampAtFace_)
    {
        FatalIOErrorInFunction(dict_)
            << "clampAt face is not available with rigid (a rigid"
            << " body has no strain to clamp); use clampAt"
            << " particles" << exit(FatalIOError);
    }
    if (implicit())
    {
        FatalIOErrorInFunction(dict_)
            << "timeIntegration generalisedAlpha is for the elastic models;"
            << " rigid integrates its body's motion by its own step (remove"
            << " timeIntegration)" << exit(FatalIOError);
    }

    forAll(X_, i)
    {
        Xc_ += X_[i];
        prescribed_ = prescribed_ || clamped_[i];
    }
    Xc_ /= max(size(), label(1));
    xc_ = Xc_;
    forAll(X_, i)
    {
        J_ += mass()*magSqr(X_[i] - Xc_) + rotationalInertia();
    }
    evaluate();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::structureModels::rigid::subStep()
{
    const scalar dt = dt_;
    // The external forces' resultant and moment about the centre,
    // constant over the step: their work is F.dxc + T dphi, gravity's
    // M g.dxc; a prescribed motion's support takes -(F + M g).dxc
    vector2D F(Zero);
    scalar T = 0;
    forAll(f_, i)
    {
        const vector2D r(x_[i] - xc_);
        F += f_[i];
        T += r.x()*f_[i].y() - r.y()*f_[i].x();
    }
    const vector2D xc0(xc_);
    const scalar phi0 = phi_;

    if (prescribed_)
    {
        vc_ = clampedVelocity_;
        xc_ += dt*vc_;
    }
    else
    {
        vc_ += 0.5*dt*ac_;
        Omega_ += 0.5*dt*alphaC_;
        xc_ += dt*vc_;
        phi_ += dt*Omega_;
    }
    time_ += dt;
    const vector2D dxc(xc_ - xc0);
    externalWork_ += ((F + M_*g_) & dxc) + T*(phi_ - phi0);
    if (prescribed_)
    {
        supportWork_ -= (F + M_*g_) & dxc;
    }
    place();
    updateAcceleration();
    if (!prescribed_)
    {
        vc_ += 0.5*dt*ac_;
        Omega_ += 0.5*dt*alphaC_;
    }
}


void Foam::structureModels::rigid::restored()
{
    xc_ = Zero;
    vc_ = Zero;
    forAll(x_, i)
    {
        xc_ += x_[i];
        vc_ += v_[i];
    }
    xc_ /= max(size(), label(1));
    vc_ /= max(size(), label(1));
    phi_ = size() ? theta_[0] : 0;
    Omega_ = size() ? omega_[0] : 0;
    place();
    updateAcceleration();
}


// ************************************************************************* //
