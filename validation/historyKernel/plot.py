"""The flagship's lift with the classical and the finite-Re history kernel
(see Allrun): the lift against time in the shaken and the still riser.

usage: plot.py <work folder> <output png>"""
import os
import sys

from riserfoam.cli import help_requested  # noqa: E402

help_requested(__doc__)

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from riserfoam import tables  # noqa: E402

work, out = sys.argv[1:3]
TABLE = "postProcessing/lagrangian/kinematicCloud/riserParticleTable/particles.dat"
LABELS = {"classical": "classical kernel, C_H = 6",
          "michaelidesRoig": "classical kernel, C_H Michaelides-Roig",
          "meiAdrian": "finite-Re kernel (Mei & Adrian 1992)"}
fig, axes = plt.subplots(1, 2, figsize=(11, 4.2))
for ax, scene, title in zip(axes, ("flagship", "still"),
                            ("riser shaken at 3 Hz, A = 0.1 m (flagship)", "riser at rest")):
    for kernel, label in LABELS.items():
        t = tables.read(os.path.join(work, "%s_%s" % (scene, kernel), TABLE))
        ax.plot(t["t"], t["lift"], label=label)
    ax.set_xlabel("t [s]")
    ax.set_ylabel("lift [m]")
    ax.set_title(title, fontsize=10)
    ax.grid(alpha=0.3)
axes[0].legend(fontsize=8)
fig.suptitle("10 mm ore, 2000 kg/m$^3$, in water at $u_c$ = 1 m/s (Re$_p$ ~ 5e3): the history kernel",
             fontsize=10)
fig.tight_layout()
fig.savefig(out, dpi=120)
print("wrote", out)
