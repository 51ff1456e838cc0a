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
    const mpsCloud& cloud,
    const neighbourList& nbrs,
    const UList<scalar>& w,
    const scalar n0,
    const scalar minR2,
    const UList<scalar>& p,
    List<vector2D>& grad
) const
{
    const UList<vector2D>& x = cloud.x();
    const UList<particleKind>& kind = cloud.kind();
    const labelList& offsets = nbrs.offsets();
    const labelList& nbr = nbrs.neighbours();
    const label n = cloud.size();
    const scalar coeff = 2/n0;

    grad.setSize(n);

    #pragma omp parallel for schedule(static)
    for (label i = 0; i < n; ++i)
    {
        grad[i] = Zero;
        if (kind[i] != particleKind::fluid)
        {
            continue;
        }
        const scalar pMin = neighbourhoodMinimum(cloud, nbrs, w, p, i);
        vector2D sum(Zero);
        for (label k = offsets[i]; k < offsets[i + 1]; ++k)
        {
            const label j = nbr[k];
            if (kind[j] == particleKind::dummy)
            {
                continue;
            }
            const vector2D r(x[j] - x[i]);
            sum += ((p[j] - pMin)*w[k]/max(magSqr(r), minR2))*r;
        }
        grad[i] = coeff*sum;
    }
}


// ************************************************************************* //
