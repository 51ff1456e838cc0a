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

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::mpsCloudOutput::mpsCloudOutput(const polyMesh& mesh)
:
    mesh_(mesh),
    lagrangian_(mesh),
    vtk_(mesh.time()),
    writeVTK_(mesh.time().controlDict().getOrDefault<bool>("writeVTK", true))
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
        cellOrder.setSize(cloud.size());
        forAll(cellOrder, i)
        {
            const vector2D& x = cloud.x()[i];
            cellOrder[i] = mesh_.findCell(point(x.x(), x.y(), 0));
        }
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


void Foam::mpsCloudOutput::completeTime(const mpsCloud& cloud)
{
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
            vtk_.write(clouds[i]);
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

    forAll(clouds, i)
    {
        cloudFields& c = clouds[i];
        if (!any[i])
        {
            continue;
        }
        lagrangian_.write(c, runTime.timeName(), staging);
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

    forAll(clouds, i)
    {
        if (any[i] && writeVTK_)
        {
            vtk_.write(clouds[i]);
        }
    }
}


// ************************************************************************* //
