"""The paper's Figs. 14-16: the riser amplitude. A = 0.5 .. 2 at f = 0.05
and f = 0.3, release at x_p0 = y_p0 = 0.2 D with the local carrier speed,
mesh-free: relative lateral velocity, vertical velocity, lifting distance
over a fixed time. Claim: the relative lateral velocity grows and the
lifting distance falls with A.

SPDX-License-Identifier: GPL-3.0-or-later
"""
from paperFigures import D, UCM, RiserCase, claim, np, plt, quick, root, save, scratch

As = [0.5, 0.75, 1.0, 1.5, 2.0]
duration = 4.0 if quick else 10.0
fig, ax = plt.subplots(2, 3, figsize=(16, 8))
for row, f in enumerate((0.05, 0.3)):
    lat, lift = [], []
    for A in As:
        c = (RiserCase(root, scratch, "fig14_%g_%g" % (f, A)).riser(A=A, f=f)
             .run_for(duration, 2e-3).releases([(0.2, 0.2)]).engine().table()[0])
        t = c["t"] * UCM / D
        ax[row, 0].plot(t, c["Urx"] / UCM, lw=0.8, label="A = %g" % A)
        ax[row, 1].plot(t, c["Uz"] / UCM, lw=0.8)
        ax[row, 2].plot(t, c["lift"] / D, label="A = %g" % A)
        half = c["t"] >= duration / 2
        lat.append(np.abs(c["Urx"][half]).max() / UCM)
        lift.append(c["lift"][-1] / D)
    for a, label in zip(ax[row], ("(v_px - U_r) / u_cm", "v_pz / u_cm", "lifting distance / D")):
        a.set_xlabel("t u_cm / D")
        a.set_ylabel(label)
        a.set_title("f = %g" % f)
        a.grid(True, alpha=0.3)
    ax[row, 0].set_xlim(0, 40 if f < 0.1 else 10)
    ax[row, 1].set_xlim(0, 40 if f < 0.1 else 10)
    ax[row, 2].legend(fontsize=8)
    claim("amplitudeTrends_f%g" % f, {"lateral": lat, "lift": lift},
          "f = %g: largest relative lateral speed %s u_cm and lifting distance after %g D/u_cm "
          "%s D for A = %s" % (f, "/".join("%.2f" % v for v in lat), duration * UCM / D,
                              "/".join("%.1f" % v for v in lift), "/".join("%g" % a for a in As)))
fig.suptitle("riser amplitude (riserParticle)")
save(fig, "paper_fig14_16_amplitude.png")
