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

#include "improved.H"
#include "addToRunTimeSelectionTable.H"
#include "inputChecks.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace freeSurfaceModels
{
    defineTypeNameAndDebug(improved, 0);
    addToRunTimeSelectionTable(freeSurfaceModel, improved, dictionary);
}
}


const Foam::Enum<Foam::freeSurfaceModels::improved::wallTestType>
Foam::freeSurfaceModels::improved::wallTestTypeNames
({
    { wallTestType::numberDensity, "numberDensity" },
    { wallTestType::asymmetry, "asymmetry" },
});


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::freeSurfaceModels::improved::improved(const dictionary& dict)
:
    freeSurfaceModel(dict),
    beta_(readFraction("beta", 0.8)),
    asymmetry_(readFraction("asymmetry", 0.6)),
    wallTest_
    (
        wallTestTypeNames.getOrDefault
        (
            "wallTest",
            inputChecks::value(dict, "wallTest"),
            wallTestType::numberDensity
        )
    ),
    wallBeta_(readFraction("wallBeta", 0.97))
{
    inputChecks::keywords
    (
        dict,
        {"type", "beta", "asymmetry", "wallTest", "wallBeta"},
        "freeSurface improved"
    );
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::freeSurfaceModels::improved::identify
(
    const mpsCloud& cloud,
    const neighbourList& nbrs,
    const UList<scalar>& w,
    const scalar n0,
    const scalar F0,
    UList<bool>& surface
) const
{
    surface = false;
    asymmetryTest
    (
        cloud, nbrs, w, n0, F0, beta_, asymmetry_, particleKind::fluid, surface
    );
    if (wallTest_ == wallTestType::asymmetry)
    {
        asymmetryTest
        (
            cloud, nbrs, w, n0, F0, beta_, asymmetry_, particleKind::wall,
            surface, true
        );
    }
    else
    {
        numberDensityTest
        (
            cloud, wallBeta_, n0, particleKind::wall, surface
        );
    }
}


// ************************************************************************* //
