/*---------------------------------------------------------------------------*\
  mpsFsiFoam test helper: readCloud

  Reads an OpenFOAM case with VTK's own OpenFOAM reader (vtkOpenFOAMReader,
  the reader behind ParaView's "OpenFOAMReader" / paraFoam -builtin) and
  checks a lagrangian cloud in it; or reads a VTK XML PolyData particle
  file (.vtp, vtkXMLPolyDataReader) directly or through a ParaView
  collection (.pvd) and checks it the same way.

  Usage:
      readCloud <case>/<name>.foam <time> <cloud> <expectedCount>
                [<field> <expectedMin> <expectedMax>]...
      readCloud <case>/<name>.foam <time> --list
      readCloud <file>.vtp <expectedCount>
                [<field> <expectedMin> <expectedMax>]...
      readCloud <file>.pvd <time> <expectedCount>
                [<field> <expectedMin> <expectedMax>]...
      readCloud <file>.pvd --list

  The mode is chosen by the first argument: ending in ".vtp" or ".pvd" as
  above, anything else is read as an OpenFOAM case (.foam).

  For every check one line is printed, "... OK" or "FAILED: ...".
  Exit status: 0 all checks passed, 1 a check failed, 2 bad arguments.

  Each <field> is a point-data array of the cloud (one per lagrangian field
  file); it must exist, have <expectedCount> tuples, and the minimum and
  maximum over all of its components must lie in [expectedMin, expectedMax].
  The pseudo-field "positions" checks the particle coordinates.
  The reader stores floating-point values as 32-bit floats, so the bounds
  are widened by 1e-6 relative (|bound|*1e-6) for the comparison (the same
  in all modes; .vtp files hold Float32 data too).

  .foam mode - reader settings: 0/ is not skipped (ParaView skips it by
  default), the cloud's patch entry "lagrangian/<cloud>" and all lagrangian
  arrays are enabled, labels 32 bit and scalars 64 bit
  (linux64GccDPInt32Opt), "positions" in the "(x y z) celli" form
  (PositionsIsIn13Format) that OpenFOAM v1912 writes. Errors reported by
  VTK while reading count as a failed check (in all modes).

  The reader offers a cloud only if some time directory has
  lagrangian/<cloud>/positions (the "coordinates" file is not read), and
  only if the case has a mesh (constant/polyMesh). At a time without the
  cloud's files the cloud block is empty (0 points). With expectedCount 0 a
  cloud that the reader does not offer at all passes.

  .vtp mode: besides the point count and the fields, checks that there is
  one vertex cell per point (GetNumberOfVerts() == expectedCount) and that
  the FieldData array "TimeValue" exists (its value is printed).

  .pvd mode: the collection is parsed with vtkXMLDataParser. --list prints
  every DataSet's timestep and file. Otherwise the DataSet whose timestep
  matches <time> (|t - time| <= 1e-9*max(1, |time|)) is looked up, its file
  resolved relative to the .pvd's folder (unless absolute) and checked as
  in the .vtp mode. A time that is not listed, several DataSets (parts) at
  that time, or a missing file fail.
\*---------------------------------------------------------------------------*/

#include <vtkCellData.h>
#include <vtkCompositeDataSet.h>
#include <vtkDataArray.h>
#include <vtkDataArraySelection.h>
#include <vtkDataSet.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkLogger.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkOpenFOAMReader.h>
#include <vtkOutputWindow.h>
#include <vtkPointData.h>
#include <vtkPointSet.h>
#include <vtkPolyData.h>
#include <vtkPoints.h>
#include <vtkStreamingDemandDrivenPipeline.h>
#include <vtkStringArray.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLDataParser.h>
#include <vtkXMLPolyDataReader.h>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <iostream>
#include <limits>
#include <sstream>
#include <string>
#include <sys/stat.h>
#include <vector>

namespace
{

// Counts (and echoes to stderr) the errors and warnings VTK reports
class CountingOutputWindow : public vtkOutputWindow
{
public:
    static CountingOutputWindow* New();
    vtkTypeMacro(CountingOutputWindow, vtkOutputWindow);

    int nErrors = 0;
    int nWarnings = 0;
    std::vector<std::string> errors;

    void DisplayText(const char* txt) override
    {
        std::cerr << "VTK: " << (txt ? txt : "") << std::flush;
    }
    void DisplayErrorText(const char* txt) override
    {
        ++nErrors;
        errors.emplace_back(txt ? txt : "");
        std::cerr << "VTK error: " << (txt ? txt : "") << std::flush;
    }
    void DisplayWarningText(const char* txt) override
    {
        ++nWarnings;
        std::cerr << "VTK warning: " << (txt ? txt : "") << std::flush;
    }
    void DisplayGenericWarningText(const char* txt) override
    {
        DisplayWarningText(txt);
    }
    void DisplayDebugText(const char* txt) override
    {
        std::cerr << "VTK debug: " << (txt ? txt : "") << std::flush;
    }
};
vtkStandardNewMacro(CountingOutputWindow);


void usage(const char* prog)
{
    std::cerr
        << "Usage:\n"
        << "  " << prog << " <case>/<name>.foam <time> <cloud> <expectedCount>"
           " [<field> <expectedMin> <expectedMax>]...\n"
        << "  " << prog << " <case>/<name>.foam <time> --list\n"
        << "  " << prog << " <file>.vtp <expectedCount>"
           " [<field> <expectedMin> <expectedMax>]...\n"
        << "  " << prog << " <file>.pvd <time> <expectedCount>"
           " [<field> <expectedMin> <expectedMax>]...\n"
        << "  " << prog << " <file>.pvd --list\n"
        << "\n"
        << "Reads the case with VTK's vtkOpenFOAMReader (as ParaView does) and"
           " checks\nthe lagrangian cloud <cloud> at time <time>: number of"
           " particles and, per\n<field> (a lagrangian field, or 'positions'),"
           " that min and max over all\ncomponents lie in"
           " [<expectedMin>, <expectedMax>].\n"
        << "--list prints every block, its point count and array names.\n"
        << "A .vtp file (VTK XML PolyData) is read with vtkXMLPolyDataReader"
           " and checked\nthe same way, plus one vertex per point and a"
           " FieldData array 'TimeValue'.\n"
        << "A .pvd collection: the file of the DataSet with timestep <time>"
           " (relative to\nthe .pvd's folder) is checked as a .vtp;"
           " --list prints every timestep and file.\n"
        << "Exit status: 0 all OK, 1 a check failed, 2 bad arguments.\n";
}


bool parseDouble(const char* s, double& val)
{
    if (!s || !*s) return false;
    errno = 0;
    char* end = nullptr;
    val = std::strtod(s, &end);
    return errno == 0 && end && *end == '\0';
}


bool parseCount(const char* s, long long& val)
{
    if (!s || !*s) return false;
    errno = 0;
    char* end = nullptr;
    val = std::strtoll(s, &end, 10);
    return errno == 0 && end && *end == '\0' && val >= 0;
}


std::string fmt(double v)
{
    std::ostringstream os;
    os.precision(10);
    os << v;
    return os.str();
}


// Visit every leaf of a multiblock, with its "/"-separated block-name path
struct Leaf
{
    std::string path;
    std::string name;
    vtkDataObject* obj;
};

void collectLeaves
(
    vtkMultiBlockDataSet* mb,
    const std::string& prefix,
    std::vector<Leaf>& leaves
)
{
    if (!mb) return;
    for (unsigned i = 0; i < mb->GetNumberOfBlocks(); ++i)
    {
        std::string name;
        if (mb->HasMetaData(i))
        {
            const char* n =
                mb->GetMetaData(i)->Get(vtkCompositeDataSet::NAME());
            if (n) name = n;
        }
        if (name.empty()) name = "block" + std::to_string(i);

        const std::string path = prefix.empty() ? name : prefix + "/" + name;
        vtkDataObject* obj = mb->GetBlock(i);

        if (auto* sub = vtkMultiBlockDataSet::SafeDownCast(obj))
        {
            collectLeaves(sub, path, leaves);
        }
        else
        {
            leaves.push_back({path, name, obj});
        }
    }
}


bool endsWith(const std::string& s, const std::string& tail)
{
    return
        s.size() >= tail.size()
     && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}


// The message line of a (multi-line) VTK error, trimmed: the first
// non-empty line that is not the "ERROR: In <file>, line <n>" locator
std::string firstLine(const std::string& msg)
{
    std::istringstream is(msg);
    std::string line;
    while (std::getline(is, line))
    {
        const auto b = line.find_first_not_of(" \t\r");
        if (b == std::string::npos) continue;
        const auto e = line.find_last_not_of(" \t\r");
        line = line.substr(b, e - b + 1);
        if (line.compare(0, 10, "ERROR: In ") == 0) continue;
        return line;
    }
    return msg;
}


struct FieldCheck
{
    std::string name;
    double min;
    double max;
};

using FailFn = std::function<void(const std::string&)>;

// Checks the point count of ds: "<label>: <n> points (expected <m>)"
// label is "cloud <name>" or "file <path>"
void checkPointCount
(
    vtkDataSet* ds,
    const std::string& label,
    const long long expectedCount,
    const FailFn& fail
)
{
    const vtkIdType nPoints = ds->GetNumberOfPoints();
    std::ostringstream os;
    os  << label << ": " << nPoints << " points (expected "
        << expectedCount << ")";
    if (nPoints == expectedCount)
        std::cout << os.str() << " OK" << std::endl;
    else
        fail(os.str());
}


// Checks the point-data fields (or "positions") of ds, one line each;
// label names ds in messages
void checkFields
(
    vtkDataSet* ds,
    const std::string& label,
    const long long expectedCount,
    const std::vector<FieldCheck>& fields,
    const FailFn& fail
)
{
    vtkPointData* pd = ds->GetPointData();

    for (const FieldCheck& fc : fields)
    {
        vtkDataArray* arr = nullptr;
        if (fc.name == "positions")
        {
            auto* ps = vtkPointSet::SafeDownCast(ds);
            vtkPoints* pts = ps ? ps->GetPoints() : nullptr;
            arr = pts ? pts->GetData() : nullptr;
        }
        else
        {
            arr = pd->GetArray(fc.name.c_str());
        }

        const std::string what = "field " + fc.name;

        if (!arr)
        {
            std::string names;
            for (int a = 0; a < pd->GetNumberOfArrays(); ++a)
            {
                const char* n = pd->GetArrayName(a);
                names += (a ? ", " : "") + std::string(n ? n : "?");
            }
            fail
            (
                what + ": no such array on " + label
              + (pd->GetAbstractArray(fc.name.c_str())
                  ? " (exists but is not numeric)" : "")
              + " (arrays: " + (names.empty() ? "none" : names) + ")"
            );
            continue;
        }

        const vtkIdType nTuples = arr->GetNumberOfTuples();
        const int nComp = arr->GetNumberOfComponents();

        if (nTuples != expectedCount)
        {
            fail
            (
                what + ": " + std::to_string(nTuples)
              + " tuples (expected " + std::to_string(expectedCount) + ")"
            );
        }

        double lo = std::numeric_limits<double>::infinity();
        double hi = -std::numeric_limits<double>::infinity();
        vtkIdType nNan = 0;
        for (vtkIdType i = 0; i < nTuples; ++i)
        {
            for (int c = 0; c < nComp; ++c)
            {
                const double v = arr->GetComponent(i, c);
                if (std::isnan(v)) { ++nNan; continue; }
                if (v < lo) lo = v;
                if (v > hi) hi = v;
            }
        }

        // The reader stores floating-point fields as 32-bit floats:
        // allow their rounding on the bounds
        const double relTol = 1e-6;

        std::ostringstream rs;
        rs  << what << ": " << nTuples << " x " << nComp
            << " (" << arr->GetClassName() << "), range ["
            << fmt(lo) << ", " << fmt(hi) << "], expected within ["
            << fmt(fc.min) << ", " << fmt(fc.max) << "]";

        if (nNan)
        {
            fail(rs.str() + ", " + std::to_string(nNan) + " NaN value(s)");
        }
        else if
        (
            nTuples > 0
         && (
                lo < fc.min - relTol*std::fabs(fc.min)
             || hi > fc.max + relTol*std::fabs(fc.max)
            )
        )
        {
            fail(rs.str());
        }
        else if (nTuples == 0 && expectedCount != 0)
        {
            // already reported by the tuple count check
        }
        else
        {
            std::cout << rs.str() << " OK" << std::endl;
        }
    }
}

} // End anonymous namespace


// The .foam mode
int foamMode(int argc, char* argv[])
{
    const char* prog = "readCloud";

    // ---- arguments
    const bool listMode = (argc == 4 && std::strcmp(argv[3], "--list") == 0);

    if (!listMode && (argc < 5 || (argc - 5) % 3 != 0))
    {
        usage(prog);
        return 2;
    }

    const std::string foamFile = argv[1];
    const std::string timeArg = argv[2];
    double timeVal = 0;
    if (!parseDouble(argv[2], timeVal))
    {
        std::cerr << prog << ": bad time '" << argv[2] << "'\n\n";
        usage(prog);
        return 2;
    }

    std::string cloud;
    long long expectedCount = 0;
    std::vector<FieldCheck> fields;

    if (!listMode)
    {
        cloud = argv[3];
        if (!parseCount(argv[4], expectedCount))
        {
            std::cerr << prog << ": bad expectedCount '" << argv[4] << "'\n\n";
            usage(prog);
            return 2;
        }
        for (int i = 5; i + 2 < argc; i += 3)
        {
            FieldCheck fc;
            fc.name = argv[i];
            if
            (
                !parseDouble(argv[i+1], fc.min)
             || !parseDouble(argv[i+2], fc.max)
            )
            {
                std::cerr
                    << prog << ": bad range '" << argv[i+1] << "' '"
                    << argv[i+2] << "' for field " << fc.name << "\n\n";
                usage(prog);
                return 2;
            }
            fields.push_back(fc);
        }
    }

    {
        struct stat st;
        if (stat(foamFile.c_str(), &st) != 0)
        {
            std::cout
                << "FAILED: " << foamFile << " does not exist"
                << " (create an empty <case>/<name>.foam file)" << std::endl;
            return 1;
        }
    }

    // ---- capture VTK's messages
    vtkNew<CountingOutputWindow> outWin;
    vtkOutputWindow::SetInstance(outWin);
    // The messages go to the window above only (not also through vtkLogger)
    vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);

    int nFailed = 0;
    auto fail = [&nFailed](const std::string& msg)
    {
        ++nFailed;
        std::cout << "FAILED: " << msg << std::endl;
    };

    // Errors VTK reported count as a failed check
    auto vtkErrorsCheck = [&]()
    {
        if (outWin->nErrors)
        {
            fail
            (
                "VTK reported " + std::to_string(outWin->nErrors)
              + " error(s) while reading (see stderr), first: "
              + firstLine(outWin->errors.front())
            );
        }
    };

    // ---- reader, set up as ParaView's OpenFOAMReader (except SkipZeroTime)
    vtkNew<vtkOpenFOAMReader> reader;
    reader->SetFileName(foamFile.c_str());
    reader->SkipZeroTimeOff();
    reader->CreateCellToPointOn();
    reader->CacheMeshOn();
    // "positions" as OpenFOAM v1912 writes it: (x y z) celli
    reader->PositionsIsIn13FormatOn();
    reader->ListTimeStepsByControlDictOff();
    reader->SetUse64BitLabels(false);
    reader->SetUse64BitFloats(true);

    reader->UpdateInformation();

    // ---- available times
    vtkStringArray* timeNames = reader->GetTimeNames();
    vtkDoubleArray* timeValues = reader->GetTimeValues();
    const vtkIdType nTimes = timeValues ? timeValues->GetNumberOfTuples() : 0;

    std::string timeList;
    for (vtkIdType i = 0; i < nTimes; ++i)
    {
        timeList += (i ? " " : "");
        if (timeNames && i < timeNames->GetNumberOfValues())
            timeList += timeNames->GetValue(i);
        else
            timeList += fmt(timeValues->GetValue(i));
    }

    vtkIdType timeIndex = -1;
    for (vtkIdType i = 0; i < nTimes && timeIndex < 0; ++i)
    {
        if
        (
            timeNames && i < timeNames->GetNumberOfValues()
         && timeNames->GetValue(i) == timeArg
        )
        {
            timeIndex = i;
        }
    }
    for (vtkIdType i = 0; i < nTimes && timeIndex < 0; ++i)
    {
        const double t = timeValues->GetValue(i);
        if (std::fabs(t - timeVal) <= 1e-9*std::max(1.0, std::fabs(timeVal)))
        {
            timeIndex = i;
        }
    }

    if (timeIndex < 0)
    {
        fail
        (
            "time " + timeArg + " not found by the reader in " + foamFile
          + " (times: " + (timeList.empty() ? "none" : timeList) + ")"
        );
        vtkErrorsCheck();
        return 1;
    }
    const double t = timeValues->GetValue(timeIndex);
    std::cout
        << "time " << timeArg << ": found (reader times: " << timeList
        << ") OK" << std::endl;

    // Refresh the region/cloud/array lists for the chosen time (VTK 9.1
    // offers a cloud found in any time directory; at a time without its
    // files the cloud's block is empty)
    reader->SetTimeValue(t);
    reader->UpdateInformation();

    // ---- select what to read
    const std::string cloudEntry = "lagrangian/" + cloud;
    if (listMode)
    {
        reader->EnableAllPatchArrays();
    }
    else
    {
        bool have = false;
        std::string patchList;
        for (int i = 0; i < reader->GetNumberOfPatchArrays(); ++i)
        {
            const std::string n = reader->GetPatchArrayName(i);
            patchList += (i ? ", " : "") + n;
            if (n == cloudEntry) have = true;
        }
        if (!have && expectedCount == 0)
        {
            // OpenFOAM writes no files for an empty cloud
            std::cout
                << "cloud " << cloud << ": not in the case (no '"
                << cloudEntry << "' entry), 0 points (expected 0) OK"
                << std::endl;
            for (const FieldCheck& fc : fields)
            {
                std::cout
                    << "field " << fc.name << ": not checked (empty cloud)"
                    << std::endl;
            }
            vtkErrorsCheck();
            return nFailed ? 1 : 0;
        }
        if (!have)
        {
            fail
            (
                "cloud " + cloud + ": no entry '" + cloudEntry
              + "' in the reader's region list at time " + timeArg
              + " (entries: " + (patchList.empty() ? "none" : patchList) + ")"
            );
            vtkErrorsCheck();
            return 1;
        }
        reader->SetPatchArrayStatus(cloudEntry.c_str(), 1);
    }
    reader->EnableAllLagrangianArrays();
    reader->EnableAllCellArrays();
    reader->EnableAllPointArrays();

    reader->UpdateTimeStep(t);

    vtkMultiBlockDataSet* output = reader->GetOutput();
    std::vector<Leaf> leaves;
    collectLeaves(output, "", leaves);

    // ---- --list: print everything
    if (listMode)
    {
        std::cout << "regions/patches offered by the reader:";
        for (int i = 0; i < reader->GetNumberOfPatchArrays(); ++i)
            std::cout << " " << reader->GetPatchArrayName(i);
        std::cout << "\nlagrangian arrays offered:";
        for (int i = 0; i < reader->GetNumberOfLagrangianArrays(); ++i)
            std::cout << " " << reader->GetLagrangianArrayName(i);
        std::cout << "\ncell arrays offered:";
        for (int i = 0; i < reader->GetNumberOfCellArrays(); ++i)
            std::cout << " " << reader->GetCellArrayName(i);
        std::cout << "\npoint arrays offered:";
        for (int i = 0; i < reader->GetNumberOfPointArrays(); ++i)
            std::cout << " " << reader->GetPointArrayName(i);
        std::cout << "\nblocks:\n";

        for (const Leaf& l : leaves)
        {
            auto* ds = vtkDataSet::SafeDownCast(l.obj);
            std::cout << "  " << l.path << ": ";
            if (!ds)
            {
                std::cout
                    << (l.obj ? l.obj->GetClassName() : "(empty)") << "\n";
                continue;
            }
            std::cout
                << ds->GetClassName() << ", "
                << ds->GetNumberOfPoints() << " points, "
                << ds->GetNumberOfCells() << " cells\n";
            vtkPointData* pd = ds->GetPointData();
            for (int a = 0; a < pd->GetNumberOfArrays(); ++a)
            {
                vtkAbstractArray* arr = pd->GetAbstractArray(a);
                std::cout
                    << "    point array " << (arr->GetName() ? arr->GetName() : "?")
                    << " (" << arr->GetClassName() << ", "
                    << arr->GetNumberOfTuples() << " x "
                    << arr->GetNumberOfComponents() << ")\n";
            }
            vtkCellData* cd = ds->GetCellData();
            for (int a = 0; a < cd->GetNumberOfArrays(); ++a)
            {
                vtkAbstractArray* arr = cd->GetAbstractArray(a);
                std::cout
                    << "    cell array " << (arr->GetName() ? arr->GetName() : "?")
                    << " (" << arr->GetClassName() << ", "
                    << arr->GetNumberOfTuples() << " x "
                    << arr->GetNumberOfComponents() << ")\n";
            }
        }
        std::cout
            << "VTK errors: " << outWin->nErrors
            << ", warnings: " << outWin->nWarnings << std::endl;
        return outWin->nErrors ? 1 : 0;
    }

    // ---- find the cloud: a leaf ".../lagrangian/<cloud>"
    vtkDataSet* cloudDs = nullptr;
    std::string cloudPath;
    for (const Leaf& l : leaves)
    {
        if
        (
            l.name == cloud
         && (l.path == cloudEntry || endsWith(l.path, "/" + cloudEntry))
        )
        {
            cloudDs = vtkDataSet::SafeDownCast(l.obj);
            cloudPath = l.path;
            if (cloudDs) break;
        }
    }

    if (!cloudDs)
    {
        std::string blockList;
        for (const Leaf& l : leaves)
            blockList += (blockList.empty() ? "" : ", ") + l.path;
        fail
        (
            "cloud " + cloud + ": no block 'lagrangian/" + cloud
          + "' in the reader's output (blocks: "
          + (blockList.empty() ? "none" : blockList) + ")"
        );
    }
    else
    {
        checkPointCount(cloudDs, "cloud " + cloud, expectedCount, fail);
        checkFields(cloudDs, "cloud " + cloud, expectedCount, fields, fail);
    }

    vtkErrorsCheck();

    return nFailed ? 1 : 0;
}


// ---- .vtp and .pvd modes

namespace
{

// Collects VTK's messages and the failed checks
struct Checker
{
    vtkNew<CountingOutputWindow> outWin;
    int nFailed = 0;

    Checker()
    {
        vtkOutputWindow::SetInstance(outWin);
        // The messages go to the window above only (not also via vtkLogger)
        vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
    }

    void fail(const std::string& msg)
    {
        ++nFailed;
        std::cout << "FAILED: " << msg << std::endl;
    }

    FailFn failFn()
    {
        return [this](const std::string& msg) { fail(msg); };
    }

    // Errors VTK reported count as a failed check
    void vtkErrorsCheck()
    {
        if (outWin->nErrors)
        {
            fail
            (
                "VTK reported " + std::to_string(outWin->nErrors)
              + " error(s) while reading (see stderr), first: "
              + firstLine(outWin->errors.front())
            );
        }
    }

    int status() const
    {
        return nFailed ? 1 : 0;
    }
};


bool isFile(const std::string& f)
{
    struct stat st;
    return stat(f.c_str(), &st) == 0 && S_ISREG(st.st_mode);
}


// Folder part of a path ("." if none)
std::string dirName(const std::string& f)
{
    const auto slash = f.find_last_of('/');
    if (slash == std::string::npos) return ".";
    if (slash == 0) return "/";
    return f.substr(0, slash);
}


// <field> <min> <max> triples from argv[first] on
bool parseFieldArgs
(
    const char* prog,
    int argc,
    char* argv[],
    int first,
    std::vector<FieldCheck>& fields
)
{
    for (int i = first; i + 2 < argc; i += 3)
    {
        FieldCheck fc;
        fc.name = argv[i];
        if (!parseDouble(argv[i+1], fc.min) || !parseDouble(argv[i+2], fc.max))
        {
            std::cerr
                << prog << ": bad range '" << argv[i+1] << "' '"
                << argv[i+2] << "' for field " << fc.name << "\n\n";
            return false;
        }
        fields.push_back(fc);
    }
    return true;
}


// Reads <file> with vtkXMLPolyDataReader and checks it: point count, one
// vertex cell per point, FieldData "TimeValue", the fields
void checkVtp
(
    Checker& chk,
    const std::string& file,
    const long long expectedCount,
    const std::vector<FieldCheck>& fields
)
{
    if (!isFile(file))
    {
        chk.fail("file " + file + " does not exist (or is not a file)");
        return;
    }

    vtkNew<vtkXMLPolyDataReader> reader;
    reader->SetFileName(file.c_str());
    reader->Update();

    vtkPolyData* poly = reader->GetOutput();
    if (!poly || chk.outWin->nErrors)
    {
        chk.fail
        (
            "file " + file + ": vtkXMLPolyDataReader could not read it"
            " (not VTK XML PolyData?)"
        );
        return;
    }

    const std::string label = "file " + file;
    const FailFn fail = chk.failFn();

    checkPointCount(poly, label, expectedCount, fail);

    {
        const vtkIdType nVerts = poly->GetNumberOfVerts();
        std::ostringstream os;
        os  << "verts: " << nVerts << " vertex cells (expected "
            << expectedCount << ", one per point; "
            << poly->GetNumberOfCells() << " cells in all)";
        if (nVerts == expectedCount)
            std::cout << os.str() << " OK" << std::endl;
        else
            chk.fail(os.str());
    }

    {
        vtkFieldData* fd = poly->GetFieldData();
        vtkDataArray* tv = fd ? fd->GetArray("TimeValue") : nullptr;
        if (!tv)
        {
            std::string names;
            for (int a = 0; fd && a < fd->GetNumberOfArrays(); ++a)
            {
                const char* n = fd->GetArrayName(a);
                names += (a ? ", " : "") + std::string(n ? n : "?");
            }
            chk.fail
            (
                "FieldData TimeValue: no such numeric array in " + file
              + " (field data arrays: " + (names.empty() ? "none" : names)
              + ")"
            );
        }
        else if (tv->GetNumberOfTuples() < 1)
        {
            chk.fail("FieldData TimeValue: empty array in " + file);
        }
        else
        {
            std::cout
                << "FieldData TimeValue: " << fmt(tv->GetComponent(0, 0))
                << " OK" << std::endl;
        }
    }

    checkFields(poly, label, expectedCount, fields, fail);
}

} // End anonymous namespace


// The .vtp mode: readCloud <file>.vtp <expectedCount> [fields...]
int vtpMode(int argc, char* argv[])
{
    const char* prog = "readCloud";

    long long expectedCount = 0;
    std::vector<FieldCheck> fields;
    if (argc < 3 || (argc - 3) % 3 != 0)
    {
        usage(prog);
        return 2;
    }
    if (!parseCount(argv[2], expectedCount))
    {
        std::cerr << prog << ": bad expectedCount '" << argv[2] << "'\n\n";
        usage(prog);
        return 2;
    }
    if (!parseFieldArgs(prog, argc, argv, 3, fields))
    {
        usage(prog);
        return 2;
    }

    Checker chk;
    checkVtp(chk, argv[1], expectedCount, fields);
    chk.vtkErrorsCheck();
    return chk.status();
}


// The .pvd mode: readCloud <file>.pvd --list
//                readCloud <file>.pvd <time> <expectedCount> [fields...]
int pvdMode(int argc, char* argv[])
{
    const char* prog = "readCloud";

    const bool listMode = (argc == 3 && std::strcmp(argv[2], "--list") == 0);

    const std::string pvdFile = argv[1];
    std::string timeArg;
    double timeVal = 0;
    long long expectedCount = 0;
    std::vector<FieldCheck> fields;

    if (!listMode)
    {
        if (argc < 4 || (argc - 4) % 3 != 0)
        {
            usage(prog);
            return 2;
        }
        timeArg = argv[2];
        if (!parseDouble(argv[2], timeVal))
        {
            std::cerr << prog << ": bad time '" << argv[2] << "'\n\n";
            usage(prog);
            return 2;
        }
        if (!parseCount(argv[3], expectedCount))
        {
            std::cerr
                << prog << ": bad expectedCount '" << argv[3] << "'\n\n";
            usage(prog);
            return 2;
        }
        if (!parseFieldArgs(prog, argc, argv, 4, fields))
        {
            usage(prog);
            return 2;
        }
    }

    Checker chk;

    if (!isFile(pvdFile))
    {
        chk.fail(pvdFile + " does not exist (or is not a file)");
        return 1;
    }

    // ---- parse the collection
    vtkNew<vtkXMLDataParser> parser;
    parser->SetFileName(pvdFile.c_str());
    if (!parser->Parse())
    {
        chk.fail(pvdFile + ": could not be parsed as XML");
        chk.vtkErrorsCheck();
        return 1;
    }

    vtkXMLDataElement* root = parser->GetRootElement();
    const char* rootType = root ? root->GetAttribute("type") : nullptr;
    vtkXMLDataElement* coll =
        root ? root->FindNestedElementWithName("Collection") : nullptr;
    if
    (
        !root || std::strcmp(root->GetName(), "VTKFile") != 0
     || !rootType || std::strcmp(rootType, "Collection") != 0 || !coll
    )
    {
        chk.fail
        (
            pvdFile + ": not a ParaView collection (expected"
            " <VTKFile type=\"Collection\"> with a <Collection> element)"
        );
        chk.vtkErrorsCheck();
        return 1;
    }

    struct Entry
    {
        std::string timestep;   // as written
        double time;
        std::string file;       // as written
        std::string path;       // resolved
    };
    std::vector<Entry> entries;
    const std::string pvdDir = dirName(pvdFile);

    for (int i = 0; i < coll->GetNumberOfNestedElements(); ++i)
    {
        vtkXMLDataElement* e = coll->GetNestedElement(i);
        if (!e || std::strcmp(e->GetName(), "DataSet") != 0) continue;

        const char* ts = e->GetAttribute("timestep");
        const char* f = e->GetAttribute("file");
        Entry en;
        en.timestep = ts ? ts : "";
        en.file = f ? f : "";
        if (!ts || !parseDouble(ts, en.time))
        {
            chk.fail
            (
                pvdFile + ": DataSet " + std::to_string(entries.size())
              + " has no valid timestep attribute ('" + en.timestep + "')"
            );
            continue;
        }
        if (en.file.empty())
        {
            chk.fail
            (
                pvdFile + ": DataSet at timestep " + en.timestep
              + " has no file attribute"
            );
            continue;
        }
        en.path = (en.file[0] == '/') ? en.file : pvdDir + "/" + en.file;
        entries.push_back(en);
    }

    // ---- --list
    if (listMode)
    {
        std::cout
            << pvdFile << ": " << entries.size() << " DataSet(s)"
            << std::endl;
        for (const Entry& en : entries)
        {
            std::cout
                << "  timestep " << en.timestep << ": " << en.file
                << (isFile(en.path) ? "" : " (file missing: " + en.path + ")")
                << std::endl;
        }
        chk.vtkErrorsCheck();
        return chk.status();
    }

    // ---- find the time
    std::string timeList;
    std::vector<const Entry*> matches;
    for (const Entry& en : entries)
    {
        timeList += (timeList.empty() ? "" : " ") + en.timestep;
        if
        (
            std::fabs(en.time - timeVal)
         <= 1e-9*std::max(1.0, std::fabs(timeVal))
        )
        {
            matches.push_back(&en);
        }
    }

    if (matches.empty())
    {
        chk.fail
        (
            "time " + timeArg + " not listed in " + pvdFile + " (timesteps: "
          + (timeList.empty() ? "none" : timeList) + ")"
        );
        chk.vtkErrorsCheck();
        return 1;
    }
    if (matches.size() > 1)
    {
        std::string files;
        for (const Entry* en : matches)
            files += (files.empty() ? "" : ", ") + en->file;
        chk.fail
        (
            "time " + timeArg + ": " + std::to_string(matches.size())
          + " DataSets (parts) at this timestep in " + pvdFile + " ("
          + files + "); cannot choose one"
        );
        chk.vtkErrorsCheck();
        return 1;
    }

    const Entry& en = *matches.front();
    if (!isFile(en.path))
    {
        chk.fail
        (
            "time " + timeArg + ": DataSet file " + en.file + " of "
          + pvdFile + " does not exist (looked for " + en.path + ")"
        );
        chk.vtkErrorsCheck();
        return 1;
    }
    std::cout
        << "time " << timeArg << ": DataSet timestep " << en.timestep
        << ", file " << en.file << " (timesteps: " << timeList << ") OK"
        << std::endl;

    checkVtp(chk, en.path, expectedCount, fields);
    chk.vtkErrorsCheck();
    return chk.status();
}


int main(int argc, char* argv[])
{
    if (argc >= 2)
    {
        const std::string first = argv[1];
        if (endsWith(first, ".vtp")) return vtpMode(argc, argv);
        if (endsWith(first, ".pvd")) return pvdMode(argc, argv);
    }
    return foamMode(argc, argv);
}
