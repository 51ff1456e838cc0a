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

#include "neumann.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace ppeWallConditions
{
    defineTypeNameAndDebug(neumann, 0);
    addToRunTimeSelectionTable(ppeWallCondition, neumann, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::ppeWallConditions::neumann::neumann(const dictionary& dict)
:
    ppeWallCondition(dict)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::ppeWallConditions::neumann::info(Ostream& os) const
{
    os  << type() << " (walls take the fluid's pressure)";
}


void Foam::ppeWallConditions::neumann::update
(
    const kernelPairs& laplacian,
    const scalar rho,
    const vector2D& g,
    const scalar dt
)
{
    const mpsCloud& cloud = laplacian.cloud;
    const UList<particleKind>& kind = cloud.kind();
    const UList<vector2D>& x = cloud.x();
    const labelList& offsets = laplacian.pairs.offsets();
    const labelList& nbr = laplacian.pairs.neighbours();
    const UList<scalar>& w = laplacian.w;
    const scalar n0 = laplacian.n0;
    const label n = offsets.size() - 1;

    coeff_.setSize(w.size());
    hydro_.setSize(n);

    #pragma omp parallel for schedule(static)
    for (label i = 0; i < n; ++i)
    {
        hydro_[i] = 0;
        if (kind[i] != particleKind::wall)
        {
            for (label k = offsets[i]; k < offsets[i + 1]; ++k)
            {
                coeff_[k] = 0;
            }
            continue;
        }
        scalar fluid = 0, boundary = 0;
        for (label k = offsets[i]; k < offsets[i + 1]; ++k)
        {
            (kind[nbr[k]] == particleKind::fluid ? fluid : boundary) += w[k];
        }
        const scalar N = max(n0 - boundary, fluid);
        scalar h = 0;
        for (label k = offsets[i]; k < offsets[i + 1]; ++k)
        {
            const label f = nbr[k];
            coeff_[k] = 0;
            if (kind[f] == particleKind::fluid && N > 0)
            {
                coeff_[k] = w[k]/N;
                h += coeff_[k]*(g & (x[i] - x[f]));
            }
        }
        hydro_[i] = rho*h;
    }
}


void Foam::ppeWallConditions::neumann::couplings
(
    const kernelPairs& laplacian,
    const label i,
    const scalar lapCoeff,
    couplingList& c
) const
{
    const UList<particleKind>& kind = laplacian.cloud.kind();
    const labelList& offsets = laplacian.pairs.offsets();
    const labelList& nbr = laplacian.pairs.neighbours();
    const UList<scalar>& w = laplacian.w;

    c.entries.clear();
    c.rhs = 0;
    for (label k = offsets[i]; k < offsets[i + 1]; ++k)
    {
        const label wall = nbr[k];
        if (kind[wall] != particleKind::wall)
        {
            continue;
        }
        const scalar a = lapCoeff*w[k];
        c.rhs += a*hydro_[wall];
        for (label m = offsets[wall]; m < offsets[wall + 1]; ++m)
        {
            if (coeff_[m] > 0)
            {
                c.entries.emplace_back(nbr[m], -a*coeff_[m]);
            }
        }
    }
}


void Foam::ppeWallConditions::neumann::wallPressures
(
    const kernelPairs& laplacian,
    const bool clampNegative,
    UList<scalar>& p
) const
{
    const UList<particleKind>& kind = laplacian.cloud.kind();
    const labelList& offsets = laplacian.pairs.offsets();
    const labelList& nbr = laplacian.pairs.neighbours();
    const label n = offsets.size() - 1;

    // (the walls' pressures read only the fluid's)
    #pragma omp parallel for schedule(static)
    for (label i = 0; i < n; ++i)
    {
        if (kind[i] != particleKind::wall)
        {
            continue;
        }
        scalar pw = hydro_[i];
        bool wet = false;
        for (label k = offsets[i]; k < offsets[i + 1]; ++k)
        {
            if (coeff_[k] > 0)
            {
                wet = true;
                pw += coeff_[k]*p[nbr[k]];
            }
        }
        p[i] = !wet ? 0 : clampNegative ? max(pw, scalar(0)) : pw;
    }
}


// ************************************************************************* //
