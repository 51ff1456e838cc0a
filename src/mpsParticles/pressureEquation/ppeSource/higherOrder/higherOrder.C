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

#include "higherOrder.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace ppeSources
{
    defineTypeNameAndDebug(higherOrder, 0);
    addToRunTimeSelectionTable(ppeSource, higherOrder, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::ppeSources::higherOrder::higherOrder
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


// * * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * //

Foam::scalar Foam::ppeSources::higherOrder::compressionRate
(
    const label i,
    const scalar dt,
    const bool airSites
) const
{
    scalar nRate = numberDensityRate(number_, i)/number_.n0;
    if (nRate > 0)
    {
        nRate = max(nRate - deficit(i, airSites)/dt, scalar(0));
    }
    return nRate;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::ppeSource::row Foam::ppeSources::higherOrder::source
(
    const label i,
    const scalar dt,
    const bool airSites
) const
{
    const scalar densitySource = -rho_/sqr(dt)*densityError(i, airSites);
    const scalar relax = relaxation(dt);

    row s;
    s.rhs = -rho_/dt*compressionRate(i, dt, airSites) + relax*densitySource;
    s.gamma = relax;
    return s;
}


// ************************************************************************* //
