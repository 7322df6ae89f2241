#!/usr/bin/python3
"""Plots the table of riserCarrierError: scaled errors against cell size."""
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

rows = [[float(v) for v in line.split()] for line in open(sys.argv[1])
        if line.strip() and not line.startswith("#")]
size = [r[1] * 1000 for r in rows]
fig, ax = plt.subplots(figsize=(6.4, 4.4))
for col, label, colour in ((2, "velocity u / u_cm", "C0"),
                           (4, "vorticity / (2 u_cm / R)", "C1"),
                           (6, "Du/Dt / (A omega^2)", "C2")):
    ax.loglog(size, [r[col] for r in rows], "o-", color=colour, label=label + ", RMS")
    ax.loglog(size, [r[col + 1] for r in rows], "s--", color=colour, ms=4, label="max")
ax.set_xlabel("mean cell size [mm]")
ax.set_ylabel("scaled interpolation error")
ax.set_title("Interpolated against exact carrier, riser D = 0.1 m, f = 3 Hz\n"
             "(cellPoint; Du/Dt limited by the step dt = 1e-5 s of ddt)", fontsize=9)
ax.grid(alpha=0.3, which="both")
ax.legend(fontsize=7, ncol=2)
fig.tight_layout()
fig.savefig(sys.argv[2], dpi=120)
print("wrote", sys.argv[2])
