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

#include "structureModel.H"
#include "inputChecks.H"

// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::structureModel> Foam::structureModel::New
(
    const dictionary& dict,
    const UList<vector2D>& X,
    const UList<bool>& clamped,
    const scalar spacing
)
{
    const dictionary& modelDict =
        inputChecks::subDict(dict, "structureModel");
    inputChecks::keywords(modelDict, {"type"}, "structureModel");
    const word modelType(modelDict.get<word>("type"));

    Info<< "Selecting structure model " << modelType << endl;

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(modelType);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            modelDict,
            "structureModel",
            modelType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    autoPtr<structureModel> model(cstrIter()(dict, X, clamped, spacing));

    // A structural step given as such is checked now; nSubSteps needs the
    // fluid step (setSubSteps)
    if (dict.found("deltaT"))
    {
        model->setDeltaT(dict.get<scalar>("deltaT"));
    }
    return model;
}


// ************************************************************************* //
