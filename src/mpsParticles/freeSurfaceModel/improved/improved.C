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

#include <vector>

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


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::freeSurfaceModels::improved::wallNumberDensityTest
(
    const mpsCloud& cloud,
    const neighbourList& nbrs,
    UList<bool>& surface
) const
{
    const mpsKernel& kernel = wallKernel_();
    if (kernel.re() > nbrs.radius()*(1 + 1e-9))
    {
        FatalIOErrorInFunction(dict_)
            << "Entry 'wallRadius' " << kernel.re()/l0_ << " (in l0) exceeds"
            << " the neighbour search radius " << nbrs.radius()/l0_
            << ", the largest of re's numberDensity, gradient and laplacian:"
            << " valid up to that radius" << exit(FatalIOError);
    }

    const UList<vector2D>& x = cloud.x();
    const UList<particleKind>& kinds = cloud.kind();
    const labelList& offsets = nbrs.offsets();
    const labelList& nbr = nbrs.neighbours();
    const scalar limit = wallBeta_*wallN0_;
    const scalar minR = 1e-3*l0_;

    #pragma omp parallel
    {
        // A row's weights at once (the kernel's vectorised values), summed
        // in the row's order
        std::vector<scalar> w;

        #pragma omp for schedule(dynamic, 64)
        for (label i = 0; i < cloud.size(); ++i)
        {
            if (kinds[i] != particleKind::wall)
            {
                continue;
            }
            const label k0 = offsets[i], nk = offsets[i + 1] - k0;
            if (label(w.size()) < nk)
            {
                w.resize(nk);
            }
            for (label l = 0; l < nk; ++l)
            {
                w[l] = max(mag(x[nbr[k0 + l]] - x[i]), minR);
            }
            kernel.values(w.data(), nk, w.data());
            scalar n = 0;
            for (label l = 0; l < nk; ++l)
            {
                n += w[l];
            }
            surface[i] = (n < limit);
        }
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::freeSurfaceModels::improved::improved
(
    const dictionary& dict,
    const dictionary& mpsProperties,
    const scalar l0
)
:
    freeSurfaceModel(dict),
    beta_(inputChecks::number<scalar>(dict, "beta", 0.8, "(0, 1]")),
    asymmetry_(inputChecks::number<scalar>(dict, "asymmetry", 0.6, "(0, 1]")),
    wallTest_
    (
        inputChecks::choice
        (
            dict, "wallTest", wallTestTypeNames, wallTestType::numberDensity
        )
    ),
    wallBeta_(inputChecks::number<scalar>(dict, "wallBeta", 0.97, "(0, 1]")),
    wallKernel_(nullptr),
    wallN0_(0),
    l0_(l0)
{
    inputChecks::keywords
    (
        dict,
        {"type", "beta", "asymmetry", "wallTest", "wallBeta", "wallRadius"},
        "freeSurface improved"
    );
    if (wallTest_ != wallTestType::numberDensity && dict.found("wallBeta"))
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'wallBeta' is the numberDensity wall test's threshold,"
            << " not wallTest " << wallTestTypeNames[wallTest_]
            << "'s (it would be ignored): remove it, or use wallTest"
            << " numberDensity" << exit(FatalIOError);
    }
    if (dict.found("wallRadius"))
    {
        // The kernel radii's own range (re, mpsFluid)
        const scalar radius = inputChecks::value(dict, "wallRadius")
            .get<scalar>("wallRadius");
        if (!(radius > 1 && radius <= 10))
        {
            FatalIOErrorInFunction(dict)
                << "Entry 'wallRadius' (the wall test's kernel radius in"
                << " units of l0) must lie in (1, 10], got " << radius
                << exit(FatalIOError);
        }
        if (wallTest_ != wallTestType::numberDensity)
        {
            FatalIOErrorInFunction(dict)
                << "Entry 'wallRadius' sizes the numberDensity wall test,"
                << " not wallTest " << wallTestTypeNames[wallTest_]
                << exit(FatalIOError);
        }
        wallKernel_ = mpsKernel::New(mpsProperties, radius*l0);
        wallN0_ = wallKernel_->latticeNumberDensity(l0);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::freeSurfaceModels::improved::identify
(
    const kernelPairs& pairs,
    const scalar F0,
    UList<bool>& surface
) const
{
    const mpsCloud& cloud = pairs.cloud;
    surface = false;
    asymmetryTest(pairs, F0, beta_, asymmetry_, particleKind::fluid, surface);
    if (wallTest_ == wallTestType::asymmetry)
    {
        asymmetryTest
        (
            pairs, F0, beta_, asymmetry_, particleKind::wall, surface, true
        );
    }
    else if (wallKernel_.valid())
    {
        wallNumberDensityTest(cloud, pairs.pairs, surface);
    }
    else
    {
        numberDensityTest
        (
            cloud, wallBeta_, pairs.n0, particleKind::wall, surface
        );
    }
}


void Foam::freeSurfaceModels::improved::info(Ostream& os) const
{
    os  << type() << " (beta " << beta_ << ", asymmetry " << asymmetry_
        << ", wallTest " << wallTestTypeNames[wallTest_] << ", wallBeta "
        << wallBeta_;
    if (wallKernel_.valid())
    {
        os  << ", wallRadius " << wallKernel_->re()/l0_ << " l0";
    }
    os  << ')';
}


// ************************************************************************* //
