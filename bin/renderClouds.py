#------------------------------------------------------------------------------
# mpsFsiFoam: renderClouds.py (run by pvbatch; see bin/renderClouds)
#
# Draws a case's particles as ParaView shows them, read with ParaView's own
# OpenFOAM reader: the fluid coloured by pressure p, the structure by its
# axial strain (its displacement D magnified by -scale, stated in the
# picture, about a reference particle), the wall and dummy particles grey. One PNG per time:
# <output>_<time>.png.
#
# Arguments (one a line in RENDERCLOUDS_ARGS): <case>.foam <output> <scale> <anchor|auto> <box|auto>
#            <pMax|auto> <time>...
#   anchor "x y" [m]: the structure's deformation is magnified about the
#   particle that started nearest to it (auto: about the mean displacement)
#   box "x0 x1 y0 y1" [m] (auto: the bounds of the fluid and structure)
#   pMax [Pa]: top of the pressure colour map (auto: the largest p drawn)
#------------------------------------------------------------------------------

import math
import sys

from paraview import servermanager
import paraview.simple as pv
from vtkmodules.vtkCommonDataModel import vtkPointLocator

import os
args = os.environ["RENDERCLOUDS_ARGS"].split("\n")  # from bin/renderClouds
foamFile, output, scale, anchorArg, boxArg, pMaxArg = args[:6]
times = [float(t) for t in args[6:]]
scale = float(scale)

reader = pv.OpenFOAMReader(FileName=foamFile)
reader.SkipZeroTime = 0
reader.Refresh()
reader.UpdatePipelineInformation()
available = list(reader.GetProperty("MeshRegions").Available)
clouds = [c for c in ("fluid", "wall", "structure") if "lagrangian/" + c in available]
reader.MeshRegions = ["lagrangian/" + c for c in clouds]
# Only the fields drawn are read (all of them cost 0.1-0.15 s a picture)
reader.LagrangianArrays = [
    a for a in reader.GetProperty("LagrangianArrays").Available
    if a in ("p", "D", "axialStrain")
]
try:
    caseTimes = [float(t) for t in reader.TimestepValues]
except TypeError:
    caseTimes = [float(reader.TimestepValues)]


def nearest(t):
    return min(caseTimes, key=lambda s: abs(s - t))


def strained(ds):
    """Whether the structure carries an axial strain anywhere (not rigid)."""
    a = ds.GetPointData().GetArray("axialStrain")
    return a is not None and max(abs(v) for v in a.GetRange()) > 0


def particleSpacing(ds):
    """Median nearest-neighbour distance of (up to 400 of) the points."""
    n = ds.GetNumberOfPoints()
    if n < 2:
        return 0.0
    loc = vtkPointLocator()
    loc.SetDataSet(ds)
    loc.BuildLocator()
    from vtkmodules.vtkCommonCore import vtkIdList
    ids = vtkIdList()
    d = []
    for i in range(0, n, max(1, n // 400)):
        p = ds.GetPoint(i)
        loc.FindClosestNPoints(2, p, ids)
        q = ds.GetPoint(ids.GetId(1))
        d.append(math.dist(p, q))
    d.sort()
    return d[len(d) // 2]


view = pv.CreateRenderView()
view.ViewSize = [1600, 1000]
view.OrientationAxesVisibility = 0
view.Background = [1, 1, 1]
try:
    view.UseColorPaletteForBackground = 0
except AttributeError:
    pass
view.CameraParallelProjection = 1

blocks = {c: pv.ExtractBlock(Input=reader, Selectors=["/Root/lagrangian/" + c])
          for c in clouds}
text = pv.Text()
textDisplay = pv.Show(text, view)
textDisplay.Color = [0, 0, 0]
textDisplay.FontSize = 18
textDisplay.WindowLocation = "Upper Center"

pLut = pv.GetColorTransferFunction("p")
pLut.ApplyPreset("Cool to Warm", True)
sLut = pv.GetColorTransferFunction("axialStrain")
sLut.ApplyPreset("Turbo", True)

def deformationReference(ds):
    """The displacement about which the structure's deformation is
    magnified: that of the particle that started nearest the anchor
    (without one, the mean displacement), so that the body's own motion
    is not magnified."""
    D = ds.GetPointData().GetArray("D")
    n = ds.GetNumberOfPoints()
    if anchorArg == "auto":
        return [sum(D.GetComponent(i, k) for i in range(n))/n for k in range(3)]
    ax, ay = (float(v) for v in anchorArg.split())

    def distance(i):
        x = ds.GetPoint(i)
        return (x[0] - D.GetComponent(i, 0) - ax)**2 + (x[1] - D.GetComponent(i, 1) - ay)**2
    i = min(range(n), key=distance)
    return [D.GetComponent(i, k) for k in range(3)]


# One pipeline per cloud: its block, (the structure) warped, as one dataset
merged = {}
for c in clouds:
    merged[c] = pv.MergeBlocks(Input=blocks[c])
    if c == "structure" and scale != 1:
        unwarped = merged[c]
        merged[c] = pv.Calculator(Input=unwarped, CoordinateResults=1,
                                  ResultArrayName="magnified")

for t in times:
    tc = nearest(t)
    pixel = 0.0 if boxArg == "auto" else (
        (float(boxArg.split()[1]) - float(boxArg.split()[0]))/view.ViewSize[0])
    view.ViewTime = tc
    shown = {}
    bounds = [math.inf, -math.inf, math.inf, -math.inf]
    for c in clouds:
        if c == "structure" and scale != 1:
            unwarped.UpdatePipeline(tc)
            ref = deformationReference(servermanager.Fetch(unwarped))
            merged[c].Function = "coords + %.17g*(D - (%.17g*iHat + %.17g*jHat + %.17g*kHat))" % (
                scale - 1, ref[0], ref[1], ref[2])
        merged[c].UpdatePipeline(tc)
        ds = servermanager.Fetch(merged[c])
        if ds is None or ds.GetNumberOfPoints() == 0:
            continue
        d = pv.Show(merged[c], view)
        d.SetRepresentationType("Point Gaussian")
        d.ShaderPreset = "Plain circle"
        # Discs that touch, but a structure at least 5 pixels across
        d.GaussianRadius = 0.5*particleSpacing(ds)
        if c == "structure":
            d.GaussianRadius = max(d.GaussianRadius, 2.5*pixel)
        # All particles lie in z = 0: lift the structure over the wall
        # particles that overlap it, and the fluid over the walls
        d.Position = [0, 0, {"wall": 0.0, "fluid": 0.01, "structure": 0.02}[c]]
        if c == "fluid":
            pv.ColorBy(d, ("POINTS", "p"))
            d.SetScalarBarVisibility(view, True)
        elif c == "structure" and strained(ds):
            pv.ColorBy(d, ("POINTS", "axialStrain"))
            d.SetScalarBarVisibility(view, True)
        elif c == "structure":
            # A rigid body (no strain anywhere): one colour, no colour bar
            d.ColorArrayName = ["POINTS", ""]
            d.AmbientColor = d.DiffuseColor = [0.3, 0.3, 0.35]
        else:
            pv.ColorBy(d, None)
            d.AmbientColor = d.DiffuseColor = [0.75, 0.75, 0.75]
        shown[c] = (merged[c], d, ds)
        if c != "wall":
            b = ds.GetBounds()
            bounds = [min(bounds[0], b[0]), max(bounds[1], b[1]),
                      min(bounds[2], b[2]), max(bounds[3], b[3])]

    if "fluid" in shown:
        r = shown["fluid"][2].GetPointData().GetArray("p").GetRange()
        pMax = r[1] if pMaxArg == "auto" else float(pMaxArg)
        pLut.RescaleTransferFunction(0.0, max(pMax, 1e-12))
        bar = pv.GetScalarBar(pLut, view)
        bar.Title, bar.ComponentTitle = "p [Pa]", ""
        bar.TitleColor = bar.LabelColor = [0, 0, 0]
        bar.Orientation = "Horizontal"
        bar.WindowLocation = "Any Location"
        bar.Position = [0.05, 0.03]
        bar.ScalarBarLength = 0.35
        bar.DrawTickLabels = 0
        bar.RangeLabelFormat = "%.3g"
    if "structure" in shown and strained(shown["structure"][2]):
        r = shown["structure"][2].GetPointData().GetArray("axialStrain").GetRange()
        e = max(abs(r[0]), abs(r[1]), 1e-12)
        sLut.RescaleTransferFunction(-e, e)
        bar = pv.GetScalarBar(sLut, view)
        bar.Title, bar.ComponentTitle = "axial strain", ""
        bar.TitleColor = bar.LabelColor = [0, 0, 0]
        bar.Orientation = "Horizontal"
        bar.WindowLocation = "Any Location"
        bar.Position = [0.6, 0.03]
        bar.ScalarBarLength = 0.35
        bar.DrawTickLabels = 0
        bar.RangeLabelFormat = "%.3g"

    if boxArg != "auto":
        bounds = [float(v) for v in boxArg.split()]
    cx, cy = 0.5*(bounds[0] + bounds[1]), 0.5*(bounds[2] + bounds[3])
    w, h = bounds[1] - bounds[0], bounds[3] - bounds[2]
    aspect = view.ViewSize[0]/view.ViewSize[1]
    # The picture's lower eighth is kept for the colour bars
    half = 0.5*max(h, w/aspect)/0.85
    view.CameraPosition = [cx, cy - 0.2*half, 10]
    view.CameraFocalPoint = [cx, cy - 0.2*half, 0]
    view.CameraViewUp = [0, 1, 0]
    view.CameraParallelScale = half

    text.Text = "t = %g s%s" % (
        tc, "   (the structure's deformation x %g)" % scale
        if "structure" in shown and scale != 1 else "")
    name = "%s_%g.png" % (output, tc)
    pv.SaveScreenshot(name, view, ImageResolution=view.ViewSize)
    sys.__stdout__.write("Wrote %s\n" % name)
    for src, d, ds in shown.values():
        pv.Hide(src, view)
