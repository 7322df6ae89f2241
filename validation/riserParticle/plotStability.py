"""Stability map of the mesh-free engine's methods, from stabilityMap's tables.

usage: plotStability.py <results folder> <png>
SPDX-License-Identifier: GPL-3.0-or-later
"""
import math
import os
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402  (after the backend)
import numpy as np  # noqa: E402
from riserfoam import tables  # noqa: E402

results, png = sys.argv[1:3]


def rows(name):
    """the table's rows, each a dict by column name"""
    return list(tables.read(os.path.join(results, name)))


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
ds = sorted({r["d"] for r in flow})
cmap = plt.get_cmap("viridis")
for law, style in (("paper", "-"), ("continuous", ":")):
    for k, d in enumerate(ds):
        pts = [r for r in flow if r["dragLaw"] == law and r["d"] == d and r["scheme"] == "paper"]
        ok = [(r["h/tau_p"], r["positionError/D"]) for r in pts if r["failed"] == 0]
        bad = [r["h/tau_p"] for r in pts if r["failed"] != 0]
        colour = cmap(k / max(1, len(ds) - 1))
        if ok:
            x, y = np.array(ok).T
            ax.loglog(x, np.maximum(y, 1e-14), style, color=colour, marker=".",
                      label=("d = %g um" % (d * 1e6)) if law == "paper" else None)
        if bad:
            ax.loglog(bad, [3.0] * len(bad), "x", color=colour)
        a = [r for r in flow if r["dragLaw"] == law and r["d"] == d and r["scheme"] == "adaptive"][0]
        ax.loglog(a["h/tau_p"], max(a["positionError/D"], 1e-14), "*", color=colour, ms=10,
                  mec="k" if law == "paper" else "w")
    paper = [r for r in flow if r["dragLaw"] == law and r["scheme"] == "paper"]
    first = min((r["h/tau_p"] for r in paper if r["failed"] != 0), default=float("nan"))
    worstOk = max(r["h/tau_p"] for r in paper if r["failed"] == 0)
    summary.append("flow steps (%s drag): fixed DP5 steps fail from h/tau_p = %.3g (largest "
                   "stable tried %.3g; linear bound %.2f)" % (law, first, worstOk, limit))
ax.axvline(limit, color="r", ls="--", lw=1)
ax.text(limit * 1.1, 0.03, "DP5 real-axis\nstability limit %.2f" % limit, color="r", fontsize=7,
        transform=ax.get_xaxis_transform())
ax.set_xlabel("flow step h / particle response time tau_p")
ax.set_ylabel("largest position error / D over one period (x: diverged)")
ax.set_title("fixed DP5 steps (paper scheme), f = 0.3 scene, no contact\n"
             "solid: paper drag (jumps at Re_p = 1, 100), dotted: continuous;\n"
             "stars: adaptive, tolerance 1e-10, the default (mean step)", fontsize=8)
ax.legend(fontsize=7, loc="lower right")
ax.grid(True, which="both", alpha=0.3)

# 2. contact steps against the Hertz contact time
ax = axes[1]
contact = rows("stabilityContact.dat")
for en, colour in ((0.76, "C0"), (1.0, "C1")):
    for scheme, style in (("paper", "o-"), ("adaptive", "s--")):
        pts = [r for r in contact if r["e_n"] == en and r["scheme"] == scheme and r["failed"] == 0]
        x = [r["h/t_c"] for r in pts]
        ax.loglog(x, [max(r["restitutionError"], 1e-12) for r in pts], style, color=colour,
                  label="%s, e_n = %g: |e - e_n|/e_n" % (scheme, en))
        if en == 1.0:
            gain = [(r["h/t_c"], r["energyChange"]) for r in pts if r["energyChange"] > 0]
            if gain:
                gx, gy = np.array(gain).T
                ax.loglog(gx, gy, "^", color="r", ms=9, mfc="none",
                          label="energy gain per contact, e_n = 1" if scheme == "paper" else None)
paper = [r for r in contact if r["scheme"] == "paper" and r["e_n"] == 0.76]
bad = [r["h/t_c"] for r in paper if r["restitutionError"] > 1e-2]
summary.append("contact steps (paper RK4 at frozen position): restitution error above 1%% "
               "from h_c/t_c = %.2g; energy gain at e_n = 1 from h_c/t_c = %s"
               % (min(bad), min((r["h/t_c"] for r in contact if r["e_n"] == 1.0 and r["scheme"] == "paper"
                                 and r["energyChange"] > 1e-3), default=float("nan"))))
ada = [r for r in contact if r["scheme"] == "adaptive" and r["e_n"] == 0.76]
# (settings as the table writes them: %.4e)
summary.append("contact, adaptive: restitution error %s at tolerances %s, with %s force "
               "evaluations per impact" % (" ".join("%.1e" % r["restitutionError"] for r in ada),
                                          " ".join("%.4e" % r["setting"] for r in ada),
                                          " ".join("%d" % r["forceEvaluations"] for r in ada)))
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
    pts = [r for r in start if r["start"] == name and r["failed"] == 0]
    ax.loglog([r["v0*h/deltaMax"] for r in pts], [max(abs(r["energyChange"]), 1e-12) for r in pts], style,
              label="contact starts at %s" % ("detection (default)" if name == "detection"
                                              else "the flow step's overlap"))
geo = [r for r in start if r["start"] == "geometric" and r["energyChange"] > 1e-3]
if geo:
    summary.append("paper scheme, contact from the geometric overlap: energy gain %.2g per contact "
                   "from v0 h = %.2g delta_max (the paper's flow step 1e-4 s at 1 m/s is %.1f delta_max: "
                   "gain %.3g)" % (geo[0]["energyChange"], geo[0]["v0*h/deltaMax"],
                                   start[-1]["v0*h/deltaMax"], start[-1]["energyChange"]))
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
