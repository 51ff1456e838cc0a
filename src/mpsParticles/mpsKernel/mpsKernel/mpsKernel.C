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

#include "mpsKernel.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(mpsKernel, 0);
    defineRunTimeSelectionTable(mpsKernel, dictionary);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::mpsKernel::mpsKernel(const dictionary& dict, const scalar re)
:
    re_(re)
{
    if (!(re_ > 0))
    {
        FatalIOErrorInFunction(dict)
            << "Kernel support radius must be positive, got " << re_
            << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::mpsKernel::weights
(
    const scalar* r,
    const label n,
    scalar* w,
    scalar* dwdrByR
) const
{
    for (label k = 0; k < n; ++k)
    {
        const scalar rk = r[k];
        w[k] = this->w(rk);
        dwdrByR[k] = dwdr(rk)/rk;
    }
}


void Foam::mpsKernel::values
(
    const scalar* r,
    const label n,
    scalar* w
) const
{
    for (label k = 0; k < n; ++k)
    {
        w[k] = this->w(r[k]);
    }
}


Foam::scalar Foam::mpsKernel::latticeNumberDensity(const scalar l0) const
{
    const label m = label(re_/l0) + 1;
    scalar sum = 0;
    for (label i = -m; i <= m; ++i)
    {
        for (label j = -m; j <= m; ++j)
        {
            if (i || j)
            {
                sum += w(l0*::hypot(scalar(i), scalar(j)));
            }
        }
    }
    return sum;
}


Foam::scalar Foam::mpsKernel::latticeLambda(const scalar l0) const
{
    const label m = label(re_/l0) + 1;
    scalar sumW = 0;
    scalar sumR2W = 0;
    for (label i = -m; i <= m; ++i)
    {
        for (label j = -m; j <= m; ++j)
        {
            if (i || j)
            {
                const scalar r2 = l0*l0*scalar(i*i + j*j);
                const scalar wij = w(::sqrt(r2));
                sumW += wij;
                sumR2W += r2*wij;
            }
        }
    }
    return sumR2W/sumW;
}

Foam::scalar Foam::mpsKernel::latticeSurfaceAsymmetry(const scalar l0) const
{
    const label m = label(re_/l0) + 1;
    scalar Fy = 0;
    for (label i = -m; i <= m; ++i)
    {
        for (label j = -m; j <= 0; ++j)
        {
            if (i || j)
            {
                const scalar r = l0*::hypot(scalar(i), scalar(j));
                Fy += (-j*l0/r)*w(r);
            }
        }
    }
    return 2*Fy/latticeNumberDensity(l0);
}


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //
