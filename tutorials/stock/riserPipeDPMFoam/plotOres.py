#!/usr/bin/python3
"""oreVelocities.png: the ores' axial velocity against their distance from
the axis at the case's last time, beside the water's Poiseuille velocity
2 u_b (1 - r^2/R^2); the gap between them is each ore's slip.

usage: plotOres.py [-bulk 0.1]   (in the case, after the solver)
"""
from riserfoam.cli import help_requested  # noqa: E402

help_requested(__doc__)

import argparse
import math
import os
import re

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

from riserfoam import foamfields as ff


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("-bulk", type=float, default=0.1, help="bulk velocity [m/s]")
    args = ap.parse_args()
    D = float(re.search(r"D = (\S+) m", open("system/blockMeshDict").read()).group(1))
    R = 0.5 * D
    times = [t for t in os.listdir(".") if re.fullmatch(r"[0-9.e+-]+", t) and t != "0"]
    last = max(times, key=float)
    cloud = os.path.join(last, "lagrangian", "kinematicCloud")
    # the positions file of this OpenFOAM: one "(x y z) cell" row per ore
    rows = re.findall(r"^\(([-0-9.eE+]+) ([-0-9.eE+]+) [-0-9.eE+]+\) \d+$",
                      open(os.path.join(cloud, "positions")).read(), re.M)
    r = [math.hypot(float(x), float(y)) / R for x, y in rows]
    vz = [u[2] for u in ff.read_vectors(os.path.join(cloud, "U"))]
    if len(r) != len(vz):
        raise SystemExit("plotOres.py: %d positions, %d velocities" % (len(r), len(vz)))

    fig, ax = plt.subplots(figsize=(6, 4))
    grid = [i / 100 for i in range(101)]
    ax.plot(grid, [2 * args.bulk * (1 - s * s) for s in grid], "b-", label="water, Poiseuille")
    ax.plot(r, vz, "k.", label="ores at t = %s s (%d)" % (last, len(vz)))
    ax.axhline(0, color="0.6", lw=0.8)
    ax.set_xlabel("distance from the axis r/R")
    ax.set_ylabel("axial velocity [m/s]")
    ax.set_xlim(0, 1)
    ax.legend()
    ax.set_title("DPMFoam with the riser forces: ores in laminar pipe flow")
    fig.tight_layout()
    fig.savefig("oreVelocities.png", dpi=120)


main()
