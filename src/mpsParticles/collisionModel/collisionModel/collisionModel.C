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

#include "collisionModel.H"
#include "inputChecks.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(collisionModel, 0);
    defineRunTimeSelectionTable(collisionModel, dictionary);
}

const Foam::Enum<Foam::collisionModel::stageType>
Foam::collisionModel::stageTypeNames
({
    {stageType::predicted, "predicted"},
    {stageType::corrected, "corrected"},
});


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::collisionModel::collisionModel(const dictionary& dict)
:
    dict_(dict),
    stage_(stageType::predicted)
{}


// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * * //

void Foam::collisionModel::readStage()
{
    stage_ =
        inputChecks::choice(dict_, "stage", stageTypeNames, stage_);
}


// ************************************************************************* //
