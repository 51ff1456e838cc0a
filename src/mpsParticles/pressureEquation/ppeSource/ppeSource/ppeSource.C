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

#include "ppeSource.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(ppeSource, 0);
    defineRunTimeSelectionTable(ppeSource, dictionary);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::ppeSource::ppeSource
(
    const dictionary& dict,
    const kernelPairs& number,
    const scalar rho
)
:
    dict_(dict),
    number_(number),
    rho_(rho),
    relaxation_(0.05),
    relaxationTime_(0),
    fillVoids_(false)
{}


// * * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * //

void Foam::ppeSource::readRelaxation()
{
    relaxation_ = dict_.getOrDefault<scalar>("relaxation", relaxation_);
    if (dict_.found("relaxationTime"))
    {
        relaxationTime_ = dict_.get<scalar>("relaxationTime");
        if (dict_.found("relaxation"))
        {
            FatalIOErrorInFunction(dict_)
                << "Entries 'relaxation' and 'relaxationTime': the one"
                << " stands in place of the other, give one of them"
                << exit(FatalIOError);
        }
        if (!(relaxationTime_ > 0))
        {
            FatalIOErrorInFunction(dict_)
                << "Entry 'relaxationTime' [s] must be positive, got "
                << relaxationTime_ << exit(FatalIOError);
        }
    }
    if (relaxation_ < 0 || relaxation_ > 1)
    {
        FatalIOErrorInFunction(dict_)
            << "Entry 'relaxation' must lie in [0, 1], got " << relaxation_
            << exit(FatalIOError);
    }
    fillVoids_ = dict_.getOrDefault<bool>("fillVoids", false);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::ppeSource::checkDeltaT(const scalar dt) const
{
    if (relaxationTime_ > 0 && dt > relaxationTime_)
    {
        FatalIOErrorInFunction(dict_)
            << "Entry 'relaxationTime' " << relaxationTime_ << " s is shorter"
            << " than the time step " << dt << " s: the relaxation"
            << " dt/relaxationTime would be clamped to 1 (the whole density"
            << " error corrected each step, another scheme). Give"
            << " relaxationTime above the step (the tutorials' 0.01 s is"
            << " 50 to 500 steps), or the fixed 'relaxation'"
            << exit(FatalIOError);
    }
}


void Foam::ppeSource::info(Ostream& os) const
{
    os  << type();
    writeRelaxation(os);
    if (fillVoids_)
    {
        os  << ", fillVoids";
    }
}


void Foam::ppeSource::writeRelaxation(Ostream& os) const
{
    if (relaxationTime_ > 0)
    {
        os  << ", relaxationTime " << relaxationTime_ << " s";
    }
    else
    {
        os  << ", relaxation " << relaxation_;
    }
}


Foam::scalar Foam::ppeSource::numberDensityRate
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


Foam::scalar Foam::ppeSource::numberDensityRate
(
    const kernelPairs& pairs,
    const label i
)
{
    if (pairs.rate)
    {
        return (*pairs.rate)[i];
    }
    return numberDensityRate
    (
        pairs.cloud, pairs.pairs, pairs.kernel, i, pairs.minR
    );
}


// ************************************************************************* //
