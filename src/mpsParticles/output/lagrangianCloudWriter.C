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
// current time's folder whatever its instance says)
static void writeInto(const regIOobject& obj, const fileName& folder)
{
    const Time& runTime = obj.time();
    const fileName file(staged(obj, folder));
    mkDir(file.path());
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
    if (!os.good())
    {
        FatalErrorInFunction
            << "Cannot write " << os.name() << exit(FatalError);
    }
}


template<class Type>
static void writeFields
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
        writeInto(fld, folder);
    }
}

} // End namespace Foam


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::lagrangianCloudWriter::lagrangianCloudWriter(const polyMesh& mesh)
:
    mesh_(mesh)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::lagrangianCloudWriter::write
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
        mkDir(file.path());
        OFstream os(file);
        io.writeHeader(os, "Cloud<passiveParticle>");

        const pointField& x = cloud.positions();
        os  << x.size() << nl << token::BEGIN_LIST << nl;
        for (const point& p : x)
        {
            os  << p << token::SPACE << mesh_.findCell(p) << nl;
        }
        os  << token::END_LIST << nl;
        IOobject::writeEndDivider(os);
    }

    writeFields(mesh_, instance, folder, local, cloud.vectorFields());
    writeFields(mesh_, instance, folder, local, cloud.scalarFields());
    writeFields(mesh_, instance, folder, local, cloud.labelFields());

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
    writeInto(props, folder);
}


// ************************************************************************* //
