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
#include "inputChecks.H"
#include "mpsStructure.H"
#include "mpsState.H"
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
    fvMeshFunctionObject(name, runTime, dict),
    logFiles(mesh_, name),
    headerWritten_(false)
{
    read(dict);

    // In the solver (the particles registered), a case without a
    // structure stops here, before anything is written
    if (mesh_.foundObject<mpsState>(mpsState::typeName))
    {
        mpsStructure::lookup(mesh_);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::functionObjects::structureEnergy::read(const dictionary& dict)
{
    fvMeshFunctionObject::read(dict);
    inputChecks::keywords
    (
        dict,
        inputChecks::functionObjectKeywords({}),
        "function object " + name()
    );
    logFiles::read(dict);
    return true;
}


bool Foam::functionObjects::structureEnergy::write()
{
    const structureModel& s = mpsStructure::lookup(mesh_).model();

    if (!headerWritten_)
    {
        // Opened at the first write: a run stopped before leaves the file
        // of an earlier run as it was
        resetName("energy");
        if (Pstream::master())
        {
            OFstream& os = file();
            writeHeader(os, "Energy balance of the structure [J/m]");
            writeHeaderValue
            (
                os, "kinetic + strain at the start", s.initialEnergy()
            );
            writeCommented(os, "Time");
            for
            (
                const word& c
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
        headerWritten_ = true;
    }

    if (Pstream::master())
    {
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

        OFstream& os = file();
        writeCurrentTime(os);
        os  << tab << kinetic << tab << strain << tab << work
            << tab << s.externalWork() << tab << s.supportWork()
            << tab << s.dampingLoss() << tab << balance
            << tab << wallWork << endl;
    }
    return true;
}


// ************************************************************************* //
