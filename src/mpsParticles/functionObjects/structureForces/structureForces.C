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
#include "fluidStructureInterface.H"
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
    timeSeriesFile(name, runTime, dict, "force")
{
    read(dict);

    // In the solver, a case without coupling stops here, before anything
    // is written
    if (inSolver())
    {
        fluidStructureInterface::lookup(mesh_);
    }
}


// * * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * //

void Foam::functionObjects::structureForces::writeFileHeader(OFstream& os)
{
    writeHeader(os, "Force of the fluid on the structure [N/m]");
    writeCommented(os, "Time");
    writeTabbed(os, "Fx");
    writeTabbed(os, "Fy");
    os  << endl;
}


void Foam::functionObjects::structureForces::writeValues(OFstream& os)
{
    const vector2D& F = fluidStructureInterface::lookup(mesh_).fluidForce();
    os  << tab << F.x() << tab << F.y();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::functionObjects::structureForces::read(const dictionary& dict)
{
    readEntries(dict, {});
    return true;
}


// ************************************************************************* //
