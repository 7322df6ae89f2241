"""Lifting efficiency and contact rates against the solids volume fraction
C_v: the scene of tutorials/riser/oreTransport (ores d ~ N(10 mm, 1 mm),
8..12 mm, 2000 kg/m^3, filled at rest relative to the carrier by riserFill;
wall and pair contact; riser frame, exact carrier, the paper's forces with
Basset) in a shorter periodic section, for several C_v, the riser shaken at
A = 0.1 m, f = 3 Hz (the paper's A = 1, f = 0.3 in units of D = 0.1 m and
u_cm = 1 m/s). The single-ore limit (C_v -> 0) is the same scene with one
10 mm ore from a manual injection, from a few release positions.

Each case runs riserParcelFoam for a few riser periods; the tables of
riserTransportStatistics (transport.dat, read by column name) are sampled
twelve times a period. The first period is start-up and discarded; the
others are averaged period by period (the wall impacts' mean speed
weighted by the impacts of each row), and the spread between those period
means is reported with their mean. Columns a version of the table lacks
(pairContactRate, wallEnergy, pairEnergy) are skipped. The CPU time of
each run is its log's last ExecutionTime; the log also gives the ores
placed, the largest pair overlap and any particle outside the pipe.

usage: sweep.py [-cv 0.005 0.01 ...] [-periods 6] [-L 4.5] [-j 2]
                [-single 4 (single-ore releases)]
                [-endTime T (a pipeline check: overrides -periods)]
                [-scratch DIR] [-results DIR] [-figure PNG]
                [-reuse (no runs: rebuild the results from the cases)]

Writes results/sweep.md and results/sweep.json and
../figures/oreTransport_solidsFraction.png.

SPDX-License-Identifier: GPL-3.0-or-later
"""
import argparse
import datetime
import json
import math
import os
import re
import sys
import time
from concurrent.futures import ThreadPoolExecutor

import numpy as np
from riserfoam import cases, tables
from riserfoam import foamfields as ff
from riserfoam.carrier import D, UCM

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "../.."))
A, F = 1.0 * D, 0.3 * UCM / D          # 0.1 m, 3 Hz
PERIOD = 1.0 / F
SAMPLES = 12                            # statistics samples a period
STEPS = 660                             # flow steps a period (dt = 5.05e-4 s)
CELLS = 8                               # across the core, as the tutorial
SINGLE_RELEASES = ((0.0, 0.0), (0.2, 0.2), (-0.3, 0.1), (0.1, -0.35))   # [D], the single ore
# columns averaged a period at a time; the pair ones only when present
INSTANT = ("Cv", "particles", "liftingEfficiency", "slipz")
RATES = ("contactRate", "pairContactRate")
OPTIONAL = ("pairContactRate", "wallEnergy", "pairEnergy")
TRANSPORT = "postProcessing/lagrangian/kinematicCloud/riserTransportStatistics/transport.dat"


def set_run(case, end):
    """run length, flow step and one write at the end; samples SAMPLES a period"""
    control = os.path.join(case, "system/controlDict")
    ff.set_entry(control, "endTime", "%.15g" % end)
    ff.set_entry(control, "deltaT", "%.15g" % (PERIOD / STEPS))
    ff.set_entry(control, "writeInterval", "%.15g" % end)
    props = os.path.join(case, "constant/kinematicCloudProperties")
    ff.edit(props, r"^(\s*interval\s+)[^;]*;", r"\g<1>%.15g;" % (PERIOD / SAMPLES))


def fill_case(scratch, cv, end, L):
    """oreTransport filled at C_v, in scratch/cv<C_v>"""
    case = os.path.join(scratch, "cv%g" % cv)
    cases.copy_tutorial("riser/oreTransport", case)
    ff.edit(os.path.join(case, "constant/kinematicCloudProperties"),
            r"^(\s*solidsFraction\s+)[^;]*;", r"\g<1>%r;" % cv)
    set_run(case, end)
    cases.riser_mesh(case, D, L, CELLS)
    return case


def single_case(scratch, i, release, end, L):
    """oreTransport with one 10 mm ore released at (x, y) [D] instead of the fill"""
    case = cases.RiserCase(ROOT, scratch, "single%d" % i, tutorial="oreTransport")
    case.releases([release], d=0.01)
    set_run(case.path, end)
    cases.riser_mesh(case.path, D, L, CELLS)
    return case.path


def solve(case):
    """run riserParcelFoam in case"""
    cases.run(["riserParcelFoam", "-case", case], os.path.join(case, "log.riserParcelFoam"),
              cwd=case)


def run_times(case):
    """(CPU [s], clock [s]) of the solver log's last ExecutionTime"""
    text = open(os.path.join(case, "log.riserParcelFoam")).read()
    times = re.findall(r"ExecutionTime = ([-+0-9.eE]+) s\s+ClockTime = ([-+0-9.eE]+) s", text)
    return tuple(float(v) for v in times[-1]) if times else (math.nan, math.nan)


def log_facts(case):
    """what the solver's log says: ores placed and the fraction achieved,
    the largest pair overlap, particles outside the pipe"""
    text = open(os.path.join(case, "log.riserParcelFoam")).read()
    facts = {}
    overlaps = re.findall(r"largest pair overlap in this run ([-+0-9.eE]+)", text)
    facts["largestPairOverlap/d"] = float(overlaps[-1]) if overlaps else None
    facts["outsideWarnings"] = len(re.findall(r"outside the pipe", text))
    fill = re.search(r"riserFill: placed (\d+) ores, solids fraction C_v = ([-+0-9.eE]+)", text)
    facts["oresPlaced"] = int(fill.group(1)) if fill else None
    facts["CvFilled"] = float(fill.group(2)) if fill else None
    return facts


def periods(case, end):
    """{column: [mean over each period after the first]} of transport.dat"""
    table = tables.read(os.path.join(case, TRANSPORT))
    t = table["t"]
    n = int(round(end / PERIOD))
    out = {"periods": list(range(2, n + 1))}
    present = [c for c in INSTANT + RATES + OPTIONAL if c in table]
    for column in present:
        values = table[column]
        means = []
        for k in range(1, n):
            # the samples of period k+1: t in (k T, (k+1) T]; each rate row covers
            # the interval since the previous row, so its mean is the period's rate
            rows = (t > k * PERIOD + 0.25 * PERIOD / SAMPLES) & \
                   (t <= (k + 1) * PERIOD + 0.25 * PERIOD / SAMPLES)
            means.append(float(np.mean(values[rows])) if rows.any() else math.nan)
        out[column] = means
    # the wall impacts' mean normal speed, each row weighted by its impacts
    speeds, impacts = table["impactSpeedMean"], table["impacts"]
    out["impactSpeedMean"] = []
    for k in range(1, n):
        rows = (t > k * PERIOD + 0.25 * PERIOD / SAMPLES) & \
               (t <= (k + 1) * PERIOD + 0.25 * PERIOD / SAMPLES) & (impacts > 0)
        out["impactSpeedMean"].append(float(np.sum(speeds[rows] * impacts[rows])
                                            / np.sum(impacts[rows])) if rows.any() else math.nan)
    out["missing"] = [c for c in OPTIONAL if c not in table]
    out["rows"] = len(table)
    return out


def summary(p, column):
    """(mean, half the range) of a column's period means"""
    values = np.array(p.get(column, []), dtype=float)
    values = values[np.isfinite(values)]
    if not len(values):
        return None
    return [float(values.mean()), float(0.5 * (values.max() - values.min()))]


def machine():
    cpu = "unknown"
    try:
        for line in open("/proc/cpuinfo"):
            if line.startswith("model name"):
                cpu = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    return {"nproc": os.cpu_count(), "cpu": cpu}


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("-cv", type=float, nargs="+", default=[0.005, 0.01, 0.02, 0.05, 0.1])
    ap.add_argument("-periods", type=int, default=6)
    ap.add_argument("-endTime", type=float, default=None)
    ap.add_argument("-L", type=float, default=4.5, help="periodic section [m] (the tutorial's)")
    ap.add_argument("-j", type=int, default=2, help="solver runs at a time (at most 2)")
    ap.add_argument("-single", type=int, default=len(SINGLE_RELEASES),
                    help="single-ore releases (0: none)")
    ap.add_argument("-scratch", default=os.path.join(ROOT, "build/validation/oreTransportSweep"))
    ap.add_argument("-results", default=os.path.join(HERE, "results"))
    ap.add_argument("-figure", default=os.path.join(ROOT, "validation/figures",
                                                      "oreTransport_solidsFraction.png"))
    ap.add_argument("-reuse", action="store_true",
                    help="no runs: the tables, chart and results from the cases of an earlier "
                         "sweep in -scratch (its command, date and run time kept from sweep.json)")
    args = ap.parse_args()
    jobs = max(1, min(args.j, 2))
    end = args.endTime if args.endTime else args.periods * PERIOD
    nPeriods = int(round(end / PERIOD))
    os.makedirs(args.scratch, exist_ok=True)
    started = time.time()

    if args.reuse:
        work = [("cv", cv, os.path.join(args.scratch, "cv%g" % cv)) for cv in args.cv]
        work += [("single", release, os.path.join(args.scratch, "single%d" % i))
                 for i, release in enumerate(SINGLE_RELEASES[:args.single])]
    else:
        work = [("cv", cv, fill_case(args.scratch, cv, end, args.L)) for cv in args.cv]
        work += [("single", release, single_case(args.scratch, i, release, end, args.L))
                 for i, release in enumerate(SINGLE_RELEASES[:args.single])]
        # the densest first, so that the two slots finish about together

        def one(item):
            kind, key, case = item
            solve(case)
            print("  %s %s: CPU %.1f s, clock %.0f s" % ((kind, key) + run_times(case)), flush=True)

        with ThreadPoolExecutor(max_workers=jobs) as pool:
            list(pool.map(one, sorted(work, key=lambda w: -(w[1] if w[0] == "cv" else 0.0))))

    rows, singles = [], []
    for kind, key, case in work:
        cpu, clock = run_times(case)
        entry = {"case": os.path.relpath(case, ROOT), "cpu": cpu, "clock": clock}
        entry.update(log_facts(case))
        if nPeriods >= 2:
            p = periods(case, end)
            entry["periodMeans"] = p
            for column in INSTANT + RATES + OPTIONAL + ("impactSpeedMean",):
                entry[column] = summary(p, column)
        if kind == "cv":
            entry["CvRequested"] = key
            rows.append(entry)
        else:
            entry["release"] = list(key)
            singles.append(entry)
    rows.sort(key=lambda r: r["CvRequested"])

    result = {
        "command": " ".join([os.path.relpath(sys.argv[0], ROOT)] + sys.argv[1:]),
        "date": datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC"),
        "machine": machine(),
        "jobs": jobs,
        "scene": {"D": D, "u_cm": UCM, "A": A, "f": round(F, 12), "L": args.L, "cells": CELLS,
                  "deltaT": PERIOD / STEPS, "endTime": end, "periods": nPeriods,
                  "samplesPerPeriod": SAMPLES, "discarded": "the first period (start-up)"},
        "sweep": rows,
        "single": singles,
        "totalWallClock": time.time() - started,
    }
    previous = os.path.join(args.results, "sweep.json")
    if args.reuse and os.path.exists(previous):
        with open(previous) as f:
            old = json.load(f)
        for key in ("command", "date", "machine", "jobs", "totalWallClock"):
            result[key] = old[key]
    if nPeriods < 2:
        print("sweep.py: %g s is less than two periods: nothing averaged, results/ left as "
              "they were (a pipeline check)" % end)
        return
    os.makedirs(args.results, exist_ok=True)
    with open(os.path.join(args.results, "sweep.json"), "w") as f:
        json.dump(result, f, indent=1, allow_nan=True)
    write_markdown(result, os.path.join(args.results, "sweep.md"))
    plot(result, args.figure)
    print(open(os.path.join(args.results, "sweep.md")).read())


def fmt(pair, scale=1.0, digits=3):
    if pair is None:
        return "-"
    return "%.*g ± %.*g" % (digits, pair[0] * scale, 2, pair[1] * scale)


def single_reference(result):
    """(mean, half range) of the single ore's lifting efficiency over releases"""
    values = [s["liftingEfficiency"][0] for s in result["single"] if s.get("liftingEfficiency")]
    if not values:
        return None
    return [float(np.mean(values)), float(0.5 * (max(values) - min(values)))]


def write_markdown(result, path):
    scene = result["scene"]
    present = [c for c in OPTIONAL if any(r.get(c) for r in result["sweep"])]
    head = ["C_v requested", "C_v filled", "in-situ C_v", "ores", "lifting efficiency", "slip_z / u_cm",
            "wall contacts / ore / s", "wall impact speed [m/s]"] + \
        [{"pairContactRate": "pair contacts / ore / s", "wallEnergy": "wallEnergy (mean of rows)",
          "pairEnergy": "pairEnergy (mean of rows)"}[c] for c in present] + \
        ["CPU [s]", "largest pair overlap / d", "outside the pipe"]
    lines = ["# Lifting efficiency and contact rates against C_v", "",
             "Scene: tutorials/riser/oreTransport in a %g m periodic section (D = %g m, "
             "%d cells across the core), A = %g m, f = %g Hz (the paper's A = 1, f = 0.3), "
             "riser frame, exact carrier; ores d ~ N(10 mm, 1 mm) in 8..12 mm, 2000 kg/m^3, "
             "wall and pair contact. %d periods (%.4g s) at dt = %.4g s, %d samples a period; "
             "the first period is start-up and discarded, each value is the mean of the "
             "period means of periods 2..%d ± half their range (the spread between periods)."
             % (scene["L"], scene["D"], scene["cells"], scene["A"], scene["f"], scene["periods"],
                scene["endTime"], scene["deltaT"], scene["samplesPerPeriod"], scene["periods"]),
             "",
             "| " + " | ".join(head) + " |",
             "|" + "---|" * len(head)]
    for r in result["sweep"]:
        cells = ["%g" % r["CvRequested"], "%.4g" % r["CvFilled"], fmt(r["Cv"], digits=4),
                 "%d" % r["oresPlaced"],
                 fmt(r["liftingEfficiency"]), fmt(r["slipz"], 1 / UCM), fmt(r["contactRate"]),
                 fmt(r["impactSpeedMean"])]
        cells += [fmt(r.get(c)) for c in present]
        cells += ["%.1f" % r["cpu"],
                  "-" if r["largestPairOverlap/d"] is None else "%.3g" % r["largestPairOverlap/d"],
                  "%d" % r["outsideWarnings"]]
        lines.append("| " + " | ".join(cells) + " |")
    lines.append("")
    # each period's mean: the trend the ± above folds in
    n = scene["periods"]
    shown = [c for c in ("liftingEfficiency", "contactRate", "pairContactRate") if c == "liftingEfficiency"
             or c == "contactRate" or c in present]
    names = {"liftingEfficiency": "lifting efficiency", "contactRate": "wall contacts / ore / s",
             "pairContactRate": "pair contacts / ore / s"}
    lines += ["Each period's mean, periods 2..%d:" % n, "",
              "| C_v requested | " + " | ".join(names[c] for c in shown) + " |",
              "|" + "---|" * (1 + len(shown))]
    for r in result["sweep"] + result["single"]:
        key = "%g" % r["CvRequested"] if "CvRequested" in r else \
            "single ore at (%g, %g) D" % tuple(r["release"])
        lines.append("| %s | " % key + " | ".join(
            " / ".join("%.4g" % v for v in r["periodMeans"][c]) for c in shown) + " |")
    lines.append("")
    if n >= 3:
        excess = ["%g: %+.0f %%" % (r["CvRequested"], 100 * (r["periodMeans"]["contactRate"][0]
                                                          / np.mean(r["periodMeans"]["contactRate"][1:])
                                                          - 1))
                  for r in result["sweep"]]
        lines += ["Wall contact rate of period 2 against the mean of periods 3..%d (what is left "
                  "of the start-up): C_v = %s." % (n, ", ".join(excess)), ""]
    ref = single_reference(result)
    if result["single"]:
        lines += ["Single ore (d = 10 mm, manual injection, same scene, the C_v -> 0 limit):", "",
                  "| release (x, y) / D | lifting efficiency | slip_z / u_cm | "
                  "wall contacts / s | wall impact speed [m/s] | CPU [s] |",
                  "|---|---|---|---|---|---|"]
        for s in result["single"]:
            lines.append("| (%g, %g) | %s | %s | %s | %s | %.1f |"
                         % (s["release"][0], s["release"][1], fmt(s["liftingEfficiency"]),
                            fmt(s["slipz"], 1 / UCM), fmt(s["contactRate"]),
                            fmt(s["impactSpeedMean"]), s["cpu"]))
        lines += ["", "Single-ore lifting efficiency over the releases: %s." % fmt(ref), ""]
    missing = [c for c in OPTIONAL if c not in present]
    if missing:
        lines += ["Columns not in this version's transport.dat (skipped): %s." % ", ".join(missing),
                  ""]
    m = result["machine"]
    lines += ["Command: `%s` (%d solver runs at a time); %s; %d cores, %s; the whole sweep "
              "took %.0f s." % (result["command"], result["jobs"], result["date"], m["nproc"],
                                m["cpu"], result["totalWallClock"]), ""]
    with open(path, "w") as f:
        f.write("\n".join(lines))


def plot(result, out):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import matplotlib.ticker

    rows = result["sweep"]
    cv = np.array([r["CvRequested"] for r in rows])

    def series(column, scale=1.0):
        m = np.array([r[column][0] if r.get(column) else np.nan for r in rows]) * scale
        e = np.array([r[column][1] if r.get(column) else np.nan for r in rows]) * scale
        return m, e

    fig, axes = plt.subplots(2, 2, figsize=(12, 9))
    ax = axes.ravel()
    periods = result["scene"]["periods"]
    m, e = series("liftingEfficiency")
    ax[0].errorbar(cv, m, yerr=e, fmt="o-", capsize=3,
                   label="cloud, periods 2..%d (bars: range of the period means)" % periods)
    ref = single_reference(result)
    if ref:
        ax[0].axhline(ref[0], ls="--", color="k",
                      label="single ore, C_v -> 0 (%.3f)" % ref[0])
        if ref[1] > 0:
            ax[0].axhspan(ref[0] - ref[1], ref[0] + ref[1], color="k", alpha=0.08,
                          label="single ore: range over %d releases" % len(result["single"]))
    ax[0].set(ylabel="mean v_z / u_cm", title="lifting efficiency")

    m, e = series("contactRate")
    ax[1].errorbar(cv, m, yerr=e, fmt="o-", capsize=3, label="wall")
    if any(r.get("pairContactRate") for r in rows):
        m, e = series("pairContactRate")
        ax[1].errorbar(cv, m, yerr=e, fmt="s-", capsize=3, label="pair")
    singles = [s["contactRate"][0] for s in result["single"] if s.get("contactRate")]
    if singles:
        ax[1].axhline(np.mean(singles), ls="--", color="k", label="wall, single ore")
    ax[1].set(ylabel="contacts per ore per second", title="contact rates")

    m, e = series("impactSpeedMean")
    ax[2].errorbar(cv, m, yerr=e, fmt="o-", capsize=3, label="cloud")
    singles = [s["impactSpeedMean"][0] for s in result["single"] if s.get("impactSpeedMean")]
    if singles:
        ax[2].axhline(np.mean(singles), ls="--", color="k", label="single ore")
    ax[2].set_ylim(bottom=0)
    ax[2].set(ylabel="mean normal impact speed [m/s]",
              title="wall impacts: mean speed towards the wall")
    for a in ax[:3]:
        a.set(xscale="log", xlabel="C_v (requested)")
        a.set_xticks(cv)
        a.xaxis.set_major_formatter(matplotlib.ticker.FormatStrFormatter("%g"))
        a.xaxis.set_minor_formatter(matplotlib.ticker.NullFormatter())
        a.legend(fontsize=8)

    ores = np.array([r["oresPlaced"] for r in rows], dtype=float)
    cpu = np.array([r["cpu"] for r in rows])
    ax[3].loglog(ores, cpu, "o-", label="cloud")
    for n, c, x in zip(ores, cpu, cv):
        ax[3].annotate("C_v = %g" % x, (n, c), textcoords="offset points", xytext=(4, -10),
                       fontsize=7)
    if result["single"]:
        ax[3].loglog([1], [np.mean([s["cpu"] for s in result["single"]])], "k^",
                     label="single ore")
    ax[3].set(xlabel="ores", ylabel="CPU [s] for %d periods" % periods,
              title="cost (riserParcelFoam, serial)")
    ax[3].legend(fontsize=8)
    for a in ax:
        a.grid(True, which="both", alpha=0.3)
    fig.suptitle("ores in the shaken riser (A = 1, f = 0.3, %g m periodic section): "
                 "against the solids fraction" % result["scene"]["L"])
    fig.tight_layout(rect=(0, 0, 1, 0.97))
    os.makedirs(os.path.dirname(out), exist_ok=True)
    fig.savefig(out, dpi=110)


if __name__ == "__main__":
    main()
