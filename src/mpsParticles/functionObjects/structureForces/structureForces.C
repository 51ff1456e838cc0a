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

#include "structureForces.H"
#include "inputChecks.H"
#include "fluidStructureInterface.H"
#include "mpsState.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace functionObjects
{
    defineTypeNameAndDebug(structureForces, 0);
    addToRunTimeSelectionTable(functionObject, structureForces, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::functionObjects::structureForces::structureForces
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

    // In the solver (the particles registered), a case without coupling
    // stops here, before anything is written
    if (mesh_.foundObject<mpsState>(mpsState::typeName))
    {
        fluidStructureInterface::lookup(mesh_);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::functionObjects::structureForces::read(const dictionary& dict)
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


bool Foam::functionObjects::structureForces::write()
{
    const fluidStructureInterface& fsi =
        fluidStructureInterface::lookup(mesh_);

    if (!headerWritten_)
    {
        // Opened at the first write: a run stopped before leaves the file
        // of an earlier run as it was
        resetName("force");
        if (Pstream::master())
        {
            OFstream& os = file();
            writeHeader(os, "Force of the fluid on the structure [N/m]");
            writeCommented(os, "Time");
            writeTabbed(os, "Fx");
            writeTabbed(os, "Fy");
            os  << endl;
        }
        headerWritten_ = true;
    }

    if (Pstream::master())
    {
        OFstream& os = file();
        writeCurrentTime(os);
        os  << tab << fsi.fluidForce().x() << tab << fsi.fluidForce().y()
            << endl;
    }
    return true;
}


// ************************************************************************* //
