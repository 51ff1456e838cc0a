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

#include "fluidSummary.H"
#include "inputChecks.H"
#include "mpsState.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace functionObjects
{
    defineTypeNameAndDebug(fluidSummary, 0);
    addToRunTimeSelectionTable(functionObject, fluidSummary, dictionary);
}
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::functionObjects::fluidSummary::writeFileHeader(OFstream& os)
{
    writeHeader(os, "MPS fluid summary");
    writeCommented(os, "Time");
    for
    (
        const word col
      : {
            "nFluid", "nWall", "nDummy", "nSurface", "volume", "nError",
            "ppeIterations", "ppeResidual", "nCollisions", "kineticEnergy",
            "maxSpeed", "xMax", "yMax"
        }
    )
    {
        writeTabbed(os, col);
    }
    os  << endl;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::functionObjects::fluidSummary::fluidSummary
(
    const word& name,
    const Time& runTime,
    const dictionary& dict
)
:
    timeSeriesFile(name, runTime, dict, typeName)
{
    // (the file is opened at the first write: a run stopped before, by
    // another function object's bad entry, leaves no empty file behind)
    read(dict);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::functionObjects::fluidSummary::read(const dictionary& dict)
{
    readEntries(dict, {});
    return true;
}


void Foam::functionObjects::fluidSummary::update()
{
    const mpsState& state = mpsState::lookup(mesh_);
    const mpsCloud& cloud = state.cloud();
    const mpsFluid& fluid = state.fluid();
    const mpsFluid::stepInfo& info = fluid.info();
    const scalar n0 = fluid.n0();
    const scalar l0 = fluid.l0();

    label nSurface = 0;
    label nInterior = 0;
    scalar nError = 0;
    scalar sumU2 = 0;
    scalar maxU2 = 0;
    vector2D xMax(-GREAT, -GREAT);
    labelList count(nParticleKinds, Zero);
    forAll(cloud.kind(), i)
    {
        const particleKind k = cloud.kind()[i];
        if (cloud.halo()[i])
        {
            continue;
        }
        ++count[label(k)];
        if (k == particleKind::dummy || k == particleKind::structure)
        {
            continue;
        }
        nSurface += cloud.surface()[i];
        if (k == particleKind::fluid)
        {
            const scalar u2 = magSqr(cloud.U()[i]);
            xMax = max(xMax, cloud.x()[i]);
            sumU2 += u2;
            maxU2 = max(maxU2, u2);
            if (!cloud.surface()[i])
            {
                nError += mag(cloud.n()[i]/n0 - 1);
                ++nInterior;
            }
        }
    }

    // (under -parallel: over every rank's own particles)
    Pstream::listCombineGather(count, plusEqOp<label>());
    reduce(nSurface, sumOp<label>());
    reduce(nInterior, sumOp<label>());
    reduce(nError, sumOp<scalar>());
    reduce(sumU2, sumOp<scalar>());
    reduce(maxU2, maxOp<scalar>());
    reduce(xMax, maxOp<vector2D>());

    const label nFluid = count[label(particleKind::fluid)];
    row_ =
    {
        scalar(nFluid),
        scalar(count[label(particleKind::wall)]),
        scalar(count[label(particleKind::dummy)]),
        scalar(nSurface),
        nFluid*sqr(l0),
        (nInterior ? nError/nInterior : 0),
        scalar(info.ppeIterations),
        info.ppeResidual,
        scalar(info.nCollisions),
        0.5*fluid.rho()*sqr(l0)*sumU2,
        ::sqrt(maxU2),
        xMax.x(),
        xMax.y()
    };
}


void Foam::functionObjects::fluidSummary::writeValues(OFstream& os)
{
    // The counts as integers (particles, iterations, pairs)
    forAll(row_, i)
    {
        if (i <= 3 || i == 6 || i == 8)
        {
            os  << tab << label(row_[i]);
        }
        else
        {
            os  << tab << row_[i];
        }
    }
}


// ************************************************************************* //
