"""Chart of a riser tutorial's cloud from the output of the function object
vtkCloud, read through ParaView (paraview.simple): for one particle, the
magnitude of each force (the F_<force> fields of particleForceFields), its
wall contacts so far (wallContacts) and, in a riser-frame run, its lateral
position relative to the riser and in the lab (position and labPosition),
at each time vtkCloud wrote. Needs no display (nothing is rendered).

usage: pvbatch plotCloudFields.py <cloud>.vtp.series <png> [origId]
SPDX-License-Identifier: GPL-3.0-or-later
"""
from riserfoam.cli import help_requested  # noqa: E402

help_requested(__doc__)

import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
from paraview import servermanager
from paraview.simple import OpenDataFile, UpdatePipeline
from vtkmodules.numpy_interface import dataset_adapter as dsa

series, png = sys.argv[1:3]
origId = int(sys.argv[3]) if len(sys.argv) > 3 else 0

reader = OpenDataFile(series)
times = list(reader.TimestepValues)
if not times:
    sys.exit("plotCloudFields: no times in " + series)

rows = []
for t in times:
    UpdatePipeline(time=t, proxy=reader)
    data = dsa.WrapDataObject(servermanager.Fetch(reader))
    ids = np.asarray(data.PointData["origId"])
    found = np.flatnonzero(ids == origId)
    if found.size == 0:
        continue
    i = found[0]
    fields = {name: np.asarray(data.PointData[name])[i] for name in data.PointData.keys()}
    fields["position"] = np.asarray(data.Points)[i]
    rows.append((t, fields))
if not rows:
    sys.exit("plotCloudFields: no particle %d in %s" % (origId, series))

t = np.array([r[0] for r in rows])
forces = sorted(n for n in rows[-1][1] if n.startswith("F_"))
if not forces:
    sys.exit("plotCloudFields: no F_<force> fields in %s (is particleForceFields on, and"
             " vtkCloud's writeControl writeTime?)" % series)
lab = "labPosition" in rows[-1][1]

fig, axes = plt.subplots(3 if lab else 2, 1, figsize=(8, 9 if lab else 6.5), sharex=True)
for name in forces:
    magnitude = [np.linalg.norm(r[1][name]) for r in rows]
    axes[0].plot(t, magnitude, marker=".",
                 label=name[2:] + ("" if any(magnitude) else " (zero)"))
axes[0].set_ylabel("|F| [N]")
axes[0].legend(fontsize=7, ncol=2)
axes[0].set_title("particle %d at the write times: forces, wall contacts%s (vtkCloud)"
                  % (origId, ", lab position" if lab else ""))
axes[1].step(t, [r[1]["wallContacts"] for r in rows], where="post")
axes[1].set_ylabel("wall contacts so far")
if lab:
    axes[2].plot(t, [r[1]["position"][0] for r in rows], marker=".",
                 label="x relative to the riser (position)")
    axes[2].plot(t, [r[1]["labPosition"][0] for r in rows], marker=".",
                 label="x in the lab (labPosition)")
    axes[2].set_ylabel("x [m]")
    axes[2].legend(fontsize=7)
axes[-1].set_xlabel("t [s]")
fig.tight_layout()
fig.savefig(png, dpi=120)
print("plotCloudFields: %d times, forces %s, %d wall contacts at t = %g; wrote %s"
      % (len(rows), " ".join(f[2:] for f in forces), rows[-1][1]["wallContacts"], t[-1], png))
