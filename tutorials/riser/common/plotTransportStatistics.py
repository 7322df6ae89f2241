#!/usr/bin/python3
"""Plots the tables of the cloud function riserTransportStatistics, read by
column name (riserfoam.tables); with --compare, several runs overlaid.

usage: plotTransportStatistics.py <riserTransportStatistics folder> <out.png> [title]
           [--compare <folder> ... [--labels a,b,...]]

A folder is postProcessing/lagrangian/<cloud>/riserTransportStatistics of
a case, holding transport.dat, radialProfile.dat, axialProfile.dat,
impactSpeeds.dat and pairImpactSpeeds.dat. Writes one figure of eight
panels:
  - the radial profile of the solids volume fraction C_v against r/R (each
    annulus of equal area at its area-mean radius), averaged over the
    samples, and that of the last sample;
  - the axial profile, averaged over the samples and at the last one;
  - the overall C_v over time, and the number of blocked slices where some
    sample had one (a note otherwise);
  - the lifting efficiency (mean relative v_z / u_cm) over time;
  - the wall and pair contact rates per parcel over time;
  - the energy dissipated in wall and in pair contacts, summed over the
    intervals from the table's start, over time;
  - the histograms of the wall impact speeds and of the pair approach
    speeds of the whole run (the sums of the rows of impactSpeeds.dat and
    pairImpactSpeeds.dat).
With --compare the further runs (dry against wet, one mesh against
another) are drawn in the same panels, one colour a run, the means only
for the profiles; --labels names the runs in the legends (default: the
case folders' names). The runs' speed bins must have the same width.
"""
from riserfoam.cli import help_requested  # noqa: E402

help_requested(__doc__)

import os
import re
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402  (after the backend)
import numpy as np  # noqa: E402
from riserfoam import tables  # noqa: E402


def bins(table, prefix):
    """The columns prefix0, prefix1, ... as an array of one row per sample."""
    names = sorted((n for n in table.names if re.fullmatch(prefix + r"\d+", n)),
                   key=lambda n: int(n[len(prefix):]))
    return np.column_stack([table[n] for n in names])


def bin_width(path):
    """The speed bins' width, from the title line of impactSpeeds.dat."""
    with open(path) as f:
        match = re.search(r"bins of ([-+0-9.eE]+) m/s", f.readline())
    return float(match.group(1))


def load(folder):
    """One run's tables"""
    impacts_path = os.path.join(folder, "impactSpeeds.dat")
    return {
        "transport": tables.read(os.path.join(folder, "transport.dat")),
        "radial": bins(tables.read(os.path.join(folder, "radialProfile.dat")), "Cv_r"),
        "axial": bins(tables.read(os.path.join(folder, "axialProfile.dat")), "Cv_z"),
        "impacts": bins(tables.read(impacts_path), "n_").sum(axis=0),
        "pairImpacts": bins(tables.read(os.path.join(folder, "pairImpactSpeeds.dat")),
                            "n_").sum(axis=0),
        "width": bin_width(impacts_path),
    }


def case_name(folder):
    """The case folder of a statistics folder (four levels up)"""
    path = os.path.abspath(folder)
    for _ in range(4):
        path = os.path.dirname(path)
    return os.path.basename(path) or folder


def parse(argv):
    """folders, labels, output, title"""
    if "--compare" in argv:
        k = argv.index("--compare")
        main_args, rest = argv[:k], argv[k + 1:]
    else:
        main_args, rest = argv, []
    labels = None
    if "--labels" in rest:
        k = rest.index("--labels")
        labels = rest[k + 1].split(",") if k + 1 < len(rest) else []
        rest = rest[:k] + rest[k + 2:]
    if len(main_args) not in (2, 3) or ("--compare" in argv and not rest):
        sys.exit(__doc__)
    folders = [main_args[0]] + rest
    if labels is None:
        labels = [case_name(f) for f in folders]
    if len(labels) != len(folders):
        sys.exit("plotTransportStatistics: --labels names %d runs, %d are given"
                 % (len(labels), len(folders)))
    title = main_args[2] if len(main_args) == 3 else " against ".join(labels)
    return folders, labels, main_args[1], title


def draw(ax, run, label, colour, alone):
    """One run's curves in the eight panels"""
    transport = run["transport"]
    t = transport["t"]
    radial, axial = run["radial"], run["axial"]
    n, m = radial.shape[1], axial.shape[1]
    # annulus k: (r/R)^2 in [k/n, (k+1)/n]; its area-mean radius
    r = np.sqrt((np.arange(n) + 0.5) / n)
    z = (np.arange(m) + 0.5) / m
    mean = "mean of %d samples" % len(t) if alone else label
    ax[0, 0].plot(r, radial.mean(axis=0), "o-", color=colour, label=mean)
    ax[0, 1].plot(axial.mean(axis=0), z, "o-", color=colour, label="mean" if alone else label)
    if alone:
        ax[0, 0].plot(r, radial[-1], "s--", color="C1", label="t = %.4g s" % t[-1])
        ax[0, 1].plot(axial[-1], z, "s--", color="C1", label="t = %.4g s" % t[-1])
    ax[1, 0].plot(t, transport["Cv"], color=colour, label="C_v" if alone else label)
    ax[1, 1].plot(t, transport["liftingEfficiency"], color=colour, label=label)
    suffix = "" if alone else " (%s)" % label
    ax[2, 0].step(t, transport["contactRate"], where="pre", color=colour,
                  label="wall%s, %d contacts" % (suffix, int(np.sum(transport["contacts"]))))
    ax[2, 0].step(t, transport["pairContactRate"], where="pre", color=colour, linestyle="--",
                  label="pair%s, %g contacts" % (suffix, np.sum(transport["pairContacts"])))
    # the energy dissipated from the start of the table on (the sum of the
    # intervals' energies)
    ax[2, 1].plot(t, np.cumsum(transport["wallEnergy"]), color=colour, label="wall" + suffix)
    ax[2, 1].plot(t, np.cumsum(transport["pairEnergy"]), color=colour, linestyle="--",
                  label="pair" + suffix)
    width = run["width"]
    for k, counts in enumerate((run["impacts"], run["pairImpacts"])):
        edges = width * np.arange(len(counts))
        if alone:
            ax[3, k].bar(edges, counts, width=width, align="edge")
        else:
            ax[3, k].step(np.append(edges, edges[-1] + width), np.append(counts, counts[-1]),
                          where="post", color=colour, label=label)


def main():
    folders, labels, out, title = parse(sys.argv[1:])
    runs = [load(f) for f in folders]
    if len({run["width"] for run in runs}) > 1:
        sys.exit("plotTransportStatistics: the runs' speed bins differ in width (%s m/s)"
                 % ", ".join("%g" % run["width"] for run in runs))
    alone = len(runs) == 1

    fig, ax = plt.subplots(4, 2, figsize=(11, 14))
    for k, (run, label) in enumerate(zip(runs, labels)):
        draw(ax, run, label, "C%d" % (0 if alone else k), alone)

    ax[0, 0].set(xlabel="r/R (annuli of equal area)", ylabel="C_v", xlim=(0, 1),
                 title="radial profile")
    ax[0, 1].set(xlabel="C_v", ylabel="z/L", ylim=(0, 1), title="axial profile")
    ax[1, 0].set(xlabel="t [s]", ylabel="C_v", title="solids fraction and blockage")
    # blocked slices, where some sample had one
    if any(np.max(run["transport"]["blockedBins"]) > 0 for run in runs):
        blocked = ax[1, 0].twinx()
        for k, run in enumerate(runs):
            blocked.step(run["transport"]["t"], run["transport"]["blockedBins"],
                         color="r" if alone else "C%d" % k, linestyle=":", where="post")
        blocked.set_ylabel("blocked slices (dotted)", color="r")
    else:
        ax[1, 0].text(0.02, 0.02, "no slice above blockageFraction at any sample",
                      transform=ax[1, 0].transAxes, fontsize=8)
    ax[1, 1].set(xlabel="t [s]", ylabel="mean v_z / u_cm", title="lifting efficiency")
    ax[2, 0].set(xlabel="t [s]", ylabel="contacts / s / parcel", title="contact rates")
    ax[2, 1].set(xlabel="t [s]", ylabel="J", title="energy dissipated in contacts, cumulative")
    speeds = (("impact speed UnIn", "wall impacts, whole run"),
              ("approach speed", "pair impacts (each parcel's), whole run"))
    for k, (speed, what) in enumerate(speeds):
        ax[3, k].set(xlabel="%s [m/s] (last bin: all faster)" % speed, ylabel="impacts",
                     title=what)
    for a in ax.flat:
        if a.get_legend_handles_labels()[0] and (not alone or a in (ax[0, 0], ax[0, 1], ax[2, 0],
                                                                     ax[2, 1])):
            a.legend(fontsize=8)

    fig.suptitle(title)
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    for run, label in zip(runs, labels):
        transport = run["transport"]
        print("plotTransportStatistics: %s: %d samples, %d wall and %g pair contacts -> %s"
              % (label, len(transport["t"]), int(np.sum(transport["contacts"])),
                 np.sum(transport["pairContacts"]), out))


if __name__ == "__main__":
    main()
