"""The paper's Figs. 17-19: without and with wall contacts, A = 1, f = 0.05
and f = 0.3, release at x_p0 = y_p0 = 0.2 D with the local carrier speed,
run by both engines side by side: riserParcelFoam (riser frame, static
O-grid, exact carrier) and the mesh-free riserParticle; the particle and the
riser walls x(t), v_px, v_pz, and the 3-D track. Claims: contacts shift the
phase of the particle's lateral motion against the riser's; the two engines
agree (largest relative position difference, lifting distance).

SPDX-License-Identifier: GPL-3.0-or-later
"""
from paperFigures import (D, UCM, Riser, RiserCase, claim, np, phase_lag, plt, quick, root, save,
                          scratch)

d = 0.01
fig = plt.figure(figsize=(18, 9))
phases = {}
for row, (f, periods) in enumerate(((0.05, 1 if quick else 2), (0.3, 2 if quick else 5))):
    T = D / UCM / f
    case = (RiserCase(root, scratch, "fig17_%g" % f).riser(A=1.0, f=f)
            .run_for(periods * T, 5e-4).releases([(0.2, 0.2)], d).engine().solver(cells=8))
    engine = case.table()[0]
    solver = case.table("riserParcelFoam")[0]
    e = engine[1:]                                  # the engine also writes the release
    riser = Riser(D, UCM, A=1.0 * D, f=f * UCM / D)
    xc = riser.axis(e["t"])
    wall = 0.5 * D - 0.5 * d
    axes = [fig.add_subplot(2, 4, 4 * row + k + 1) for k in range(3)]
    axes[0].plot(e["t"] / T, (xc + wall) / D, "k-", lw=0.8)
    axes[0].plot(e["t"] / T, (xc - wall) / D, "k-", lw=0.8, label="walls (centre's reach)")
    for c, style, name in ((e, "-", "riserParticle"), (solver, "--", "riserParcelFoam")):
        t = c["t"]
        axes[0].plot(t / T, (c["xr"] + riser.axis(t)) / D, style, label=name)
        axes[1].plot(t / T, (c["Urx"] + riser.velocity(t)) / UCM, style, label=name)
        axes[2].plot(t / T, c["Uz"] / UCM, style, label=name)
    for a, label in zip(axes, ("x / D (lab)", "v_px / u_cm (lab)", "v_pz / u_cm")):
        a.set_xlabel("t / T")
        a.set_ylabel(label)
        a.set_title("f = %g" % f)
        a.grid(True, alpha=0.3)
    axes[0].legend(fontsize=7)
    track = fig.add_subplot(2, 4, 4 * row + 4, projection="3d")
    track.plot(e["xr"] / D, e["yr"] / D, e["lift"] / D)
    track.set_xlabel("(x - x_c) / D")
    track.set_ylabel("y / D")
    track.set_zlabel("lift / D")
    track.set_title("3-D track relative to the riser")
    # agreement of the engines at the solver's rows
    assert np.allclose(e["t"], solver["t"])
    gap = np.hypot(np.hypot(e["xr"] - solver["xr"], e["yr"] - solver["yr"]),
                   e["lift"] - solver["lift"]).max() / D
    lift = abs(e["lift"][-1] - solver["lift"][-1]) / abs(e["lift"][-1])
    contacts = len(case.contacts())
    claim("enginesAgree_f%g" % f, {"position": gap, "lift": lift},
          "f = %g, %d periods (%d contacts): riserParcelFoam (dt 5e-4 s) against riserParticle: "
          "largest relative position difference %.2g D, lifting distance %.3g %%"
          % (f, periods, contacts, gap, 100 * lift))
    # phase of the lateral velocity against the riser's, over the last period
    last = e["t"] >= (periods - 1) * T
    Ur = riser.velocity(e["t"])
    phases[f] = phase_lag(e["t"][last], (e["Urx"] + Ur)[last], Ur[last], f * UCM / D)
fig.suptitle("without (f = 0.05) and with (f = 0.3) wall contacts, A = 1: both engines")
save(fig, "paper_fig17_19_contacts.png")
claim("phaseShiftWithContacts", phases,
      "phase of v_px's fundamental against the riser velocity's: %+.1f deg at f = 0.05 (no "
      "contact), %+.1f deg at f = 0.3 (contacts every half period)" % (phases[0.05], phases[0.3]))
