"""Plot the Basset benchmark (bassetBenchmark's .dat files) into one PNG.

usage: plot.py <folder with the .dat files> <output png>
SPDX-License-Identifier: GPL-3.0-or-later
"""
import os
import sys
from collections import defaultdict

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402  (after the backend)
import numpy as np  # noqa: E402
from riserfoam import tables  # noqa: E402

folder, out = sys.argv[1:3]


def table(name):
    return tables.read(os.path.join(folder, name))


fig, (a1, a2, a3) = plt.subplots(1, 3, figsize=(16, 4.8))

cost = defaultdict(list)
for r in table("costPerStep.dat"):
    label = ("full history" if r["method"] == "fullHistory"
             else "window %g steps + tail" % float(r["window"]))
    cost[label].append((int(r["n"]), float(r["ns_per_step"]) * 1e-3, int(r["bytes_per_particle"])))
for label, data in cost.items():
    n, us, mem = np.array(data).T
    a1.loglog(n, us, "o-", label="%s (%.1f kB/particle at 1e5)" % (label, mem[-1] / 1024))
a1.set_xlabel("history length [steps]")
a1.set_ylabel("cost per particle-step [us]")
a1.set_title("cost of the history per step (3-vector)")
a1.legend(fontsize=8)
a1.grid(True, which="both", alpha=0.3)

work = defaultdict(list)
for r in table("workPrecision.dat"):
    if r["method"] == "fullHistory":
        label = "full history"
    elif r["method"] == "noBasset":
        label = "Basset dropped"
    else:
        label = "window %g s + tail (%s)" % (float(r["windowTime"]), r["tail"])
    work[label].append((float(r["cpu"]), float(r["maxRelError"]), float(r["h"])))
for label, data in work.items():
    cpu, err, h = np.array(data).T
    style = "x--" if label == "Basset dropped" else "o-"
    a2.loglog(np.maximum(cpu, 1e-6), err, style, label=label)
a2.set_xlabel("CPU time for 1 s of settling [s]")
a2.set_ylabel("largest error / V(1 s)")
a2.set_title("settling from rest: h = 1e-2 .. 1e-4 s")
a2.legend(fontsize=8)
a2.grid(True, which="both", alpha=0.3)

stability = table("stability.dat")
ratio = stability["h/hCrit"]
lagged = stability["largest|v|/Vt_lagged"]
implicit = stability["largest|v|/Vt_implicit"]
a3.loglog(ratio, np.minimum(lagged, 1e30), "s-", label="newest weight lagged (explicit)")
a3.loglog(ratio, implicit, "o-", label="newest weight implicit (library)")
a3.axvline(1.0, color="k", lw=0.8, ls=":")
a3.set_xlabel("h / h_c,  K_H (4/3) sqrt(h_c) = m_p + m_A")
a3.set_ylabel("largest |v| / V_t over the run")
a3.set_title("light sphere, rho_p/rho_f = 0.1")
a3.legend(fontsize=8)
a3.grid(True, which="both", alpha=0.3)

fig.tight_layout()
fig.savefig(out, dpi=110)
print("wrote", out)
