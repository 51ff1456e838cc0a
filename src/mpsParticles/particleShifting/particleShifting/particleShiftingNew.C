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

#include "particleShifting.H"
#include "inputChecks.H"

// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::particleShifting> Foam::particleShifting::New
(
    const dictionary& mpsProperties
)
{
    const dictionary* given =
        inputChecks::optionalDict(mpsProperties, "shifting");
    dictionary dict;
    if (given)
    {
        dict = *given;
    }
    const word modelType(given ? dict.get<word>("type") : word("none"));

    Info<< "Selecting particle shifting " << modelType
        << (given ? "" : " (no entry shifting)") << endl;

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(modelType);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "shifting",
            modelType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    return autoPtr<particleShifting>(cstrIter()(dict));
}


// ************************************************************************* //
