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

#include "corrected.H"
#include "inputChecks.H"
#include "addToRunTimeSelectionTable.H"
#include "rowChunks.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace pressureGradients
{
    defineTypeNameAndDebug(corrected, 0);
    addToRunTimeSelectionTable(pressureGradient, corrected, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::pressureGradients::corrected::corrected(const dictionary& dict)
:
    pressureGradient(dict),
    particleReference_(true),
    minDeterminant_(inputChecks::number<scalar>(dict, "minDeterminant", 0.1, "(0, 1)"))
{
    inputChecks::keywords
    (
        dict,
        {"type", "reference", "minDeterminant"},
        "pressureGradient corrected"
    );
    const word reference(dict.getOrDefault<word>("reference", "particle"));
    if (reference != "particle" && reference != "minimum")
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'reference': " << reference << " is not valid" << nl
            << "Valid references: (particle minimum)" << exit(FatalIOError);
    }
    particleReference_ = (reference == "particle");
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::pressureGradients::corrected::gradient
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
    const UList<vector2D>& x = cloud.x();
    const UList<particleKind>& kind = cloud.kind();
    const labelList& offsets = nbrs.offsets();
    const labelList& nbr = nbrs.neighbours();
    const label n = cloud.size();

    grad.setSize(n);

    rowChunks rows(n);
    #pragma omp parallel
    rows.forEach([&](const label i)
    {
        grad[i] = Zero;
        if (kind[i] != particleKind::fluid)
        {
            return;
        }
        const scalar pRef =
            particleReference_
          ? p[i]
          : neighbourhoodMinimum(cloud, nbrs, w, p, i);

        // The moment matrix sum w r r/r^2 and the corrected form's sum
        scalar mxx = 0, mxy = 0, myy = 0;
        vector2D sum(Zero);
        for (label k = offsets[i]; k < offsets[i + 1]; ++k)
        {
            const label j = nbr[k];
            if (kind[j] == particleKind::dummy || !(w[k] > 0))
            {
                continue;
            }
            const vector2D r(x[j] - x[i]);
            const scalar a = w[k]/max(magSqr(r), minR2);
            mxx += a*r.x()*r.x();
            mxy += a*r.x()*r.y();
            myy += a*r.y()*r.y();
            sum += ((p[j] - pRef)*a)*r;
        }
        const scalar det = mxx*myy - mxy*mxy;
        const scalar half = 0.5*(mxx + myy);
        if (det > minDeterminant_*half*half)
        {
            // C sum, C = [[myy, -mxy], [-mxy, mxx]]/det
            grad[i] = vector2D
            (
                (myy*sum.x() - mxy*sum.y())/det,
                (mxx*sum.y() - mxy*sum.x())/det
            );
        }
        else
        {
            grad[i] = minimumGradient(cloud, nbrs, w, n0, minR2, p, i);
        }
    });
}


void Foam::pressureGradients::corrected::info(Ostream& os) const
{
    os  << type() << " (particleReference " << particleReference_
        << ", minDeterminant " << minDeterminant_ << ')';
}


// ************************************************************************* //
