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

#include "lagrangianCloudWriter.H"
#include "cloud.H"
#include "IOField.H"
#include "IOdictionary.H"
#include "OFstream.H"
#include "Time.H"
#include "Pstream.H"
#include "writeChecks.H"
#include "indexedOctree.H"
#include "treeDataCell.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace Foam
{

// Where an object goes: in the folder (under the case) in place of its
// instance, which its header names as its location
static fileName staged(const IOobject& io, const fileName& folder)
{
    return io.time().path()/folder/io.db().dbDir()/io.local()/io.name();
}


// Write an object into the folder (regIOobject::write would put it in the
// current time's folder whatever its instance says); the file's name if
// it could not be written, empty if it was
static fileName writeInto(const regIOobject& obj, const fileName& folder)
{
    const Time& runTime = obj.time();
    const fileName file(staged(obj, folder));
    if (!isDir(file.path()) && !mkDir(file.path()))
    {
        return file.path();
    }
    OFstream os
    (
        file,
        runTime.writeFormat(),
        IOstream::currentVersion,
        runTime.writeCompression()
    );
    obj.writeHeader(os);
    obj.writeData(os);
    IOobject::writeEndDivider(os);
    return writeChecks::flushed(os) ? fileName() : file;
}


template<class Type>
static fileName writeFields
(
    const objectRegistry& db,
    const fileName& instance,
    const fileName& folder,
    const fileName& local,
    const HashTable<Field<Type>>& fields
)
{
    forAllConstIters(fields, iter)
    {
        IOField<Type> fld
        (
            IOobject
            (
                iter.key(),
                instance,
                local,
                db,
                IOobject::NO_READ,
                IOobject::NO_WRITE,
                false
            ),
            iter.val()
        );
        const fileName failed(writeInto(fld, folder));
        if (!failed.empty())
        {
            return failed;
        }
    }
    return fileName();
}

} // End namespace Foam


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::lagrangianCloudWriter::lagrangianCloudWriter(const polyMesh& mesh)
:
    mesh_(mesh)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::labelList Foam::lagrangianCloudWriter::cells
(
    const word& name,
    const UList<point>& x
) const
{
    // polyMesh::findCell would try the nearest cell centre (of all cells)
    // and then every cell for a point outside the mesh; the octree tries
    // the ten or so cells of a leaf, the hint one
    const indexedOctree<treeDataCell>& tree = mesh_.cellTree();
    labelList& hint = cellHints_(name);
    labelList c(x.size());
    forAll(x, i)
    {
        const label h = (i < hint.size()) ? hint[i] : -1;
        c[i] =
            (h >= 0 && mesh_.pointInCell(x[i], h, polyMesh::CELL_TETS))
          ? h
          : tree.findInside(x[i]);
    }
    hint = c;
    return c;
}


Foam::fileName Foam::lagrangianCloudWriter::write
(
    const cloudFields& cloud,
    const fileName& instance,
    const fileName& folder
) const
{
    const fileName local(cloud::prefix/cloud.name());

    // positions: "(x y z) celli", always ASCII so every reader parses it
    {
        IOobject io
        (
            "positions",
            instance,
            local,
            mesh_,
            IOobject::NO_READ,
            IOobject::NO_WRITE,
            false
        );
        const fileName file(staged(io, folder));
        if (!isDir(file.path()) && !mkDir(file.path()))
        {
            return file.path();
        }
        OFstream os(file);
        io.writeHeader(os, "Cloud<passiveParticle>");

        const pointField& x = cloud.positions();
        const labelList c
        (
            cloud.cells().size() == x.size()
          ? cloud.cells()
          : cells(cloud.name(), x)
        );
        os  << x.size() << nl << token::BEGIN_LIST << nl;
        forAll(x, i)
        {
            os  << x[i] << token::SPACE << c[i] << nl;
        }
        os  << token::END_LIST << nl;
        IOobject::writeEndDivider(os);
        if (!writeChecks::flushed(os))
        {
            return file;
        }
    }

    fileName failed
    (
        writeFields(mesh_, instance, folder, local, cloud.vectorFields())
    );
    if (failed.empty())
    {
        failed = writeFields(mesh_, instance, folder, local, cloud.scalarFields());
    }
    if (failed.empty())
    {
        failed = writeFields(mesh_, instance, folder, local, cloud.labelFields());
    }
    if (!failed.empty())
    {
        return failed;
    }

    // uniform/lagrangian/<cloud>/cloudProperties
    IOdictionary props
    (
        IOobject
        (
            "cloudProperties",
            instance,
            "uniform"/local,
            mesh_,
            IOobject::NO_READ,
            IOobject::NO_WRITE,
            false
        )
    );
    props.add("geometry", word("positions"));
    props.add("regions", cloud.regionNames());   // the field region's names
    dictionary procDict;
    procDict.add("particleCount", cloud.size());
    props.add
    (
        word("processor" + Foam::name(Pstream::myProcNo())),
        procDict
    );
    return writeInto(props, folder);
}


// ************************************************************************* //
