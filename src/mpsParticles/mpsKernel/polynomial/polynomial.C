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

#include "polynomial.H"
#include "addToRunTimeSelectionTable.H"
#include "inputChecks.H"
#include "wideVectors.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace mpsKernels
{
    defineTypeNameAndDebug(polynomial, 0);
    addToRunTimeSelectionTable(mpsKernel, polynomial, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::mpsKernels::polynomial::polynomial(const dictionary& dict, const scalar re)
:
    mpsKernel(dict, re),
    invRe_(1/re)
{
    inputChecks::keywords(dict, {"type"}, "kernel polynomial");
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::mpsKernels::polynomial::w(const scalar r) const
{
    if (r >= re_)
    {
        return 0;
    }
    const scalar s = 1 - r*invRe_;
    return s*s*s;
}


Foam::scalar Foam::mpsKernels::polynomial::dwdr(const scalar r) const
{
    // w = (1 - r/re)^3: dw/dr = -3 (1 - r/re)^2/re
    if (r >= re_)
    {
        return 0;
    }
    const scalar s = 1 - r*invRe_;
    return -3*s*s*invRe_;
}


namespace
{
    using Foam::label;
    using Foam::scalar;

    // The rows' loops, compiled for AVX-512 and for any x86-64 (the same
    // numbers: wideVectors.H), the first where the processor has it

    // s = max(1 - r/re, 0): w = s^3, (dw/dr)/r = -3 s^2/(re r)
    MPS_ALWAYS_INLINE void weightsRow
    (
        const scalar invRe,
        const scalar* r,
        const label n,
        scalar* w,
        scalar* dwdrByR
    )
    {
        #pragma omp simd
        for (label k = 0; k < n; ++k)
        {
            const scalar rk = r[k];
            const scalar s = std::max(1 - rk*invRe, scalar(0));
            w[k] = s*s*s;
            dwdrByR[k] = -3*s*s*invRe/rk;
        }
    }

    MPS_COMPILED_TWICE
    (
        void,
        weights,
        (
            const scalar invRe,
            const scalar* r,
            const label n,
            scalar* w,
            scalar* dwdrByR
        ),
        (invRe, r, n, w, dwdrByR)
    )

    // w(r) as one select (0 at and beyond re)
    MPS_ALWAYS_INLINE void valuesRow
    (
        const scalar re,
        const scalar invRe,
        const scalar* r,
        const label n,
        scalar* w
    )
    {
        #pragma omp simd
        for (label k = 0; k < n; ++k)
        {
            const scalar rk = r[k];
            const scalar s = 1 - rk*invRe;
            w[k] = (rk >= re) ? scalar(0) : s*s*s;
        }
    }

    MPS_COMPILED_TWICE
    (
        void,
        values,
        (
            const scalar re,
            const scalar invRe,
            const scalar* r,
            const label n,
            scalar* w
        ),
        (re, invRe, r, n, w)
    )
}


void Foam::mpsKernels::polynomial::weights
(
    const scalar* r,
    const label n,
    scalar* w,
    scalar* dwdrByR
) const
{
    if (wideVectors())
    {
        weightsWide(invRe_, r, n, w, dwdrByR);
    }
    else
    {
        weightsPlain(invRe_, r, n, w, dwdrByR);
    }
}


void Foam::mpsKernels::polynomial::values
(
    const scalar* r,
    const label n,
    scalar* w
) const
{
    if (wideVectors())
    {
        valuesWide(re_, invRe_, r, n, w);
    }
    else
    {
        valuesPlain(re_, invRe_, r, n, w);
    }
}


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //
