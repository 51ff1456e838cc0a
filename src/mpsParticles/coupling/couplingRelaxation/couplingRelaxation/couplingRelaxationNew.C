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

#include "couplingRelaxation.H"
#include "inputChecks.H"

// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::couplingRelaxation> Foam::couplingRelaxation::New
(
    const dictionary& couplingDict
)
{
    const dictionary* given =
        inputChecks::optionalDict(couplingDict, "relaxation");
    dictionary dict;
    if (given)
    {
        dict = *given;
    }
    const word modelType(given ? dict.get<word>("type") : word("aitken"));

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(modelType);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "relaxation",
            modelType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    return autoPtr<couplingRelaxation>(cstrIter()(dict));
}


// ************************************************************************* //
