#!/usr/bin/python3
"""Plots the per-particle table of riserParticleTable (riserParcelFoam) or
the mesh-free engine, in the paper's dimensionless units (length D, velocity
u_cm, time D/u_cm), as in Wei et al. (2023), figs. 6-19.

usage: plotRiserTable.py <particles.dat> <out prefix> [title]
                         [--label NAME] [--compare <other particles.dat> NAME]

The riser (D, u_cm, A, f, phi0) is the case's constant/riserProperties, in
the current folder (the case's), so the walls drawn and the title's A and f
are those the case ran with.

Writes <prefix>_track3d.png (the particle tracks relative to the riser
axis, inside the riser wall, in 3-D; ParaView is not installed by the
project's scripts, so this stands in for a rendered picture), <prefix>_motion.png (lateral position with the riser walls, relative
lateral velocity, vertical velocity, lifting distance) and, when the wall
contact wrote contacts (riserContact/contacts.dat beside the table's
folder), <prefix>_contacts.png: each contact's largest normal overlap and
normal force, and the velocity relative to the wall before and after.
(A contact lasts tens of microseconds, far less than a flow step: the
overlaps in the table, taken at the ends of steps, are mostly zero.)

--compare overlays a second table of the same particles (another solver
or carrier of the same scene: solid lines the first, dashed the second,
--label and the compare NAME in the legends) in <prefix>_motion.png and
<prefix>_track3d.png, and prints for each table the lifting distance at
its end, the wall contacts and their mean normal restitution (the normal
speed after over before, UnOut/UnIn of contacts.dat), and the largest
differences between the two tracks at the common times.
"""
from riserfoam.cli import help_requested  # noqa: E402

help_requested(__doc__)

import argparse
import math
import os

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402  (after the backend)
import numpy as np  # noqa: E402
from riserfoam import tables  # noqa: E402
from riserfoam.carrier import Riser  # noqa: E402


def contacts_of(path):
    """riserContact's contacts.dat beside the table's folder (under the
    model's old name riserWallContact in a case that selects it), or None"""
    for model in ("riserContact", "riserWallContact"):
        found = os.path.join(os.path.dirname(os.path.dirname(path)), model,
                             "contacts.dat")
        if os.path.exists(found):
            return tables.read(found)
    return None


def summary(label, table, path, D):
    """prints the table's lift at its end, its wall contacts and their mean
    normal restitution"""
    contacts = contacts_of(path)
    line = "plotRiserTable: %s: lift %.4f D at t = %.4g s" % (
        label, table["lift"][-1] / D, table["t"][-1])
    if contacts is not None and len(contacts):
        line += ", %d wall contacts, mean UnOut/UnIn %.4f" % (
            len(contacts), np.mean(contacts["UnOut"] / contacts["UnIn"]))
    print(line)


def main():
    ap = argparse.ArgumentParser(description="plots of a riser particle table")
    ap.add_argument("path")
    ap.add_argument("prefix")
    ap.add_argument("title", nargs="?")
    ap.add_argument("--label", default="")
    ap.add_argument("--compare", nargs=2, metavar=("PATH", "NAME"))
    args = ap.parse_args()
    path, prefix = args.path, args.prefix
    riser = Riser.of_case(".")
    D, ucm = riser.D, riser.u_cm
    title = "A = %.3g D, f = %.3g u_cm/D (%.3g m, %.3g Hz)" % (
        riser.A / D, riser.f * D / ucm, riser.A, riser.f)
    if args.title:
        title = args.title + ": " + title
    T = D / ucm
    table = tables.read(path)
    times = np.unique(table["t"])
    xc = riser.axis(times) / D
    # (label, line style, {(origProc, origId): rows}) of each table
    runs = [(args.label, "-", table.group_by("origProc", "origId"))]
    if args.compare:
        other = tables.read(args.compare[0])
        runs.append((args.compare[1], "--", other.group_by("origProc", "origId")))
        summary(args.label or path, table, path, D)
        summary(args.compare[1], other, args.compare[0], D)
        for key, rows in runs[0][2].items():
            if key not in runs[1][2]:
                continue
            theirs = runs[1][2][key]
            common, mine, their = np.intersect1d(rows["t"], theirs["t"], return_indices=True)
            print("plotRiserTable: particle %d over %d common times: largest difference"
                  " of x_p %.4f D, of v_pz %.4f u_cm, of the lift %.4f D"
                  % (key[1], len(common),
                     np.abs(rows["x"][mine] - theirs["x"][their]).max() / D,
                     np.abs(rows["Uz"][mine] - theirs["Uz"][their]).max() / ucm,
                     np.abs(rows["lift"][mine] - theirs["lift"][their]).max() / D))

    fig, ax = plt.subplots(2, 2, figsize=(11, 7), sharex=True)
    ax[0][0].plot(times / T, xc + 0.5, "k-", lw=0.8, label="riser walls")
    ax[0][0].plot(times / T, xc - 0.5, "k-", lw=0.8)
    for name, style, particles in runs:
        for k, ((proc, pid), c) in enumerate(particles.items()):
            ts = c["t"] / T
            lab = ("%s, particle %d" % (name, pid)) if name else ("particle %d" % pid)
            colour = "C%d" % (k % 10)
            ax[0][0].plot(ts, c["x"] / D, style, color=colour, label=lab)
            ax[0][1].plot(ts, c["Urx"] / ucm, style, color=colour, label=lab)
            ax[1][0].plot(ts, c["Uz"] / ucm, style, color=colour, label=lab)
            ax[1][1].plot(ts, c["lift"] / D, style, color=colour, label=lab)
    ax[0][0].set_ylabel("lateral position x_p / D")
    ax[0][1].set_ylabel("relative lateral velocity (v_px - U_r) / u_cm")
    ax[1][0].set_ylabel("vertical velocity v_pz / u_cm")
    ax[1][1].set_ylabel("lifting distance / D")
    for a in ax[1]:
        a.set_xlabel("t u_cm / D")
    for a in ax.flat:
        a.grid(alpha=0.3)
    ax[0][0].legend(fontsize=7)
    if len(runs) > 1:
        ax[1][1].legend(fontsize=7)
    fig.suptitle(title)
    fig.tight_layout()
    fig.savefig(prefix + "_motion.png", dpi=110)
    print("wrote", prefix + "_motion.png")

    fig = plt.figure(figsize=(5.5, 7))
    ax3 = fig.add_subplot(projection="3d")
    zmax = max(c["lift"].max() for _, _, particles in runs for c in particles.values()) / D
    theta = [2 * math.pi * k / 60 for k in range(61)]
    for frac in (0.0, 0.5, 1.0):
        ax3.plot([0.5 * math.cos(a) for a in theta], [0.5 * math.sin(a) for a in theta],
                 [frac * zmax] * len(theta), color="grey", lw=0.6)
    for a in theta[::6]:
        ax3.plot([0.5 * math.cos(a)] * 2, [0.5 * math.sin(a)] * 2, [0, zmax],
                 color="grey", lw=0.4, alpha=0.6)
    for name, style, particles in runs:
        for k, c in enumerate(particles.values()):
            ax3.plot(c["xr"] / D, c["yr"] / D, c["lift"] / D, style, color="C%d" % (k % 10),
                     lw=1.2)
    ax3.set_xlabel("(x - x_c) / D")
    ax3.set_ylabel("y / D")
    ax3.set_zlabel("lifting distance / D")
    ax3.set_box_aspect((1, 1, max(1.0, min(zmax, 4.0))))
    ax3.set_title(title + "\ntrack relative to the riser", fontsize=9)
    fig.tight_layout()
    fig.savefig(prefix + "_track3d.png", dpi=110)
    print("wrote", prefix + "_track3d.png")

    contacts = contacts_of(path)
    if contacts is not None:
        if len(contacts):
            tc = contacts["tStart"] / T
            fig, ax = plt.subplots(1, 3, figsize=(13, 3.6))
            ax[0].plot(tc, contacts["overlapMax"] * 1e6, "o")
            ax[1].plot(tc, contacts["normalForceMax"], "o", color="C1")
            ax[2].plot(tc, contacts["Uin_x"] / ucm, "v", label="before")
            ax[2].plot(tc, contacts["Uout_x"] / ucm, "^", label="after")
            ax[2].plot(tc, contacts["Uin_z"] / ucm, "s", ms=3, label="vertical before")
            ax[2].plot(tc, contacts["Uout_z"] / ucm, "d", ms=3, label="vertical after")
            ax[0].set_ylabel("largest overlap delta_n [um]")
            ax[1].set_ylabel("largest normal force [N]")
            ax[2].set_ylabel("velocity relative to the wall / u_cm")
            ax[2].legend(fontsize=7)
            for a in ax:
                a.set_xlabel("contact start, t u_cm / D")
                a.grid(alpha=0.3)
            fig.suptitle(title + " - %d wall contacts" % len(contacts))
            fig.tight_layout()
            fig.savefig(prefix + "_contacts.png", dpi=110)
            print("wrote", prefix + "_contacts.png")

main()
