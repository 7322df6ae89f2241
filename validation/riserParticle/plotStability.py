"""Stability map of the mesh-free engine's methods, from stabilityMap's tables.

usage: plotStability.py <results folder> <png>
SPDX-License-Identifier: GPL-3.0-or-later
"""
import math
import os
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

results, png = sys.argv[1:3]


def rows(name):
    return [l.split() for l in open(os.path.join(results, name)) if not l.startswith("#")]


def dp5_real_stability_limit():
    """x > 0 where |R(-x)| = 1 for Dormand-Prince 5: R(z) = sum z^k/k! (k <= 5) + z^6/600"""
    R = lambda z: sum(z ** k / math.factorial(k) for k in range(6)) + z ** 6 / 600.0
    lo, hi = 1.0, 5.0
    for _ in range(100):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if abs(R(-mid)) <= 1.0 else (lo, mid)
    return lo


fig, axes = plt.subplots(1, 3, figsize=(17, 5))
summary = []

# 1. flow steps against the response time
ax = axes[0]
flow = rows("stabilityFlow.dat")
limit = dp5_real_stability_limit()
ds = sorted({float(r[1]) for r in flow})
cmap = plt.get_cmap("viridis")
for law, style in (("paper", "-"), ("continuous", ":")):
    for k, d in enumerate(ds):
        pts = [r for r in flow if r[0] == law and float(r[1]) == d and r[3] == "paper"]
        ok = [(float(r[5]), float(r[6])) for r in pts if r[7] == "0"]
        bad = [float(r[5]) for r in pts if r[7] != "0"]
        colour = cmap(k / max(1, len(ds) - 1))
        if ok:
            x, y = np.array(ok).T
            ax.loglog(x, np.maximum(y, 1e-14), style, color=colour, marker=".",
                      label=("d = %g um" % (d * 1e6)) if law == "paper" else None)
        if bad:
            ax.loglog(bad, [3.0] * len(bad), "x", color=colour)
        a = [r for r in flow if r[0] == law and float(r[1]) == d and r[3] == "adaptive"][0]
        ax.loglog(float(a[5]), max(float(a[6]), 1e-14), "*", color=colour, ms=10,
                  mec="k" if law == "paper" else "w")
    bad = [r for r in flow if r[0] == law and r[3] == "paper" and r[7] != "0"]
    first = min(float(r[5]) for r in bad) if bad else float("nan")
    worstOk = max((float(r[5]) for r in flow if r[0] == law and r[3] == "paper" and r[7] == "0"))
    summary.append("flow steps (%s drag): fixed DP5 steps fail from h/tau_p = %.3g (largest "
                   "stable tried %.3g; linear bound %.2f)" % (law, first, worstOk, limit))
ax.axvline(limit, color="r", ls="--", lw=1)
ax.text(limit * 1.1, 0.03, "DP5 real-axis\nstability limit %.2f" % limit, color="r", fontsize=7,
        transform=ax.get_xaxis_transform())
ax.set_xlabel("flow step h / particle response time tau_p")
ax.set_ylabel("largest position error / D over one period (x: diverged)")
ax.set_title("fixed DP5 steps (paper scheme), f = 0.3 scene, no contact\n"
             "solid: paper drag (jumps at Re_p = 1, 100), dotted: continuous;\n"
             "stars: adaptive, tolerance 1e-6 (mean step)", fontsize=8)
ax.legend(fontsize=7, loc="lower right")
ax.grid(True, which="both", alpha=0.3)

# 2. contact steps against the Hertz contact time
ax = axes[1]
contact = rows("stabilityContact.dat")
for en, colour in (("0.76", "C0"), ("1", "C1")):
    for scheme, style in (("paper", "o-"), ("adaptive", "s--")):
        pts = [r for r in contact if r[0] == en and r[1] == scheme and r[6] == "0"]
        x = [float(r[3]) for r in pts]
        ax.loglog(x, [max(float(r[4]), 1e-12) for r in pts], style, color=colour,
                  label="%s, e_n = %s: |e - e_n|/e_n" % (scheme, en))
        if en == "1":
            gain = [(float(r[3]), float(r[5])) for r in pts if float(r[5]) > 0]
            if gain:
                gx, gy = np.array(gain).T
                ax.loglog(gx, gy, "^", color="r", ms=9, mfc="none",
                          label="energy gain per contact, e_n = 1" if scheme == "paper" else None)
paper = [r for r in contact if r[1] == "paper" and r[0] == "0.76"]
bad = [float(r[3]) for r in paper if float(r[4]) > 1e-2]
summary.append("contact steps (paper RK4 at frozen position): restitution error above 1%% "
               "from h_c/t_c = %.2g; energy gain at e_n = 1 from h_c/t_c = %s"
               % (min(bad), min((float(r[3]) for r in contact if r[0] == "1" and r[1] == "paper"
                                 and float(r[5]) > 1e-3), default=float("nan"))))
ada = [r for r in contact if r[1] == "adaptive" and r[0] == "0.76"]
summary.append("contact, adaptive: restitution error %s at tolerances %s, with %s force "
               "evaluations per impact" % (" ".join("%.1e" % float(r[4]) for r in ada),
                                          " ".join(r[2] for r in ada),
                                          " ".join(r[8] for r in ada)))
ax.axvline(1e-7 / 2.8e-5, color="k", ls=":", lw=1)
ax.text(1e-7 / 2.8e-5 * 1.1, 0.03, "paper's h_c\n(1e-6 D/u_cm)", fontsize=7,
        transform=ax.get_xaxis_transform())
ax.axhline(1e-2, color="r", ls="--", lw=1)
ax.set_xlabel("contact step / Hertz contact time t_c (adaptive: t_c / its steps in contact)")
ax.set_ylabel("restitution error; energy gain")
ax.set_title("dry normal impact, 10 mm ore on steel, 1 m/s (t_c = 28 us)", fontsize=8)
ax.legend(fontsize=7, loc="upper left")
ax.grid(True, which="both", alpha=0.3)

# 3. where the paper scheme's contact starts
ax = axes[2]
start = rows("stabilityStart.dat")
for name, style in (("detection", "o-"), ("geometric", "s--")):
    pts = [r for r in start if r[2] == name and r[4] == "0"]
    ax.loglog([float(r[1]) for r in pts], [max(abs(float(r[3])), 1e-12) for r in pts], style,
              label="contact starts at %s" % ("detection (default)" if name == "detection"
                                              else "the flow step's overlap"))
geo = [r for r in start if r[2] == "geometric" and float(r[3]) > 1e-3]
if geo:
    summary.append("paper scheme, contact from the geometric overlap: energy gain %.2g per contact "
                   "from v0 h = %.2g delta_max (the paper's flow step 1e-4 s at 1 m/s is %.1f delta_max: "
                   "gain %.3g)" % (float(geo[0][3]), float(geo[0][1]), float(start[-1][1]),
                                   float(start[-1][3])))
ax.axvline(1.0, color="r", ls="--", lw=1)
ax.set_xlabel("distance a flow step travels / the contact's largest overlap (v0 h / delta_max)")
ax.set_ylabel("|energy change| per contact at e_n = 1")
ax.set_title("paper scheme: where the contact's overlap starts", fontsize=8)
ax.legend(fontsize=7)
ax.grid(True, which="both", alpha=0.3)

fig.tight_layout()
fig.savefig(png, dpi=110)
open(os.path.join(results, "stability.txt"), "w").write("\n".join(summary) + "\n")
print("\n".join(summary))
