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

#include "freeSurfaceModel.H"
#include "inputChecks.H"

// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::freeSurfaceModel> Foam::freeSurfaceModel::New
(
    const dictionary& mpsProperties,
    const scalar l0
)
{
    const dictionary& dict =
        inputChecks::subDict(mpsProperties, "freeSurface");
    const word modelType(dict.get<word>("type"));

    Info<< "Selecting freeSurface model " << modelType << endl;

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(modelType);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "freeSurface",
            modelType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    return autoPtr<freeSurfaceModel>(cstrIter()(dict, mpsProperties, l0));
}


// ************************************************************************* //
