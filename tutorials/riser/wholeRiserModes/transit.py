"""Transit times and lifting efficiencies of the ore through the 1,000 m
riser in its 5th mode and through the rigid riser of the same largest
amplitude (riserParticle's particle tables); writes transit.dat and, with
matplotlib, wholeRiserModes.png.

usage: transit.py     (in the case folder, after its riserParticle runs)"""
from riserfoam.cli import help_requested  # noqa: E402

help_requested(__doc__)

import sys

import numpy as np

from riserfoam import tables

TOP, UCM = 1000.0, 1.0
rows = []
tracks = {}
for case in ("mode5", "rigid"):
    t = tables.read("%s/postProcessing/riserParticle/particles.dat" % case)
    time, z = np.asarray(t["t"]), np.asarray(t["z"])
    above = np.nonzero(z >= TOP)[0]
    if len(above) == 0:
        sys.exit("transit.py: the ore of %s did not reach the top (z = %.1f m at t = %.0f s):"
                 " raise endTime" % (case, z[-1], time[-1]))
    k = above[0]
    # the crossing, linear between the rows about it
    crossing = time[k - 1] + (TOP - z[k - 1]) / (z[k] - z[k - 1]) * (time[k] - time[k - 1])
    transit = crossing - time[0]
    efficiency = (TOP - z[0]) / transit / UCM
    contacts = sum(1 for line in open("%s/postProcessing/riserParticle/contacts.dat" % case)
                   if not line.startswith("#"))
    rows.append((case, transit, efficiency, contacts))
    tracks[case] = (time[:k + 1], z[:k + 1], np.asarray(t["xr"])[:k + 1])
with open("transit.dat", "w") as out:
    out.write("# riser transit_time[s] lifting_efficiency[-] wall_contacts\n")
    for r in rows:
        out.write("%s %.1f %.4f %d\n" % r)
        print("%-6s transit %.1f s, lifting efficiency %.4f, %d wall contacts" % r)
try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
except ImportError:
    sys.exit(0)
fig, (a, b) = plt.subplots(1, 2, figsize=(10, 5), sharey=True)
edges = np.arange(0.0, TOP + 1.0, 25.0)
for case, (time, z, xr) in tracks.items():
    # per 25 m of riser: the ore's mean rise speed and its largest sideways
    # excursion from the local axis
    speed, reach, mids = [], [], []
    for lo, hi in zip(edges[:-1], edges[1:]):
        inside = np.nonzero((z >= lo) & (z < hi))[0]
        if len(inside) < 2:
            continue
        speed.append((z[inside[-1]] - z[inside[0]]) / (time[inside[-1]] - time[inside[0]]))
        reach.append(np.abs(xr[inside]).max() / 0.05)
        mids.append(0.5 * (lo + hi))
    a.plot(speed, mids, label=case)
    b.plot(reach, mids, label=case)
zz = np.linspace(0, TOP, 400)
b.plot(np.abs(np.sin(5 * np.pi * zz / TOP)), zz, "k:", lw=0.8, label="mode 5's amplitude / 0.5 m")
a.set_xlabel("mean rise speed of the ore [m/s] (per 25 m)")
a.set_ylabel("z [m]")
a.legend()
b.set_xlabel("largest |x - x_c| / R of the ore (per 25 m)")
b.legend(fontsize=8)
fig.suptitle("one ore through a 1,000 m riser: 5th mode against the rigid riser (0.5 m, 0.2 Hz)")
fig.tight_layout()
fig.savefig("wholeRiserModes.png", dpi=120)
