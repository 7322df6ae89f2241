"""The paper's Fig. 5: Saffman migration in a stationary riser (A = f = 0).
Releases at 0.05 .. 0.4 D from the axis with the local carrier speed,
mesh-free; lateral distance from the axis, lateral and vertical velocity.
Claim: the particles migrate to the axis.

SPDX-License-Identifier: GPL-3.0-or-later
"""
from paperFigures import D, UCM, RiserCase, claim, np, plt, quick, root, save, scratch
from riserfoam.carrier import Riser

riser = Riser()         # distances from the axis of the stationary riser

radii = [0.05, 0.1, 0.2, 0.3, 0.4]
T = 2.0 if quick else 5.0
case = (RiserCase(root, scratch, "fig05", "stationary").riser(A=0, f=0)
        .run_for(T, 2e-3).releases([(r, 0.0) for r in radii]).engine())
table = case.table()
fig, ax = plt.subplots(1, 3, figsize=(14, 4))
final = []
for pid, r in zip(sorted(table), radii):
    c = table[pid]
    dist = riser.axis_distance(c["xr"], c["yr"]) / D
    final.append(dist[-1])
    ax[0].plot(c["t"] * UCM / D, dist, label="released at %.2f D" % r)
    ax[1].plot(c["t"] * UCM / D, c["Urx"] / UCM)
    ax[2].plot(c["t"] * UCM / D, c["Urz"] / UCM)
for a, label in zip(ax, ("distance from the axis / D", "lateral velocity / u_cm",
                         "vertical velocity / u_cm")):
    a.set_xlabel("t u_cm / D")
    a.set_ylabel(label)
    a.grid(True, alpha=0.3)
ax[0].legend(fontsize=8)
fig.suptitle("Saffman migration in a stationary riser (riserParticle, d = 0.1 D, rho_p = 2000)")
save(fig, "paper_fig05_saffman.png")
settled = max(float(c["t"][np.argmax(riser.axis_distance(c["xr"], c["yr"]) / D < 0.01)])
              for c in table.values()) * UCM / D
claim("saffmanMigration", max(final),
      "all five releases (0.05..0.4 D from the axis) reach the axis: within 0.01 D by "
      "t = %.1f D/u_cm, %.1e D at %g D/u_cm" % (settled, max(final), T * UCM / D))
