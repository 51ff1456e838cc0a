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

#include "structureEnergy.H"
#include "mpsStructure.H"
#include "fluidStructureInterface.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace functionObjects
{
    defineTypeNameAndDebug(structureEnergy, 0);
    addToRunTimeSelectionTable(functionObject, structureEnergy, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::functionObjects::structureEnergy::structureEnergy
(
    const word& name,
    const Time& runTime,
    const dictionary& dict
)
:
    timeSeriesFile(name, runTime, dict, "energy")
{
    read(dict);

    // In the solver, a case without a structure stops here, before
    // anything is written
    if (inSolver())
    {
        mpsStructure::lookup(mesh_);
    }
}


// * * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * //

void Foam::functionObjects::structureEnergy::writeFileHeader(OFstream& os)
{
    const structureModel& s = mpsStructure::lookup(mesh_).model();
    writeHeader(os, "Energy balance of the structure [J/m]");
    writeHeaderValue(os, "kinetic + strain at the start", s.initialEnergy());
    writeCommented(os, "Time");
    for
    (
        const word c
      : {
            "kinetic", "strain", "work", "fluidWork", "motionWork",
            "damping", "balance", "wallWork"
        }
    )
    {
        writeTabbed(os, c);
    }
    os  << endl;
}


void Foam::functionObjects::structureEnergy::writeValues(OFstream& os)
{
    const structureModel& s = mpsStructure::lookup(mesh_).model();
    const scalar kinetic = s.kineticEnergy();
    const scalar strain = s.strainEnergy();
    const scalar work = s.externalWork() + s.supportWork();
    const scalar balance =
        kinetic + strain - s.initialEnergy() - work + s.dampingLoss();

    // The fluid's work along the walls' motion (0 without a coupling)
    const fluidStructureInterface* fsi =
        mesh_.findObject<fluidStructureInterface>
        (
            fluidStructureInterface::typeName
        );
    const scalar wallWork = fsi ? fsi->wallWork() : 0;

    os  << tab << kinetic << tab << strain << tab << work
        << tab << s.externalWork() << tab << s.supportWork()
        << tab << s.dampingLoss() << tab << balance
        << tab << wallWork;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::functionObjects::structureEnergy::read(const dictionary& dict)
{
    readEntries(dict, {});
    return true;
}


// ************************************************************************* //
