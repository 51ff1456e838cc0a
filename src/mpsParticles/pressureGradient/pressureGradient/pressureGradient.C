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

#include "pressureGradient.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(pressureGradient, 0);
    defineRunTimeSelectionTable(pressureGradient, dictionary);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::pressureGradient::pressureGradient(const dictionary& dict)
:
    dict_(dict)
{}


// * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * * //

Foam::scalar Foam::pressureGradient::neighbourhoodMinimum
(
    const mpsCloud& cloud,
    const neighbourList& nbrs,
    const UList<scalar>& w,
    const UList<scalar>& p,
    const label i
)
{
    const UList<particleKind>& kind = cloud.kind();
    const labelList& offsets = nbrs.offsets();
    const labelList& nbr = nbrs.neighbours();
    scalar pMin = p[i];
    for (label k = offsets[i]; k < offsets[i + 1]; ++k)
    {
        const label j = nbr[k];
        if (kind[j] != particleKind::dummy && w[k] > 0)
        {
            pMin = min(pMin, p[j]);
        }
    }
    return pMin;
}


Foam::vector2D Foam::pressureGradient::minimumGradient
(
    const mpsCloud& cloud,
    const neighbourList& nbrs,
    const UList<scalar>& w,
    const scalar n0,
    const scalar minR2,
    const UList<scalar>& p,
    const label i
)
{
    const UList<vector2D>& x = cloud.x();
    const UList<particleKind>& kind = cloud.kind();
    const labelList& offsets = nbrs.offsets();
    const labelList& nbr = nbrs.neighbours();
    const scalar pMin = neighbourhoodMinimum(cloud, nbrs, w, p, i);

    vector2D sum(Zero);
    for (label k = offsets[i]; k < offsets[i + 1]; ++k)
    {
        const label j = nbr[k];
        if (kind[j] == particleKind::dummy)
        {
            continue;
        }
        const vector2D r(x[j] - x[i]);
        sum += ((p[j] - pMin)*w[k]/max(magSqr(r), minR2))*r;
    }
    return (2/n0)*sum;
}


Foam::scalar Foam::pressureGradient::extrapolate
(
    const mpsCloud& cloud,
    const neighbourList& nbrs,
    const mpsKernel& kernel,
    const label i,
    const UList<scalar>& p,
    const UList<vector2D>& gradP
)
{
    const UList<vector2D>& x = cloud.x();
    const UList<particleKind>& kind = cloud.kind();
    const labelList& offsets = nbrs.offsets();
    const labelList& nbr = nbrs.neighbours();
    const scalar re = kernel.re();
    const scalar minR = 1e-3*re;

    scalar sumW = 0, sumP = 0;
    for (label k = offsets[i]; k < offsets[i + 1]; ++k)
    {
        const label j = nbr[k];
        if (kind[j] != particleKind::fluid)
        {
            continue;
        }
        const vector2D d(x[i] - x[j]);
        const scalar r = mag(d);
        if (r < re)
        {
            const scalar w = kernel.w(max(r, minR));
            sumW += w;
            sumP += w*(p[j] + (gradP[j] & d));
        }
    }
    return sumW > 0 ? sumP/sumW : scalar(0);
}


// ************************************************************************* //
