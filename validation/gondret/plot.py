"""Plot the Gondret bounce (gondret's curves and the digitized experiment):
gap h(t) and velocity v(t), with and without the Basset force, wet by the
restitution e(St) and wet by the lubrication film.

usage: plot.py <results folder> <experiment csv> <output png>
SPDX-License-Identifier: GPL-3.0-or-later
"""
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

folder, csv, out = sys.argv[1:4]

t_e, h_e = np.loadtxt(csv, delimiter=",", comments="#", unpack=True)
# experimental velocity: differences of consecutive points, at their
# midpoints, leaving out the intervals next to a contact (a local minimum)
v_e = np.diff(h_e) / np.diff(t_e)
tm_e = 0.5 * (t_e[1:] + t_e[:-1])
minimum = np.zeros(len(h_e), bool)
minimum[1:-1] = (h_e[1:-1] < h_e[:-2]) & (h_e[1:-1] < h_e[2:])
keep = ~(minimum[:-1] | minimum[1:])

published = np.array([[0.037, 7.47], [0.106, 2.23], [0.140, 0.52]])

fig, (a1, a2) = plt.subplots(2, 1, figsize=(8, 7.5), sharex=True)
styles = [("curve_basset.dat", "model, with Basset (C_H = 6)", "C0", "-"),
          ("curve_noBasset.dat", "model, without Basset", "C3", "--"),
          ("curve_wet.dat", "model, with Basset, wet restitution e_dry exp(-35/St)", "C2", "-."),
          ("curve_wetNoBasset.dat", "model, without Basset, wet restitution", "C1", ":"),
          ("curve_film.dat", "model, with Basset, lubrication film (defaults)", "C4", "-"),
          ("curve_filmNoBasset.dat", "model, without Basset, lubrication film", "C5", "--")]
for name, label, color, ls in styles:
    t, h, v = np.loadtxt("%s/%s" % (folder, name), unpack=True)
    a1.plot(t, h * 1e3, ls, color=color, lw=1.4, label=label)
    a2.plot(t, v, ls, color=color, lw=1.2, label=label)
a1.plot(t_e, h_e * 1e3, "o", ms=3.5, mfc="none", color="k", label="Gondret et al. (2002), digitized")
a1.plot(published[:, 0], published[:, 1], "k+", ms=10, mew=1.5, label="published apexes")
a2.plot(tm_e[keep], v_e[keep], "o", ms=3.5, mfc="none", color="k",
        label="experiment, differences of the digitized gap")
a1.set_ylabel("gap h [mm]")
a1.set_ylim(-0.5, 13.5)
a1.set_title("steel sphere d = 3 mm in silicone oil on glass, St = 152: released 1 m above the wall,\n"
              "Hertz-Mindlin e_dry = 0.97 (dry), e(St) (wet) or e_dry behind the lubrication film", fontsize=10)
a1.legend(fontsize=8)
a1.grid(alpha=0.3)
a2.axhline(0.0, color="k", lw=0.6)
a2.set_xlabel("t after the first contact [s]")
a2.set_ylabel("v [m/s] (up > 0)")
a2.legend(fontsize=8, loc="lower right")
a2.grid(alpha=0.3)
a2.set_xlim(-0.02, 0.25)
fig.tight_layout()
fig.savefig(out, dpi=110)
print("wrote", out)
