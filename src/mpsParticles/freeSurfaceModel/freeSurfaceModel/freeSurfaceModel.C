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

#include "freeSurfaceModel.H"
#include "rowChunks.H"
#include "inputChecks.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(freeSurfaceModel, 0);
    defineRunTimeSelectionTable(freeSurfaceModel, dictionary);
}


// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * * //

void Foam::freeSurfaceModel::numberDensityTest
(
    const mpsCloud& cloud,
    const scalar beta,
    const scalar n0,
    const particleKind kind,
    UList<bool>& surface
)
{
    const UList<scalar>& n = cloud.n();
    const UList<particleKind>& kinds = cloud.kind();

    #pragma omp parallel for schedule(static)
    for (label i = 0; i < cloud.size(); ++i)
    {
        if (kinds[i] == kind)
        {
            surface[i] = (n[i] < beta*n0);
        }
    }
}


void Foam::freeSurfaceModel::asymmetryTest
(
    const kernelPairs& pairs,
    const scalar F0,
    const scalar beta,
    const scalar asymmetry,
    const particleKind kind,
    UList<bool>& surface,
    const bool wallNeighbourhood
)
{
    const mpsCloud& cloud = pairs.cloud;
    const UList<vector2D>& x = cloud.x();
    const UList<scalar>& n = cloud.n();
    const UList<particleKind>& kinds = cloud.kind();
    const labelList& offsets = pairs.pairs.offsets();
    const labelList& nbr = pairs.pairs.neighbours();
    const UList<scalar>& w = pairs.w;
    const scalar n0 = pairs.n0;
    const scalar limit = sqr(asymmetry*F0*n0/2);
    const UList<vector2D>* given =
        wallNeighbourhood ? nullptr : pairs.asymmetry;

    rowChunks rows(cloud.size());
    #pragma omp parallel
    rows.forEach([&](const label i)
    {
        if (kinds[i] != kind)
        {
            return;
        }
        if (n[i] < beta*n0)
        {
            surface[i] = true;
            return;
        }
        if (given)
        {
            surface[i] = (magSqr((*given)[i]) > limit);
            return;
        }
        bool wet = !wallNeighbourhood;
        vector2D F(Zero);
        for (label k = offsets[i]; k < offsets[i + 1]; ++k)
        {
            const label j = nbr[k];
            if (kinds[j] == particleKind::dummy && !wallNeighbourhood)
            {
                continue;
            }
            wet = wet || kinds[j] == particleKind::fluid;
            const vector2D d(x[i] - x[j]);
            F += (w[k]/max(mag(d), SMALL))*d;
        }
        // |(2/n0) F| > asymmetry F0
        surface[i] = !wet || (magSqr(F) > limit);
    });
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::freeSurfaceModel::freeSurfaceModel(const dictionary& dict)
:
    dict_(dict)
{}


// ************************************************************************* //
