"""The paper's Figs. 8-13: the riser frequency. A = 1, f = 0.025 .. 0.4,
release at x_p0 = y_p0 = 0.2 D with the local carrier speed, mesh-free:
relative lateral velocity, vertical velocity, lifting distance over a fixed
time, each contact's largest overlap and impact speed, and the inside of one
contact at f = 0.3 (the fourth; rows every 0.2 us): the overlaps delta_n and
delta_t and the vertical velocity. Claims: the
vertical velocity oscillates at twice the riser frequency; the relative
lateral velocity grows and the lifting distance falls with f; contacts
drop the vertical velocity.

SPDX-License-Identifier: GPL-3.0-or-later
"""
from paperFigures import (D, UCM, RiserCase, claim, dominant_frequency, np, plt, quick, root,
                          save, scratch)

fs = [0.025, 0.05, 0.1, 0.2, 0.3, 0.4]
duration = 4.0 if quick else 10.0        # [s] = 40 or 100 D/u_cm
runs = {}
for f in fs:
    case = (RiserCase(root, scratch, "fig08_%g" % f).riser(A=1.0, f=f)
            .run_for(duration, 2e-3).releases([(0.2, 0.2)]).engine())
    runs[f] = (case.table()[0], case.contacts())

fig, ax = plt.subplots(3, 3, figsize=(16, 12))
late = {}
for f in fs:
    c, contacts = runs[f]
    t = c["t"] * UCM / D
    ax[0, 0].plot(t, c["Urx"] / UCM, lw=0.8, label="f = %g" % f)
    ax[0, 1].plot(t, c["Uz"] / UCM, lw=0.8)
    ax[0, 2].plot(t, c["lift"] / D, label="f = %g" % f)
    half = c["t"] >= duration / 2
    late[f] = (np.abs(c["Urx"][half]).max() / UCM, c["lift"][-1] / D, len(contacts))
    if len(contacts):
        ax[1, 0].plot(np.full(len(contacts), f), contacts["maxOverlap"] / 0.01, "o", ms=3,
                      color="C%d" % fs.index(f))
        ax[1, 1].plot(np.full(len(contacts), f), contacts["impactSpeed"] / UCM, "o", ms=3,
                      color="C%d" % fs.index(f))
for a, label in zip(ax[0], ("(v_px - U_r) / u_cm", "v_pz / u_cm", "lifting distance / D")):
    a.set_xlabel("t u_cm / D")
    a.set_ylabel(label)
    a.grid(True, alpha=0.3)
ax[0, 0].set_xlim(0, 20)
ax[0, 1].set_xlim(0, 20)
ax[0, 2].legend(fontsize=8)
ax[1, 0].set_ylabel("largest overlap of each contact / d")
ax[1, 1].set_ylabel("impact speed relative to the wall / u_cm")
for a in ax[1, :2]:
    a.set_xlabel("f D / u_cm")
    a.grid(True, alpha=0.3)
ax[1, 2].plot(fs, [late[f][0] for f in fs], "o-", label="largest |v_px - U_r| / u_cm (second half)")
ax[1, 2].plot(fs, [late[f][1] / late[fs[0]][1] for f in fs], "s-",
              label="lifting distance / that at f = %g" % fs[0])
ax[1, 2].set_xlabel("f D / u_cm")
ax[1, 2].legend(fontsize=8)
ax[1, 2].grid(True, alpha=0.3)
# inside the fourth contact at f = 0.3: the same run, rows every 0.2 us
# around it only
fourth = runs[0.3][1][3]
start, end = fourth["start"], fourth["end"]
inside = (RiserCase(root, scratch, "fig13_contact").riser(A=1.0, f=0.3)
          .run_for(end + 0.5 * (end - start), 2e-7).releases([(0.2, 0.2)])
          .engine_settings("writeFrom %r;" % (start - 0.5 * (end - start))).engine().table()[0])
tau = (inside["t"] - start) / (end - start)
for a, key, scale, label in zip(ax[2], ("deltaN", "deltaT", "Uz"), (0.01, 0.01, UCM),
                                ("delta_n / d", "|delta_t| / d", "v_pz / u_cm")):
    a.plot(tau, inside[key] / scale)
    a.set_xlabel("(t - contact start) / contact duration (%.1f us)" % (1e6 * (end - start)))
    a.set_ylabel(label)
    a.set_title("inside the fourth contact, f = 0.3", fontsize=9)
    a.grid(True, alpha=0.3)
fig.suptitle("riser frequency, A = 1 (riserParticle, %g D/u_cm)" % (duration * UCM / D))
save(fig, "paper_fig08_13_frequency.png")

# vertical velocity at twice the riser frequency (second half of the run)
ratios = []
for f in fs:
    c = runs[f][0]
    half = c["t"] >= duration / 2
    ratios.append(dominant_frequency(c["t"][half], c["Uz"][half]) / (f * UCM / D))
claim("verticalAtTwiceFrequency", ratios,
      "dominant frequency of v_pz / f: " + ", ".join("%.2f (f = %g)" % (r, f)
                                                   for r, f in zip(ratios, fs)))
lat = [late[f][0] for f in fs]
lift = [late[f][1] for f in fs]
claim("frequencyTrends", {"lateral": lat, "lift": lift},
      "largest relative lateral speed %s u_cm and lifting distance after %g D/u_cm %s D for "
      "f = %s" % ("/".join("%.2f" % v for v in lat), duration * UCM / D,
                  "/".join("%.1f" % v for v in lift), "/".join("%g" % f for f in fs)))
# the vertical velocity across a contact: the rows just before and after
drops = []
for f in fs:
    c, contacts = runs[f]
    for start, end in zip(contacts["start"], contacts["end"]):
        before = np.searchsorted(c["t"], start) - 1
        after = np.searchsorted(c["t"], end)
        if before >= 0 and after < len(c["t"]):
            drops.append((c["Uz"][after] - c["Uz"][before]) / UCM)
claim("contactDropsVertical", float(np.mean(drops)) if drops else None,
      "v_pz changes by %.3f u_cm on average across %d contacts (largest drop %.3f u_cm; the "
      "rows 2 ms apart around each contact)" % (np.mean(drops), len(drops), np.min(drops))
      if drops else "no contacts")
