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

#include "lagrangianCloudReader.H"
#include "cloud.H"
#include "IOField.H"
#include "IFstream.H"
#include "Time.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::lagrangianCloudReader::readCloud
(
    const word& cloudName,
    mpsCloud& cloud,
    const labelList& indexOfId,
    List<bool>& found
) const
{
    const fileName local(cloud::prefix/cloudName);
    const word& timeName = mesh_.time().timeName();
    const fileName dir(mesh_.time().path()/timeName/local);
    if (!isFile(dir/"positions"))
    {
        return;
    }

    auto io = [&](const word& name)
    {
        return IOobject
        (
            name, timeName, local, mesh_,
            IOobject::MUST_READ, IOobject::NO_WRITE, false
        );
    };

    const IOField<label> id(io("id"));
    const IOField<vector> U(io("U"));
    const IOField<scalar> p(io("p"));

    // positions: "(x y z) celli" entries
    IFstream is(dir/"positions");
    IOobject posIO(io("positions"));
    if (!posIO.readHeader(is))
    {
        FatalIOErrorInFunction(is)
            << "Cannot read the header of " << is.name()
            << exit(FatalIOError);
    }
    const label n = readLabel(is);
    if (n != id.size() || n != U.size() || n != p.size())
    {
        FatalIOErrorInFunction(is)
            << "Cloud " << cloudName << " at time " << timeName << " has "
            << n << " positions but " << id.size() << " ids, " << U.size()
            << " velocities and " << p.size() << " pressures"
            << exit(FatalIOError);
    }
    is.readBegin("positions");
    for (label k = 0; k < n; ++k)
    {
        point x;
        label celli;
        is >> x >> celli;
        const label i =
            (id[k] >= 0 && id[k] < indexOfId.size()) ? indexOfId[id[k]] : -1;
        if (i < 0)
        {
            FatalIOErrorInFunction(is)
                << "Particle id " << id[k] << " of cloud " << cloudName
                << " is not one that system/particleDict generates: was"
                << " particleDict changed since the run started?"
                << exit(FatalIOError);
        }
        cloud.x()[i] = vector2D(x.x(), x.y());
        cloud.U()[i] = vector2D(U[k].x(), U[k].y());
        cloud.p()[i] = p[k];
        found[i] = true;
    }
    is.readEnd("positions");
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::lagrangianCloudReader::lagrangianCloudReader(const polyMesh& mesh)
:
    mesh_(mesh)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::lagrangianCloudReader::found() const
{
    const fileName dir
    (
        mesh_.time().path()/mesh_.time().timeName()/cloud::prefix
    );
    for (const word& c : {"fluid", "wall", "structure"})
    {
        if (isFile(dir/c/"positions"))
        {
            return true;
        }
    }
    return false;
}


void Foam::lagrangianCloudReader::read(mpsCloud& cloud) const
{
    // Ids are given at generation, before coincident particles are dropped:
    // they are unique but not contiguous
    label maxId = -1;
    for (const label id : cloud.id())
    {
        maxId = max(maxId, id);
    }
    labelList indexOfId(maxId + 1, -1);
    forAll(cloud.id(), i)
    {
        indexOfId[cloud.id()[i]] = i;
    }

    List<bool> found(cloud.size(), false);
    for (const word& c : {"fluid", "wall", "structure"})
    {
        readCloud(c, cloud, indexOfId, found);
    }

    label nMissing = 0;
    for (const bool f : found)
    {
        nMissing += !f;
    }
    if (nMissing)
    {
        Info<< "    " << nMissing << " generated particles are not in the"
            << " written clouds (they had left the domain): removed" << nl;
        cloud.subset(found);
    }
}


// ************************************************************************* //
