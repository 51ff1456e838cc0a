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

#include "vtkCloudWriter.H"
#include "writeChecks.H"
#include "foamVtkOutput.H"
#include "foamVtkOutputOptions.H"
#include "IFstream.H"
#include "OSspecific.H"
#include "Pstream.H"
#include <fstream>
#include <regex>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace Foam
{

template<class Type>
static void writeVtkFields
(
    vtk::formatter& format,
    const HashTable<Field<Type>>& fields,
    const label n
)
{
    constexpr direction nCmpt = pTraits<Type>::nComponents;

    for (const word& name : fields.sortedToc())
    {
        if (std::is_same<label, typename pTraits<Type>::cmptType>::value)
        {
            format.beginDataArray<label, nCmpt>(name);
            format.writeSize(vtk::sizeofData<label, nCmpt>(n));
        }
        else
        {
            format.beginDataArray<float, nCmpt>(name);
            format.writeSize(vtk::sizeofData<float, nCmpt>(n));
        }
        vtk::writeList(format, fields[name]);
        format.flush();
        format.endDataArray();
    }
}

} // End namespace Foam


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::vtkCloudWriter::readSeries(const word& cloudName)
{
    DynamicList<Tuple2<scalar, word>>& entries = series_(cloudName);

    const fileName pvd(dir_/cloudName + ".pvd");
    std::ifstream is(pvd);
    if (!is.good())
    {
        return;
    }

    const scalar startTime = runTime_.startTime().value();
    const std::regex entryRe
    (
        "timestep=\"([^\"]+)\".*file=\"([^\"]+)\""
    );
    std::string line;
    while (std::getline(is, line))
    {
        std::smatch m;
        if (std::regex_search(line, m, entryRe))
        {
            const scalar t = std::stod(m[1].str());
            if (t < startTime + 0.5*runTime_.deltaTValue())
            {
                entries.append(Tuple2<scalar, word>(t, word(m[2].str())));
            }
        }
    }
}


Foam::fileName Foam::vtkCloudWriter::writeSeries
(
    const word& cloudName
) const
{
    // Written under a temporary name and renamed when complete
    const fileName pvd(dir_/cloudName + ".pvd");
    {
        std::ofstream os(pvd + ".tmp");
        os  << "<?xml version=\"1.0\"?>\n"
            << "<VTKFile type=\"Collection\" version=\"0.1\""
            << " byte_order=\"LittleEndian\">\n"
            << "  <Collection>\n";
        os.precision(12);
        // Pieces of one time (one per rank under -parallel) are its parts
        label part = 0;
        scalar lastTime = -GREAT;
        for (const auto& e : series_[cloudName])
        {
            part = (e.first() == lastTime) ? part + 1 : 0;
            lastTime = e.first();
            os  << "    <DataSet timestep=\"" << e.first()
                << "\" group=\"\" part=\"" << part << "\" file=\""
                << e.second().c_str() << "\"/>\n";
        }
        os  << "  </Collection>\n"
            << "</VTKFile>\n";
        if (!writeChecks::flushed(os))
        {
            Foam::rm(pvd + ".tmp");
            return pvd;
        }
    }
    Foam::mv(pvd + ".tmp", pvd);
    return fileName();
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::vtkCloudWriter::vtkCloudWriter(const Time& runTime)
:
    runTime_(runTime),
    dir_(runTime.globalPath()/"VTK"),
    series_()
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::fileName Foam::vtkCloudWriter::write(const cloudFields& cloud)
{
    const word& name = cloud.name();
    if (!series_.found(name) && Pstream::master())
    {
        readSeries(name);
    }

    mkDir(dir_);
    // Under -parallel each rank writes its piece
    const word stem(name + "_" + Foam::name(runTime_.timeIndex()));
    auto pieceName = [&stem](const label proci)
    {
        return
            Pstream::parRun()
          ? word(stem + "_processor" + Foam::name(proci) + ".vtp")
          : word(stem + ".vtp");
    };
    const word file(pieceName(Pstream::myProcNo()));
    const label n = cloud.size();
    bool written = false;

    {
        std::ofstream os(dir_/file + ".tmp");
        autoPtr<vtk::formatter> format =
            vtk::outputOptions(vtk::formatType::INLINE_BASE64)
           .newFormatter(os);

        format()
            .xmlHeader()
            .beginVTKFile<vtk::fileTag::POLY_DATA>();

        format()
            .beginFieldData()
            .writeTimeValue(runTime_.value())
            .endFieldData();

        format().tag
        (
            vtk::fileTag::PIECE,
            vtk::fileAttr::NUMBER_OF_POINTS, n,
            vtk::fileAttr::NUMBER_OF_VERTS, n
        );

        format().tag(vtk::fileTag::POINTS)
            .beginDataArray<float, 3>(vtk::dataArrayAttr::POINTS);
        format().writeSize(vtk::sizeofData<float, 3>(n));
        vtk::writeList(format(), cloud.positions());
        format().flush();
        format().endDataArray();
        format().endTag(vtk::fileTag::POINTS);

        // One vertex cell per particle
        format().tag(vtk::fileTag::VERTS);
        format().beginDataArray<label>(vtk::dataArrayAttr::CONNECTIVITY);
        format().writeSize(vtk::sizeofData<label>(n));
        vtk::writeIdentity(format(), n);
        format().flush();
        format().endDataArray();
        format().beginDataArray<label>(vtk::dataArrayAttr::OFFSETS);
        format().writeSize(vtk::sizeofData<label>(n));
        vtk::writeIdentity(format(), n, 1);
        format().flush();
        format().endDataArray();
        format().endTag(vtk::fileTag::VERTS);

        format().beginPointData();
        writeVtkFields(format(), cloud.vectorFields(), n);
        writeVtkFields(format(), cloud.scalarFields(), n);
        writeVtkFields(format(), cloud.labelFields(), n);
        format().endPointData();

        format().endPiece();
        format().endTag(vtk::fileTag::POLY_DATA).endVTKFile();
        written = writeChecks::flushed(os);
    }
    if (written)
    {
        Foam::mv(dir_/file + ".tmp", dir_/file);
    }
    else
    {
        Foam::rm(dir_/file + ".tmp");
    }

    // The series: the master's, once every piece is in place
    bool all = written;
    reduce(all, andOp<bool>());
    if (!written)
    {
        return dir_/file;
    }
    if (!all)
    {
        return dir_/stem + "_processor*.vtp";
    }
    if (!Pstream::master())
    {
        return fileName();
    }

    // The run writes from this time on: entries of an earlier run at this
    // time or later go (as its files are overwritten, index by index)
    DynamicList<Tuple2<scalar, word>>& entries = series_(name);
    const scalar tol = 1e-9*max(runTime_.deltaTValue(), VSMALL);
    while (entries.size() && entries.last().first() > runTime_.value() - tol)
    {
        entries.remove();
    }
    for (label proci = 0; proci < Pstream::nProcs(); ++proci)
    {
        entries.append
        (
            Tuple2<scalar, word>(runTime_.value(), pieceName(proci))
        );
    }
    return writeSeries(name);
}


bool Foam::vtkCloudWriter::listed(const word& cloudName)
{
    bool found = false;
    if (Pstream::master())
    {
        if (!series_.found(cloudName))
        {
            readSeries(cloudName);
        }
        const scalar tol = 1e-9*max(runTime_.deltaTValue(), VSMALL);
        for (const Tuple2<scalar, word>& e : series_[cloudName])
        {
            found = found
                || (
                       mag(e.first() - runTime_.value()) < tol
                    && isFile(dir_/e.second())
                   );
        }
    }
    Pstream::scatter(found);
    return found;
}


// ************************************************************************* //
