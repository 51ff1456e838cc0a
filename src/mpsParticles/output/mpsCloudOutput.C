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

#include "mpsCloudOutput.H"
#include "outputClouds.H"
#include "Time.H"
#include "OSspecific.H"
#include "allRanks.H"
#include "writeChecks.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::mpsCloudOutput::mpsCloudOutput(const polyMesh& mesh)
:
    mesh_(mesh),
    lagrangian_(mesh),
    vtk_(mesh.time()),
    writeVTK_(mesh.time().controlDict().getOrDefault<bool>("writeVTK", true)),
    lastComplete_()
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::mpsCloudOutput::addSource
(
    const word& cloudName,
    const cloudFieldSource& source
)
{
    sources_.append(std::make_pair(cloudName, &source));
}


void Foam::mpsCloudOutput::moveMissing
(
    const fileName& src,
    const fileName& dst
)
{
    mkDir(dst);
    for (const fileName& f : readDir(src, fileName::FILE))
    {
        if (!exists(dst/f))
        {
            Foam::mv(src/f, dst/f);
        }
    }
    for (const fileName& d : readDir(src, fileName::DIRECTORY))
    {
        moveMissing(src/d, dst/d);
    }
}


Foam::PtrList<Foam::cloudFields> Foam::mpsCloudOutput::fields
(
    const mpsCloud& cloud,
    boolList& any
) const
{
    const cloudDistribution* distribution = cloud.distribution();
    const boolList written
    (
        distribution ? distribution->writtenHere(cloud) : boolList()
    );
    // A serial run writes its particles in the order of their cells:
    // v1912's decomposePar writes a processor's positions in cell order
    // and its fields in the file's order, which agree only so (a serial
    // time decomposed to continue under -parallel). Under -parallel each
    // rank writes in its cloud's order, so that a restart reads the
    // particles back in it and continues exactly (the writer finds the
    // cells again for the positions file: at write times only)
    labelList cellOrder;
    if (!distribution)
    {
        pointField x(cloud.size());
        forAll(x, i)
        {
            x[i] = point(cloud.x()[i].x(), cloud.x()[i].y(), 0);
        }
        cellOrder = lagrangian_.cells("cloud", x);
    }
    PtrList<cloudFields> clouds(outputClouds::names().size());
    any.setSize(clouds.size());
    forAll(clouds, i)
    {
        clouds.set
        (
            i,
            new cloudFields
            (
                outputClouds::names()[i], cloud, written, cellOrder
            )
        );
        any[i] = clouds[i].size() > 0;
    }
    // A cloud is written by every rank if one has particles of it
    combineRanks(any, orEqOp<bool>());

    forAll(clouds, i)
    {
        if (any[i])
        {
            for (const auto& source : sources_)
            {
                if (source.first == clouds[i].name())
                {
                    source.second->addFields(clouds[i].ids(), clouds[i]);
                }
            }
        }
    }
    return clouds;
}


void Foam::mpsCloudOutput::checkVTK(const fileName& failed) const
{
    bool written = failed.empty();
    reduce(written, andOp<bool>());
    if (!written)
    {
        const Time& runTime = mesh_.time();
        writeChecks::stop
        (
            failed.empty() ? string("the master's VTK files") : string(failed),
            runTime,
            "Time " + runTime.timeName() + " is complete in its clouds, not"
            " in its VTK: make space and continue with startFrom latestTime"
            " (which writes the VTK of the time from its clouds)"
        );
    }
}


void Foam::mpsCloudOutput::completeTime(const mpsCloud& cloud)
{
    lastComplete_ = mesh_.time().timeName();
    if (!writeVTK_)
    {
        return;
    }
    boolList any;
    PtrList<cloudFields> clouds(fields(cloud, any));
    DynamicList<word> written;
    forAll(clouds, i)
    {
        if (any[i] && !vtk_.listed(clouds[i].name()))
        {
            checkVTK(vtk_.write(clouds[i]));
            written.append(clouds[i].name());
        }
    }
    if (written.size())
    {
        Info<< "The VTK pieces of " << flatOutput(written) << " at time "
            << mesh_.time().timeName() << " were missing (a run stopped"
            << " between its clouds and their VTK): written again from the"
            << " time's clouds" << nl << endl;
    }
}


void Foam::mpsCloudOutput::write(const mpsCloud& cloud)
{
    const Time& runTime = mesh_.time();
    const fileName timeDir(runTime.path()/runTime.timeName());
    const word staging(runTime.timeName() + ".tmp");
    const fileName stagingDir(runTime.path()/staging);
    if (exists(stagingDir))
    {
        rmDir(stagingDir);
    }

    boolList any;
    PtrList<cloudFields> clouds(fields(cloud, any));

    // A file not written whole (a full disk) stops the run before the
    // time is renamed into place: the time goes, the ones before stay
    fileName failed;
    forAll(clouds, i)
    {
        if (any[i] && failed.empty())
        {
            failed = writeChecks::writes
            (
                [&]()
                {
                    return
                        lagrangian_.write
                        (
                            clouds[i], runTime.timeName(), staging
                        );
                }
            );
        }
    }
    bool written = failed.empty();
    reduce(written, andOp<bool>());
    if (!written)
    {
        for (const fileName& dir : {stagingDir, timeDir})
        {
            if (exists(dir))
            {
                rmDir(dir);
            }
        }
        writeChecks::stop
        (
            failed.empty() ? string("another processor's clouds") : string(failed),
            runTime,
            "Time " + runTime.timeName() + " was removed; the latest"
            " complete time is "
          + (lastComplete_.empty() ? word("none") : lastComplete_)
          + ": make space and continue with startFrom latestTime"
        );
    }

    // OpenFOAM's own files of the time (uniform/time, written just before)
    // join the clouds; then the complete time takes the time's name in one
    // rename, so that a kill leaves either the earlier state of the time or
    // the whole new one (and a <time>.tmp that no time listing reads)
    if (isDir(timeDir/"uniform"))
    {
        moveMissing(timeDir/"uniform", stagingDir/"uniform");
    }
    if (exists(timeDir))
    {
        rmDir(timeDir);
    }
    Foam::mv(stagingDir, timeDir);
    lastComplete_ = runTime.timeName();

    forAll(clouds, i)
    {
        if (any[i] && writeVTK_)
        {
            checkVTK(vtk_.write(clouds[i]));
        }
    }
}


// ************************************************************************* //
