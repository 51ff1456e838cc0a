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

#include <omp.h>
#include <charconv>
#include <locale>
#include <sstream>
#include <string>
#include <vector>

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
// current time's folder whatever its instance says): its header, its data
// as writeData(os) writes it (the object's own, or the given one); the
// file's name if it could not be written, empty if it was
template<class WriteData>
static fileName writeInto
(
    const regIOobject& obj,
    const fileName& folder,
    const WriteData& writeData
)
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
    writeData(os);
    IOobject::writeEndDivider(os);
    return writeChecks::flushed(os) ? fileName() : file;
}


static fileName writeInto(const regIOobject& obj, const fileName& folder)
{
    return writeInto(obj, folder, [&obj](OSstream& os) { obj.writeData(os); });
}


// Whether the stream writes numbers as printf's %g at its precision (no
// format flags, no width, the C locale's point): std::to_chars then gives
// the same bytes (C++17 defines its general format as printf's %g)
static bool plainNumbers(const std::ostream& s)
{
    const std::ios::fmtflags f = s.flags();
    const std::numpunct<char>& punct =
        std::use_facet<std::numpunct<char>>(s.getloc());
    return
        !(
            f
          & (
                std::ios::floatfield | std::ios::showpoint
              | std::ios::showpos | std::ios::uppercase | std::ios::showbase
            )
        )
     && (f & std::ios::basefield) == std::ios::dec
     && s.width() == 0
     && s.precision() > 0 && s.precision() <= 30
     && punct.decimal_point() == '.' && punct.grouping().empty();
}


// Appends numbers to a text as a plain stream (plainNumbers) writes them,
// by std::to_chars: some three times faster than std::ostream's <<
class plainText
{
    std::string& text_;
    const int precision_;

public:

    plainText(std::string& text, const int precision)
    :
        text_(text),
        precision_(precision)
    {}

    plainText& operator<<(const char c)
    {
        text_ += c;
        return *this;
    }

    plainText& operator<<(const double v)
    {
        char buf[64];
        text_.append
        (
            buf,
            std::to_chars
            (
                buf, buf + sizeof(buf), v, std::chars_format::general,
                precision_
            ).ptr
        );
        return *this;
    }

    template<class Int>
    plainText& appendInteger(const Int v)
    {
        char buf[24];
        text_.append(buf, std::to_chars(buf, buf + sizeof(buf), v).ptr);
        return *this;
    }

    plainText& operator<<(const int v)
    {
        return appendInteger(v);
    }

    plainText& operator<<(const long v)
    {
        return appendInteger(v);
    }
};


// One value as OSstream writes it (std::ostream's << at the stream's
// precision; a vector as "(x y z)"), into a stream or a plainText
template<class Sink, class Type>
static void formatValue(Sink& s, const Type& v)
{
    s << v;
}

template<class Sink>
static void formatValue(Sink& s, const vector& v)
{
    s << '(' << v.x() << ' ' << v.y() << ' ' << v.z() << ')';
}


// Lines 0..n-1 of a list, formatted on the threads (each a block of them
// into its own text, as the stream would format them) and written in
// order: the same bytes as one thread writing them, in a fraction of the
// time (a write of the wedge's clouds is some 400,000 numbers)
template<class Line>
static void writeLines(OSstream& os, const label n, const Line& line)
{
    std::ostream& out = os.stdStream();
    const bool plain = plainNumbers(out);
    std::vector<std::string> text(omp_get_max_threads());

    #pragma omp parallel num_threads(text.size())
    {
        const label t = omp_get_thread_num();
        const label nt = omp_get_num_threads();
        const label first = n*t/nt, last = n*(t + 1)/nt;
        if (plain)
        {
            plainText s(text[t], out.precision());
            for (label i = first; i < last; ++i)
            {
                line(s, i);
            }
        }
        else
        {
            std::ostringstream s;
            s.copyfmt(out);
            for (label i = first; i < last; ++i)
            {
                line(s, i);
            }
            text[t] = s.str();
        }
    }
    for (const std::string& t : text)
    {
        out.write(t.data(), t.size());
    }
}


// A field into the folder as writeInto writes it: a list of more than ten
// values not all the same, in ASCII, as UList::writeList writes it (size,
// one value a line) but formatted by writeLines; any other by OpenFOAM
template<class Type>
static fileName writeFieldInto(const IOField<Type>& fld, const fileName& folder)
{
    if
    (
        fld.time().writeFormat() != IOstream::ASCII
     || fld.size() <= 10
     || fld.uniform()
    )
    {
        return writeInto(fld, folder);
    }
    return writeInto
    (
        fld,
        folder,
        [&fld](OSstream& os)
        {
            os  << nl << fld.size() << nl << token::BEGIN_LIST << nl;
            writeLines
            (
                os,
                fld.size(),
                [&fld](auto& s, const label i)
                {
                    formatValue(s, fld[i]);
                    s << '\n';
                }
            );
            os  << token::END_LIST << nl;
        }
    );
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
        const fileName failed(writeFieldInto(fld, folder));
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

    // The tests read only the mesh's geometry and the tree: what the mesh
    // computes on demand is computed here, before the threads share it
    (void)mesh_.cells();
    (void)mesh_.cellCentres();
    (void)mesh_.faceCentres();
    (void)mesh_.tetBasePtIs();

    #pragma omp parallel for schedule(static)
    for (label i = 0; i < x.size(); ++i)
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
        writeLines
        (
            os,
            x.size(),
            [&x, &c](auto& s, const label i)
            {
                formatValue(s, x[i]);
                s << ' ' << c[i] << '\n';
            }
        );
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
