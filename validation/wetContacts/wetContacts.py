"""When wet contacts matter: the flagship (one 10 mm ore, 2000
kg/m^3, in water, A = 0.1 m at 3 Hz, 5 riser periods) and the 1,000-ore
scene of benchmarks/oreCloud.py (10 mm ores at C_v = 0.0667 in a 1 m
periodic section, A = 0.2 m at f = 4 Hz, wall and pair contact,
stepsPerContact 10, 0.5 s), each dry, with wet { type
stokesRestitution; } and with wet { type lubrication; } (its defaults) on
every contact (the wall's and, in the second, the pairs'). Both are in
water (mu = 1e-3 Pa s), with riserAddedMass (C_A = 1/2), as the tutorials
have them. The run time of each is reported too (the lubricated ores are
sub-stepped while in a film, and pairs within each other's film are
clusters).

Reported per run: the flagship's lifting distance (riserParticleTable's
lift at the end), the 1,000 ores' mean axial velocity over the last half
(the written U, every 0.05 s) and its ratio to the carrier's bulk velocity
(uCentre/2), the completed wall contacts per second (contacts.dat), the
completed pair contacts per second (the lagrangian field pairContacts,
each contact counted by both ores), and the impacts' Stokes numbers St =
(rho_p + rho_f/2) UnIn d/(9 mu) of the dry run's wall contacts. The chart
(validation/figures/wet_contacts.png) draws e(St)/e_n of Legendre et al.
(2006) and of the film (its closed form, for the flagship's e_n = 0.76)
over the distribution of those Stokes numbers, and the changes.

usage: wetContacts.py <work folder> <results folder> <figure>
License: GPL-3.0-or-later
"""
import json
import math
import os
import sys
import time

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "..", "benchmarks"))
import oreCloud  # noqa: E402  (the 1,000-ore scene)

from riserfoam import cases, tables  # noqa: E402
from riserfoam import foamfields as ff  # noqa: E402

work, results, figure = sys.argv[1:4]
os.makedirs(results, exist_ok=True)
RHO_P, RHO_F, MU, D = 2000.0, 1000.0, 1e-3, 0.01
WET = {"wet": "{ type stokesRestitution; }", "film": "{ type lubrication; }"}
VARIANTS = ("dry", "wet", "film")
L_FILM = math.log(0.1 / 2e-6)   # the film's defaults: cutoff 0.1, roughness 2e-6


def stokes(UnIn):
    return (RHO_P + 0.5 * RHO_F) * np.asarray(UnIn) * D / (9 * MU)


def wet_on(case, variant, pairs=False):
    cloud = os.path.join(case, "constant/kinematicCloudProperties")
    ff.set_nested(cloud, "subModels/riserContactCoeffs/wet", WET[variant])
    if pairs:
        ff.set_nested(cloud, "subModels/riserContactCoeffs/pairs/wet", WET[variant])


def solve(case):
    """contacts.dat's rows and the run's wall time [s]"""
    start = time.time()
    cases.run(["riserParcelFoam", "-case", case], os.path.join(case, "log.riserParcelFoam"))
    rows = cases.wall_contacts(case)
    return rows, time.time() - start


def times(case):
    return sorted((d for d in os.listdir(case) if d.replace(".", "").isdigit() and float(d) > 0),
                  key=float)


result = {}
# --- the flagship ---------------------------------------------------------
for variant in VARIANTS:
    case = os.path.join(work, "flagship", variant)
    cases.copy_tutorial("riser/oscillatingContact", case)
    cases.riser_mesh(case, 0.1, 0.2, 12)
    if variant != "dry":
        wet_on(case, variant)
    rows, wall = solve(case)
    table = tables.read(os.path.join(case, "postProcessing/lagrangian/kinematicCloud/"
                                     "riserParticleTable/particles.dat"))
    span = table["t"][-1]
    St = stokes(rows["UnIn"])
    result["flagship " + variant] = {
        "lift_m": float(table["lift"][-1]), "simulated_s": float(span),
        "wall_contacts_per_s": len(rows["UnIn"]) / span,
        "mean_restitution": float(np.sum(rows["UnOut"]) / np.sum(rows["UnIn"])),
        "wall_time_s": wall, "St": [float(x) for x in St]}
    print("flagship %s: %s" % (variant, {k: v for k, v in result["flagship " + variant].items()
                                        if k != "St"}))

# --- 1,000 ores -------------------------------------------------------------
end = 0.5
for variant in VARIANTS:
    case = os.path.join(work, "ores", variant)
    oreCloud.make(case, end, 0.2, 4.0, "riserContact", oreCloud.PAIRS, "tracked")
    ff.set_nested(os.path.join(case, "system/controlDict"), "writeInterval", "0.05")
    if variant != "dry":
        wet_on(case, variant, pairs=True)
    rows, wall = solve(case)
    late = [t for t in times(case) if float(t) >= 0.5 * end - 1e-9]
    Uz = [np.mean([u[2] for u in ff.read_vectors(os.path.join(case, t, "lagrangian/kinematicCloud/U"))])
          for t in late]
    last = os.path.join(case, times(case)[-1], "lagrangian/kinematicCloud")
    pairs = sum(ff.read_scalars(os.path.join(last, "pairContacts"))) / 2
    n = len(ff.read_scalars(os.path.join(last, "d")))
    uBulk = 0.5 * ff.read_entry(os.path.join(case, "constant/riserProperties"), "uCentre")
    St = stokes(rows["UnIn"])
    result["ores " + variant] = {
        "ores": n, "simulated_s": end, "mean_axial_velocity": float(np.mean(Uz)),
        "over_bulk": float(np.mean(Uz)) / uBulk,
        "wall_contacts_per_s": len(rows["UnIn"]) / end, "pair_contacts_per_s": pairs / end,
        "mean_restitution": float(np.sum(rows["UnOut"]) / np.sum(rows["UnIn"])),
        "wall_time_s": wall, "St": [float(x) for x in St]}
    print("ores %s: %s" % (variant, {k: v for k, v in result["ores " + variant].items()
                                    if k != "St"}))

json.dump(result, open(os.path.join(results, "wetContacts.json"), "w"), indent=1)
with open(os.path.join(results, "summary.md"), "w") as out:
    out.write("# Dry and wet contacts in water (validation/wetContacts)\n\n")
    out.write("wet: `wet { type stokesRestitution; }`; film: `wet { type lubrication; }`"
              " (cutoff 0.1, roughness 2e-6). The film's UnIn is the speed left after the film.\n\n")
    out.write("| run | lift or mean axial velocity | wall contacts / s | pair contacts / s |"
              " mean UnOut/UnIn | wall impacts' St: median, share below 100 | run time [s] |\n"
              "|---|---|---|---|---|---|---|\n")
    for key, r in result.items():
        moved = ("lift %.4f m" % r["lift_m"] if "lift_m" in r else
                 "%.4f m/s (%.3f of the bulk)" % (r["mean_axial_velocity"], r["over_bulk"]))
        St = np.asarray(r["St"])
        out.write("| %s | %s | %.1f | %s | %.3f | %.0f, %.0f %% | %.0f |\n" % (
            key, moved, r["wall_contacts_per_s"],
            "%.1f" % r["pair_contacts_per_s"] if "pair_contacts_per_s" in r else "-",
            r["mean_restitution"], np.median(St) if len(St) else float("nan"),
            100 * np.mean(St < 100) if len(St) else float("nan"), r["wall_time_s"]))

import matplotlib  # noqa: E402
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

fig, (a1, a2) = plt.subplots(1, 2, figsize=(12, 4.5))
St = np.logspace(-2, 4, 600)
e = np.where(St >= 10, np.exp(-35 / St), 0.0)
a1.semilogx(St, e, "k-", lw=1.6, label="e/e_n = exp(-35/St), 0 below St 10 (Legendre et al. 2006)")
eFilm = np.maximum(0.0, 1 - L_FILM / St - L_FILM / (0.76 * St))
a1.semilogx(St, eFilm, "k--", lw=1.4,
            label="lubrication film: e/e_n = 1 - L/St - L/(e_n St), e_n = 0.76, L = %.2f" % L_FILM)
b1 = a1.twinx()
bins = np.logspace(-2, 4, 49)
for key, color in (("flagship dry", "C0"), ("ores dry", "C3")):
    values = np.clip(result[key]["St"], 1e-2, None)   # (0 and below: in the first bin)
    b1.hist(values, bins=bins, alpha=0.4, color=color,
            weights=np.full(len(values), 1.0 / max(len(values), 1)),
            label="%s: %d wall impacts (dry run)" % (key.replace(" dry", ""), len(values)))
a1.set_xlabel("impact Stokes number St = (rho_p + rho_f/2) v_n d / (9 mu)")
a1.set_ylabel("wet restitution e / e_n")
b1.set_ylabel("fraction of the scene's wall impacts")
a1.set_ylim(0, 1.05)
h1, l1 = a1.get_legend_handles_labels()
h2, l2 = b1.get_legend_handles_labels()
a1.legend(h1 + h2, l1 + l2, fontsize=8, loc="upper left")
a1.set_title("where the scenes' wall impacts sit (10 mm ores in water)", fontsize=10)
labels, dry, wet, film = [], [], [], []
for what, key, unit in (("flagship: lift", "lift_m", 1.0),
                        ("1,000 ores: axial velocity", "mean_axial_velocity", 1.0),
                        ("flagship: wall contacts/s", "wall_contacts_per_s", 1.0),
                        ("1,000 ores: wall contacts/s", "wall_contacts_per_s", 1.0),
                        ("1,000 ores: pair contacts/s", "pair_contacts_per_s", 1.0)):
    scene = "flagship" if what.startswith("flagship") else "ores"
    d, w = result[scene + " dry"][key], result[scene + " wet"][key]
    fl = result[scene + " film"][key]
    labels.append(what)
    dry.append(1.0)
    wet.append(w / d if d else float("nan"))
    film.append(fl / d if d else float("nan"))
x = np.arange(len(labels))
a2.bar(x - 0.27, dry, 0.27, label="dry", color="0.6")
a2.bar(x, wet, 0.27, label="wet: e(St) imposed", color="C2")
a2.bar(x + 0.27, film, 0.27, label="wet: lubrication film", color="C4")
for i, (w, fl) in enumerate(zip(wet, film)):
    a2.text(x[i], w + 0.02, "%.3f" % w, ha="center", fontsize=7)
    a2.text(x[i] + 0.27, fl + 0.02, "%.3f" % fl, ha="center", fontsize=7)
a2.set_xticks(x)
a2.set_xticklabels(labels, rotation=20, ha="right", fontsize=8)
a2.set_ylabel("wet / dry")
a2.legend(fontsize=8)
a2.set_title("what changes with the wet models", fontsize=10)
fig.tight_layout()
fig.savefig(figure, dpi=110)
print("wrote", figure)
