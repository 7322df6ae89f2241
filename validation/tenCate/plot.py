"""Plot the ten Cate settling runs (tenCate's curves): the sphere's speed
over its fall against the published terminal speed and the measured maximum
speed (read from the summary's section 3), and its gap near the bottom (no
rebound when wet; the dry contact's rebound).

usage: plot.py <results folder> <output png>
SPDX-License-Identifier: GPL-3.0-or-later
"""
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

folder, out = sys.argv[1:3]
oils = [("E1", 0.038, 1.5), ("E2", 0.060, 4.1), ("E3", 0.091, 11.6), ("E4", 0.128, 31.9)]
styles = [("dry", "dry, Basset", "C3", "-"),
          ("dryNoBasset", "dry, no Basset", "C3", ":"),
          ("wet", "e(St), Basset", "C0", "-"),
          ("film", "film, Basset", "C2", "--"),
          ("filmNoBasset", "film, no Basset", "C2", ":")]

# measured maximum speeds [m/s], section 3 of the summary
u_max = {}
with open(f"{folder}/summary.txt") as f:
    section3 = False
    for line in f:
        section3 = section3 or line.startswith("3. ")
        words = line.split()
        if section3 and words and words[0] in {o[0] for o in oils}:
            u_max[words[0]] = float(words[2])
assert len(u_max) == len(oils), f"no measured u_max for every oil in {folder}/summary.txt"

fig, axes = plt.subplots(2, 4, figsize=(15, 7))
for col, (oil, u_inf, Re) in enumerate(oils):
    top, bottom = axes[0, col], axes[1, col]
    for name, label, colour, ls in styles:
        t, gap, v = np.loadtxt(f"{folder}/curve_{oil}_{name}.dat", unpack=True)
        top.plot(gap * 1e3, -v / u_inf, color=colour, ls=ls, label=label)
        arrive = t[np.argmax(gap < 1e-3)]
        bottom.plot(t - arrive, gap * 1e3, color=colour, ls=ls, label=label)
    top.axhline(1.0, color="k", lw=0.8)
    top.axhline(u_max[oil] / u_inf, color="k", lw=1.2, ls="--",
                label="measured u_max" if col == 0 else None)
    top.set_xlim(125, -2)
    top.set_ylim(0, 1.2)
    top.set_title(f"{oil}: Re = {Re}, u_inf = {u_inf} m/s")
    top.set_xlabel("gap above the bottom [mm]")
    bottom.set_xlim(-0.05, 0.6)
    bottom.set_ylim(-0.05, 1.5 if col < 3 else 5.0)
    bottom.set_xlabel("t - t(gap = 1 mm) [s]")
    bottom.axhline(0.0, color="k", lw=0.8)
axes[0, 0].set_ylabel("descent speed / published u_inf")
axes[1, 0].set_ylabel("gap [mm]")
axes[0, 0].legend(fontsize=8, loc="lower center")
fig.suptitle("ten Cate et al. (2002): a 15 mm nylon sphere settling onto the bottom"
             " (model: unbounded drag; no rebound when wet)")
fig.tight_layout()
fig.savefig(out, dpi=110)
print("wrote", out)
