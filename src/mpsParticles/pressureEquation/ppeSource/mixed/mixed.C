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

#include "mixed.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace ppeSources
{
    defineTypeNameAndDebug(mixed, 0);
    addToRunTimeSelectionTable(ppeSource, mixed, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::ppeSources::mixed::mixed
(
    const dictionary& dict,
    const kernelPairs& number,
    const scalar rho
)
:
    ppeSource(dict, number, rho)
{
    readRelaxation();
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::ppeSources::mixed::divergence(const label i) const
{
    const UList<vector2D>& x = number_.cloud.x();
    const UList<vector2D>& U = number_.cloud.U();
    const UList<particleKind>& kind = number_.cloud.kind();
    const labelList& offsets = number_.pairs.offsets();
    const labelList& nbr = number_.pairs.neighbours();
    const scalar minR2 = sqr(number_.minR);

    scalar div = 0;
    for (label k = offsets[i]; k < offsets[i + 1]; ++k)
    {
        const label j = nbr[k];
        if (kind[j] != particleKind::dummy)
        {
            const vector2D r(x[j] - x[i]);
            div += ((U[j] - U[i]) & r)*number_.w[k]/max(magSqr(r), minR2);
        }
    }
    const scalar divCoeff = 2/number_.n0;
    return divCoeff*div;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::ppeSource::row Foam::ppeSources::mixed::source
(
    const label i,
    const scalar dt,
    const bool airSites
) const
{
    const scalar densitySource = -rho_/sqr(dt)*densityError(i, airSites);
    const scalar relax = relaxation(dt);

    scalar div = divergence(i);
    if (div < 0)
    {
        div = min(div + deficit(i, airSites)/dt, scalar(0));
    }

    row s;
    s.rhs = rho_/dt*div + relax*densitySource;
    s.gamma = relax;
    return s;
}


// ************************************************************************* //
