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

#include "numberDensity.H"
#include "addToRunTimeSelectionTable.H"
#include "inputChecks.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace freeSurfaceModels
{
    defineTypeNameAndDebug(numberDensity, 0);
    addToRunTimeSelectionTable(freeSurfaceModel, numberDensity, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::freeSurfaceModels::numberDensity::numberDensity
(
    const dictionary& dict,
    const dictionary&,
    const scalar
)
:
    freeSurfaceModel(dict),
    beta_(inputChecks::number<scalar>(dict, "beta", 0.97, "(0, 1]"))
{
    inputChecks::keywords(dict, {"type", "beta"}, "freeSurface numberDensity");
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::freeSurfaceModels::numberDensity::identify
(
    const kernelPairs& pairs,
    const scalar F0,
    UList<bool>& surface
) const
{
    surface = false;
    for (const particleKind kind : {particleKind::fluid, particleKind::wall})
    {
        numberDensityTest(pairs.cloud, beta_, pairs.n0, kind, surface);
    }
}


void Foam::freeSurfaceModels::numberDensity::info(Ostream& os) const
{
    os  << type() << " (beta " << beta_ << ')';
}


// ************************************************************************* //
