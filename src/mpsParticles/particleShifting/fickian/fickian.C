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

#include "fickian.H"
#include "addToRunTimeSelectionTable.H"
#include "inputChecks.H"
#include "rowChunks.H"
#include "wideVectors.H"
#include "tensor2D.H"
#include "mathematicalConstants.H"

#include <vector>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace particleShiftings
{
    defineTypeNameAndDebug(fickian, 0);
    addToRunTimeSelectionTable(particleShifting, fickian, dictionary);
}
}

const Foam::Enum<Foam::particleShiftings::fickian::diffusionType>
Foam::particleShiftings::fickian::diffusionTypeNames
({
    { diffusionType::velocity, "velocity" },
    { diffusionType::fixed, "fixed" },
});


const Foam::Enum<Foam::particleShiftings::fickian::surfaceType>
Foam::particleShiftings::fickian::surfaceTypeNames
({
    { surfaceType::tangential, "tangential" },
    { surfaceType::fixed, "fixed" },
});


const Foam::Enum<Foam::particleShiftings::fickian::wallsType>
Foam::particleShiftings::fickian::wallsTypeNames
({
    { wallsType::shift, "shift" },
    { wallsType::tangential, "tangential" },
    { wallsType::hold, "hold" },
});


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

inline Foam::scalar Foam::particleShiftings::fickian::antiClumping
(
    const scalar ratio
) const
{
    if (wholeExponent_ == 4)
    {
        // Lind et al.'s n, every pair: no loop, no branch
        const scalar r2 = ratio*ratio;
        return r2*r2;
    }
    if (wholeExponent_ < 0)
    {
        return ::pow(ratio, exponent_);
    }
    // By squaring: n = 4 is two multiplications
    scalar result = 1, base = ratio;
    for (label n = wholeExponent_; n > 0; n >>= 1)
    {
        if (n & 1)
        {
            result *= base;
        }
        base *= base;
    }
    return result;
}


Foam::particleShiftings::fickian::wendland::wendland
(
    const scalar re,
    const scalar V
)
:
    invH(2/re),
    sigma(7*sqr(invH)/(4*constant::mathematical::pi)),
    gradCoeff(5*V*sigma*sqr(invH))
{}


Foam::scalar Foam::particleShiftings::fickian::smallestEigenvalue
(
    const tensor2D& M
)
{
    // M is symmetric: (xx + yy)/2 -+ sqrt(((xx - yy)/2)^2 + xy^2)
    const scalar mean = 0.5*(M.xx() + M.yy());
    return mean - ::sqrt(sqr(0.5*(M.xx() - M.yy())) + sqr(M.xy()));
}


const Foam::dictionary& Foam::particleShiftings::fickian::checkEntries
(
    const dictionary& dict
)
{
    inputChecks::keywords
    (
        dict,
        {
            "type", "diffusion", "surface", "walls", "coefficient",
            "maxShift", "tensileCorrection", "tensileExponent"
        },
        "shifting fickian"
    );
    return inputChecks::values
    (
        dict,
        {
            "diffusion", "surface", "walls", "coefficient", "maxShift",
            "tensileCorrection", "tensileExponent"
        }
    );
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::particleShiftings::fickian::fickian(const dictionary& dict)
:
    particleShifting(dict),
    diffusion_
    (
        inputChecks::choice
        (
            checkEntries(dict),
            "diffusion",
            diffusionTypeNames,
            diffusionType::velocity
        )
    ),
    surface_
    (
        inputChecks::choice
        (
            dict, "surface", surfaceTypeNames, surfaceType::fixed
        )
    ),
    walls_
    (
        inputChecks::choice(dict, "walls", wallsTypeNames, wallsType::tangential)
    ),
    A_
    (
        dict.getOrDefault<scalar>
        (
            "coefficient", diffusion_ == diffusionType::velocity ? 2 : 0.05
        )
    ),
    maxShift_(inputChecks::number<scalar>(dict, "maxShift", 0.1, "(0, 0.5]")),
    R_(inputChecks::number<scalar>(dict, "tensileCorrection", 0.2, "[0, 1]")),
    exponent_(inputChecks::number<scalar>(dict, "tensileExponent", 4, "[1, 8]")),
    wholeExponent_
    (
        exponent_ == std::round(exponent_) ? label(exponent_) : label(-1)
    )
{
    // The fixed form diffuses explicitly: with this kernel it is stable at
    // A = 0.1 and unstable at 0.25 (the hydrostatic tank at l0 10 mm, dt
    // 5e-4 s, breaks up)
    const scalar maxA = diffusion_ == diffusionType::velocity ? 10 : 0.1;
    if (!(A_ > 0 && A_ <= maxA))
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'coefficient' (A of the diffusion coefficient, "
            << diffusionTypeNames[diffusion_] << " form) must lie in (0, "
            << maxA << "], got " << A_ << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

MPS_ALWAYS_INLINE void Foam::particleShiftings::fickian::shiftRow
(
    const stepData& step,
    const label i,
    rowBuffers& row
) const
{
    const UList<vector2D>& x = step.x;
    const UList<vector2D>& U = step.U;
    const UList<particleKind>& kind = step.kind;
    const UList<bool>& surface = step.surface;
    const labelList& offsets = step.offsets;
    const labelList& nbr = step.nbr;
    const wendland& kernel = step.kernel;
    const scalar invWl0 = step.invWl0;
    const scalar re2 = step.re2;
    const scalar minR2 = step.minR2;
    const scalar maxShift = step.maxShift;
    const scalar h = step.h;
    const scalar dt = step.dt;
    // A renormalisation matrix is used where it is far from singular (it
    // is the identity on a full neighbourhood, 0.09 in a quarter plane, 0
    // with all neighbours on one line)
    const scalar minEigenvalue = 0.05;
    // The row's pairs within the support, gathered (index, d, r^2), their
    // kernel values and anti-clumping factors computed in vectorisable
    // loops, then summed in the row's order
    std::vector<label>& J = row.J;
    std::vector<scalar>& dx = row.dx;
    std::vector<scalar>& dy = row.dy;
    std::vector<scalar>& rr = row.rr;
    std::vector<scalar>& Wr = row.Wr;
    std::vector<scalar>& c = row.c;

    if
    (
        kind[i] != particleKind::fluid
     || (surface[i] && surface_ == surfaceType::fixed)
    )
    {
        return;
    }

    const label k0 = offsets[i], nk = offsets[i + 1] - k0;
    if (label(J.size()) < nk)
    {
        for (auto* v : {&dx, &dy, &rr, &Wr, &c})
        {
            v->resize(nk);
        }
        J.resize(nk);
    }
    label m = 0;
    for (label k = k0; k < k0 + nk; ++k)
    {
        const label j = nbr[k];
        const vector2D d(x[j] - x[i]);
        const scalar r2 = magSqr(d);
        if (r2 >= minR2 && r2 < re2)
        {
            J[m] = j;
            dx[m] = d.x();
            dy[m] = d.y();
            rr[m] = r2;
            ++m;
        }
    }
    {
        const scalar* rp = rr.data();
        scalar* Wp = Wr.data();
        scalar* cp = c.data();
        #pragma omp simd
        for (label l = 0; l < m; ++l)
        {
            kernel.evaluate(std::sqrt(rp[l]), Wp[l], cp[l]);
        }
        // The anti-clumping factor 1 + R (W/W(l0))^n in place of W
        if (wholeExponent_ == 4)
        {
            #pragma omp simd
            for (label l = 0; l < m; ++l)
            {
                Wp[l] = 1 + R_*antiClumping(Wp[l]*invWl0);
            }
        }
        else
        {
            for (label l = 0; l < m; ++l)
            {
                Wp[l] = 1 + R_*antiClumping(Wp[l]*invWl0);
            }
        }
    }

    // With d = x_j - x_i, grad_i W_ij = -W'(r) d/r points from i to j
    // (W' < 0): grad C points into the fluid, where the neighbours
    // are, and M = sum V grad_i W_ij d is symmetric positive definite
    // (the identity on a full, regular neighbourhood)
    vector2D gradC(Zero), g(Zero), gWall(Zero);
    tensor2D Mf(Zero), Mw(Zero), S(Zero);
    bool nearSurface = surface[i];
    bool nearWall = false;
    for (label l = 0; l < m; ++l)
    {
        const label j = J[l];
        const vector2D d(dx[l], dy[l]);
        const vector2D gW(c[l]*d);                  // V grad_i W_ij
        g += gW;
        gradC += Wr[l]*gW;
        if (kind[j] == particleKind::fluid)
        {
            Mf += gW*d;
            S += gW*(U[j] - U[i]);
            nearSurface = nearSurface || surface[j];
        }
        else
        {
            Mw += gW*d;
            gWall += gW;
            nearWall = true;
        }
    }
    if (nearWall && walls_ == wallsType::hold)
    {
        return;
    }
    // (M over all neighbours: the fluid's part and the walls')
    const tensor2D M(Mf + Mw);

    if (nearSurface)
    {
        // Outward normal from the renormalised concentration gradient
        vector2D nHat
        (
            smallestEigenvalue(M) > minEigenvalue ? (inv(M) & g) : g
        );
        const scalar magN = mag(nHat);
        if (magN > VSMALL)
        {
            nHat /= -magN;
            gradC -= (gradC & nHat)*nHat;
        }
    }
    if (nearWall && walls_ == wallsType::tangential)
    {
        // The walls' share of g points into the wall, along its normal
        const scalar magW = mag(gWall);
        if (magW > VSMALL)
        {
            const vector2D nWall(gWall/magW);
            gradC -= (gradC & nWall)*nWall;
        }
    }

    const scalar D =
        diffusion_ == diffusionType::velocity
      ? A_*h*mag(U[i])*dt
      : A_*sqr(h);
    vector2D& dri = step.dr[i];
    dri = -D*gradC;
    const scalar magDr = mag(dri);
    if (magDr > maxShift)
    {
        dri *= maxShift/magDr;
    }
    row.largest = max(row.largest, min(magDr, maxShift));

    if (smallestEigenvalue(Mf) > minEigenvalue)
    {
        // grad U = Mf^-1 S (S_ab = sum V (grad_i W)_a (u_j - u_i)_b)
        step.dU[i] = dri & (inv(Mf) & S);
    }
}


MPS_WIDE_VECTORS void Foam::particleShiftings::fickian::shiftRowWide
(
    const stepData& step,
    const label i,
    rowBuffers& row
) const
{
    shiftRow(step, i, row);
}


void Foam::particleShiftings::fickian::shiftRowPlain
(
    const stepData& step,
    const label i,
    rowBuffers& row
) const
{
    shiftRow(step, i, row);
}


Foam::scalar Foam::particleShiftings::fickian::shift
(
    mpsCloud& cloud,
    const neighbourList& nbrs,
    const scalar l0,
    const scalar re,
    const scalar dt
) const
{
    UList<vector2D>& x = cloud.x();
    UList<vector2D>& U = cloud.U();
    const label n = nbrs.offsets().size() - 1;

    const scalar V = sqr(l0);
    const wendland kernel(re, V);
    scalar Wl0, unused;
    kernel.evaluate(l0, Wl0, unused);
    List<vector2D> dr(n, Zero);
    List<vector2D> dU(n, Zero);
    const stepData step
    {
        x, U, cloud.kind(), cloud.surface(), nbrs.offsets(), nbrs.neighbours(),
        kernel, 1/Wl0, sqr(re), sqr(1e-3*l0), maxShift_*l0, 0.5*re, dt,
        dr, dU
    };
    scalar largest = 0;

    // Each row on the wider vectors where the processor has them (the
    // same numbers: wideVectors.H)
    const bool wide = wideVectors();
    rowChunks rows(n);
    #pragma omp parallel reduction(max:largest)
    {
        rowBuffers row;
        rows.forEach([&](const label i)
        {
            if (wide)
            {
                shiftRowWide(step, i, row);
            }
            else
            {
                shiftRowPlain(step, i, row);
            }
        });
        largest = max(largest, row.largest);
    }

    #pragma omp parallel for schedule(static)
    for (label i = 0; i < n; ++i)
    {
        x[i] += dr[i];
        U[i] += dU[i];
    }

    return largest;
}


void Foam::particleShiftings::fickian::info(Ostream& os) const
{
    os  << type() << " (diffusion " << diffusionTypeNames[diffusion_]
        << ", A " << A_ << ", maxShift " << maxShift_ << " l0, walls "
        << wallsTypeNames[walls_] << ")";
}


// ************************************************************************* //
