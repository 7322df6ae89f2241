"""Mesh-free engine charts: the (A, f) regime map and the work-precision of
the integrators, from runs of riserParticle on copies of a riser tutorial.

usage: run.py <riserFoam root> <scratch folder> <results folder> <figures folder>
SPDX-License-Identifier: GPL-3.0-or-later
"""
import os
import re
import shutil
import sys
import time

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402  (after the backend)
from matplotlib.colors import ListedColormap  # noqa: E402
import numpy as np  # noqa: E402
from riserfoam import tables  # noqa: E402
from riserfoam.carrier import D, UCM  # noqa: E402
from riserfoam.cases import RiserCase  # noqa: E402

root, scratch, results, figures = sys.argv[1:5]


def make_case(name, A=None, f=None, endTime=None, deltaT=None):
    """the f = 0.05 tutorial's case with A [m], f [Hz], endTime and deltaT [s]"""
    case = RiserCase(root, scratch, name).riser(A=None if A is None else A / D,
                                                f=None if f is None else f * D / UCM)
    if endTime is not None:
        case.run_for(endTime, deltaT)
    return case


def sweep(name, As, fs):
    """riserParticle -sweep (20 periods per case) over the grid of A [m] and
    f [Hz]: its rows (dicts by column name), kept in results/<name>.dat"""
    case = make_case(name)
    table = case.sweep(As, fs, periods=20, liftTime=10)
    shutil.copy(table.path, os.path.join(results, name + ".dat"))
    return list(table)


# --- regime map -------------------------------------------------------------
nA = nF = 40
As = np.linspace(0.25, 2.0, nA) * D
fs = np.linspace(0.025, 0.4, nF) * UCM / D
start = time.time()
rows = sweep("regimeMap", As, fs)
wall = time.time() - start
classes = ["noContact", "onceFirstPeriod", "firstPeriodsOnly", "other", "bothWallsEveryPeriod"]
grid = np.full((nA, nF), -1)
failed = 0
for i, r in enumerate(rows):
    if r["status"] != "ok":
        failed += 1
        continue
    grid[i // nF, i % nF] = classes.index(r["regime"])
summary = ["regime map: %d x %d cases, 20 periods each, %.1f s wall time (riserParticle -sweep, "
           "default integrator), %d failed" % (nA, nF, wall, failed)]

fig, ax = plt.subplots(figsize=(7.5, 6))
colours = ["#dddddd", "#9ecae1", "#4292c6", "#fdae6b", "#d94801"]
ax.pcolormesh(As / D, fs * D / UCM, np.ma.masked_less(grid, 0).T,
              cmap=ListedColormap(colours), vmin=-0.5, vmax=4.5, shading="nearest")
# boundaries f (A - a0) = c between consecutive classes in the order above
Ad = As / D
fd = fs * D / UCM
for k in range(len(classes) - 1):
    pts = []
    for i in range(nA):
        col = grid[i]
        for j in range(nF - 1):
            if 0 <= col[j] <= k < col[j + 1]:
                pts.append((Ad[i], 0.5 * (fd[j] + fd[j + 1])))
                break
    if len(pts) < 4:
        continue
    a, f = np.array(pts).T
    # f A = c + a0 f: linear least squares in (c, a0)
    (c, a0), *_ = np.linalg.lstsq(np.c_[np.ones_like(f), f], f * a, rcond=None)
    aa = np.linspace(max(a0 + 1e-3, Ad[0]), Ad[-1], 200)
    ff = c / (aa - a0)
    keep = (ff >= fd[0]) & (ff <= fd[-1])
    ax.plot(aa[keep], ff[keep], "k-", lw=1.2)
    summary.append("boundary above %s: f (A - %.3f) = %.4f (dimensionless), %d points"
                   % (classes[k], a0, c, len(pts)))
handles = [plt.Rectangle((0, 0), 1, 1, color=c) for c in colours]
ax.legend(handles, ["no contact", "one contact in the first period", "contacts in the first periods only",
                    "other (one wall, intermittent)", "both walls every period"], fontsize=8, loc="upper right")
ax.set_xlabel("A / D")
ax.set_ylabel("f D / u_cm")
ax.set_title("regime map (riserParticle, 20 periods per case)")
fig.tight_layout()
fig.savefig(os.path.join(figures, "regime_map.png"), dpi=110)

# --- frequency and amplitude sweeps (the paper's Figs. 8-16) ----------------
freq = sweep("frequencySweep", [0.1], np.linspace(0.025, 0.4, 31) * UCM / D)
amp = sweep("amplitudeSweep", np.linspace(0.5, 2.0, 31) * D, np.array([0.05, 0.3]) * UCM / D)
fig, axes = plt.subplots(2, 3, figsize=(14, 7.5), sharex="col")
quantities = (("lift", "lifting distance after 10 s / D", D),
              ("maxRelativeLateralSpeed", "largest |v_px - U_r| / u_cm", UCM),
              ("meanVerticalSpeed", "mean vertical speed / u_cm", UCM))
for col, (k, label, scale) in enumerate(quantities):
    ax = axes[0, col]
    ok = [r for r in freq if r["status"] == "ok"]
    ax.plot([float(r["f"]) * D / UCM for r in ok], [float(r[k]) / scale for r in ok], "o-", ms=3)
    contact = [r for r in ok if r["regime"] != "noContact"]
    ax.plot([float(r["f"]) * D / UCM for r in contact], [float(r[k]) / scale for r in contact], "o",
            ms=5, mfc="none", color="C3", label="with wall contacts")
    ax.set_xlabel("f D / u_cm (A = D)")
    ax.set_ylabel(label)
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=7)
    ax = axes[1, col]
    for fd, style in ((0.05, "s-"), (0.3, "o-")):
        ok = [r for r in amp if r["status"] == "ok" and abs(float(r["f"]) * D / UCM - fd) < 1e-9]
        ax.plot([float(r["A"]) / D for r in ok], [float(r[k]) / scale for r in ok], style, ms=3,
                label="f = %g" % fd)
    ax.set_xlabel("A / D")
    ax.set_ylabel(label)
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=7)
fig.suptitle("frequency sweep (A = D, top) and amplitude sweeps (f = 0.05 and 0.3, bottom): "
             "riserParticle, 20 periods per case, default integrator", fontsize=10)
fig.tight_layout()
fig.savefig(os.path.join(figures, "sweeps.png"), dpi=110)
for name, rs in (("frequency sweep (A = D)", freq), ("amplitude sweep", amp)):
    failed = sum(r["status"] != "ok" for r in rs)
    lifts = [float(r["lift"]) for r in rs if r["status"] == "ok"]
    summary.append("%s: %d cases, %d failed; lift after 10 s from %.3g D to %.3g D"
                   % (name, len(rs), failed, max(lifts) / D, min(lifts) / D))

# --- work-precision ---------------------------------------------------------
def trajectory(case):
    """the engine's x - x_c, y and lifting distance, a row per table row"""
    return tables.read(os.path.join(case.path, "postProcessing/riserParticle/particles.dat")) \
        .matrix("xr", "yr", "lift")


def cpu_of(log):
    """the integration's own time (the engine times the row writing apart)"""
    return sum(float(m) for m in re.findall(r"\(([0-9.eE+-]+) s integrating", log))


wp = []
for scene, f, T in (("f005", 0.5, 4.0), ("f03", 3.0, 5 / 3.0)):
    # rows every 1/50 period: the trajectory is compared there, and the
    # adaptive steps are not cut short by the rows
    case = make_case("wp_" + scene, A=0.1, f=f, endTime=T, deltaT=0.02/f)
    # the converged reference: without contact, fixed fifth-order steps of
    # 1e-5 s (the paper scheme with no contact to handle; 1e-4 s and 5e-5 s
    # agree with it to 6e-9 D); with contacts, the adaptive scheme at 1e-12
    case.engine_settings("integrator paper; paperCoeffs { flowStep 1e-5; }" if f < 1 else
                         "integrator adaptive; adaptiveCoeffs { tolerance 1e-12; }").engine()
    ref = trajectory(case)
    runs = [("adaptive", "tolerance %g" % tol,
             "integrator adaptive; adaptiveCoeffs { tolerance %g; }" % tol)
            for tol in (1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10, 1e-11)]
    runs += [("paper", "flow step %g s" % h,
              "integrator paper; paperCoeffs { flowStep %g; }" % h)
             for h in (5e-4, 2e-4, 1e-4, 5e-5, 2e-5)]
    for name, label, text in runs:
        case.engine_settings(text)
        # the engine times its own integration; short runs are repeated and
        # the least time kept (a noisy machine only ever adds time)
        log = case.engine_log(may_fail=True)
        if log is None:         # the integration failed: the step is too large
            wp.append((scene, name, label, float("nan"), float("nan"), float("nan")))
            continue
        cpu = cpu_of(log)
        for _ in range(2 if cpu < 0.5 else 0):
            cpu = min(cpu, cpu_of(case.engine_log()))
        t = trajectory(case)
        if t.shape != ref.shape:
            sys.exit("rows differ for %s %s" % (name, label))
        traj = np.linalg.norm(t - ref, axis=1).max() / D
        lift = abs(t[-1, 2] - ref[-1, 2]) / D
        wp.append((scene, name, label, cpu, traj, lift))
with open(os.path.join(results, "workPrecision.dat"), "w") as out:
    out.write("# scene integrator setting cpu[s] trajectoryError/D liftError/D "
              "(against fixed steps of 1e-5 s for f005, adaptive at tolerance 1e-12 for f03)\n")
    for r in wp:
        out.write("%s %s %s %.4g %.4e %.4e\n" % (r[0], r[1], r[2].replace(" ", "_"), r[3], r[4], r[5]))

fig, axes = plt.subplots(1, 2, figsize=(13, 5))
for ax, scene, title in zip(axes, ("f005", "f03"), ("A = 1, f = 0.05 (no contact), 2 periods",
                                                   "A = 1, f = 0.3 (contacts), 5 periods")):
    for name, style in (("adaptive", "o-"), ("paper", "s--")):
        pts = [r for r in wp if r[0] == scene and r[1] == name and np.isfinite(r[3])]
        cpu = [r[3] for r in pts]
        ax.loglog(cpu, [max(r[4], 1e-16) for r in pts], style, label="%s: trajectory" % name)
        ax.loglog(cpu, [max(r[5], 1e-16) for r in pts], style, alpha=0.5, label="%s: lifting distance" % name)
        for r in pts:
            ax.annotate(r[2].replace("tolerance ", "").replace("flow step ", ""), (r[3], max(r[4], 1e-16)),
                        fontsize=6, xytext=(3, 3), textcoords="offset points")
    ax.set_xlabel("CPU time [s]")
    ax.set_ylabel("largest error / D")
    ax.set_title(title)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
fig.tight_layout()
fig.savefig(os.path.join(figures, "work_precision.png"), dpi=110)

for scene in ("f005", "f03"):
    paperDefault = [r for r in wp if r[0] == scene and r[1] == "paper" and r[2] == "flow step 0.0001 s"][0]
    better = [r for r in wp if r[0] == scene and r[1] == "adaptive" and r[4] <= paperDefault[4]]
    cheapest = min(better, key=lambda r: r[3]) if better else None
    summary.append("%s: paper scheme (flow step 1e-4 s = 1e-3 D/u_cm): error %.2e D in %.3g s; "
                   % (scene, paperDefault[4], paperDefault[3])
                   + ("adaptive reaches it at %s in %.3g s (%.1f times less CPU)"
                      % (cheapest[2], cheapest[3], paperDefault[3] / max(cheapest[3], 1e-9))
                      if cheapest else "no adaptive setting reached it"))
    default = [r for r in wp if r[0] == scene and r[1] == "adaptive" and r[2] == "tolerance 1e-06"][0]
    summary.append("%s: adaptive integrator at tolerance 1e-6 (the earlier default): error %.2e D in %.3g s, "
                   "%.1f times less CPU than the paper scheme"
                   % (scene, default[4], default[3], paperDefault[3] / default[3]))
    for r in wp:
        if r[0] == scene and not np.isfinite(r[3]):
            summary.append("%s: %s at %s failed (overlap beyond the radius or a state not finite)"
                           % (scene, r[1], r[2]))
open(os.path.join(results, "summary.txt"), "w").write("\n".join(summary) + "\n")
print("\n".join(summary))
