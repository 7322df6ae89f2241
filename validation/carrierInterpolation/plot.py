#!/usr/bin/python3
"""Plots the table of riserCarrierError: scaled errors against cell size."""
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402  (after the backend)
from riserfoam import tables  # noqa: E402

errors = tables.read(sys.argv[1])
size = errors["cellSize"] * 1000
fig, ax = plt.subplots(figsize=(6.4, 4.4))
for quantity, label, colour in (("Velocity", "velocity u / u_cm", "C0"),
                                ("Vorticity", "vorticity / (2 u_cm / R)", "C1"),
                                ("MaterialDerivative", "Du/Dt / (A omega^2)", "C2")):
    ax.loglog(size, errors["rms" + quantity], "o-", color=colour, label=label + ", RMS")
    ax.loglog(size, errors["max" + quantity], "s--", color=colour, ms=4, label="max")
ax.set_xlabel("mean cell size [mm]")
ax.set_ylabel("scaled interpolation error")
ax.set_title("Interpolated against exact carrier, riser D = 0.1 m, f = 3 Hz\n"
             "(cellPoint; Du/Dt limited by the step dt = 1e-5 s of ddt)", fontsize=9)
ax.grid(alpha=0.3, which="both")
ax.legend(fontsize=7, ncol=2)
fig.tight_layout()
fig.savefig(sys.argv[2], dpi=120)
print("wrote", sys.argv[2])
