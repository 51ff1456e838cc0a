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
#include "addToRunTimeSelectionTable.H"
#include "inputChecks.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace mpsKernels
{
    defineTypeNameAndDebug(original, 0);
    addToRunTimeSelectionTable(mpsKernel, original, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::mpsKernels::original::original(const dictionary& dict, const scalar re)
:
    mpsKernel(dict, re)
{
    inputChecks::keywords(dict, {"type"}, "kernel original");
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::mpsKernels::original::w(const scalar r) const
{
    return (r < re_ && r > 0) ? re_/r - 1 : 0;
}


Foam::scalar Foam::mpsKernels::original::dwdr(const scalar r) const
{
    // w = re/r - 1: dw/dr = -re/r^2
    return (r < re_ && r > 0) ? -re_/(r*r) : 0;
}


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //
