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

#include "errorCompensating.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace ppeSources
{
    defineTypeNameAndDebug(errorCompensating, 0);
    addToRunTimeSelectionTable(ppeSource, errorCompensating, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::ppeSources::errorCompensating::errorCompensating
(
    const dictionary& dict,
    const kernelPairs& number,
    const scalar rho
)
:
    higherOrder(dict, number, rho)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::ppeSource::row Foam::ppeSources::errorCompensating::source
(
    const label i,
    const scalar dt,
    const bool airSites
) const
{
    const scalar error = densityError(i, airSites);
    const scalar densitySource = -rho_/sqr(dt)*error;
    const scalar nRate = compressionRate(i, dt, airSites);
    const scalar gamma = relaxation(dt) + mag(dt*nRate);

    row s;
    s.rhs = -(1 + mag(error))*rho_/dt*nRate + gamma*densitySource;
    s.gamma = gamma;
    return s;
}


// ************************************************************************* //
