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

#include "totalLagrangian.H"
#include "neighbourList.H"
#include "mathematicalConstants.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace structureModels
{
    defineTypeNameAndDebug(totalLagrangian, 0);
    addToRunTimeSelectionTable(structureModel, totalLagrangian, dictionary);
}
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::structureModels::totalLagrangian::dWdr(const scalar r) const
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


void Foam::structureModels::totalLagrangian::internalForces
(
    List<vector2D>& force,
    scalarList& torque
) const
{
    const scalar V = sqr(ds_);
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
        P_[i] = (F & S) & B_[i].T();
    }

    #pragma omp parallel for schedule(static)
    for (label i = 0; i < size(); ++i)
    {
        vector2D sum(Zero);
        for (label k = offsets_[i]; k < offsets_[i + 1]; ++k)
        {
            sum += (P_[i] + P_[nbr_[k]]) & gradW_[k];
        }
        force[i] = V*V*sum;
        torque[i] = 0;
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::structureModels::totalLagrangian::totalLagrangian
(
    const dictionary& dict,
    const UList<vector2D>& X,
    const UList<bool>& clamped,
    const scalar spacing
)
:
    structureModel(dict, X, clamped, spacing),
    h_(1.3*spacing),
    B_(X.size()),
    F_(X.size(), tensor2D::I),
    P_(X.size(), tensor2D::zero)
{
    if (clampAtFace_)
    {
        FatalIOErrorInFunction(dict_)
            << "clampAt face is not available with totalLagrangian (its"
            << " kernel reaches beyond the first clamped layer); use clampAt"
            << " particles" << exit(FatalIOError);
    }

    // Reference neighbours and kernel gradients, fixed from now on
    const neighbourList nbrs(X_, 2*h_);
    offsets_ = nbrs.offsets();
    nbr_ = nbrs.neighbours();
    gradW_.setSize(nbr_.size());
    const scalar V = sqr(ds_);

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

    evaluate();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::symmTensor2D Foam::structureModels::totalLagrangian::strain
(
    const label i
) const
{
    return symm(0.5*((F_[i].T() & F_[i]) - tensor2D::I));
}


Foam::scalar Foam::structureModels::totalLagrangian::strainEnergy() const
{
    const scalar V = sqr(ds_);
    scalar e = 0;
    forAll(F_, i)
    {
        const symmTensor2D E(strain(i));
        e += V*(0.5*lambda_*sqr(tr(E)) + mu_*(E && E));
    }
    return e;
}


// ************************************************************************* //
