"""Headless ParaView picture of a riser tutorial: the riser wall read from the
case (<case>.foam, ParaView's builtin OpenFOAM reader), repeated along the
axis over the height the particle rises (the tutorials' riser is a cyclic
slice), and the particle's track relative to the riser, as a tube coloured
by its height (which grows with time), from the riserParticleTable.

usage: xvfb-run -a pvbatch renderTrack.py <case.foam> <particles.dat> <png>
SPDX-License-Identifier: GPL-3.0-or-later
"""
from riserfoam.cli import help_requested  # noqa: E402

help_requested(__doc__)

import sys

from paraview.simple import (Calculator, OpenFOAMReader, PolyLineSource, Render, SaveScreenshot,
                             Transform, Tube)
from riserfoam import tables
from riserfoam.pvscene import coloured, faint_wall, white_view

foam, table, png = sys.argv[1:4]

# the track: t, x - x_c, y, z and the lifting distance (columns of the table)
rows = [tuple(r) for r in tables.read(table).matrix("t", "xr", "yr", "z", "lift").tolist()]
if not rows:
    sys.exit("renderTrack: no rows in " + table)
z0 = rows[0][3] - rows[0][4]
every = max(1, len(rows) // 2000)
track = rows[::every] + ([rows[-1]] if (len(rows) - 1) % every else [])
points = []
for t, x, y, z, lift in track:
    points += [x, y, z0 + lift]
line = PolyLineSource(Points=points)
height = Calculator(Input=line, ResultArrayName="height", Function="coordsZ")
tube = Tube(Input=height, Radius=0.002, NumberofSides=12)

view = white_view(900, 1400)
view.OrientationAxesVisibility = 1

# the wall: the case's wall patch, one copy per slice length over the rise
reader = OpenFOAMReader(FileName=foam)
reader.MeshRegions = ["patch/riserWall"]
reader.UpdatePipeline()
zmin, zmax = reader.GetDataInformation().GetBounds()[4:6]
length = zmax - zmin
top = max(p for p in points[2::3])
copies = int((top - zmin) // length) + 1
for k in range(copies):
    piece = Transform(Input=reader)
    piece.Transform.Translate = [0.0, 0.0, k * length]
    faint_wall(piece, view)
coloured(tube, view, "height", "height [m]")

view.CameraPosition = [0.9 * (top - zmin + 0.3), -0.9 * (top - zmin + 0.3), 0.5 * (zmin + top)]
view.CameraFocalPoint = [0.0, 0.0, 0.5 * (zmin + top)]
view.CameraViewUp = [0.0, 0.0, 1.0]
view.ResetCamera()
Render(view)
SaveScreenshot(png, view, ImageResolution=[900, 1400])
print("renderTrack: wrote %s (%d track points, %d wall copies, %.2f s of track)"
      % (png, len(track), copies, track[-1][0] - track[0][0]))
