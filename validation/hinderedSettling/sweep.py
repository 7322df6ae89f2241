"""Hindered settling of ores in riserCoupledFoam against Richardson & Zaki
(1954) and Garside & Al-Dibouni (1977), C_v = 0.05 .. 0.3.

The scene (riserfoam.suspension.settling_case): a periodic riser section
of D = 25 mm and L = 10 mm (O-grid of 10 cells across the core, core cells
cubes of h = 1 mm = d; 3,400 cells), water (1000 kg/m^3, 1e-6 m^2/s) at
rest, ores of d = 1 mm and 2000 kg/m^3 filled at C_v by riserFill (937 ores
at C_v = 0.1, 2,812 at 0.3), at rest; the drive holds the carrier's flow
rate at zero (the slip does not depend on the frame: batch settling and
fluidisation are the same suspension in a periodic section), no-slip
wall; wall and pair contact (riserWallContact with pairs, ores of
E = 1e8 Pa: soft, so that a contact spans ~100 sub-steps; the contacts
barely matter here: a run without them gives the same slip to 4 digits);
the coarse-particle kernel { type diffusion; width 6; widthUnit diameters; }
(b = 6 mm, more than the largest cell, a ring cell at the wall). dt = 1 ms,
0.45 s; written every 10 ms.

Two drag laws:
- WenYuDrag (stock, Wen & Yu 1966): the single sphere's drag
  (Schiller-Naumann, Newton above Re = 1000) at the superficial slip,
  times eps^-4.65 per ore; it holds the pressure gradient's share (the
  form of the stock DPMFoam), so the ores have no fluid stress force;
- wallCorrectedDrag (law continuous: Clift-Gauvin with the pipe wall's
  factors, no voidage function) with riserFluidStress: the hindrance is
  the volume-averaged pressure gradient's alone.

Measured (riserfoam.suspension.measure): over the written times in
(0.15, 0.45] s (the ores reach their hindered speed within ~0.1 s), the
ores' mean axial velocity w against the carrier's interstitial mean
u_b/(1 - C_v) (u_b the drive's bulk velocity, zero to 1e-5 m/s): the slip
u_s = u_b/(1 - C_v) - w; and the drive's -dp/dz over the ores' buoyant
weight per volume C_v (rho_p - rho_f) g.

Reference, slip form (see riserfoam.suspension): u_s / u_t = u_i/u_t
eps^(n - 1), eps = 1 - C_v (the solids fraction the run achieved), u_t =
0.1124 m/s the ore's terminal velocity in unbounded water by the
Schiller-Naumann law (Re_t = 112; Clift-Gauvin's, the other drag's, is
0.1% lower), d/D = 0.04:
- Richardson & Zaki: n = (4.45 + 18 d/D) Re_t^-0.1 = 3.224 (1 < Re_t <
  200), u_i = u_t 10^(-d/D) = 0.912 u_t;
- Garside & Al-Dibouni: (5.1 - n)/(n - 2.7) = 0.1 Re_t^0.9: n = 3.000,
  u_i = u_t (no wall correction).
The target: the measured u_s/u_t lies within 15 % of the band's width
outside the band between the two, i.e. excess = (distance outside the
band) / width <= 0.15, the width at least 5 % of the band's midpoint
(riserfoam.suspension.band_excess; here the band is 0.08 to 0.09 u_t wide
and the floor is not used). Also drawn: the Wen & Yu balance for a
homogeneous suspension (riserfoam.suspension.slip_wen_yu), the closed
form the WenYuDrag runs should follow while the suspension stays
homogeneous.

usage: sweep.py [-cv 0.05 0.1 0.2 0.3] [-endTime 0.45] [-j 2] [-scratch DIR]
                [-reuse (no runs: rebuild the results from the cases)]

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
d, D, RHO_P, T0 = sus.SCENE_DIAMETER, sus.SCENE_D, sus.SCENE_RHO_P, sus.SCENE_T0
CV_LIST = (0.05, 0.1, 0.2, 0.3)
DRAGS = {"WenYuDrag": sus.WEN_YU_FORCES, "wallCorrectedDrag": cases.COUPLED_FORCES}
UT = sus.slip_wen_yu(d, RHO_P)
RE_T = UT * d / sus.NU


def case_path(scratch, drag, cv):
    return os.path.join(scratch, "%s_cv%g" % (drag, cv))


def run(scratch, drag, cv, end):
    case = case_path(scratch, drag, cv)
    sus.solve(sus.hindered_case(case, cv, end, forces=DRAGS[drag]))
    return case


def cpu(case):
    """the solver's CPU time [s], its log's last ExecutionTime"""
    text = open(os.path.join(case, "log.riserCoupledFoam")).read()
    return float(re.findall(r"ExecutionTime = ([-+0-9.eE]+) s", text)[-1])


def evaluate(scratch, drag, cv):
    m = sus.measure(case_path(scratch, drag, cv), T0, rho_p=RHO_P)
    ref = sus.hindered_reference(m["cv"])
    rz, gad = ref["richardsonZaki"], ref["garsideAlDibouni"]
    excess, width, floored = sus.band_excess(m["slip"] / UT, (rz, gad))
    return {"drag": drag, "cvRequested": cv, "cv": m["cv"], "ores": m["count"],
            "slip": m["slip"], "slipRatio": m["slip"] / UT, "richardsonZaki": rz,
            "garsideAlDibouni": gad, "wenYuHomogeneous": ref["wenYu"],
            "excess": excess, "bandWidth": width, "floored": floored,
            "dpdzRatio": m["dpdzRatio"], "uzRms": m["uzRms"],
            "cpu": cpu(case_path(scratch, drag, cv)),
            "history": m["history"]}


def table(rows):
    lines = ["| drag | C_v | ores | u_s [m/s] | u_s/u_t | R&Z | G&A-D | Wen-Yu homogeneous "
             "| excess over band width | -dp/dz / (C_v (rho_p - rho_f) g) | carrier u_z RMS at the end "
             "[mm/s] | CPU [s] |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        lines.append("| %s | %.4f | %d | %.5f | %.4f | %.4f | %.4f | %.4f | %.3f%s | %.4f | %.1f | %.0f |"
                     % (r["drag"], r["cv"], r["ores"], r["slip"], r["slipRatio"],
                        r["richardsonZaki"], r["garsideAlDibouni"], r["wenYuHomogeneous"],
                        r["excess"], " (floor)" if r["floored"] else "", r["dpdzRatio"],
                        1e3 * r["uzRms"], r["cpu"]))
    return "\n".join(lines)


def plot(rows, figure):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np
    cv = np.linspace(0.0, 0.35, 200)
    rz = np.array([sus.richardson_zaki(1 - c, RE_T, d / D) for c in cv])
    gad = np.array([sus.garside_al_dibouni(1 - c, RE_T) for c in cv])
    lo, hi = np.minimum(rz, gad), np.maximum(rz, gad)
    width = np.maximum(hi - lo, sus.BAND_FLOOR * 0.5 * (lo + hi))
    wy = [sus.slip_wen_yu(d, RHO_P, 1 - c) / UT for c in cv]
    fig, (ax, bx) = plt.subplots(1, 2, figsize=(12, 4.8))
    ax.fill_between(cv, lo - 0.15 * width, hi + 0.15 * width, color="0.88",
                    label="band + 15 % of its width")
    ax.plot(cv, rz, "C0-", label="Richardson & Zaki (n = %.3f, u_i = %.3f u_t)"
            % (sus.n_richardson_zaki(RE_T, d / D), 10 ** -(d / D)))
    ax.plot(cv, gad, "C1-", label="Garside & Al-Dibouni (n = %.3f)"
            % sus.n_garside_al_dibouni(RE_T))
    ax.plot(cv, wy, "k:", label="Wen & Yu balance, homogeneous")
    for drag, style in (("WenYuDrag", "C3o"), ("wallCorrectedDrag", "C2s")):
        pts = [(r["cv"], r["slipRatio"]) for r in rows if r["drag"] == drag]
        if pts:
            ax.plot(*zip(*pts), style, ms=7, label="riserCoupledFoam, %s" % drag)
    ax.set_xlabel("C_v")
    ax.set_ylabel("u_s / u_t")
    ax.set_title("slip of 1 mm ores (Re_t = %.0f, d/D = %.2f)" % (RE_T, d / D))
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)
    for i, r in enumerate(rows):
        t, w = zip(*r["history"])
        bx.plot(t, -np.array(w) / UT, "-" if r["drag"] == "WenYuDrag" else "--",
                color="C%d" % (i % len(CV_LIST)), lw=1,
                label="%s, C_v = %.2f" % (r["drag"], r["cvRequested"]))
    bx.axvspan(T0, max(r["history"][-1][0] for r in rows), color="0.92")
    bx.set_xlabel("t [s]")
    bx.set_ylabel("-w / u_t (ores' mean axial velocity)")
    bx.set_title("approach and averaging window (grey)")
    bx.legend(fontsize=7, ncol=2)
    bx.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(figure, dpi=110)



def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("-cv", type=float, nargs="+", default=list(CV_LIST))
    ap.add_argument("-endTime", type=float, default=0.45)
    ap.add_argument("-j", type=int, default=2)
    ap.add_argument("-scratch", default=os.path.join(ROOT, "build/validation/hinderedSettling"))
    ap.add_argument("-reuse", action="store_true")
    args = ap.parse_args()
    os.makedirs(args.scratch, exist_ok=True)
    jobs = [(drag, cv) for drag in DRAGS for cv in args.cv]
    if not args.reuse:
        with ThreadPoolExecutor(max_workers=args.j) as pool:
            list(pool.map(lambda job: run(args.scratch, job[0], job[1], args.endTime), jobs))
    rows = [evaluate(args.scratch, drag, cv) for drag, cv in jobs]
    text = table(rows)
    print(text)
    results = os.path.join(HERE, "results")
    os.makedirs(results, exist_ok=True)
    with open(os.path.join(results, "hinderedSettling.md"), "w") as out:
        out.write("u_t = %.5f m/s, Re_t = %.2f, d/D = %.3f; n: Richardson & Zaki %.4f, "
                  "Garside & Al-Dibouni %.4f; window (%g, %g] s\n\n%s\n"
                  % (UT, RE_T, d / D, sus.n_richardson_zaki(RE_T, d / D),
                     sus.n_garside_al_dibouni(RE_T), T0, args.endTime, text))
    with open(os.path.join(results, "hinderedSettling.json"), "w") as out:
        json.dump([{k: v for k, v in r.items() if k != "history"} for r in rows], out, indent=1)
    plot(rows, os.path.join(ROOT, "validation/figures/hinderedSettling.png"))


if __name__ == "__main__":
    main()
