"""riserFoam benchmarks: riserParcelFoam against stock OpenFOAM v1912,
scaling with particles and with processors.

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
(the median over the repeats of each variant) at N particles and at N0 = 1
particle, so that the per-step work that does not depend on the particles
(mesh motion, carrier imposition, mesh-wide fields, output) is reported
separately, as t(N0). The ratio of two variants' costs per particle-step is
taken repeat by repeat (repeat i of both ran minutes apart at most) and the
median of those ratios reported, with their range: on this shared virtual
machine the CPU time of the same run varies by up to +-25% from one run to
the next.

usage: bench.py [--quick] [--suites stock,riserFrame,particles,processors,contact]
                [--build DIR] [--results DIR] [--label TEXT]
       (the optional suite pairCollision times stock pairCollision on the
       moving mesh: minutes per step)

License: GPL-3.0-or-later
"""
import argparse
import datetime
import fcntl
import glob
import hashlib
import json
import math
import os
import platform
import shutil
import statistics
import subprocess
import time

import riserCases as rc
from riserfoam import foamfields
from riserfoam.cases import run

HERE = os.path.dirname(os.path.abspath(__file__))

DT = 1e-4                   # flow step [s], as the reference points
LENGTH = 0.5                # riser length: 5 D, cyclic ends
MESH_N, MESH_NZ = 12, 44    # riserMesh -n 12 -nz 44: 21,120 cells


# ------------------------------------------------------------------ running

F_SETPIPE_SZ = 1031     # fcntl.h (Linux)


class ProcessClock:
    """CPU time [s] used by a process's threads and its peak resident
    memory, read through /proc files kept open (a few microseconds a
    reading, so that the reader keeps up with 0.1 ms steps)."""

    def __init__(self, pid):
        self.pid = pid
        self.fds = {}
        self.stat = self._open("/proc/%d/stat" % pid)
        self.status = self._open("/proc/%d/status" % pid)
        self.refresh()

    @staticmethod
    def _open(path):
        try:
            return os.open(path, os.O_RDONLY)
        except OSError:
            return None

    def refresh(self):
        """Pick up threads started since the last call."""
        for path in glob.glob("/proc/%d/task/*/schedstat" % self.pid):
            if path not in self.fds:
                fd = self._open(path)
                if fd is not None:
                    self.fds[path] = fd

    def alive(self):
        """Running (not exited and waiting to be reaped)."""
        try:
            data = os.pread(self.stat, 512, 0)
            return data.rsplit(b") ", 1)[1][:1] not in (b"Z", b"X")
        except (OSError, IndexError, TypeError):
            return False

    def cpu(self):
        """CPU time so far, None once the process has exited."""
        if not self.alive():
            return None
        total = 0
        for fd in self.fds.values():
            try:
                total += int(os.pread(fd, 128, 0).split()[0])
            except (OSError, ValueError, IndexError):
                pass
        return total * 1e-9

    def peak_rss_kb(self):
        try:
            for line in os.pread(self.status, 4096, 0).split(b"\n"):
                if line.startswith(b"VmHWM:"):
                    return int(line.split()[1])
        except (OSError, ValueError, IndexError, TypeError):
            pass
        return None

    def close(self):
        for fd in list(self.fds.values()) + [self.stat, self.status]:
            if fd is not None:
                try:
                    os.close(fd)
                except OSError:
                    pass


def descendants(pid, name):
    """Processes below pid whose command is name (the MPI ranks)."""
    found, todo = [], [pid]
    while todo:
        p = todo.pop()
        for task in glob.glob("/proc/%d/task/*/children" % p):
            try:
                kids = [int(k) for k in open(task).read().split()]
            except (OSError, ValueError):
                continue
            for k in kids:
                try:
                    comm = open("/proc/%d/comm" % k).read().strip()
                except OSError:
                    continue
                if comm == name[:15]:
                    found.append(k)
                todo.append(k)
    return sorted(set(found))


def run_solver(case, application, np=1, env=None):
    """Run application on case (np > 1: the case decomposed, mpirun).
    Returns the per-step wall and CPU times and the run's facts. A CPU
    stamp is None when the solver had already exited as its line was read
    (the reader fell behind)."""
    log = os.path.join(case, "log.%s%s" % (application, "" if np == 1 else ".np%d" % np))
    if np == 1:
        cmd = [application, "-case", case]
    else:
        cmd = ["mpirun", "--allow-run-as-root", "--oversubscribe", "-np", str(np),
               application, "-parallel", "-case", case]
    wall, cpu, rss = [], [], None
    clocks, rank_cpu = [], []
    parcels = None
    subcycles = 0
    subcycle_counts = []
    lost = 0
    start = time.perf_counter()
    busy0 = busy_seconds()
    with open(log, "wb") as out:
        proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                                bufsize=1 << 16, env=env)
        # the smallest pipe (one page): a solver faster than this reader
        # blocks (asleep, using no CPU time) after a few steps' output, so
        # that the CPU time read at an ExecutionTime line is that step's
        try:
            fcntl.fcntl(proc.stdout.fileno(), F_SETPIPE_SZ, 4096)
        except OSError:
            pass
        if np == 1:
            clocks = [ProcessClock(proc.pid)]
        for line in proc.stdout:
            if np > 1 and len(clocks) < np:
                ranks = descendants(proc.pid, application)
                if len(ranks) == np:
                    clocks = [ProcessClock(r) for r in ranks]
            if line.startswith(b"ExecutionTime"):
                wall.append(time.perf_counter())
                if np == 1:
                    if len(wall) % 50 == 1:
                        clocks[0].refresh()
                    cpu.append(clocks[0].cpu())
                    rss = clocks[0].peak_rss_kb() or rss
                else:
                    # CPU time of every rank (mpirun's children)
                    rank_cpu.append([c.cpu() for c in clocks] if len(clocks) == np else None)
            elif b"Current number of parcels" in line:
                parcels = int(line.split()[-1])
            elif b"move-collide subCycles" in line:
                subcycles += 1
                subcycle_counts.append(int(line.split()[0]))
            elif b"outside the pipe" in line:
                lost += 1
            out.write(line)
        proc.wait()
    for c in clocks:
        c.close()
    total = time.perf_counter() - start
    # the other work on the machine during the run [cores]: busy time not
    # spent by this solver (its last CPU reading, all ranks)
    own = 0.0
    valid = [c for c in cpu if c is not None]
    if valid:
        own = valid[-1]
    elif rank_cpu and rank_cpu[-1] and None not in rank_cpu[-1]:
        own = sum(rank_cpu[-1])
    background = max(0.0, (busy_seconds() - busy0 - own) / total) if total > 0 else 0.0
    if proc.returncode != 0:
        raise RuntimeError("%s failed in %s (see %s)" % (application, case, log))
    return {
        "wallStamps": wall,
        "cpuStamps": cpu,
        "rankCpuStamps": rank_cpu,
        "peakRssKB": rss,
        "parcels": parcels,
        "subCycledSteps": subcycles,
        "subCycles": subcycle_counts,
        "lostMessages": lost,
        "totalWall": total,
        "backgroundCores": background,
        "lateStamps": sum(1 for c in cpu if c is None),
    }


def per_step(stamps, first, last):
    """Mean time per step over steps first..last (1-based step numbers:
    stamp i is the end of step i + 1). Stamps taken after the solver had
    exited (None) shorten the window from its end."""
    if len(stamps) < last:
        raise RuntimeError("only %d steps logged, %d expected" % (len(stamps), last))
    while last > first and stamps[last - 1] is None:
        last -= 1
    if stamps[first - 2] is None or last - first < 2:
        raise RuntimeError("the log reader fell behind the solver: too few timed steps")
    return (stamps[last - 1] - stamps[first - 2]) / (last - first + 1)


def step_costs(stamps):
    """Cost of each step from step 2 on (None where a stamp is missing)."""
    return [b - a if a is not None and b is not None else None
            for a, b in zip(stamps, stamps[1:])]


# ------------------------------------------------------------------ context

def cpu_ticks():
    return [int(v) for v in open("/proc/stat").readline().split()[1:]]


STAT0 = cpu_ticks()


def busy_seconds():
    """CPU time the whole machine has spent busy (user, nice, system, irq,
    softirq), in seconds."""
    t = cpu_ticks()
    return (t[0] + t[1] + t[2] + t[5] + t[6]) / float(os.sysconf("SC_CLK_TCK"))


def wait_for_quiet(limit=30.0, threshold=0.3, window=2.0, say=print):
    """Wait until the machine's other work uses less than threshold cores
    (measured over window seconds), at most limit seconds. Returns the last
    background load measured [cores]."""
    start = time.perf_counter()
    while True:
        b0 = busy_seconds()
        time.sleep(window)
        load = (busy_seconds() - b0) / window
        if load < threshold or time.perf_counter() - start > limit:
            if load >= threshold:
                say("machine still busy (%.2f cores of other work) after %.0f s: measuring anyway"
                    % (load, limit))
            return load
        

def steal_fraction(since=None):
    """Share of the machine's CPU time stolen by the host (virtual machine)
    since the benchmark started."""
    a, b = since or STAT0, cpu_ticks()
    d = [y - x for x, y in zip(a, b)]
    total = sum(d[:8])
    return d[7] / total if total else 0.0


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
    "stockDyMPair": rc.Variant("stockDyMPair", "stock", "lab", "drag",
                               "stock DyM: sphereDrag + gravity, pairCollision", collision="pair"),
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
    def summarise(runs, n0, ref=None):
        """Per variant and N: the median over the repeats of the time per
        step (minimum and all repeats kept too); cost per particle-step
        against N0; peak memory. With ref, the ratio of each variant's cost
        per particle-step to ref's, paired repeat by repeat (repeat i of
        both ran back to back) and the median of those ratios taken."""
        med = statistics.median
        out = {}
        for k, byN in runs.items():
            t = {n: med(r["cpuPerStep"] for r in rs) for n, rs in byN.items()}
            tmin = {n: min(r["cpuPerStep"] for r in rs) for n, rs in byN.items()}
            tw = {n: med(r["wallPerStep"] for r in rs) for n, rs in byN.items()}
            rss = {n: min(r["peakRssKB"] for r in rs if r["peakRssKB"]) for n, rs in byN.items()}
            per = {n: (t[n] - t[n0]) / (n - n0) for n in t if n != n0}
            out[k] = {
                "label": VARIANTS[k].label,
                "application": VARIANTS[k].application,
                "cpuPerStep": {str(n): v for n, v in t.items()},
                "cpuPerStepMin": {str(n): v for n, v in tmin.items()},
                "cpuPerStepAllRepeats": {str(n): [r["cpuPerStep"] for r in rs]
                                         for n, rs in byN.items()},
                "wallPerStep": {str(n): v for n, v in tw.items()},
                "costPerParticleStep": {str(n): v for n, v in per.items()},
                "peakRssKB": {str(n): v for n, v in rss.items()},
                "subCycledSteps": {str(n): max(r["subCycledSteps"] for r in rs)
                                   for n, rs in byN.items()},
                "backgroundCores": {str(n): [round(r["backgroundCores"], 3) for r in rs]
                                    for n, rs in byN.items()},
            }
        if ref:
            def costs(k, n):
                return [(a["cpuPerStep"] - b["cpuPerStep"]) / (n - n0)
                        for a, b in zip(runs[k][n], runs[k][n0])]
            for k in runs:
                out[k]["ratioToReference"] = {}
                out[k]["ratioToReferenceAllRepeats"] = {}
                for n in runs[k]:
                    if n == n0:
                        continue
                    ratios = [c / r for c, r in zip(costs(k, n), costs(ref, n))]
                    out[k]["ratioToReference"][str(n)] = med(ratios)
                    out[k]["ratioToReferenceAllRepeats"][str(n)] = ratios
        return out

    def against_stock(self, suite, keys, steps, reps, mesh, frame):
        """N = 1 and N particles of the variants keys (the first: the
        stock reference), alternated, steps steps, reps repeats."""
        n = 2000 if self.quick else 10000
        self.say("suite %s (%s): N = 1 and %d, %d steps, %d repeats" % (suite, mesh, n, steps, reps))
        runs = self.alternate(suite, keys, [1, n], steps, 3, reps)
        s = self.summarise(runs, 1, ref=keys[0])
        self.results["suites"][suite] = {
            "frame": frame,
            "N0": 1, "N": n, "steps": steps, "measuredSteps": [3, steps - 1], "repeats": reps,
            "variants": s,
        }

    # --- suite 1: against stock on the moving mesh
    def suite_stock(self):
        self.against_stock("stock", ["stockDyM", "riserLab", "riserLabBasset", "stockDyMCarrier"],
                           steps=12 if self.quick else 25, reps=2 if self.quick else 3,
                           mesh="moving mesh, lab frame",
                           frame="lab (moving mesh, riserOscillation for both solvers)")

    # --- suite 2: the riser frame against stock on the static mesh
    def suite_riser_frame(self):
        self.against_stock("riserFrame",
                           ["stockStatic", "riserFrame", "riserFrameBasset", "stockStaticCarrier"],
                           steps=30 if self.quick else 60, reps=2 if self.quick else 5,
                           mesh="static mesh",
                           frame="riser (static mesh) for riserParcelFoam; static mesh for stock")

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
        s = self.summarise(runs, 1, ref="stockStatic")
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
                    "steps 3-30": statistics.median(c for c in costs[1:29] if c is not None),
                    "steps 102-109": statistics.median(c for c in costs[100:108] if c is not None),
                    "N": big,
                }
        self.results["suites"]["particles"] = {
            "frame": "riser (static mesh)", "counts": counts, "steps": steps,
            "measuredSteps": [first, steps - 1], "repeats": reps, "variants": s,
        }

    # --- suite 5: what a wall contact costs the whole cloud
    def suite_contact(self):
        n = 1000
        steps = 15 if self.quick else 20
        reps = 1 if self.quick else 2
        key = "riserFrameBasset"
        # one more particle 0.05 mm from the wall: closer than it can travel
        # in a step (|U_p| dt = 0.068 mm; the riser frame's wall stands
        # still), so riserContact sub-cycles every step for it
        gap = 5e-5
        near = [(rc.R - 0.5 * rc.PARTICLE_D - gap, 0.0, 0.25)]
        self.say("suite contact (static mesh, riser frame): N = %d, with and without one "
                 "particle at the wall, %d steps, %d repeats" % (n, steps, reps))
        cases = {
            "offWall": self.case("contact", key, n, steps),
        }
        path = os.path.join(self.build, "contact", "%s_N%d_nearWall" % (key, n))
        rc.make_case(path, VARIANTS[key], self.mesh, n, steps, DT, LENGTH, extra=near)
        cases["nearWall"] = path
        runs = {k: [] for k in cases}
        for rep in range(reps):
            for k in (("offWall", "nearWall") if rep % 2 == 0 else ("nearWall", "offWall")):
                r = run_solver(cases[k], VARIANTS[key].application)
                r["cpuPerStep"] = per_step(r["cpuStamps"], 3, steps - 1)
                runs[k].append(r)
                self.say("%-8s rep %d: %8.3f ms/step CPU, %d sub-cycled steps, sub-cycles %s"
                         % (k, rep + 1, 1e3 * r["cpuPerStep"], r["subCycledSteps"],
                            sorted(set(r["subCycles"]))[:3]))
        t_off = min(r["cpuPerStep"] for r in runs["offWall"])
        t_near = min(r["cpuPerStep"] for r in runs["nearWall"])
        sub = runs["nearWall"][0]["subCycles"]
        self.results["suites"]["contact"] = {
            "frame": "riser (static mesh)", "N": n, "steps": steps, "repeats": reps,
            "variant": VARIANTS[key].label, "nearWallGap_m": gap,
            "cpuPerStep": {"offWall": t_off, "nearWall": t_near},
            "ratio": t_near / t_off,
            "subCycledSteps": runs["nearWall"][0]["subCycledSteps"],
            "subCyclesPerStep": statistics.median(sub) if sub else 0,
        }
        self.say("one particle at the wall: %.1fx the step cost (%s sub-cycles per step)"
                 % (t_near / t_off, statistics.median(sub) if sub else 0))

    # --- optional: stock pairCollision on the moving mesh (slow)
    def suite_pair_collision(self):
        steps = 3
        self.say("suite pairCollision (moving mesh): stock DyM with pairCollision, 1 particle, "
                 "%d steps" % steps)
        out = {}
        for key in ("stockDyMPair", "riserLab"):
            path = self.case("pairCollision", key, 1, steps)
            r = run_solver(path, VARIANTS[key].application)
            costs = [c for c in step_costs(r["cpuStamps"]) if c is not None]
            out[key] = {"label": VARIANTS[key].label, "cpuStepCosts": costs,
                        "cpuPerStep": min(costs), "firstStep": r["cpuStamps"][0],
                        "totalWall": r["totalWall"]}
            self.say("%-14s steps 2..%d: %s s CPU each; run %.0f s" % (
                key, steps, ", ".join("%.3f" % c for c in costs), r["totalWall"]))
        self.results["suites"]["pairCollision"] = {
            "frame": "lab (moving mesh)", "N": 1, "steps": steps, "variants": out}

    # --- suite 4: scaling with processors
    def suite_processors(self):
        n = 20000 if self.quick else 100000
        steps = 20 if self.quick else 30
        reps = 1 if self.quick else 3
        key = "riserFrameBasset"
        self.say("suite processors (static mesh, riser frame): N = %d, %d steps, np 1 and 2, "
                 "%d repeats" % (n, steps, reps))
        cases = {}
        for np in (1, 2):
            path = os.path.join(self.build, "processors", "np%d" % np)
            rc.make_case(path, VARIANTS[key], self.mesh, n, steps, DT, LENGTH, write_at_end=True)
            if np > 1:
                rc.write_dictionary(os.path.join(path, "system", "decomposeParDict"),
                                    "numberOfSubdomains %d;\nmethod simple;\n"
                                    "coeffs { n (%d 1 1); }\n" % (np, np))
                run(["decomposePar", "-case", path], os.path.join(path, "log.decomposePar"))
            cases[np] = path
        wall = {1: [], 2: []}
        cpu = {1: [], 2: []}
        background = {1: [], 2: []}
        for rep in range(reps):
            for np in ((1, 2) if rep % 2 == 0 else (2, 1)):
                # two ranks on two cores: a busy core slows the pair
                wait_for_quiet(say=self.say)
                r = run_solver(cases[np], VARIANTS[key].application, np)
                background[np].append(r["backgroundCores"])
                # steps 4 .. steps-1: the median step (wall), the mean step (CPU)
                w = statistics.median(step_costs(r["wallStamps"])[2:steps - 2])
                if np == 1:
                    c = per_step(r["cpuStamps"], 4, steps - 1)
                else:
                    # the busiest rank's CPU time (ranks poll while they wait)
                    rc_ = r["rankCpuStamps"]
                    c = max(per_step([x[i] if x else None for x in rc_], 4, steps - 1)
                            for i in range(np))
                wall[np].append(w)
                cpu[np].append(c)
                self.say("np %d rep %d: %8.3f ms/step wall (median), %8.3f ms/step CPU "
                         "(busiest rank), run %.1f s, other work %.2f cores"
                         % (np, rep + 1, 1e3 * w, 1e3 * c, r["totalWall"], r["backgroundCores"]))
        # speedup repeat by repeat (np 1 and np 2 of a repeat ran back to
        # back), the median taken: the host's speed drifts between repeats
        ratios = [a / b for a, b in zip(wall[1], wall[2])]
        ratios_cpu = [a / b for a, b in zip(cpu[1], cpu[2])]
        t1, t2 = statistics.median(wall[1]), statistics.median(wall[2])
        c1, c2 = statistics.median(cpu[1]), statistics.median(cpu[2])
        diff = compare_clouds(cases[1], cases[2], steps * DT, n)
        self.results["suites"]["processors"] = {
            "frame": "riser (static mesh)", "N": n, "steps": steps,
            "measuredSteps": [4, steps - 1], "repeats": reps,
            "decomposition": "simple (2 1 1): split at x = 0",
            "wallPerStep": {"1": t1, "2": t2}, "wallPerStepAllRepeats": wall,
            "cpuPerStep": {"1": c1, "2": c2}, "cpuPerStepAllRepeats": cpu,
            "speedup": statistics.median(ratios), "speedupAllRepeats": ratios,
            "speedupCpu": statistics.median(ratios_cpu), "speedupCpuAllRepeats": ratios_cpu,
            "comparison": diff,
            "stealFraction": steal_fraction(),
            "backgroundCores": background,
        }
        self.say("speedup %.2f (wall; repeats %s), %.2f (CPU); %s" % (
            statistics.median(ratios), " ".join("%.2f" % x for x in ratios),
            statistics.median(ratios_cpu), diff))

    def write(self, results_dir):
        os.makedirs(results_dir, exist_ok=True)
        path = os.path.join(results_dir, "results.json")
        with open(path, "w") as f:
            json.dump(self.results, f, indent=1, sort_keys=True)
        self.say("wrote %s" % path)


# -------------------------------------------------------------- comparison

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
            x = foamfields.read_vectors(os.path.join(cloud, "positions"))
            u = foamfields.read_vectors(os.path.join(cloud, "U"))
            rows += [a + b for a, b in zip(x, u)]
        return rows
    a = load([time_dir(serial, t)])
    procs = sorted(glob.glob(os.path.join(parallel, "processor*"))) or [parallel]
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
    ap.add_argument("--suites", default="stock,riserFrame,particles,processors,contact")
    ap.add_argument("--build", default=os.path.join(os.environ["RISER_DIR"], "build", "benchmarks"))
    ap.add_argument("--results", default=os.path.join(HERE, "results"))
    ap.add_argument("--merge", action="store_true",
                    help="keep the other suites of an existing results.json (re-run some suites)")
    ap.add_argument("--label", default="",
                    help="what is measured, when not the tree's own build (goes into the summary)")
    args = ap.parse_args()

    start = time.perf_counter()
    os.makedirs(args.build, exist_ok=True)
    b = Bench(args.build, args.quick)
    b.results["label"] = args.label
    old = os.path.join(args.results, "results.json")
    if args.merge and os.path.isfile(old):
        kept = json.load(open(old))
        b.results["suites"] = kept.get("suites", {})
        b.results["mergedInto"] = {"machine": kept.get("machine"), "elapsed_s": kept.get("elapsed_s")}
    b.make_mesh()
    for suite in args.suites.split(","):
        suite_start = datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC")
        {"stock": b.suite_stock, "riserFrame": b.suite_riser_frame,
         "particles": b.suite_particles, "processors": b.suite_processors,
         "contact": b.suite_contact, "pairCollision": b.suite_pair_collision}[suite]()
        b.results["suites"][suite]["date"] = suite_start
        b.results["suites"][suite]["loadAverage"] = open("/proc/loadavg").read().split()[:3]
        b.results["elapsed_s"] = time.perf_counter() - start
        b.write(args.results)
    b.results["machine"]["loadAverageAtEnd"] = open("/proc/loadavg").read().split()[:3]
    b.results["machine"]["stealFraction"] = steal_fraction()
    b.results["elapsed_s"] = time.perf_counter() - start
    b.write(args.results)


if __name__ == "__main__":
    main()
