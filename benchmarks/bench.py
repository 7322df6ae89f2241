"""riserFoam benchmarks: riserParcelFoam against stock OpenFOAM v1912,
scaling with particles and with processors (issue 8).

Runs the suites below on one riser mesh, in one process, alternating the
variants (A, B, C, A, B, C, ...) so that the machine's load falls on all of
them alike, and writes results/results.json. benchmarks/Allrun calls it;
plot.py turns the results into results/benchmarks.png and results/summary.md.

Timing: each solver's standard output is read line by line as it runs. At
every "ExecutionTime" line (one per time step) the runner records the wall
clock (time.perf_counter) and the CPU time the solver's threads have used
(/proc/<pid>/task/*/schedstat, nanoseconds: OpenFOAM's own ExecutionTime is
counted in 10 ms ticks, too coarse for a 0.1 ms step) and the solver's peak
resident memory so far (VmHWM in /proc/<pid>/status, the figure
/usr/bin/time -v reports as maximum resident set size, read before the
solver tears down). The cost of a step is the difference between
consecutive lines; a run's time per step is the mean over the measured
steps, which leave out the first steps (start-up, the injection of all
particles at the first step) and the last one (it writes). CPU time is used
for the serial comparisons (the other work on a shared machine inflates it
far less than wall time), wall time for the parallel speedup.

Cost per particle-step = (t(N) - t(N0)) / (N - N0), with t the time per step
(the minimum over the repeats of each variant) at N particles and at N0 = 1
particle, so that the per-step work that does not depend on the particles
(mesh motion, carrier imposition, mesh-wide fields, output) is reported
separately, as t(N0).

usage: bench.py [--quick] [--suites stock,riserFrame,particles,processors]
                [--build DIR] [--results DIR]

License: GPL-3.0-or-later
"""
import argparse
import datetime
import glob
import hashlib
import json
import math
import os
import platform
import re
import shutil
import statistics
import subprocess
import sys
import time

import riserCases as rc

HERE = os.path.dirname(os.path.abspath(__file__))

DT = 1e-4                   # flow step [s], as the reference points
LENGTH = 0.5                # riser length: 5 D, cyclic ends
MESH_N, MESH_NZ = 12, 44    # riserMesh -n 12 -nz 44: 21,120 cells


# ------------------------------------------------------------------ running

def cpu_ns(pid):
    """CPU time [ns] used so far by all threads of process pid."""
    total = 0
    for stat in glob.glob("/proc/%d/task/*/schedstat" % pid):
        try:
            total += int(open(stat).read().split()[0])
        except (OSError, ValueError, IndexError):
            pass
    return total


def peak_rss_kb(pid):
    try:
        for line in open("/proc/%d/status" % pid):
            if line.startswith("VmHWM:"):
                return int(line.split()[1])
    except OSError:
        pass
    return None


def run_solver(case, application, np=1):
    """Run application on case (np > 1: decomposePar first, mpirun).
    Returns the per-step wall and CPU times and the run's facts."""
    log = os.path.join(case, "log.%s%s" % (application, "" if np == 1 else ".np%d" % np))
    if np == 1:
        cmd = [application, "-case", case]
    else:
        cmd = ["mpirun", "--allow-run-as-root", "--oversubscribe", "-np", str(np),
               application, "-parallel", "-case", case]
    wall, cpu, rss = [], [], None
    parcels = None
    subcycles = 0
    lost = 0
    start = time.perf_counter()
    with open(log, "w") as out:
        proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                                text=True, bufsize=1)
        for line in proc.stdout:
            if line.startswith("ExecutionTime"):
                wall.append(time.perf_counter())
                if np == 1:
                    cpu.append(cpu_ns(proc.pid) * 1e-9)
                    rss = peak_rss_kb(proc.pid) or rss
            elif "Current number of parcels" in line:
                parcels = int(line.split()[-1])
            elif "move-collide subCycles" in line:
                subcycles += 1
            elif "outside the pipe" in line:
                lost += 1
            out.write(line)
        proc.wait()
    total = time.perf_counter() - start
    if proc.returncode != 0:
        raise RuntimeError("%s failed in %s (see %s)" % (application, case, log))
    return {
        "wallStamps": wall,
        "cpuStamps": cpu,
        "peakRssKB": rss,
        "parcels": parcels,
        "subCycledSteps": subcycles,
        "lostMessages": lost,
        "totalWall": total,
    }


def per_step(stamps, first, last):
    """Mean time per step over steps first..last-1 (1-based step numbers:
    stamp i is the end of step i + 1)."""
    if len(stamps) < last:
        raise RuntimeError("only %d steps logged, %d expected" % (len(stamps), last))
    return (stamps[last - 1] - stamps[first - 2]) / (last - first + 1)


def step_costs(stamps):
    """Cost of each step from step 2 on."""
    return [b - a for a, b in zip(stamps, stamps[1:])]


# ------------------------------------------------------------------ context

def machine():
    model = "?"
    for line in open("/proc/cpuinfo"):
        if line.startswith("model name"):
            model = line.split(":", 1)[1].strip()
            break
    mem = "?"
    for line in open("/proc/meminfo"):
        if line.startswith("MemTotal"):
            mem = "%.1f GB" % (int(line.split()[1]) / 1048576.0)
    def digest(path):
        try:
            return hashlib.sha256(open(path, "rb").read()).hexdigest()[:12]
        except OSError:
            return None
    appbin = os.environ.get("RISER_APPBIN", "")
    libbin = os.environ.get("RISER_LIBBIN", "")
    load = open("/proc/loadavg").read().split()[:3]
    return {
        "date": datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC"),
        "nproc": os.cpu_count(),
        "cpu": model,
        "memory": mem,
        "kernel": platform.release(),
        "loadAverageAtStart": load,
        "openfoam": os.environ.get("WM_PROJECT_VERSION", "?") + " (Debian package)",
        "riserParcelFoam": shutil.which("riserParcelFoam"),
        "riserParcelFoamSha256": digest(os.path.join(appbin, "riserParcelFoam")),
        "libriserLagrangianSha256": digest(os.path.join(libbin, "libriserLagrangian.so")),
    }


# ------------------------------------------------------------------- suites

VARIANTS = {
    # moving mesh (lab frame)
    "stockDyM": rc.Variant("stockDyM", "stock", "lab", "drag",
                           "stock DyM: sphereDrag + gravity"),
    "stockDyMCarrier": rc.Variant("stockDyMCarrier", "stock", "lab", "dragCarrier",
                                  "stock DyM: + SaffmanMei, virtualMass, pressureGradient"),
    "riserLab": rc.Variant("riserLab", "riser", "lab", "paper",
                           "riserParcelFoam lab: paper forces, contacts"),
    "riserLabBasset": rc.Variant("riserLabBasset", "riser", "lab", "paperBasset",
                                 "riserParcelFoam lab: paper forces + Basset, contacts"),
    # static mesh (riser frame for ours)
    "stockStatic": rc.Variant("stockStatic", "stock", "riser", "drag",
                              "stock static: sphereDrag + gravity"),
    "stockStaticCarrier": rc.Variant("stockStaticCarrier", "stock", "riser", "dragCarrier",
                                     "stock static: + SaffmanMei, virtualMass, pressureGradient"),
    "riserFrame": rc.Variant("riserFrame", "riser", "riser", "paper",
                             "riserParcelFoam riser frame: paper forces, contacts"),
    "riserFrameBasset": rc.Variant("riserFrameBasset", "riser", "riser", "paperBasset",
                                   "riserParcelFoam riser frame: full paper physics + Basset, contacts"),
}


class Bench:
    def __init__(self, build, quick):
        self.build = build
        self.quick = quick
        self.mesh = os.path.join(build, "mesh")
        self.results = {"machine": machine(), "quick": quick, "suites": {}}
        self.log = []

    def say(self, text):
        stamp = time.strftime("%H:%M:%S")
        print("[%s] %s" % (stamp, text), flush=True)

    def make_mesh(self):
        if os.path.isdir(self.mesh):
            shutil.rmtree(self.mesh)
        cells = rc.make_mesh(self.mesh, LENGTH, MESH_N, MESH_NZ)
        self.results["mesh"] = {
            "cells": cells, "command": "riserMesh -D 0.1 -L %g -n %d -nz %d -ends cyclic"
            % (LENGTH, MESH_N, MESH_NZ), "D": rc.D, "L": LENGTH,
        }
        self.say("mesh: %d cells" % cells)

    def case(self, suite, key, n, steps, write_at_end=False):
        path = os.path.join(self.build, suite, "%s_N%d" % (key, n))
        rc.make_case(path, VARIANTS[key], self.mesh, n, steps, DT, LENGTH, write_at_end)
        return path

    def alternate(self, suite, keys, counts, steps, first, reps):
        """Run every (variant, N) of keys x counts reps times, alternating;
        return {key: {N: [run, ...]}}."""
        cases = {(k, n): self.case(suite, k, n, steps) for k in keys for n in counts}
        runs = {k: {n: [] for n in counts} for k in keys}
        for rep in range(reps):
            for n in counts:
                order = keys if rep % 2 == 0 else list(reversed(keys))
                for k in order:
                    app = VARIANTS[k].application
                    r = run_solver(cases[(k, n)], app)
                    if r["parcels"] != n:
                        raise RuntimeError("%s: %s parcels at the end, %d injected"
                                           % (cases[(k, n)], r["parcels"], n))
                    r["cpuPerStep"] = per_step(r["cpuStamps"], first, steps - 1)
                    r["wallPerStep"] = per_step(r["wallStamps"], first, steps - 1)
                    r["cpuStepCosts"] = step_costs(r["cpuStamps"])
                    runs[k][n].append(r)
                    self.say("%-18s N = %-6d rep %d: %8.3f ms/step CPU, %8.3f ms wall, "
                             "peak RSS %s kB%s" % (k, n, rep + 1, 1e3 * r["cpuPerStep"],
                                                   1e3 * r["wallPerStep"], r["peakRssKB"],
                                                   ", %d sub-cycled steps" % r["subCycledSteps"]
                                                   if r["subCycledSteps"] else ""))
        return runs

    @staticmethod
    def summarise(runs, n0):
        """Per variant and N: min over repeats of the time per step; cost per
        particle-step against N0; peak memory."""
        out = {}
        for k, byN in runs.items():
            t = {n: min(r["cpuPerStep"] for r in rs) for n, rs in byN.items()}
            tw = {n: min(r["wallPerStep"] for r in rs) for n, rs in byN.items()}
            rss = {n: min(r["peakRssKB"] for r in rs if r["peakRssKB"]) for n, rs in byN.items()}
            per = {n: (t[n] - t[n0]) / (n - n0) for n in t if n != n0}
            out[k] = {
                "label": VARIANTS[k].label,
                "application": VARIANTS[k].application,
                "cpuPerStep": {str(n): v for n, v in t.items()},
                "cpuPerStepAllRepeats": {str(n): [r["cpuPerStep"] for r in rs]
                                         for n, rs in byN.items()},
                "wallPerStep": {str(n): v for n, v in tw.items()},
                "costPerParticleStep": {str(n): v for n, v in per.items()},
                "peakRssKB": {str(n): v for n, v in rss.items()},
                "subCycledSteps": {str(n): max(r["subCycledSteps"] for r in rs)
                                   for n, rs in byN.items()},
            }
        return out

    # --- suite 1: against stock on the moving mesh
    def suite_stock(self):
        n = 2000 if self.quick else 10000
        steps = 12 if self.quick else 25
        reps = 2 if self.quick else 3
        keys = ["stockDyM", "riserLab", "riserLabBasset", "stockDyMCarrier"]
        self.say("suite stock (moving mesh, lab frame): N = 1 and %d, %d steps, %d repeats"
                 % (n, steps, reps))
        runs = self.alternate("stock", keys, [1, n], steps, 3, reps)
        s = self.summarise(runs, 1)
        self.results["suites"]["stock"] = {
            "frame": "lab (moving mesh, riserOscillation for both solvers)",
            "N0": 1, "N": n, "steps": steps, "measuredSteps": [3, steps - 1], "repeats": reps,
            "variants": s,
        }

    # --- suite 2: the riser frame against stock on the static mesh
    def suite_riser_frame(self):
        n = 2000 if self.quick else 10000
        steps = 30 if self.quick else 60
        reps = 2 if self.quick else 3
        keys = ["stockStatic", "riserFrame", "riserFrameBasset", "stockStaticCarrier"]
        self.say("suite riserFrame (static mesh): N = 1 and %d, %d steps, %d repeats"
                 % (n, steps, reps))
        runs = self.alternate("riserFrame", keys, [1, n], steps, 3, reps)
        s = self.summarise(runs, 1)
        self.results["suites"]["riserFrame"] = {
            "frame": "riser (static mesh) for riserParcelFoam; static mesh for stock",
            "N0": 1, "N": n, "steps": steps, "measuredSteps": [3, steps - 1], "repeats": reps,
            "variants": s,
        }

    # --- suite 3: scaling with particles (riser frame, full physics)
    def suite_particles(self):
        counts = [1, 100, 1000, 10000] if self.quick else [1, 100, 1000, 10000, 100000]
        # the Basset window (0.01 s) holds 100 steps: past it the per-step
        # cost and the memory per particle are those of a long run
        steps = 40 if self.quick else 110
        first = 3 if self.quick else 102
        reps = 1 if self.quick else 2
        keys = ["riserFrameBasset", "stockStatic"]
        self.say("suite particles (static mesh): N = %s, %d steps (measured %d..%d), %d repeats"
                 % (counts, steps, first, steps - 1, reps))
        runs = self.alternate("particles", keys, counts, steps, first, reps)
        s = self.summarise(runs, 1)
        # cost per particle-step between successive N, and memory per particle
        for k in keys:
            t = {int(n): v for n, v in s[k]["cpuPerStep"].items()}
            rss = {int(n): v for n, v in s[k]["peakRssKB"].items()}
            ns = sorted(t)
            s[k]["costPerParticleStepBetween"] = {
                "%d-%d" % (a, b): (t[b] - t[a]) / (b - a) for a, b in zip(ns, ns[1:])}
            s[k]["bytesPerParticle"] = {
                str(n): 1024.0 * (rss[n] - rss[1]) / (n - 1) for n in ns if n >= 1000}
            # Basset window filling: per-step cost early against late (largest N)
            big = max(ns)
            costs = runs[k][big][0]["cpuStepCosts"]
            if len(costs) > 100:
                s[k]["stepCostEarlyLate"] = {
                    "steps 3-30": statistics.median(costs[1:29]),
                    "steps 102-109": statistics.median(costs[100:108]),
                    "N": big,
                }
        self.results["suites"]["particles"] = {
            "frame": "riser (static mesh)", "counts": counts, "steps": steps,
            "measuredSteps": [first, steps - 1], "repeats": reps, "variants": s,
        }

    # --- suite 4: scaling with processors
    def suite_processors(self):
        n = 20000 if self.quick else 100000
        steps = 20 if self.quick else 30
        reps = 1 if self.quick else 2
        key = "riserFrameBasset"
        self.say("suite processors (static mesh, riser frame): N = %d, %d steps, np 1 and 2, "
                 "%d repeats" % (n, steps, reps))
        cases = {}
        for np in (1, 2):
            path = os.path.join(self.build, "processors", "np%d" % np)
            rc.make_case(path, VARIANTS[key], self.mesh, n, steps, DT, LENGTH, write_at_end=True)
            if np > 1:
                with open(os.path.join(path, "system", "decomposeParDict"), "w") as f:
                    f.write(rc.header("dictionary", "decomposeParDict")
                            + "numberOfSubdomains %d;\nmethod simple;\n"
                              "coeffs { n (%d 1 1); }\n" % (np, np))
                rc.run(["decomposePar", "-case", path], os.path.join(path, "log.decomposePar"))
            cases[np] = path
        wall = {1: [], 2: []}
        for rep in range(reps):
            for np in ((1, 2) if rep % 2 == 0 else (2, 1)):
                r = run_solver(cases[np], VARIANTS[key].application, np)
                w = statistics.median(step_costs(r["wallStamps"])[2:steps - 2])
                wall[np].append(w)
                self.say("np %d rep %d: %8.3f ms/step wall (median), run %.1f s"
                         % (np, rep + 1, 1e3 * w, r["totalWall"]))
        t1, t2 = min(wall[1]), min(wall[2])
        diff = compare_clouds(cases[1], cases[2], steps * DT, n)
        self.results["suites"]["processors"] = {
            "frame": "riser (static mesh)", "N": n, "steps": steps,
            "measuredSteps": [4, steps - 1], "repeats": reps,
            "decomposition": "simple (2 1 1): split at x = 0",
            "wallPerStep": {"1": t1, "2": t2}, "wallPerStepAllRepeats": wall,
            "speedup": t1 / t2, "comparison": diff,
        }
        self.say("speedup %.2f; %s" % (t1 / t2, diff))

    def write(self, results_dir):
        os.makedirs(results_dir, exist_ok=True)
        path = os.path.join(results_dir, "results.json")
        with open(path, "w") as f:
            json.dump(self.results, f, indent=1, sort_keys=True)
        self.say("wrote %s" % path)


# -------------------------------------------------------------- comparison

def read_cloud_field(path):
    """A lagrangian vector field or the positions (ascii): list of tuples."""
    text = open(path).read()
    text = text[text.index("}", text.index("FoamFile")) + 1:]
    text = re.sub(r"//[^\n]*", "", text)
    n = int(re.search(r"\d+", text).group(0))
    out = [tuple(float(v) for v in m.group(1).split())
           for m in re.finditer(r"\(([-+0-9.eE ]+)\)", text)]
    if len(out) != n:
        raise RuntimeError("%s: %d values read, %d expected" % (path, len(out), n))
    return out


def time_dir(case, t):
    for d in os.listdir(case):
        try:
            if abs(float(d) - t) < 1e-9:
                return os.path.join(case, d)
        except ValueError:
            pass
    raise RuntimeError("no time %g in %s" % (t, case))


def compare_clouds(serial, parallel, t, n):
    """Final positions and velocities of the serial run against the
    processors' (each particle matched by sorting on its position rounded
    to 1 um: positions agree far closer than that, and particles lie far
    further apart)."""
    def load(case_dirs):
        rows = []
        for d in case_dirs:
            cloud = os.path.join(d, "lagrangian", "kinematicCloud")
            if not os.path.isdir(cloud):
                continue
            x = read_cloud_field(os.path.join(cloud, "positions"))
            u = read_cloud_field(os.path.join(cloud, "U"))
            rows += [a + b for a, b in zip(x, u)]
        return rows
    a = load([time_dir(serial, t)])
    procs = sorted(glob.glob(os.path.join(parallel, "processor*")))
    b = load([time_dir(p, t) for p in procs])
    counts = [len(load([time_dir(p, t)])) for p in procs]
    if len(a) != n or len(b) != n:
        return {"identical": False, "serialParticles": len(a), "parallelParticles": len(b)}
    key = lambda r: tuple(round(v, 6) for v in r[:3])
    a.sort(key=key)
    b.sort(key=key)
    dx = max(math.dist(p[:3], q[:3]) for p, q in zip(a, b))
    du = max(math.dist(p[3:], q[3:]) for p, q in zip(a, b))
    return {"identical": dx < 1e-9 and du < 1e-9, "particles": n,
            "particlesPerProcessor": counts,
            "maxPositionDifference_m": dx, "maxVelocityDifference_m_s": du}


# --------------------------------------------------------------------- main

def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--suites", default="stock,riserFrame,particles,processors")
    ap.add_argument("--build", default=os.path.join(os.environ["RISER_DIR"], "build", "benchmarks"))
    ap.add_argument("--results", default=os.path.join(HERE, "results"))
    args = ap.parse_args()

    start = time.perf_counter()
    os.makedirs(args.build, exist_ok=True)
    b = Bench(args.build, args.quick)
    b.make_mesh()
    for suite in args.suites.split(","):
        {"stock": b.suite_stock, "riserFrame": b.suite_riser_frame,
         "particles": b.suite_particles, "processors": b.suite_processors}[suite]()
        b.results["elapsed_s"] = time.perf_counter() - start
        b.write(args.results)
    b.results["machine"]["loadAverageAtEnd"] = open("/proc/loadavg").read().split()[:3]
    b.results["elapsed_s"] = time.perf_counter() - start
    b.write(args.results)


if __name__ == "__main__":
    main()
