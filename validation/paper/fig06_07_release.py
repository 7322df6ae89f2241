"""The paper's Figs. 6 and 7: the release position. A = 1, phi0 = 0,
f = 0.05 (no contact) and f = 0.15 (contacts), releases at
x_p0 = y_p0 = 0.05 .. 0.25 D with the local carrier speed, mesh-free;
x_p - x_c, y_p, v_px - U_r, v_py, v_pz. Claim: the settled motion does not
depend on the release position (its spread over the releases in the last
period, against the first).

SPDX-License-Identifier: GPL-3.0-or-later
"""
from paperFigures import D, UCM, RiserCase, claim, np, plt, quick, root, save, scratch

starts = [0.05, 0.1, 0.15, 0.2, 0.25]
for f, periods in ((0.05, 3 if quick else 5), (0.15, 5 if quick else 10)):
    T = D / UCM / f
    case = (RiserCase(root, scratch, "fig06_%g" % f).riser(A=1.0, f=f)
            .run_for(periods * T, T / 100).releases([(s, s) for s in starts]).engine())
    table = case.table()
    fig, ax = plt.subplots(1, 5, figsize=(20, 4))
    for pid, s in zip(sorted(table), starts):
        c = table[pid]
        for a, key, scale in zip(ax, ("xr", "yr", "Urx", "Ury", "Uz"), (D, D, UCM, UCM, UCM)):
            a.plot(c["t"] / T, c[key] / scale, label="x_p0 = y_p0 = %.2f D" % s)
    for a, label in zip(ax, ("(x_p - x_c) / D", "y_p / D", "(v_px - U_r) / u_cm",
                             "v_py / u_cm", "v_pz / u_cm")):
        a.set_xlabel("t / T")
        a.set_ylabel(label)
        a.grid(True, alpha=0.3)
    ax[0].legend(fontsize=7)
    fig.suptitle("release position, A = 1, f = %g (riserParticle)" % f)
    save(fig, "paper_fig06_07_release_f%g.png" % f)
    # spread over the releases of (x_p - x_c, y_p) in the first and last period
    t = table[0]["t"]
    xs = np.array([table[p]["xr"] for p in sorted(table)]) / D
    ys = np.array([table[p]["yr"] for p in sorted(table)]) / D
    spread = np.hypot(xs.max(0) - xs.min(0), ys.max(0) - ys.min(0))
    first = spread[t <= T].max()
    last = spread[t >= (periods - 1) * T].max()
    # and of the mean vertical speed over the last three periods
    late = t >= (periods - 3) * T
    vz = np.array([table[p]["Uz"][late].mean() for p in sorted(table)]) / UCM
    claim("releaseForgotten_f%g" % f, last,
          "f = %g: the releases' largest spread in position %.2g D in the first period, "
          "%.2g D in period %d; their mean vertical speeds over the last 3 periods "
          "%.3f..%.3f u_cm" % (f, first, last, periods, vz.min(), vz.max()))
