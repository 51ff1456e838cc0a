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
#include "outputClouds.H"
#include "cloud.H"
#include "IOField.H"
#include "IFstream.H"
#include "passiveParticle.H"
#include <algorithm>
#include "Time.H"
#include "mpsDecomposition.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::lagrangianCloudReader::readCloud
(
    const word& cloudName,
    mpsCloud& cloud,
    List<bool>& found,
    DynamicList<label>& order
) const
{
    const fileName local(cloud::prefix/cloudName);
    const word& timeName = mesh_.time().timeName();
    const fileName dir(mesh_.time().path()/timeName/local);
    // The positions as the solver and reconstructPar write them, or
    // OpenFOAM's barycentric coordinates alone (decomposePar writes those:
    // a serial time decomposed to continue under -parallel)
    const bool barycentric = !isFile(dir/"positions");
    const word posName(barycentric ? "coordinates" : "positions");
    if (!isFile(dir/posName))
    {
        return;
    }

    auto io = [&](const word& name) { return fieldIO(cloudName, name); };

    const IOField<label> id(io("id"));

    // positions: "(x y z) celli" entries; coordinates: OpenFOAM's
    // particles (barycentric coordinates in a tet of a cell), located by
    // OpenFOAM's own particle
    IFstream is(dir/posName);
    IOobject posIO(io(posName));
    if (!posIO.readHeader(is))
    {
        FatalIOErrorInFunction(is)
            << "Cannot read the header of " << is.name()
            << exit(FatalIOError);
    }
    const label n = readLabel(is);
    if (n != id.size())
    {
        FatalIOErrorInFunction(is)
            << "Cloud " << cloudName << " at time " << timeName << " has "
            << n << " positions but " << id.size() << " ids"
            << exit(FatalIOError);
    }
    labelList index(n);
    is.readBegin(posName.c_str());
    for (label k = 0; k < n; ++k)
    {
        point x;
        if (barycentric)
        {
            const passiveParticle p(mesh_, is, false, true);
            x = p.position();
        }
        else
        {
            label celli;
            is >> x >> celli;
        }
        const label i = cloud.index(id[k]);
        if (i < 0)
        {
            FatalIOErrorInFunction(is)
                << "Particle id " << id[k] << " of cloud " << cloudName
                << " is not one that system/particleDict generates: was"
                << " particleDict changed since the run started?"
                << exit(FatalIOError);
        }
        if (found[i])
        {
            FatalIOErrorInFunction(is)
                << "Particle id " << id[k] << " of cloud " << cloudName
                << " is written twice" << exit(FatalIOError);
        }
        cloud.x()[i] = vector2D(x.x(), x.y());
        index[k] = i;
        found[i] = true;
        order.append(i);
    }
    is.readEnd(posName.c_str());

    // The fields marked for a restart that mean something for the cloud's
    // kinds (the cloud's writer wrote those)
    for (mpsCloudField& f : cloud.fields())
    {
        bool applies = false;
        for (int k = 0; k < nParticleKinds; ++k)
        {
            applies = applies
             || (
                    f.appliesTo(particleKind(k))
                 && outputClouds::holds(cloudName, particleKind(k))
                );
        }
        if (f.restart() && applies)
        {
            f.read(io(f.name()), index);
        }
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::lagrangianCloudReader::lagrangianCloudReader(const polyMesh& mesh)
:
    mesh_(mesh)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::IOobject Foam::lagrangianCloudReader::fieldIO
(
    const word& cloudName,
    const word& fieldName
) const
{
    return IOobject
    (
        fieldName,
        mesh_.time().timeName(),
        cloud::prefix/cloudName,
        mesh_,
        IOobject::MUST_READ,
        IOobject::NO_WRITE,
        false
    );
}


bool Foam::lagrangianCloudReader::hasClouds(const fileName& timeDir)
{
    for (const word& c : outputClouds::names())
    {
        const fileName dir(timeDir/cloud::prefix/c);
        if (isFile(dir/"positions") || isFile(dir/"coordinates"))
        {
            return true;
        }
    }
    return false;
}


bool Foam::lagrangianCloudReader::found() const
{
    return hasClouds(mesh_.time().path()/mesh_.time().timeName());
}


void Foam::lagrangianCloudReader::checkComplete(const mpsCloud& cloud) const
{
    const fileName dir
    (
        mesh_.time().path()/mesh_.time().timeName()/cloud::prefix
    );
    for (const word& c : outputClouds::names())
    {
        label count = 0;
        for (int k = 0; k < nParticleKinds; ++k)
        {
            if (outputClouds::holds(c, particleKind(k)))
            {
                count += cloud.count(particleKind(k));
            }
        }
        const fileName positions(dir/c/"positions");
        // (under -parallel on some processor: decomposePar writes no
        // cloud where a processor has none of its particles)
        bool present = isFile(positions) || isFile(dir/c/"coordinates");
        reduce(present, orOp<bool>());
        if (count && !present)
        {
            FatalErrorInFunction
                << "Cannot continue from time " << mesh_.time().timeName()
                << ": it has no cloud " << c << " (no file " << positions
                << "), where system/particleDict makes " << count
                << " particles of it." << nl
                << "Start from a time that has every cloud, or from 0 (the"
                << " particles generated anew)" << exit(FatalError);
        }
    }
}


void Foam::lagrangianCloudReader::read(mpsCloud& cloud) const
{
    List<bool> found(cloud.size(), false);
    DynamicList<label> order(cloud.size());
    for (const word& c : outputClouds::names())
    {
        readCloud(c, cloud, found, order);
    }

    // Under -parallel each rank read the particles it wrote, and holds
    // all of the replicated kinds (the structure reads its state itself)
    const bool par = Pstream::parRun();
    label nMissing = 0;
    forAll(found, i)
    {
        if (par && mpsDecomposition::replicated(cloud.kind()[i]))
        {
            found[i] = true;
        }
        else if (par)
        {
            // Counted once (every rank generated every particle)
            nMissing += (Pstream::master() ? 1 : 0) - found[i];
        }
        else
        {
            nMissing += !found[i];
        }
    }
    reduce(nMissing, sumOp<label>());
    if (nMissing)
    {
        Info<< "    " << nMissing << " generated particles are not in the"
            << " written clouds (they had left the domain): removed" << nl;
    }

    // A serial run keeps the generated order (as the written run had it:
    // it writes in the order of the cells). Under -parallel the particles
    // in the order this rank wrote them (its cloud's), so that the run
    // continues with the sums over neighbours in the order the written run
    // had them: a restart continues exactly; the replicated kinds in the
    // generated order, as they always are
    if (!par)
    {
        if (found.found(false))
        {
            cloud.subset(found);
        }
        return;
    }
    DynamicList<label> from(order.size());
    for (const label i : order)
    {
        if (!mpsDecomposition::replicated(cloud.kind()[i]))
        {
            from.append(i);
        }
    }
    forAll(found, i)
    {
        if (mpsDecomposition::replicated(cloud.kind()[i]))
        {
            from.append(i);
        }
    }
    // (kinds in order: a cloud that decomposePar split by cells may hold
    // the wall cloud's wall and dummy particles mixed)
    std::stable_sort
    (
        from.begin(),
        from.end(),
        [&cloud](const label a, const label b)
        {
            return int(cloud.kind()[a]) < int(cloud.kind()[b]);
        }
    );
    cloud.reorder(from);
}


// ************************************************************************* //
