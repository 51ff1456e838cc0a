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

#include "pressureGradient.H"
#include "inputChecks.H"

// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::pressureGradient> Foam::pressureGradient::New
(
    const dictionary& mpsProperties
)
{
    const dictionary* given =
        inputChecks::optionalDict(mpsProperties, "pressureGradient");
    dictionary dict;
    if (given)
    {
        dict = *given;
    }
    const word modelType(given ? dict.get<word>("type") : word("original"));

    Info<< "Selecting pressure gradient " << modelType
        << (given ? "" : " (no entry pressureGradient)") << endl;

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(modelType);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "pressureGradient",
            modelType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    return autoPtr<pressureGradient>(cstrIter()(dict));
}


// ************************************************************************* //
