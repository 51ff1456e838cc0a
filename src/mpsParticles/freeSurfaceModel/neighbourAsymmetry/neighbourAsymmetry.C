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

#include "neighbourAsymmetry.H"
#include "addToRunTimeSelectionTable.H"
#include "inputChecks.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace freeSurfaceModels
{
    defineTypeNameAndDebug(neighbourAsymmetry, 0);
    addToRunTimeSelectionTable(freeSurfaceModel, neighbourAsymmetry, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::freeSurfaceModels::neighbourAsymmetry::neighbourAsymmetry
(
    const dictionary& dict,
    const dictionary&,
    const scalar
)
:
    freeSurfaceModel(dict),
    beta_(inputChecks::number<scalar>(dict, "beta", 0.8, "(0, 1]")),
    asymmetry_(inputChecks::number<scalar>(dict, "asymmetry", 0.6, "(0, 1]"))
{
    inputChecks::keywords
    (
        dict,
        {"type", "beta", "asymmetry"},
        "freeSurface neighbourAsymmetry"
    );
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::freeSurfaceModels::neighbourAsymmetry::identify
(
    const kernelPairs& pairs,
    const scalar F0,
    UList<bool>& surface
) const
{
    surface = false;
    for (const particleKind k : {particleKind::fluid, particleKind::wall})
    {
        asymmetryTest(pairs, F0, beta_, asymmetry_, k, surface);
    }
}


void Foam::freeSurfaceModels::neighbourAsymmetry::info(Ostream& os) const
{
    os  << type() << " (beta " << beta_ << ", asymmetry " << asymmetry_
        << ')';
}


// ************************************************************************* //
