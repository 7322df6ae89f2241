#!/usr/bin/python3
"""Settling speed of the glass bead against time, from the lagrangian
velocity the solver writes at each write time; writes settlingSpeed.png.

usage: plotSettling.py     (in the case folder, after its run)"""
from riserfoam.cli import help_requested  # noqa: E402

help_requested(__doc__)

import os

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402  (after the backend)
from riserfoam import foamfields  # noqa: E402


def parcel_velocity(time_dir):
    """z velocity of the single parcel written in time_dir, or None."""
    path = os.path.join(time_dir, "lagrangian", "kinematicCloud", "U")
    if not os.path.exists(path):
        return None
    velocities = foamfields.read_vectors(path)
    return velocities[0][2] if velocities else None


times, speeds = [0.0], [0.0]   # released from rest
for name in os.listdir("."):
    try:
        t = float(name)
    except ValueError:
        continue
    uz = parcel_velocity(name)
    if uz is not None:
        times.append(t)
        speeds.append(-uz)
order = sorted(range(len(times)), key=times.__getitem__)
times = [times[i] for i in order]
speeds = [speeds[i] for i in order]

fig, ax = plt.subplots(figsize=(6, 4))
ax.plot(times, speeds, "o-", ms=3, label="icoUncoupledKinematicParcelFoam + wallCorrectedDrag")
ax.axhline(speeds[-1], color="grey", ls="--", lw=1,
           label="final speed %.4f m/s" % speeds[-1])
ax.set_xlabel("t [s]")
ax.set_ylabel("settling speed [m/s]")
ax.set_title("0.5 mm glass bead in water (d/D = 0.025)")
ax.legend(loc="lower right")
ax.grid(alpha=0.3)
fig.tight_layout()
fig.savefig("settlingSpeed.png", dpi=120)
