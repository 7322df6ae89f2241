#!/usr/bin/python3
"""Charts of the ores along the section of a swaying riser (this tutorial,
or a case bin/riserCase made with -motion modes or table).

usage: plotAlongRiser.py <case folder> <output.png> [averaging start [s]]

From riserTransportStatistics' slices (the samples from the averaging
start on, default half the run): the solids fraction, the ores' mean
velocity relative to the riser and lifting efficiency, and the wall and
pair contacts per second in each slice, against height, beside the local
amplitude of the riser's sway (of a mode); and from riserOutflow the
transit times of the ores that left at the top."""
from riserfoam.cli import help_requested  # noqa: E402

help_requested(__doc__)

import math
import os
import re
import subprocess
import sys
import warnings

import numpy as np

from riserfoam import tables
from riserfoam import foamfields as ff


def motion_entry(case, name):
    """an entry of the riser's motion dictionary, as text (None if absent)"""
    done = subprocess.run(["foamDictionary", "-entry", "motion/" + name, "-value",
                           os.path.join(case, "constant/riserProperties")],
                          stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True)
    return done.stdout.strip() if done.returncode == 0 else None


def local_sway(case, z):
    """the amplitude of the riser's sway at heights z, and a title for the
    motion: the modes' (in x and y), None for a table or tabulated shapes"""
    if motion_entry(case, "type") != "modes":
        return None, "the riser's motion table"
    if motion_entry(case, "shapes") is not None:
        return None, "a riser in its tabulated mode shapes"
    foot, length = float(motion_entry(case, "foot")), float(motion_entry(case, "length"))
    standing = (motion_entry(case, "wave") or "standing") == "standing"
    sway = np.zeros_like(z)
    numbers = []
    for component in ("x", "y"):
        text = motion_entry(case, component) or "()"
        for n, a, _, _ in re.findall(r"\(\s*(\S+)\s+(\S+)\s+(\S+)\s+(\S+)\s*\)", text):
            shape = np.abs(np.sin(float(n) * math.pi * (z - foot) / length)) if standing else 1.0
            sway = np.hypot(sway, float(a) * shape)
            numbers.append(str(int(float(n))))
    return sway, "a riser in mode %s" % ", ".join(numbers)


def centre_line_speed(stats):
    """u_cm of the statistics (their lifting efficiency is v_z/u_cm)"""
    transport = tables.read(os.path.join(stats, "transport.dat"))
    for urz, eta in zip(transport["Urz"], transport["liftingEfficiency"]):
        if math.isfinite(urz) and math.isfinite(eta) and eta != 0:
            return urz / eta
    return None


def main():
    if len(sys.argv) not in (3, 4):
        sys.exit(__doc__)
    case, output = sys.argv[1:3]
    stats = os.path.join(case, "postProcessing/lagrangian/kinematicCloud/riserTransportStatistics")
    cv = tables.read(os.path.join(stats, "axialProfile.dat"))
    urz = tables.read(os.path.join(stats, "axialVelocity.dat"))
    contacts = tables.read(os.path.join(stats, "axialContacts.dat"))
    t = np.asarray(cv["t"])
    start = float(sys.argv[3]) if len(sys.argv) == 4 else 0.5 * t[-1]
    rows = t >= start - 1e-9
    if not rows.any():
        sys.exit("plotAlongRiser.py: no sample after %g s" % start)
    m = len(cv.names) - 1
    header = open(os.path.join(stats, "axialProfile.dat")).readline()
    z0 = float(re.search(r"from z = (\S+) m", header).group(1))
    points = ff.read_vectors(os.path.join(case, "constant/polyMesh/points"))
    length = max(p[2] for p in points) - min(p[2] for p in points)
    z = z0 + (np.arange(m) + 0.5) * length / m
    ucm = centre_line_speed(stats)
    amplitude, title = local_sway(case, z)

    def mean(table, prefix):
        values = np.array([np.asarray(table["%s%d" % (prefix, k)])[rows] for k in range(m)])
        with warnings.catch_warnings():
            # a slice empty at every sample has no mean (nan: not drawn)
            warnings.simplefilter("ignore", RuntimeWarning)
            return np.nanmean(values, axis=1)

    span = t[rows][-1] - (t[rows][0] - (t[1] - t[0]))
    wall = np.array([np.sum(np.asarray(contacts["wall_z%d" % k])[rows]) for k in range(m)]) / span
    pair = np.array([np.sum(np.asarray(contacts["pair_z%d" % k])[rows]) for k in range(m)]) / span

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(1, 4, figsize=(14, 4.2), sharey=False)
    ax[0].plot(mean(cv, "Cv_z"), z, "o-")
    ax[0].set_xlabel("solids fraction C_v")
    ax[0].set_ylabel("height z [m]")
    velocity = mean(urz, "Urz_z")
    ax[1].plot(velocity, z, "o-", label="mean v_z [m/s]")
    if ucm:
        ax[1].plot(velocity / ucm, z, "s--", label="lifting efficiency v_z/u_cm")
    ax[1].legend(fontsize=8)
    ax[1].set_xlabel("ore velocity along the riser")
    ax[2].plot(wall, z, "o-", label="wall")
    ax[2].plot(pair, z, "s-", label="pair")
    ax[2].set_xlabel("contacts per second in each slice")
    ax[2].legend(fontsize=8)
    if amplitude is not None:
        sway = ax[2].twiny()
        sway.plot(amplitude, z, "k:", lw=1)
        sway.set_xlabel("local sway amplitude [m] (dotted)")
    # outflow.dat, or one outflow_procN.dat per processor in parallel
    folder = os.path.join(case, "postProcessing/lagrangian/kinematicCloud/riserOutflow")
    top, back = [], 0
    for name in sorted(os.listdir(folder)):
        outflow = tables.read(os.path.join(folder, name))
        top += [tt for tt, p in zip(outflow["transitTime"], outflow["patch"]) if p == "top"]
        back += sum(1 for p in outflow["patch"] if p == "bottom")
    if top:
        ax[3].hist(top, bins=30)
    ax[3].set_xlabel("transit time of the ores out at the top [s]")
    ax[3].set_ylabel("ores")
    for a_ in ax[:3]:
        a_.set_ylim(z0, z0 + length)
    fig.suptitle("ores through the section z = %g-%g m of %s; slices averaged"
                 " over t = %g-%g s; %d ores out at the top"
                 % (z0, z0 + length, title, start, t[-1], len(top)))
    fig.tight_layout()
    fig.savefig(output, dpi=110)
    print("plotAlongRiser.py: %s (%d ores out at the top, %d back through the inlet)"
          % (output, len(top), back))


main()
