#!/usr/bin/python3
"""Plots the tables of the cloud function riserTransportStatistics, read by
column name (riserfoam.tables).

usage: plotTransportStatistics.py <riserTransportStatistics folder> <out.png> [title]

The folder is postProcessing/lagrangian/<cloud>/riserTransportStatistics of
a case, holding transport.dat, radialProfile.dat, axialProfile.dat,
impactSpeeds.dat and pairImpactSpeeds.dat. Writes one figure of eight
panels:
  - the radial profile of the solids volume fraction C_v against r/R (each
    annulus of equal area at its area-mean radius), averaged over the
    samples, and that of the last sample;
  - the axial profile, averaged over the samples and at the last one;
  - the overall C_v and the number of blocked slices over time;
  - the lifting efficiency (mean relative v_z / u_cm) over time;
  - the wall and pair contact rates per parcel over time;
  - the energy dissipated in wall and in pair contacts, summed over the
    intervals from the table's start, over time;
  - the histograms of the wall impact speeds and of the pair approach
    speeds of the whole run (the sums of the rows of impactSpeeds.dat and
    pairImpactSpeeds.dat), side by side.
"""
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


def main():
    folder, out = sys.argv[1:3]
    title = sys.argv[3] if len(sys.argv) > 3 else folder
    transport = tables.read(os.path.join(folder, "transport.dat"))
    radial = bins(tables.read(os.path.join(folder, "radialProfile.dat")), "Cv_r")
    axial = bins(tables.read(os.path.join(folder, "axialProfile.dat")), "Cv_z")
    impacts_path = os.path.join(folder, "impactSpeeds.dat")
    impacts = bins(tables.read(impacts_path), "n_").sum(axis=0)
    pair_impacts = bins(tables.read(os.path.join(folder, "pairImpactSpeeds.dat")),
                        "n_").sum(axis=0)
    t = transport["t"]

    fig, ax = plt.subplots(4, 2, figsize=(11, 14))
    n = radial.shape[1]
    # annulus k: (r/R)^2 in [k/n, (k+1)/n]; its area-mean radius
    r = np.sqrt((np.arange(n) + 0.5) / n)
    ax[0, 0].plot(r, radial.mean(axis=0), "o-", label="mean of %d samples" % len(t))
    ax[0, 0].plot(r, radial[-1], "s--", label="t = %.4g s" % t[-1])
    ax[0, 0].set(xlabel="r/R (annuli of equal area)", ylabel="C_v", xlim=(0, 1),
                 title="radial profile")
    ax[0, 0].legend()

    m = axial.shape[1]
    z = (np.arange(m) + 0.5) / m
    ax[0, 1].plot(axial.mean(axis=0), z, "o-", label="mean")
    ax[0, 1].plot(axial[-1], z, "s--", label="t = %.4g s" % t[-1])
    ax[0, 1].set(xlabel="C_v", ylabel="z/L", ylim=(0, 1), title="axial profile")
    ax[0, 1].legend()

    ax[1, 0].plot(t, transport["Cv"], label="C_v")
    ax[1, 0].set(xlabel="t [s]", ylabel="C_v", title="solids fraction and blockage")
    blocked = ax[1, 0].twinx()
    blocked.step(t, transport["blockedBins"], "r", where="post", label="blocked slices")
    blocked.set_ylabel("blocked slices", color="r")

    ax[1, 1].plot(t, transport["liftingEfficiency"])
    ax[1, 1].set(xlabel="t [s]", ylabel="mean v_z / u_cm", title="lifting efficiency")

    ax[2, 0].step(t, transport["contactRate"], where="pre",
                  label="wall (%d contacts)" % int(np.sum(transport["contacts"])))
    ax[2, 0].step(t, transport["pairContactRate"], where="pre",
                  label="pair (%g contacts)" % np.sum(transport["pairContacts"]))
    ax[2, 0].set(xlabel="t [s]", ylabel="contacts / s / parcel", title="contact rates")
    ax[2, 0].legend()

    # the energy dissipated from the start of the table on (the sum of the
    # intervals' energies)
    ax[2, 1].plot(t, np.cumsum(transport["wallEnergy"]), label="wall")
    ax[2, 1].plot(t, np.cumsum(transport["pairEnergy"]), label="pair")
    ax[2, 1].set(xlabel="t [s]", ylabel="J", title="energy dissipated in contacts, cumulative")
    ax[2, 1].legend()

    width = bin_width(impacts_path)
    panels = ((impacts, "impact speed UnIn", "wall impacts, whole run"),
              (pair_impacts, "approach speed", "pair impacts (each parcel's), whole run"))
    for k, (counts, speed, what) in enumerate(panels):
        edges = width * np.arange(len(counts))
        ax[3, k].bar(edges, counts, width=width, align="edge")
        ax[3, k].set(xlabel="%s [m/s] (last bin: all faster)" % speed, ylabel="impacts",
                     title=what)

    fig.suptitle(title)
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    print("plotTransportStatistics: %d samples, %d wall and %g pair contacts -> %s"
          % (len(t), int(np.sum(transport["contacts"])), np.sum(transport["pairContacts"]),
             out))


if __name__ == "__main__":
    main()
