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

#include "rotatingParticles.H"
#include "neighbourList.H"
#include "DynamicList.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace structureModels
{
    defineTypeNameAndDebug(rotatingParticles, 0);
    addToRunTimeSelectionTable
    (
        structureModel,
        rotatingParticles,
        dictionary
    );
}
}


namespace
{

//- Smallest over largest eigenvalue of a symmetric 2x2 tensor
Foam::scalar isotropy(const Foam::tensor2D& M)
{
    const Foam::scalar m = 0.5*(M.xx() + M.yy());
    const Foam::scalar r =
        ::sqrt(Foam::sqr(0.5*(M.xx() - M.yy())) + Foam::sqr(M.xy()));
    return m + r > 0 ? (m - r)/(m + r) : 0;
}

//- 2D cross product
inline Foam::scalar cross(const Foam::vector2D& a, const Foam::vector2D& b)
{
    return a.x()*b.y() - a.y()*b.x();
}

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::symmTensor2D Foam::structureModels::rotatingParticles::stress
(
    const label i,
    const symmTensor2D& eps
) const
{
    const vector2D& n = normal_[i];
    if (n == vector2D::zero)
    {
        return lambda_*tr(eps)*symmTensor2D::I + 2*mu_*eps;
    }

    // Surface particle: no Poisson coupling between t and n
    const vector2D t(-n.y(), n.x());
    const scalar stt = bendingModulus()*(t & (eps & t));
    const scalar snn = (lambda_ + 2*mu_)*(n & (eps & n));
    const scalar stn = 2*mu_*(t & (eps & n));
    return
        stt*symm(t*t) + snn*symm(n*n) + stn*symm(t*n + n*t);
}


void Foam::structureModels::rotatingParticles::internalForces
(
    List<vector2D>& force,
    scalarList& torque
) const
{
    const scalar V = sqr(ds_);

    // Deformation measures and stresses
    #pragma omp parallel for schedule(static)
    for (label i = 0; i < size(); ++i)
    {
        tensor2D G(tensor2D::zero);
        vector2D k(Zero);
        for (label e = offsets_[i]; e < offsets_[i + 1]; ++e)
        {
            const label j = nbr_[e];
            const scalar thetaBar = 0.5*(theta_[i] + theta_[j]);
            const scalar c = ::cos(thetaBar);
            const scalar s = ::sin(thetaBar);
            const vector2D r(x_[j] - x_[i]);
            const vector2D q(c*r.x() + s*r.y(), -s*r.x() + c*r.y());
            q_[e] = q;
            rot_[e] = vector2D(c, s);
            G += (q - dX_[e])*c_[e];
            k += c_[e]*(theta_[j] - theta_[i]);
        }
        Gamma_[i] = G;

        // Rotation's lattice Laplacian (the odd-even stabilisation)
        scalar lap = 0;
        for (label e = offsets_[i]; e < offsets_[i + 1]; ++e)
        {
            lap += theta_[nbr_[e]] - theta_[i];
        }
        lapTheta_[i] = ownsEnergy(i) ? lap/sqr(ds_) : 0;

        if (!ownsEnergy(i))
        {
            // a face clamp's clamped particle: no energy of its own
            kappa_[i] = Zero;
            S_[i] = tensor2D::zero;
            for (label e = offsets_[i]; e < offsets_[i + 1]; ++e)
            {
                residual_[e] = Zero;
            }
            continue;
        }
        kappa_[i] = k;

        // The fit's residual: what the uniform deformation G misses
        for (label e = offsets_[i]; e < offsets_[i + 1]; ++e)
        {
            residual_[e] =
                c_[e] == vector2D::zero
              ? vector2D::zero
              : (q_[e] - dX_[e] - (G & dX_[e]))/magSqr(dX_[e]);
        }

        const symmTensor2D sigma(stress(i, symm(G)));
        const scalar w = G.xy() - G.yx();
        S_[i] =
            V*tensor2D
            (
                sigma.xx(), sigma.xy() + mu_*w,
                sigma.xy() - mu_*w, sigma.yy()
            );
    }

    // Forces and torques, gathered per particle
    const scalar VD = V*D_;
    const scalar VHds2 = V*hourglass_/sqr(ds_);
    const scalar VGr = V*residualModulus_;

    #pragma omp parallel for schedule(static)
    for (label i = 0; i < size(); ++i)
    {
        vector2D F(Zero);
        scalar dUdTheta = 0;
        for (label e = offsets_[i]; e < offsets_[i + 1]; ++e)
        {
            const label j = nbr_[e];
            const label er = reverse_[e];
            const vector2D s
            (
                (S_[i] & c_[e]) + VGr*residual_[e]
              - (S_[j] & c_[er]) - VGr*residual_[er]
            );
            const scalar c = rot_[e].x();
            const scalar sn = rot_[e].y();
            F += vector2D(c*s.x() - sn*s.y(), sn*s.x() + c*s.y());
            dUdTheta -= 0.5*cross(q_[e], s);
            dUdTheta += VD*((kappa_[j] & c_[er]) - (kappa_[i] & c_[e]));
            dUdTheta += VHds2*(lapTheta_[j] - lapTheta_[i]);
        }
        force[i] = F;
        torque[i] = -dUdTheta;
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::structureModels::rotatingParticles::rotatingParticles
(
    const dictionary& dict,
    const UList<vector2D>& X,
    const UList<bool>& clamped,
    const scalar spacing
)
:
    structureModel(dict, X, clamped, spacing),
    D_(bendingModulus()*sqr(spacing)/12),
    hourglass_(0.25*D_*sqr(spacing)),
    residualModulus_(0.1*mu_),
    normal_(X.size(), Zero),
    Gamma_(X.size(), tensor2D::zero),
    kappa_(X.size(), Zero),
    S_(X.size(), tensor2D::zero),
    lapTheta_(X.size(), Zero),
    residual_()
{
    const label n = size();
    const neighbourList candidates(X_, 2.1*ds_);
    const labelList& cOff = candidates.offsets();
    const labelList& cNbr = candidates.neighbours();

    // Stencils: the nearest neighbours, widened where degenerate; a row
    // one particle thick keeps its nearest neighbours on the line
    List<DynamicList<label>> stencil(n);
    List<tensor2D> Minv(n);
    List<vector2D> rowTangent(n, Zero);
    for (label i = 0; i < n; ++i)
    {
        bool ok = false;
        for (scalar radius = 1.1*ds_; radius < 2.15*ds_; radius += 0.2*ds_)
        {
            stencil[i].clear();
            tensor2D M(tensor2D::zero);
            for (label e = cOff[i]; e < cOff[i + 1]; ++e)
            {
                const label j = cNbr[e];
                const vector2D d(X_[j] - X_[i]);
                if (mag(d) < radius)
                {
                    stencil[i].append(j);
                    M += (d*d)/magSqr(d);
                }
            }
            if (isotropy(M) > 0.2)
            {
                Minv[i] = inv(M);
                ok = true;
                break;
            }
        }
        if (!ok)
        {
            // A row (collinear neighbours): the fit acts along the row
            // only, M^-1 = t t/(t.M.t), a rod that stretches, shears and
            // bends with the rotations (Timoshenko-like)
            stencil[i].clear();
            tensor2D M(tensor2D::zero);
            for (label e = cOff[i]; e < cOff[i + 1]; ++e)
            {
                const label j = cNbr[e];
                const vector2D d(X_[j] - X_[i]);
                if (mag(d) < 1.1*ds_)
                {
                    stencil[i].append(j);
                    M += (d*d)/magSqr(d);
                }
            }
            if (stencil[i].size() && isotropy(M) < 1e-6)
            {
                const vector2D t(principalAxis(M.xx(), M.xy(), M.yy()));
                Minv[i] = (t*t)/(t & (M & t));
                rowTangent[i] = t;
                ok = true;
            }
        }
        if (!ok)
        {
            FatalErrorInFunction
                << "Structural particle " << i << " at " << X_[i]
                << " has no two independent neighbours within 2.1"
                << " spacings and is not in a row" << exit(FatalError);
        }

        // Free-surface normal from the nearest ring
        vector2D sum(Zero);
        for (label e = cOff[i]; e < cOff[i + 1]; ++e)
        {
            const vector2D d(X_[cNbr[e]] - X_[i]);
            if (mag(d) < 1.5*ds_)
            {
                sum -= d;
            }
        }
        if (mag(sum) > 0.5*ds_)
        {
            normal_[i] = sum/mag(sum);
        }
        if (rowTangent[i] != vector2D::zero)
        {
            // Both faces free: the surface stress with n normal to the row
            normal_[i] = vector2D(-rowTangent[i].y(), rowTangent[i].x());
        }
    }

    // A face clamp acts through the first clamped layer only
    forAll(stencil, i)
    {
        if (clamped_[i])
        {
            continue;
        }
        for (const label j : stencil[i])
        {
            if (clamped_[j] && clampAtFace_ && !isGhost(j))
            {
                FatalIOErrorInFunction(dict_)
                    << "clampAt face: the stencil of the particle at "
                    << X_[i] << " reaches the clamped particle at " << X_[j]
                    << ", beyond the first clamped layer (use clampAt"
                    << " particles)" << exit(FatalIOError);
            }
        }
    }

    // Symmetric pair lists
    List<DynamicList<label>> partners(n);
    forAll(stencil, i)
    {
        for (const label j : stencil[i])
        {
            if (!partners[i].found(j))
            {
                partners[i].append(j);
            }
            if (!partners[j].found(i))
            {
                partners[j].append(i);
            }
        }
    }
    offsets_.setSize(n + 1);
    offsets_[0] = 0;
    forAll(partners, i)
    {
        Foam::sort(partners[i]);
        offsets_[i + 1] = offsets_[i] + partners[i].size();
    }
    const label nPairs = offsets_[n];
    nbr_.setSize(nPairs);
    reverse_.setSize(nPairs);
    dX_.setSize(nPairs);
    c_.setSize(nPairs);
    q_.setSize(nPairs);
    rot_.setSize(nPairs);
    residual_.setSize(nPairs, Zero);
    forAll(partners, i)
    {
        label e = offsets_[i];
        for (const label j : partners[i])
        {
            nbr_[e] = j;
            dX_[e] = X_[j] - X_[i];
            c_[e] =
                stencil[i].found(j)
              ? vector2D(Minv[i] & dX_[e])/magSqr(dX_[e])
              : vector2D::zero;
            ++e;
        }
    }
    forAll(partners, i)
    {
        for (label e = offsets_[i]; e < offsets_[i + 1]; ++e)
        {
            const label j = nbr_[e];
            for (label f = offsets_[j]; f < offsets_[j + 1]; ++f)
            {
                if (nbr_[f] == i)
                {
                    reverse_[e] = f;
                    break;
                }
            }
        }
    }

    evaluate();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::symmTensor2D Foam::structureModels::rotatingParticles::strain
(
    const label i
) const
{
    return symm(Gamma_[i]);
}


Foam::scalar Foam::structureModels::rotatingParticles::axialStrain
(
    const label i,
    const vector2D& t,
    const vector2D& n,
    const scalar dn
) const
{
    const vector2D zt(-t.y(), t.x());
    return (t & (strain(i) & t)) - (kappa_[i] & t)*(n & zt)*dn;
}


Foam::scalar Foam::structureModels::rotatingParticles::strainEnergy() const
{
    const scalar V = sqr(ds_);
    scalar e = 0;
    forAll(Gamma_, i)
    {
        if (!ownsEnergy(i))
        {
            continue;
        }
        const symmTensor2D eps(symm(Gamma_[i]));
        const scalar w = Gamma_[i].xy() - Gamma_[i].yx();
        for (label p = offsets_[i]; p < offsets_[i + 1]; ++p)
        {
            // |r_ij|^2/|X_ij|^2
            e += 0.5*V*residualModulus_*magSqr(residual_[p])*magSqr(dX_[p]);
        }
        e += 0.5*V
           *(
                (stress(i, eps) && eps) + mu_*sqr(w) + D_*magSqr(kappa_[i])
              + hourglass_*sqr(lapTheta_[i])
            );
    }
    return e;
}


// ************************************************************************* //
