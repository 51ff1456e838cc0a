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

#include "timeSeriesFile.H"
#include "inputChecks.H"
#include "mpsState.H"
#include "writeChecks.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::functionObjects::timeSeriesFile::timeSeriesFile
(
    const word& name,
    const Time& runTime,
    const dictionary& dict,
    const word& fileName
)
:
    fvMeshFunctionObject(name, runTime, dict),
    logFiles(mesh_, name),
    fileName_(fileName),
    headerWritten_(false)
{}


// * * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * //

void Foam::functionObjects::timeSeriesFile::readEntries
(
    const dictionary& dict,
    std::initializer_list<word> own
)
{
    fvMeshFunctionObject::read(dict);
    inputChecks::keywords
    (
        dict,
        inputChecks::functionObjectKeywords(own),
        "function object " + name()
    );
    logFiles::read(dict);
}


bool Foam::functionObjects::timeSeriesFile::inSolver() const
{
    return mesh_.foundObject<mpsState>(mpsState::typeName);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::functionObjects::timeSeriesFile::write()
{
    update();
    if (!headerWritten_)
    {
        resetName(fileName_);
    }
    if (Pstream::master())
    {
        const fileName failed
        (
            writeChecks::writes
            (
                [this]()
                {
                    OFstream& os = file();
                    if (!headerWritten_)
                    {
                        writeFileHeader(os);
                    }
                    writeCurrentTime(os);
                    writeValues(os);
                    os  << endl;
                    return writeChecks::flushed(os) ? fileName() : os.name();
                }
            )
        );
        if (!failed.empty())
        {
            writeChecks::stopSeries(failed, time_);
        }
    }
    headerWritten_ = true;
    return true;
}


// ************************************************************************* //
