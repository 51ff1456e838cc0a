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

#include "original.H"
#include "inputChecks.H"
#include "addToRunTimeSelectionTable.H"
#include "rowChunks.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace pressureGradients
{
    defineTypeNameAndDebug(original, 0);
    addToRunTimeSelectionTable(pressureGradient, original, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::pressureGradients::original::original(const dictionary& dict)
:
    pressureGradient(dict)
{
    inputChecks::keywords(dict, {"type"}, "pressureGradient original");
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::pressureGradients::original::gradient
(
    const kernelPairs& pairs,
    const UList<scalar>& p,
    List<vector2D>& grad
) const
{
    const mpsCloud& cloud = pairs.cloud;
    const neighbourList& nbrs = pairs.pairs;
    const UList<scalar>& w = pairs.w;
    const scalar n0 = pairs.n0;
    const scalar minR2 = sqr(pairs.minR);
    const UList<particleKind>& kind = cloud.kind();
    const label n = cloud.size();

    grad.setSize(n);

    rowChunks rows(n);
    #pragma omp parallel
    rows.forEach([&](const label i)
    {
        grad[i] =
            kind[i] == particleKind::fluid
          ? minimumGradient(cloud, nbrs, w, n0, minR2, p, i)
          : vector2D::zero;
    });
}


// ************************************************************************* //
