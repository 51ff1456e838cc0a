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

#include "wallPressure.H"
#include "inputChecks.H"
#include "mpsState.H"
#include "OFstream.H"
#include "OSspecific.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace functionObjects
{
    defineTypeNameAndDebug(wallPressure, 0);
    addToRunTimeSelectionTable(functionObject, wallPressure, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::functionObjects::wallPressure::wallPressure
(
    const word& name,
    const Time& runTime,
    const dictionary& dict
)
:
    fvMeshFunctionObject(name, runTime, dict),
    writeFile(mesh_, name),
    Uref_(0),
    pRef_(0)
{
    read(dict);

    // The region is checked now, when the particles are there: a wrong
    // name stops the run before anything is written
    const mpsState* state = mesh_.findObject<mpsState>(mpsState::typeName);
    if (state)
    {
        const wordList valid
        (
            state->cloud().regionNames({particleKind::wall})
        );
        if (!valid.found(regionName_))
        {
            FatalIOErrorInFunction(dict)
                << "Entry 'wall': " << regionName_ << " is not a region of"
                << " wall particles in system/particleDict" << nl
                << "Valid wall regions: " << valid << exit(FatalIOError);
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::functionObjects::wallPressure::read(const dictionary& dict)
{
    fvMeshFunctionObject::read(dict);
    inputChecks::keywords
    (
        dict,
        inputChecks::functionObjectKeywords({"wall", "Uref", "pRef"}),
        "function object " + name()
    );
    writeFile::read(dict);
    regionName_ = dict.get<word>("wall");
    Uref_ = dict.get<scalar>("Uref");
    if (!(Uref_ > 0))
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'Uref' (reference speed [m/s]) must be positive, got "
            << Uref_ << exit(FatalIOError);
    }
    pRef_ = dict.getOrDefault<scalar>("pRef", 0);
    return true;
}


bool Foam::functionObjects::wallPressure::write()
{
    if (!Pstream::master())
    {
        return true;
    }
    const mpsState& state = mpsState::lookup(mesh_);
    const mpsCloud& cloud = state.cloud();
    const scalar q = 0.5*state.fluid().rho()*sqr(Uref_);
    const label r = cloud.regionIndex(regionName_);

    // Written under a temporary name and renamed when complete
    const fileName dir(baseTimeDir());
    mkDir(dir);
    const fileName path(dir/"wallPressure.dat");
    {
        OFstream os(path + ".tmp");
        os.precision(writePrecision_);
        writeHeader
        (
            os,
            "Pressure of the wall particles of region " + regionName_
        );
        writeHeaderValue(os, "rho [kg/m3]", state.fluid().rho());
        writeHeaderValue(os, "Uref [m/s]", Uref_);
        writeHeaderValue(os, "pRef [Pa]", pRef_);
        writeCommented(os, "x");
        writeTabbed(os, "y");
        writeTabbed(os, "p");
        writeTabbed(os, "Cp");
        os  << nl;
        for
        (
            label i = cloud.begin(particleKind::wall);
            i < cloud.end(particleKind::wall);
            ++i
        )
        {
            if (cloud.region()[i] == r)
            {
                const scalar p = cloud.p()[i];
                os  << cloud.x()[i].x() << tab << cloud.x()[i].y() << tab
                    << p << tab << (p - pRef_)/q << nl;
            }
        }
    }
    Foam::mv(path + ".tmp", path);
    return true;
}


// ************************************************************************* //
