"""Hindered settling of ores in riserCoupledFoam against Richardson & Zaki
(1954) and Garside & Al-Dibouni (1977), C_v = 0.05, 0.1, 0.2, 0.3.

The scenes (riserfoam.suspension.SCENES, hindered_case): a periodic riser
section, water (1000 kg/m^3, 1e-6 m^2/s) at rest, ores of 2000 kg/m^3
filled at C_v by riserFill, at rest; the drive holds the carrier's flow
rate at zero (the slip does not depend on the frame: batch settling and
fluidisation are the same suspension in a periodic section); no-slip wall;
wall and pair contact (riserContact with pairs, ores of E = 1e8 Pa:
soft, so that a contact spans ~100 sub-steps; a run at C_v = 0.1 without
contacts gave the same slip to 4 digits); core cells of h = d; dt = 1 ms.
- "1mm": d = 1 mm, D = 25 mm (d/D = 0.04), L = 10 mm, 10 cells across
  the core and along (3,400 cells), kernel width 6 d, 469 to 2,812 ores;
  0.45 s, measured over (0.15, 0.45] s;
- "10mm": the riser's ore, d = 10 mm, D = 0.1 m (d/D = 0.1), L = 0.1 m,
  4 cells across the core, 10 along (640 cells), kernel width 3 d, 75 to
  450 ores; 0.9 s, measured over (0.3, 0.9] s.
The ores reach their hindered speed well before the window opens.

Four drags:
- WenYuDrag (stock, Wen & Yu 1966): the single sphere's drag
  (Schiller-Naumann, Newton above Re = 1000) at the superficial slip,
  times eps^-4.65 per ore; it holds the pressure gradient's share (the
  form of the stock DPMFoam), so the ores have no fluid stress force;
- wallCorrectedDrag (law continuous: Clift-Gauvin with the pipe wall's
  factors, no voidage function) with riserFluidStress;
- wallCorrectedDrag_wenYu: the same with `voidage wenYu` (the Wen & Yu
  voidage function in model B's form, c(eps Re) eps^-3.65) and
  riserFluidStress: the riser's own forces in a suspension;
- wallCorrectedDrag_rong: the same with `voidage rong`, the voidage
  function of Rong, Dong & Yu (2013), chi = 2.65 (eps + 1) - (5.3 -
  3.5 eps) eps^2 exp(-(1.5 - log10 Re_s)^2/2), Re_s = eps Re. At the
  balance of a homogeneous suspension chi = 5.01, 4.86, 4.55, 4.25 for
  the 10 mm ore (Re_s = 5000 to 2200, far above the dip at 10^1.5) and
  3.58, 3.44, 3.23, 3.12 for the 1 mm ore (Re_s = 96 to 42, near it),
  against Wen & Yu's 3.65 for both. Its fit (lattice-Boltzmann flow
  through packings of spheres) does not reach the 10 mm ore's
  Re_s ~ 4000: there it is an extrapolation.

Measured (riserfoam.suspension.measure): over the window, the ores' mean
axial velocity w against the carrier's interstitial mean u_b/(1 - C_v)
(u_b the drive's bulk velocity, zero to 1e-5 m/s): the slip
u_s = u_b/(1 - C_v) - w; the drive's -dp/dz over the ores' buoyant weight
per volume C_v (rho_p - rho_f) g; the RMS of the carrier's axial velocity
at the end.

Reference, slip form (riserfoam.suspension): u_s / u_t = u_i/u_t
eps^(n - 1), eps = 1 - C_v (the solids fraction the run achieved), u_t the
ore's terminal velocity in unbounded water by the drag law's single
sphere (Schiller-Naumann/Newton for WenYuDrag, Clift-Gauvin for
wallCorrectedDrag), Re_t = u_t d / nu:
- Richardson & Zaki: n(Re_t, d/D) (for 1 < Re_t < 200
  (4.45 + 18 d/D) Re_t^-0.1, above 500 2.39), u_i = u_t 10^(-d/D);
- Garside & Al-Dibouni: (5.1 - n)/(n - 2.7) = 0.1 Re_t^0.9, u_i = u_t.
1 mm: u_t = 0.1124 m/s, Re_t = 112: n = 3.224 and 3.000; 10 mm: u_t =
0.5452 m/s, Re_t = 5452: n = 2.390 and 2.710. The target: the measured
u_s/u_t lies within 15 % of the band's width outside the band between
the two, i.e. excess = (distance outside the band) / width <= 0.15, the
width at least 5 % of the band's midpoint (riserfoam.suspension.band_excess;
the floor is not reached in these scenes). Also drawn: the Wen & Yu
balance for a homogeneous suspension (riserfoam.suspension.slip_wen_yu),
the closed form the WenYuDrag runs follow while the suspension stays
homogeneous, and Rong, Dong & Yu's (riserfoam.suspension.slip_rong, on
the Clift-Gauvin sphere, without the wall factors).

Measured (results/hinderedSettling.md): WenYuDrag, 1 mm: u_s/u_t = 0.908,
0.814, 0.637, 0.479, excess 0.059, 0.046, 0, 0 (met); 10 mm: 0.939,
0.873, 0.751, 0.629, excess 0.13, 0.25, 0.68, 1.45 (missed from
C_v = 0.1: the runs follow the Wen & Yu balance within 1 %, and that
law's exponent in Newton's regime, n = 2.325, is below both correlations'
and carries no wall correction, while Richardson & Zaki's intercept is
10^(-0.1) = 0.79 u_t at d/D = 0.1). wallCorrectedDrag with riserFluidStress:
0.98 to 0.99 u_t at every C_v in both scenes, no hindrance: the fluid
stress force is rho_f V Du/Dt of the carrier, about zero in a suspension
at rest on average, not the pressure gradient that carries the suspended
weight. wallCorrectedDrag_wenYu (the voidage function): 1 mm: 0.892,
0.799, 0.624, 0.467, inside the band at every C_v (met); 10 mm: 0.922,
0.858, 0.739, 0.612, excess 0.03, 0.15, 0.56, 1.16 (met at C_v = 0.05
only: the same Wen & Yu exponent; the pipe wall's factors lower the slip
by 1.5 to 2.1 % against the balance without them).
wallCorrectedDrag_rong (Rong, Dong & Yu's voidage function): 10 mm:
0.889, 0.806, 0.669, 0.548, excess 0, 0, 0, 0.081 (met at every C_v: in
Newton's regime the balance gives n = (chi + 1)/2 = 3.0 to 2.6, about
Garside & Al-Dibouni's 2.71, where Wen & Yu's 3.65 gives 2.325); 1 mm:
0.894, 0.812, 0.664, 0.532, excess 0, 0.02, 0.29, 0.54 (met at C_v = 0.05
and 0.1, missed from 0.2: near Re_s = 10^1.5 its chi, 3.1 to 3.6, is
below Wen & Yu's and falls with C_v). The runs lie 1.4 to 2.1 % (10 mm)
and 1.0 to 1.2 % (1 mm) below the balance without the wall factors.
Which closure for which ore: wenYu for the 1 mm ore, rong for the
riser's 10 mm ore (an extrapolation of its fit there); neither serves
both.

usage: sweep.py [-cv 0.05 0.1 0.2 0.3] [-scenes 1mm 10mm] [-drags DRAG ...] [-j 2]
                [-scratch DIR] [-reuse (no runs: rebuild the results from the cases)]
                [-merge (keep the rows of results/hinderedSettling.json that
                         this run does not redo, matched by scene, drag and
                         requested C_v; their history is not stored, so
                         the figure's history panels show this run's only)]
The drags (-drags): WenYuDrag, wallCorrectedDrag, wallCorrectedDrag_wenYu,
wallCorrectedDrag_rong; all by default.

Writes results/hinderedSettling.md and .json and
../figures/hinderedSettling.png.

SPDX-License-Identifier: GPL-3.0-or-later
"""
import argparse
import json
import os
import re
from concurrent.futures import ThreadPoolExecutor

from riserfoam import cases
from riserfoam import suspension as sus

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "../.."))
CV_LIST = (0.05, 0.1, 0.2, 0.3)
DRAGS = {"WenYuDrag": sus.WEN_YU_FORCES, "wallCorrectedDrag": cases.COUPLED_FORCES,
         "wallCorrectedDrag_wenYu": sus.RISER_WEN_YU_FORCES,
         "wallCorrectedDrag_rong": sus.RISER_RONG_FORCES}
# the homogeneous balance of each drag with a voidage function: the key of
# its column in the results (riserfoam.suspension.hindered_reference's
# wenYu or rong + "Homogeneous")
HOMOGENEOUS = {"WenYuDrag": "wenYuHomogeneous", "wallCorrectedDrag_wenYu": "wenYuHomogeneous",
               "wallCorrectedDrag_rong": "rongHomogeneous"}
# the figure's marker and history line of each drag
STYLES = {"WenYuDrag": ("C3o", "-"), "wallCorrectedDrag": ("C2s", "--"),
          "wallCorrectedDrag_wenYu": ("C4^", ":"), "wallCorrectedDrag_rong": ("C9D", "-.")}
RESULTS = os.path.join(HERE, "results")


def reference(scene):
    """u_t, Re_t and d/D of a scene, u_t by the Wen & Yu law's single sphere"""
    ref = sus.hindered_reference(0.0, scene)
    return ref["ut"], ref["Re_t"], ref["a"]


def case_path(scratch, scene, drag, cv):
    return os.path.join(scratch, "%s_%s_cv%g" % (scene, drag, cv))


def run(scratch, scene, drag, cv):
    case = case_path(scratch, scene, drag, cv)
    cases.solve_coupled(sus.hindered_case(case, cv, sus.SCENES[scene]["end"], forces=DRAGS[drag],
                                scene=scene))


def cpu(case):
    """the solver's CPU time [s], its log's last ExecutionTime"""
    text = open(os.path.join(case, "log.riserCoupledFoam")).read()
    return float(re.findall(r"ExecutionTime = ([-+0-9.eE]+) s", text)[-1])


def evaluate(scratch, scene, drag, cv):
    case = case_path(scratch, scene, drag, cv)
    m = sus.measure(case, sus.SCENES[scene]["t0"])
    ref = sus.hindered_reference(m["cv"], scene, drag)
    rz, gad = ref["richardsonZaki"], ref["garsideAlDibouni"]
    ratio = m["slip"] / ref["ut"]
    excess, width, floored = sus.band_excess(ratio, (rz, gad))
    return {"scene": scene, "drag": drag, "cvRequested": cv, "cv": m["cv"], "ores": m["count"],
            "ut": ref["ut"], "Re_t": ref["Re_t"],
            "slip": m["slip"], "slipRatio": ratio, "richardsonZaki": rz,
            "garsideAlDibouni": gad, "wenYuHomogeneous": ref["wenYu"],
            "rongHomogeneous": ref["rong"],
            "excess": excess, "bandWidth": width, "floored": floored,
            "dpdzRatio": m["dpdzRatio"], "uzRms": m["uzRms"], "cpu": cpu(case),
            "history": m["history"]}


def key(row):
    """what identifies a row: scene, drag and requested C_v"""
    return (row["scene"], row["drag"], row["cvRequested"])


def merged(rows, path):
    """rows and those of the results file path (a former run) that rows do
    not replace (same key), ordered by scene, drag and C_v; the closed-form
    columns a former run may lack are computed"""
    new = {key(r) for r in rows}
    old = []
    if os.path.exists(path):
        with open(path) as f:
            old = [r for r in json.load(f) if key(r) not in new]
    for r in old:
        ref = sus.hindered_reference(r["cv"], r["scene"], r["drag"])
        r.setdefault("wenYuHomogeneous", ref["wenYu"])
        r.setdefault("rongHomogeneous", ref["rong"])
    scenes, drags = list(sus.SCENES), list(DRAGS)
    return sorted(rows + old, key=lambda r: (scenes.index(r["scene"]), drags.index(r["drag"]),
                                             r["cvRequested"]))


def table(rows):
    lines = ["| ore | drag | u_t [m/s] | C_v | ores | u_s [m/s] | u_s/u_t | R&Z | G&A-D "
             "| own voidage function, homogeneous | excess over band width "
             "| -dp/dz / (C_v (rho_p - rho_f) g) "
             "| carrier u_z RMS at the end [mm/s] | CPU [s] |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        own = "%.4f" % r[HOMOGENEOUS[r["drag"]]] if r["drag"] in HOMOGENEOUS else "-"
        lines.append("| %s | %s | %.4f | %.4f | %d | %.5f | %.4f | %.4f | %.4f | %s | %.3f%s "
                     "| %.4f | %.1f | %.0f |"
                     % (r["scene"], r["drag"], r["ut"], r["cv"], r["ores"], r["slip"],
                        r["slipRatio"], r["richardsonZaki"], r["garsideAlDibouni"], own,
                        r["excess"], " (floor)" if r["floored"] else "", r["dpdzRatio"],
                        1e3 * r["uzRms"], r["cpu"]))
    return "\n".join(lines)


def color(cv):
    """the colour of the requested C_v in the figure's history panels"""
    return "C%d" % CV_LIST.index(cv) if cv in CV_LIST else "k"


def plot(rows, figure):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np
    from matplotlib.lines import Line2D
    fig, axes = plt.subplots(2, 2, figsize=(12, 9))
    cv = np.linspace(0.0, 0.35, 200)
    for (ax, bx), scene in zip(axes, sus.SCENES):
        ut, Re_t, a = reference(scene)
        rz = np.array([sus.richardson_zaki(1 - c, Re_t, a) for c in cv])
        gad = np.array([sus.garside_al_dibouni(1 - c, Re_t) for c in cv])
        lo, hi = np.minimum(rz, gad), np.maximum(rz, gad)
        width = np.maximum(hi - lo, sus.BAND_FLOOR * 0.5 * (lo + hi))
        d = sus.SCENES[scene]["d"]
        wy = [sus.slip_wen_yu(d, sus.ORE_DENSITY, 1 - c) / ut for c in cv]
        ut_cg = sus.terminal_velocity(d, sus.ORE_DENSITY, sus.clift_gauvin_cdre)
        rong = [sus.slip_rong(d, sus.ORE_DENSITY, 1 - c) / ut_cg for c in cv]
        ax.fill_between(cv, lo - 0.15 * width, hi + 0.15 * width, color="0.88",
                        label="band + 15 % of its width")
        ax.plot(cv, rz, "C0-", label="Richardson & Zaki (n = %.3f, u_i = %.3f u_t)"
                % (sus.n_richardson_zaki(Re_t, a), 10 ** -a))
        ax.plot(cv, gad, "C1-", label="Garside & Al-Dibouni (n = %.3f)"
                % sus.n_garside_al_dibouni(Re_t))
        ax.plot(cv, wy, "k:", label="Wen & Yu balance, homogeneous")
        ax.plot(cv, rong, "k-.", lw=1,
                label="Rong, Dong & Yu balance, homogeneous (Clift-Gauvin sphere)")
        mine = [r for r in rows if r["scene"] == scene]
        for drag, (style, _) in STYLES.items():
            pts = [(r["cv"], r["slipRatio"]) for r in mine if r["drag"] == drag]
            if pts:
                ax.plot(*zip(*pts), style, ms=7, label="riserCoupledFoam, %s" % drag)
        ax.set_xlabel("C_v")
        ax.set_ylabel("u_s / u_t")
        ax.set_title("slip, ores of d = %g mm (u_t = %.3f m/s, Re_t = %.0f, d/D = %.2f)"
                     % (1e3 * sus.SCENES[scene]["d"], ut, Re_t, a), fontsize=10)
        ax.set_ylim(0.1, 1.05)  # room for the legend below the curves
        ax.legend(fontsize=7, loc="lower left")
        ax.grid(alpha=0.3)
        for r in mine:
            if "history" not in r:  # a row of a former run, merged
                continue
            t, w = zip(*r["history"])
            bx.plot(t, -np.array(w) / r["ut"], STYLES[r["drag"]][1], color=color(r["cvRequested"]),
                    lw=1)
        # the legend: a colour per C_v, a line style per drag
        drawn = [r for r in mine if "history" in r]
        handles = [Line2D([], [], color=color(c), lw=1, label="C_v = %.2f" % c)
                   for c in sorted({r["cvRequested"] for r in drawn})]
        handles += [Line2D([], [], color="k", ls=STYLES[drag][1], lw=1, label=drag)
                    for drag in STYLES if any(r["drag"] == drag for r in drawn)]
        bx.axvspan(sus.SCENES[scene]["t0"], sus.SCENES[scene]["end"], color="0.92")
        bx.set_xlabel("t [s]")
        bx.set_ylabel("-w / u_t (ores' mean axial velocity)")
        bx.set_title("d = %g mm: approach and averaging window (grey)"
                     % (1e3 * sus.SCENES[scene]["d"]), fontsize=10)
        bx.legend(handles=handles, fontsize=7, ncol=2, loc="lower right")
        bx.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(figure, dpi=100)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("-cv", type=float, nargs="+", default=list(CV_LIST))
    ap.add_argument("-scenes", nargs="+", default=list(sus.SCENES), choices=list(sus.SCENES))
    ap.add_argument("-j", type=int, default=2)
    ap.add_argument("-scratch", default=os.path.join(ROOT, "build/validation/hinderedSettling"))
    ap.add_argument("-drags", nargs="+", default=list(DRAGS), choices=list(DRAGS))
    ap.add_argument("-reuse", action="store_true")
    ap.add_argument("-merge", action="store_true")
    args = ap.parse_args()
    os.makedirs(args.scratch, exist_ok=True)
    jobs = [(scene, drag, cv) for scene in args.scenes for drag in args.drags for cv in args.cv]
    if not args.reuse:
        with ThreadPoolExecutor(max_workers=args.j) as pool:
            list(pool.map(lambda job: run(args.scratch, *job), jobs))
    rows = [evaluate(args.scratch, *job) for job in jobs]
    if args.merge:
        rows = merged(rows, os.path.join(RESULTS, "hinderedSettling.json"))
    text = table(rows)
    print(text)
    lines = []
    for scene in sorted({r["scene"] for r in rows}, key=list(sus.SCENES).index):
        ut, Re_t, a = reference(scene)
        lines.append("- %s: u_t = %.5f m/s, Re_t = %.2f, d/D = %.3f; n: Richardson & Zaki %.4f, "
                     "Garside & Al-Dibouni %.4f; window (%g, %g] s"
                     % (scene, ut, Re_t, a, sus.n_richardson_zaki(Re_t, a),
                        sus.n_garside_al_dibouni(Re_t), sus.SCENES[scene]["t0"],
                        sus.SCENES[scene]["end"]))
    os.makedirs(RESULTS, exist_ok=True)
    with open(os.path.join(RESULTS, "hinderedSettling.md"), "w") as out:
        out.write("%s\n\n%s\n" % ("\n".join(lines), text))
    with open(os.path.join(RESULTS, "hinderedSettling.json"), "w") as out:
        json.dump([{k: v for k, v in r.items() if k != "history"} for r in rows], out, indent=1)
    plot(rows, os.path.join(ROOT, "validation/figures/hinderedSettling.png"))


if __name__ == "__main__":
    main()
