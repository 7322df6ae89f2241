"""The cloud of a riser case in ParaView, run by pvbatch (bin/riserView
runs it): the riser wall (the case's wall patch, faint), and each particle
as a sphere of its diameter d, coloured by a field of the cloud (a vector by
its magnitude), read by ParaView's builtin OpenFOAM reader from the case's
written times. One picture, or one a written time (frames of an
animation).

usage: pvbatch cloudview.py <case.foam> <cloud> <field> <time|latest|all> <png>
       (all: <png stem>_0000.png, ... one a written time)

Prints one line a picture: its file, its time and the particles drawn.
SPDX-License-Identifier: GPL-3.0-or-later
"""
import os
import sys

from paraview.simple import ExtractBlock, Glyph, OpenFOAMReader, Render, SaveScreenshot
from riserfoam.pvscene import coloured, faint_wall, white_view

foam, cloud, field, when, png = sys.argv[1:6]
reader = OpenFOAMReader(FileName=foam)
region = "lagrangian/" + cloud
if region not in reader.GetProperty("MeshRegions").Available:
    sys.exit("riserView: the case has no cloud '%s' (regions: %s)"
             % (cloud, " ".join(reader.GetProperty("MeshRegions").Available)))
reader.MeshRegions = ["patch/riserWall", region]
available = reader.GetProperty("LagrangianArrayInfo")[::2]
for needed in ("d", field):
    if needed not in available:
        sys.exit("riserView: the cloud has no field '%s' (fields: %s)" % (needed, " ".join(available)))
reader.LagrangianArrays = sorted({"d", field})
times = list(reader.TimestepValues) if reader.TimestepValues else [0.0]
if when == "latest":
    chosen = [times[-1]]
elif when == "all":
    chosen = times
else:
    t = float(when)
    near = min(times, key=lambda x: abs(x - t))
    if abs(near - t) > 1e-9 * max(1.0, abs(t)):
        sys.exit("riserView: no written time %s (written: %s)" % (when, " ".join("%g" % x for x in times)))
    chosen = [near]

wall = ExtractBlock(Input=reader, Selectors=["/Root/boundary/riserWall"])
particles = ExtractBlock(Input=reader, Selectors=["/Root/lagrangian/" + cloud])
spheres = Glyph(Input=particles, GlyphType="Sphere", GlyphMode="All Points")
spheres.ScaleArray = ["POINTS", "d"]
spheres.ScaleFactor = 1.0       # after the array: ParaView sets its own on it
spheres.GlyphType.ThetaResolution = 16
spheres.GlyphType.PhiResolution = 12

view = white_view(900, 1200)
faint_wall(wall, view)
lut = coloured(spheres, view, field, field)

reader.UpdatePipeline(times[-1])
x0, x1, y0, y1, z0, z1 = wall.GetDataInformation().GetBounds()
height = z1 - z0
view.CameraFocalPoint = [0.0, 0.0, 0.5 * (z0 + z1)]
view.CameraPosition = [1.2 * height + 3 * (x1 - x0), -1.2 * height - 3 * (y1 - y0), 0.5 * (z0 + z1)]
view.CameraViewUp = [0.0, 0.0, 1.0]
view.ResetCamera()

stem = os.path.splitext(png)[0]
for k, t in enumerate(chosen):
    view.ViewTime = t
    spheres.UpdatePipeline(t)
    lut.RescaleTransferFunction(*(spheres.PointData[field].GetRange(-1)
                                  if spheres.PointData.GetArray(field) else (0.0, 1.0)))
    out = png if len(chosen) == 1 else "%s_%04d.png" % (stem, k)
    Render(view)
    SaveScreenshot(out, view, ImageResolution=[900, 1200])
    count = particles.GetDataInformation().GetNumberOfPoints()
    print("riserView: wrote %s (t = %g, %d particles)" % (out, t, count), flush=True)
