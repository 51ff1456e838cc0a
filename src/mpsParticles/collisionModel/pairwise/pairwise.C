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

#include "pairwise.H"
#include "addToRunTimeSelectionTable.H"
#include "inputChecks.H"
#include "rowChunks.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace collisionModels
{
    defineTypeNameAndDebug(pairwise, 0);
    addToRunTimeSelectionTable(collisionModel, pairwise, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::collisionModels::pairwise::pairwise(const dictionary& dict)
:
    collisionModel(dict),
    alpha_(inputChecks::number<scalar>(dict, "alpha", 0.85, "(0, 1)")),
    e_(inputChecks::number<scalar>(dict, "e", 0.2, "[0, 1]"))
{
    inputChecks::keywords
    (
        dict,
        {"type", "alpha", "e", "stage"},
        "collision pairwise"
    );
    readStage();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::collisionModels::pairwise::correct
(
    const mpsCloud& cloud,
    const neighbourList& nbrs,
    const scalar l0,
    const scalar dt,
    UList<vector2D>& x,
    UList<vector2D>& U
) const
{
    const UList<particleKind>& kind = cloud.kind();
    const UList<bool>& halo = cloud.halo();
    const UList<label>& id = cloud.id();
    const labelList& offsets = nbrs.offsets();
    const labelList& nbr = nbrs.neighbours();
    const scalar d2 = sqr(alpha_*l0);
    const label n = cloud.size();

    List<vector2D> dU(n);
    label nPairs = 0;

    rowChunks rows(n);
    #pragma omp parallel reduction(+:nPairs)
    rows.forEach([&](const label i)
    {
        if (kind[i] != particleKind::fluid)
        {
            dU[i] = Zero;
            return;
        }
        vector2D dUi(Zero);
        for (label k = offsets[i]; k < offsets[i + 1]; ++k)
        {
            const label j = nbr[k];
            const vector2D r(x[j] - x[i]);
            const scalar r2 = magSqr(r);
            if (r2 >= d2 || r2 < VSMALL)
            {
                continue;
            }
            const scalar approach = ((U[i] - U[j]) & r);
            if (approach <= 0)
            {
                continue;
            }
            const scalar massFactor =
                (kind[j] == particleKind::fluid ? 0.5 : 1.0);
            dUi -= ((1 + e_)*massFactor*approach/r2)*r;
            // Each pair once: a halo's correction is its owner's, and a
            // pair of fluid particles is the one of lower id's
            if (!halo[i] && (kind[j] != particleKind::fluid || id[i] < id[j]))
            {
                ++nPairs;
            }
        }
        dU[i] = dUi;
    });

    #pragma omp parallel for schedule(static)
    for (label i = 0; i < n; ++i)
    {
        U[i] += dU[i];
        x[i] += dt*dU[i];
    }

    return nPairs;
}


void Foam::collisionModels::pairwise::info(Ostream& os) const
{
    os  << type() << " (alpha " << alpha_ << ", e " << e_
        << ", stage " << stageTypeNames[stage_] << ')';
}


// ************************************************************************* //
