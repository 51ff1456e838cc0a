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

#include "numberDensity.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace ppeSources
{
    defineTypeNameAndDebug(numberDensity, 0);
    addToRunTimeSelectionTable(ppeSource, numberDensity, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::ppeSources::numberDensity::numberDensity
(
    const dictionary& dict,
    const kernelPairs& number,
    const scalar rho
)
:
    ppeSource(dict, number, rho)
{
    for (const word key : {"relaxation", "relaxationTime", "fillVoids"})
    {
        if (dict.found(key))
        {
            FatalIOErrorInFunction(dict)
                << "Entry '" << key << "' applies to the sources mixed,"
                << " higherOrder and errorCompensating, not to "
                << typeName << " (its density error is the whole source)"
                << exit(FatalIOError);
        }
    }
}


// ************************************************************************* //
