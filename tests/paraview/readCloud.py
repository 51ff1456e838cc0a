#------------------------------------------------------------------------------
# mpsFsiFoam test helper: readCloud.py (run by pvpython; see ./readCloud)
#
# Reads an OpenFOAM case with ParaView's own OpenFOAM reader (the
# "OpenFOAMReader" proxy that paraFoam and File > Open *.foam use) and checks
# a lagrangian cloud in it; or reads a ParaView collection (.pvd) with
# ParaView's PVD reader, or one VTK XML PolyData file (.vtp), and checks it
# the same way. It is the only VTK the project uses: ParaView's own.
#
# Usage:
#     readCloud <case>/<name>.foam <time> <cloud> <expectedCount>
#               [<field> <expectedMin> <expectedMax>]...
#     readCloud <case>/<name>.foam <time> --list
#     readCloud <file>.vtp <expectedCount> [<field> <min> <max>]...
#     readCloud <file>.pvd <time> <expectedCount> [<field> <min> <max>]...
#     readCloud <file>.pvd --list
# Any checking form also takes "--arrays a,b,c": the cloud's point arrays
# must be exactly these.
#
# For every check one line is printed, "... OK" or "FAILED: ...".
# Exit status: 0 all checks passed, 1 a check failed, 2 bad arguments.
#
# Each <field> is a point-data array of the cloud (one per lagrangian field
# file); it must exist, have <expectedCount> tuples, and the minimum and
# maximum over all of its components must lie in [expectedMin, expectedMax]
# (widened by 1e-6 relative: .vtp files hold Float32). The pseudo-field
# "positions" checks the particle coordinates.
#
# .foam mode: the reader as the GUI sets it up, except that 0/ is not
# skipped (ParaView skips it by default; the tests check the initial
# particles); the cloud's region "lagrangian/<cloud>" and all lagrangian
# arrays enabled. With expectedCount 0 a cloud the reader does not offer
# passes (OpenFOAM writes no files for an empty cloud).
# .vtp and .pvd modes: also one vertex cell per point and a FieldData array
# "TimeValue"; a .pvd time of several parts (pieces per rank) is checked
# as the pieces joined. A .pvd time must be one of the collection's timesteps
# (|t - time| <= 1e-9 max(1, |time|)).
#
# Errors and warnings VTK reports while reading count as failed checks.
#------------------------------------------------------------------------------

import math
import os
import sys
import tempfile

# ParaView's modules first: importing them sets up ParaView's own output
# window, which Checks then replaces
from paraview import servermanager
from paraview.simple import OpenFOAMReader, PVDReader, XMLPolyDataReader
from vtkmodules.vtkCommonCore import vtkFileOutputWindow, vtkLogger, vtkOutputWindow
from vtkmodules.vtkCommonDataModel import (
    vtkCompositeDataSet, vtkMultiBlockDataSet, vtkPolyData)
from vtkmodules.vtkFiltersCore import vtkAppendPolyData

usageText = """Usage:
  readCloud <case>/<name>.foam <time> <cloud> <expectedCount> [<field> <min> <max>]...
  readCloud <case>/<name>.foam <time> --list
  readCloud <file>.vtp <expectedCount> [<field> <min> <max>]...
  readCloud <file>.pvd <time> <expectedCount> [<field> <min> <max>]...
  readCloud <file>.pvd --list
  (any checking form: --arrays a,b,c, the cloud's point arrays exactly)
Reads with ParaView's OpenFOAM reader (a .foam case), PVD reader (.pvd) or
XML PolyData reader (.vtp) and checks a cloud: its particle count and, per
<field> (a point array, or 'positions'), that min and max over all
components lie in [<min>, <max>]. --list prints what the reader offers.
Exit status: 0 all OK, 1 a check failed, 2 bad arguments."""


def say(line):
    """One line on the standard output. pvpython sends Python's sys.stdout
    through VTK's output window, which Checks points at a file."""
    sys.__stdout__.write(line + "\n")
    sys.__stdout__.flush()


def badArguments(msg=None):
    if msg:
        sys.stderr.write("readCloud: %s\n\n" % msg)
    sys.stderr.write(usageText + "\n")
    sys.exit(2)


def number(s, what):
    try:
        return float(s)
    except ValueError:
        badArguments("bad %s '%s'" % (what, s))


def count(s):
    try:
        n = int(s)
    except ValueError:
        n = -1
    if n < 0:
        badArguments("bad expectedCount '%s'" % s)
    return n


def arraysOption(args):
    """Takes "--arrays a,b,c" out of args: the cloud's point arrays must be
    exactly these (None if not given)."""
    if "--arrays" not in args:
        return args, None
    i = args.index("--arrays")
    if i + 1 >= len(args):
        badArguments("--arrays needs a comma-separated list")
    return args[:i] + args[i + 2:], sorted(a for a in args[i + 1].split(",") if a)


def fieldChecks(args):
    if len(args) % 3:
        badArguments("fields come as <field> <min> <max> triples")
    return [
        (args[i], number(args[i + 1], "minimum of " + args[i]),
         number(args[i + 2], "maximum of " + args[i]))
        for i in range(0, len(args), 3)
    ]


def fmt(v):
    return "%.10g" % v


class Checks:
    """Counts the failed checks; VTK's messages go to a file it reads."""

    def __init__(self):
        self.nFailed = 0
        fd, self.messages = tempfile.mkstemp(prefix="readCloud.", suffix=".log")
        os.close(fd)
        self.window = vtkFileOutputWindow()
        self.window.SetFileName(self.messages)
        self.window.SetFlush(1)
        vtkOutputWindow.SetInstance(self.window)
        # Only there: not also through the logger, on stderr
        vtkLogger.SetStderrVerbosity(vtkLogger.VERBOSITY_OFF)

    def ok(self, msg):
        say(msg + " OK")

    def fail(self, msg):
        self.nFailed += 1
        say("FAILED: " + msg)

    def vtkMessages(self):
        """Fails for every error or warning VTK wrote; echoes them."""
        with open(self.messages) as f:
            text = f.read()
        os.remove(self.messages)
        blocks = [b.strip() for b in text.split("\n\n") if b.strip()]
        bad = [b for b in blocks if b.startswith(("ERROR", "Warning"))]
        for b in blocks:
            sys.__stderr__.write("VTK: " + b + "\n")
        if bad:
            first = [l.strip() for l in bad[0].splitlines()
                     if l.strip() and not l.strip().startswith(("ERROR: In", "Warning: In"))]
            self.fail("VTK reported %d error(s) or warning(s) while reading "
                      "(see stderr), first: %s" % (len(bad), first[0] if first else bad[0]))

    def status(self):
        self.vtkMessages()
        return 1 if self.nFailed else 0


def arrays(ds):
    pd = ds.GetPointData()
    return [pd.GetArrayName(i) for i in range(pd.GetNumberOfArrays())]


def checkCloud(chk, ds, label, expectedCount, fields, expectedArrays=None):
    """The point count of ds, its arrays (if given), then each field's
    tuples and range."""
    n = ds.GetNumberOfPoints()
    msg = "%s: %d points (expected %d)" % (label, n, expectedCount)
    (chk.ok if n == expectedCount else chk.fail)(msg)
    if expectedArrays is not None:
        have = sorted(arrays(ds))
        msg = "%s: arrays %s (expected %s)" % (label, " ".join(have), " ".join(expectedArrays))
        (chk.ok if have == expectedArrays else chk.fail)(msg)
    for name, lo, hi in fields:
        what = "field " + name
        if name == "positions":
            pts = ds.GetPoints()
            arr = pts.GetData() if pts else None
        else:
            arr = ds.GetPointData().GetArray(name)
        if arr is None:
            chk.fail("%s: no such array on %s (arrays: %s)"
                     % (what, label, ", ".join(arrays(ds)) or "none"))
            continue
        nTuples = arr.GetNumberOfTuples()
        nComp = arr.GetNumberOfComponents()
        if nTuples != expectedCount:
            chk.fail("%s: %d tuples (expected %d)" % (what, nTuples, expectedCount))
            continue
        values = [arr.GetComponent(i, c) for i in range(nTuples) for c in range(nComp)]
        nNan = sum(1 for v in values if math.isnan(v))
        finite = [v for v in values if not math.isnan(v)]
        vMin = min(finite) if finite else float("inf")
        vMax = max(finite) if finite else -float("inf")
        msg = ("%s: %d x %d (%s), range [%s, %s], expected within [%s, %s]"
               % (what, nTuples, nComp, arr.GetClassName(), fmt(vMin), fmt(vMax),
                  fmt(lo), fmt(hi)))
        if nNan:
            chk.fail("%s, %d NaN value(s)" % (msg, nNan))
        elif nTuples and (vMin < lo - 1e-6*abs(lo) or vMax > hi + 1e-6*abs(hi)):
            chk.fail(msg)
        else:
            chk.ok(msg)


def checkPolyData(chk, poly, label, expectedCount, fields, expectedArrays=None):
    """A particle file: vertices, TimeValue, then the cloud checks."""
    nVerts = poly.GetNumberOfVerts()
    msg = ("verts: %d vertex cells (expected %d, one per point; %d cells in all)"
           % (nVerts, expectedCount, poly.GetNumberOfCells()))
    (chk.ok if nVerts == expectedCount else chk.fail)(msg)
    t = poly.GetFieldData().GetArray("TimeValue")
    if t is None:
        chk.fail("%s: no FieldData array TimeValue" % label)
    else:
        chk.ok("%s: TimeValue %s" % (label, fmt(t.GetComponent(0, 0))))
    checkCloud(chk, poly, label, expectedCount, fields, expectedArrays)


def leaves(mb, prefix=""):
    """(path, dataset) of every leaf of a multiblock."""
    out = []
    if mb is None:
        return out
    for i in range(mb.GetNumberOfBlocks()):
        name = None
        if mb.HasMetaData(i):
            name = mb.GetMetaData(i).Get(vtkCompositeDataSet.NAME())
        name = name or "block%d" % i
        path = name if not prefix else prefix + "/" + name
        block = mb.GetBlock(i)
        if isinstance(block, vtkMultiBlockDataSet):
            out += leaves(block, path)
        else:
            out.append((path, block))
    return out


def timesteps(reader):
    """The reader's times as a list (ParaView gives a number for one time)."""
    tv = reader.TimestepValues
    if tv is None:
        return []
    try:
        return [float(t) for t in tv]
    except TypeError:
        return [float(tv)]


def sameTime(t, time):
    return abs(t - time) <= 1e-9*max(1.0, abs(time))


def foamMode(args):
    args, expectedArrays = arraysOption(args)
    listMode = len(args) == 3 and args[2] == "--list"
    if not listMode and (len(args) < 4 or (len(args) - 4) % 3):
        badArguments()
    foamFile, timeArg = args[0], args[1]
    time = number(timeArg, "time")
    if not listMode:
        cloud, expectedCount, fields = args[2], count(args[3]), fieldChecks(args[4:])
    if not os.path.isfile(foamFile):
        say("FAILED: %s does not exist (create an empty <case>/<name>.foam file)"
              % foamFile)
        return 1

    chk = Checks()

    reader = OpenFOAMReader(FileName=foamFile)
    reader.SkipZeroTime = 0
    reader.Refresh()  # the times are read again only on a refresh
    reader.UpdatePipelineInformation()
    times = timesteps(reader)
    timeList = " ".join(fmt(t) for t in times) or "none"
    match = [t for t in times if sameTime(t, time)]
    if not match:
        chk.fail("time %s not found by the reader in %s (times: %s)"
                 % (timeArg, foamFile, timeList))
        return chk.status()
    chk.ok("time %s: found (reader times: %s)" % (timeArg, timeList))

    regions = list(reader.GetProperty("MeshRegions").Available)
    entry = "lagrangian/" + (args[2] if not listMode else "")
    if listMode:
        reader.MeshRegions = regions
    elif entry not in regions:
        if expectedCount == 0:
            chk.ok("cloud %s: not in the case (no '%s' region), 0 points (expected 0)"
                   % (cloud, entry))
            return chk.status()
        chk.fail("cloud %s: no region '%s' offered by the reader (regions: %s)"
                 % (cloud, entry, ", ".join(regions) or "none"))
        return chk.status()
    else:
        reader.MeshRegions = [entry]
    reader.LagrangianArrays = list(reader.GetProperty("LagrangianArrays").Available)
    reader.UpdatePipeline(match[0])
    blocks = leaves(servermanager.Fetch(reader))

    if listMode:
        say("regions offered by the reader: " + " ".join(regions))
        say("lagrangian arrays offered: "
              + " ".join(reader.GetProperty("LagrangianArrays").Available))
        say("blocks:")
        for path, ds in blocks:
            if ds is None:
                say("  %s: (empty)" % path)
                continue
            say("  %s: %s, %d points, %d cells"
                  % (path, ds.GetClassName(), ds.GetNumberOfPoints(), ds.GetNumberOfCells()))
            pd = ds.GetPointData()
            for i in range(pd.GetNumberOfArrays()):
                a = pd.GetAbstractArray(i)
                say("    point array %s (%s, %d x %d)"
                      % (a.GetName(), a.GetClassName(), a.GetNumberOfTuples(),
                         a.GetNumberOfComponents()))
        return chk.status()

    found = [ds for path, ds in blocks
             if ds is not None and (path == entry or path.endswith("/" + entry))]
    if not found:
        chk.fail("cloud %s: no block '%s' in the reader's output (blocks: %s)"
                 % (cloud, entry, ", ".join(p for p, _ in blocks) or "none"))
    else:
        checkCloud(chk, found[0], "cloud " + cloud, expectedCount, fields, expectedArrays)
    return chk.status()


def pvdMode(args):
    args, expectedArrays = arraysOption(args)
    listMode = len(args) == 2 and args[1] == "--list"
    if not listMode and (len(args) < 3 or (len(args) - 3) % 3):
        badArguments()
    pvdFile = args[0]
    if not os.path.isfile(pvdFile):
        say("FAILED: file %s does not exist" % pvdFile)
        return 1
    chk = Checks()

    reader = PVDReader(FileName=pvdFile)
    reader.UpdatePipelineInformation()
    times = timesteps(reader)
    if listMode:
        say("timesteps: " + " ".join(fmt(t) for t in times))
        return chk.status()
    time, expectedCount, fields = number(args[1], "time"), count(args[2]), fieldChecks(args[3:])
    match = [t for t in times if sameTime(t, time)]
    if not match:
        chk.fail("time %s is not a timestep of %s (timesteps: %s)"
                 % (args[1], pvdFile, " ".join(fmt(t) for t in times) or "none"))
        return chk.status()
    reader.UpdatePipeline(match[0])
    data = servermanager.Fetch(reader)
    if isinstance(data, vtkMultiBlockDataSet):
        # The parts of a time (mpsFsiFoam -parallel: one piece per rank),
        # each PolyData, joined as ParaView's Merge Blocks would
        pieces = leaves(data)
        if not pieces or not all(isinstance(b, vtkPolyData) for _, b in pieces):
            chk.fail("%s at time %s: parts that are not all PolyData" % (pvdFile, args[1]))
            return chk.status()
        append = vtkAppendPolyData()
        for _, b in pieces:
            append.AddInputData(b)
        append.Update()
        merged = vtkPolyData()
        merged.ShallowCopy(append.GetOutput())
        merged.SetFieldData(pieces[0][1].GetFieldData())
        chk.ok("%s at time %s: %d pieces (parts), %s points"
               % (pvdFile, args[1], len(pieces),
                  "+".join(str(b.GetNumberOfPoints()) for _, b in pieces)))
        data = merged
    if not isinstance(data, vtkPolyData):
        chk.fail("%s at time %s: %s, not PolyData"
                 % (pvdFile, args[1], data.GetClassName() if data else "nothing"))
        return chk.status()
    checkPolyData(chk, data, "file %s at %s" % (pvdFile, args[1]), expectedCount, fields,
                  expectedArrays)
    return chk.status()


def vtpMode(args):
    args, expectedArrays = arraysOption(args)
    if len(args) < 2 or (len(args) - 2) % 3:
        badArguments()
    vtpFile, expectedCount, fields = args[0], count(args[1]), fieldChecks(args[2:])
    if not os.path.isfile(vtpFile):
        say("FAILED: file %s does not exist" % vtpFile)
        return 1
    chk = Checks()
    data = servermanager.Fetch(XMLPolyDataReader(FileName=[vtpFile]))
    checkPolyData(chk, data, "file " + vtpFile, expectedCount, fields, expectedArrays)
    return chk.status()


def main(args):
    if not args or args[0] in ("-h", "-help", "--help"):
        badArguments()
    if args[0].endswith(".pvd"):
        return pvdMode(args)
    if args[0].endswith(".vtp"):
        return vtpMode(args)
    return foamMode(args)


if __name__ == "__main__":
    # From ./readCloud, one argument a line (pvpython would rewrite some)
    given = os.environ.get("READCLOUD_ARGS")
    sys.exit(main(given.split("\n") if given else sys.argv[1:]))
