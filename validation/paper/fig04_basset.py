"""The paper's Fig. 4: is the Basset force significant? D/d = 10, A = 1,
f = 0, 0.05 and 0.2 (for f = 0 the release at x = y = 0.3 D, otherwise at
0.2 D), with the local carrier speed, riserParcelFoam (riser frame, exact
carrier; the mesh-free engine has no history force) with and without
riserBasset (Michaelides-Roig C_H, window 0.01 s + tail): v_px and v_pz.
Claim: the Basset force barely matters for this particle.

SPDX-License-Identifier: GPL-3.0-or-later
"""
from paperFigures import D, UCM, Riser, RiserCase, claim, np, plt, quick, root, save, scratch

duration = 1.0 if quick else 2.0
fig, ax = plt.subplots(2, 3, figsize=(15, 7))
effect = {}
for col, (f, start) in enumerate(((0.0, 0.3), (0.05, 0.2), (0.2, 0.2))):
    runs = {}
    for basset in (False, True):
        case = RiserCase(root, scratch, "fig04_%g_%d" % (f, basset))
        case.riser(A=1.0 if f > 0 else 0.0, f=f).run_for(duration, 5e-4).releases([(start, start)])
        if basset:
            case.with_basset()
        runs[basset] = case.solver(cells=8).table("riserParcelFoam")[0]
    riser = Riser(D, UCM, A=D if f > 0 else 0.0, f=f * UCM / D)
    for basset, style in ((False, "--"), (True, "-")):
        c = runs[basset]
        ax[0, col].plot(c["t"] * UCM / D, (c["Urx"] + riser.velocity(c["t"])) / UCM, style,
                        label="with Basset" if basset else "without")
        ax[1, col].plot(c["t"] * UCM / D, c["Uz"] / UCM, style)
    ax[0, col].set_title("f = %g (release at %.1f D)" % (f, start))
    ax[0, col].set_ylabel("v_px / u_cm (lab)")
    ax[1, col].set_ylabel("v_pz / u_cm")
    for a in ax[:, col]:
        a.set_xlabel("t u_cm / D")
        a.grid(True, alpha=0.3)
    ax[0, col].legend(fontsize=8)
    a, b = runs[False], runs[True]
    effect[f] = (np.abs(a["Urx"] - b["Urx"]).max() / UCM, np.abs(a["Uz"] - b["Uz"]).max() / UCM,
                 abs(a["lift"][-1] - b["lift"][-1]) / abs(b["lift"][-1]))
fig.suptitle("the Basset force, D/d = 10, A = 1 (riserParcelFoam, %g D/u_cm)" % (duration * UCM / D))
save(fig, "paper_fig04_basset.png")
claim("bassetNegligible", {str(f): v for f, v in effect.items()},
      "Basset on against off, largest velocity differences (lateral/vertical) and lifting "
      "distance difference: " + "; ".join("f = %g: %.3f/%.3f u_cm, %.2f %%" % (f, v[0], v[1], 100 * v[2])
                                          for f, v in effect.items()))
