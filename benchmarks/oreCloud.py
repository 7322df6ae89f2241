"""A shaken cloud of 1,000 ores in riserParcelFoam without contact, with
wall contact only and with particle-particle contact (riserContact's
pairs): the scenes of the many-ore work. 10 mm ores (2000 kg/m^3, the
flagship's material) fill a 1 m periodic riser section (D = 0.1 m,
riserMesh -n 12, cyclic ends) at C_v = 0.0667 (riserFill, seed 1, at rest
relative to the carrier); riser frame, exact carrier, the flagship's
forces with Basset; the riser shakes at A = 0.2 m, f = 4 Hz and at
A = 2 m, f = 0.4 Hz (the same largest riser speed, 5 m/s); dt = 1e-4 s,
stepsPerContact 10; 0.5 s (quick: 0.05 s). No per-particle output.

Variants: no contact, wall contact, wall and pair contact; each with
contact the particles alone at the wall tracked through the mesh in their
sub-cycles (aloneAtWall tracked) or sub-stepped without it (meshFree: the
fluid force linearised and frozen over the flow step).

Reported per scene and variant: CPU time of the solver (user + sys) and its
ratio to the same scene without contact (collisionModel none: the ores
then bounce off the mesh's wall, the stock patch interaction), the parcels
at the start and the end, particles reported outside the pipe, the largest
number of particles near a contact in a step, of tracked sub-cycles and of
particles sub-stepped without the mesh and their contact sub-steps, with
pairs the largest pair overlap of the run (fraction of d; the log's
riserContact line), the completed wall contacts, the time average of
the fraction of ores in wall contact (their durations summed over the
ores and the run) and the contacts' mean restitution UnOut/UnIn
(contacts.dat): what aloneAtWall meshFree changes in the physics, against
what it saves.

With --scaling instead: the cost per particle-step and the memory per
particle of the wall-and-pair scene (A = 0.2 m, f = 4 Hz) at C_v = 0.05
for 1e3, 1e4 and 1e5 ores (quick: 1e3, 3e3), the section's length grown
with the number (N V_p / (C_v pi D^2/4); riserMesh -n 4, 2.5 cm cells
along), from the solver's CPU time between steps 10 and 40 (the log's
ExecutionTime) and its peak resident memory (/usr/bin/time), without
contact and with wall and pair contact.

With --processors instead: the wall time of the same scene (C_v = 0.05,
1e3 and 1e4 ores, 0.1 s; quick: 1e3, 0.02 s) serially and on 2 processors
(the section split along z), alternated three times, and their ratio in
each repetition; without contact, with wall and pair contact, and with the
ores alone at the wall sub-stepped without the mesh too.

With --dense instead: the same wall-and-pair scene (riserMesh -n 4, 2.5 cm
cells along) in its dense phase, for 1e3, 1e4 and 1e5 ores (quick: 1e3,
3e3): each is first shaken for 0.08 s on 2 processors (by then most ores
are in clusters or at the wall), then max(30, 3e5/N) steps are run from
that state (the measured ones take about a second or more: the log's
times count in 10 ms) serially and on 2 processors, alternated three
times from fresh copies: the cost per particle-step from step 10 to the
last, the speed-up (the master's time of the same steps), the particles in clusters or at
the wall, the particle copies and bytes the contact model sent between the
processors per step (its log), and the peak resident memory per particle.

usage: oreCloud.py [--quick] [--scaling | --processors | --dense] --build DIR --results DIR
writes <results>/oreCloud.json and <results>/oreCloud.md (--scaling:
oreScaling.json and oreScaling.md; --processors: oreProcessors.json and
oreProcessors.md; --dense: oreDense.json and oreDense.md)
License: GPL-3.0-or-later
"""
import argparse
import datetime
import json
import math
import os
import re
import resource
import shutil
import subprocess
import time

import numpy as np

from riserfoam import cases
from riserfoam import foamfields as ff

# variant: (collision model, pairs)
PAIRS = "{ normalRestitution 0.5; tangentialRestitution 0.5; friction 0.5; }"
# variant: collision model, pairs, aloneAtWall
VARIANTS = {
    "none": ("none", None, None),
    "wall": ("riserContact", None, "tracked"),
    "wall, alone meshFree": ("riserContact", None, "meshFree"),
    "wall+pairs": ("riserContact", PAIRS, "tracked"),
    "wall+pairs, alone meshFree": ("riserContact", PAIRS, "meshFree"),
}
# scene: riser amplitude [m] and frequency [Hz]
SCENES = {"A0.2_f4": (0.2, 4.0), "A2_f0.4": (2.0, 0.4)}


def make(case, end, A, f, collision, pairs, alone="tracked", L=1.0, n=12, nz=None, Cv=0.0667):
    cases.copy_tutorial("riser/oscillatingContact", case)
    cases.riser_mesh(case, D=0.1, L=L, n=n, nz=nz)
    props = os.path.join(case, "constant", "riserProperties")
    ff.set_nested(props, "A", repr(A))
    ff.set_nested(props, "f", repr(f))
    control = os.path.join(case, "system", "controlDict")
    for entry, value in (("deltaT", "1e-4"), ("endTime", repr(end)), ("writeInterval", repr(end))):
        ff.set_nested(control, entry, value)
    ff.remove_entry(control, "functions")
    cloud = os.path.join(case, "constant", "kinematicCloudProperties")
    ff.set_nested(cloud, "cloudFunctions", "{}")
    ff.set_nested(cloud, "subModels/injectionModels",
              "{ ores { type riserFill; SOI 0; massTotal 0; parcelBasisType fixed; nParticle 1;"
              " solidsFraction %g; seed 1; velocity carrier;"
              " sizeDistribution { type fixedValue; fixedValueDistribution { value 0.01; } } } }"
              % Cv)
    ff.set_nested(cloud, "subModels/riserContactCoeffs/stepsPerContact", "10")
    ff.set_nested(cloud, "subModels/collisionModel", collision)
    if pairs:
        ff.set_nested(cloud, "subModels/riserContactCoeffs/pairs", pairs)
    if alone:
        ff.set_nested(cloud, "subModels/riserContactCoeffs/aloneAtWall", alone)


def stamped(**entries):
    """a result: the entries with the date and the load average"""
    return dict(date=datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC"),
                load=open("/proc/loadavg").read().split()[:3], **entries)


def saved(args, stem, result):
    """<results>/<stem>.json written; <results>/<stem>.md opened for the table"""
    with open(os.path.join(args.results, stem + ".json"), "w") as out:
        json.dump(result, out, indent=1)
    return open(os.path.join(args.results, stem + ".md"), "w")


def section_length(N, Cv):
    """the length [m] of the riser section (D = 0.1 m) that holds N ores of
    10 mm at the solids fraction Cv"""
    return N * math.pi / 6 * 0.01 ** 3 / (Cv * math.pi / 4 * 0.1 ** 2)


def steps_time(text):
    """the master's time in a solver log from the end of step 10 to the last
    (start-up and injection left out; MPI waits spin, so in parallel it is
    the wall time of the steps)"""
    spent = [float(c) for c in re.findall(r"ExecutionTime = (\S+) s", text)]
    return spent[-1] - spent[9]


def memory_growth(rows, key=None):
    """each row after the first gets the growth of the peak resident memory
    per particle from the row before (of its entry key, or of itself)"""
    for a, b in zip(rows, rows[1:]):
        ra, rb = (a[key], b[key]) if key else (a, b)
        rb["bytes_per_particle"] = (1024 * 1024 * (rb["peak_rss_MB"] - ra["peak_rss_MB"])
                                    / (b["N"] - a["N"]))


def scaling(args, work):
    """cost per particle-step and memory per particle against N (see above)"""
    Cv = 0.05
    rows = []
    for N in ((1000, 3000) if args.quick else (1000, 10000, 100000)):
        L = section_length(N, Cv)
        row = {"L_m": L}
        for name in ("none", "wall+pairs"):
            case = os.path.join(work, "scaling", "N%d_%s" % (N, name.replace("+", "_")))
            collision, pairs, alone = VARIANTS[name]
            make(case, 40e-4, 0.2, 4.0, collision, pairs, alone,
                 L=L, n=4, nz=max(4, int(round(L / 0.025))), Cv=Cv)
            log = os.path.join(case, "log.riserParcelFoam")
            with open(log, "w") as out:
                subprocess.run(["/usr/bin/time", "-v", "riserParcelFoam", "-case", case],
                               stdout=out, stderr=subprocess.STDOUT, check=True)
            text = open(log).read()
            cpu = [float(c) for c in re.findall(r"ExecutionTime = (\S+) s", text)]
            row["N"] = int(re.search(r"riserFill: placed (\d+) ores", text).group(1))
            rss = int(re.search(r"Maximum resident set size \(kbytes\): (\d+)", text).group(1))
            clustered = [int(c) for c in
                         re.findall(r"(\d+) particle\(s\) in clusters or alone", text)] or [0]
            row[name] = {"us_per_particle_step": 1e6 * (cpu[39] - cpu[9]) / (30 * row["N"]),
                         "peak_rss_MB": rss / 1024, "max_clustered": max(clustered),
                         "outside_pipe_reports": text.count("outside the pipe")}
        row["ratio"] = (row["wall+pairs"]["us_per_particle_step"]
                        / row["none"]["us_per_particle_step"])
        rows.append(row)
        print(row)
    for name in ("none", "wall+pairs"):
        memory_growth(rows, name)
    result = stamped(rows=rows)
    with saved(args, "oreScaling", result) as out:
        out.write("# Ores with wall and pair contact against their number "
                  "(benchmarks/oreCloud.py --scaling%s)\n\n" % (" --quick" if args.quick else ""))
        out.write("Measured %s, load average %s. C_v = 0.05, A = 0.2 m, f = 4 Hz, dt = 1e-4 s, "
                  "the section's length (and mesh) grown with the number of ores; CPU time of "
                  "steps 10..40 per particle-step, without contact and with wall and pair "
                  "contact, and their ratio; peak resident memory of the solver and its growth "
                  "per particle between two sizes (the mesh's growth included).\n\n"
                  % (result["date"], " ".join(result["load"])))
        out.write("| ores | section [m] | us/particle-step, no contact | wall + pairs | ratio | "
                  "most clustered | peak RSS [MB] no contact / wall + pairs | "
                  "bytes per particle (from the previous row) no contact / wall + pairs | "
                  "outside-pipe reports |\n|---|---|---|---|---|---|---|---|---|\n")
        for r in rows:
            a, b = r["none"], r["wall+pairs"]
            out.write("| %d | %.2f | %.2f | %.2f | %.2f | %d | %.0f / %.0f | %s | %d |\n"
                      % (r["N"], r["L_m"], a["us_per_particle_step"], b["us_per_particle_step"],
                         r["ratio"], b["max_clustered"], a["peak_rss_MB"], b["peak_rss_MB"],
                         "%.0f / %.0f" % (a["bytes_per_particle"], b["bytes_per_particle"])
                         if "bytes_per_particle" in a else "",
                         a["outside_pipe_reports"] + b["outside_pipe_reports"]))


def processors(args, work):
    """wall time on 2 processors against serial (see above)"""
    Cv = 0.05
    rows = []
    # (ores, simulated time)
    sizes = ((1000, 0.03),) if args.quick else ((1000, 0.1), (10000, 0.03))
    for N, end in sizes:
        L = section_length(N, Cv)
        for name in ("none", "wall+pairs", "wall+pairs, alone meshFree"):
            collision, pairs, alone = VARIANTS[name]
            base = os.path.join(work, "processors", "N%d_%s" % (N, re.sub(r"[^A-Za-z0-9]+", "_", name)))
            make(base, end, 0.2, 4.0, collision, pairs, alone,
                 L=L, n=6, nz=max(4, int(round(L / 0.02))), Cv=Cv)
            row = {"N": N, "variant": name, "simulated_s": end, "serial_s": [], "np2_s": []}
            for repeat in range(3):
                # the two runs alternated, each from a fresh copy
                for key, np in (("serial_s", 1), ("np2_s", 2)):
                    case = base + "_np%d" % np
                    shutil.rmtree(case, ignore_errors=True)
                    shutil.copytree(base, case)
                    command = ["riserParcelFoam", "-case", case]
                    if np > 1:
                        decompose(case)
                        command = parallel(case)
                    text = cases.run(command, os.path.join(case, "log.riserParcelFoam"))
                    row[key].append(steps_time(text))
                    clustered = [int(c) for c in
                                 re.findall(r"(\d+) particle\(s\) in clusters or alone", text)] or [0]
                    row["max_clustered"] = max(clustered)
                    row["outside_pipe_reports"] = text.count("outside the pipe")
            row["speedup"] = [a / b for a, b in zip(row["serial_s"], row["np2_s"])]
            rows.append(row)
            print(row)
    result = stamped(rows=rows)
    with saved(args, "oreProcessors", result) as out:
        out.write("# Ores on 2 processors against serial (benchmarks/oreCloud.py --processors%s)\n\n"
                  % (" --quick" if args.quick else ""))
        out.write("Measured %s, load average %s. C_v = 0.05, A = 0.2 m, f = 4 Hz, dt = 1e-4 s, "
                  "the section's length grown with the number of ores and split along z "
                  "(simple decomposition); the solver's time from the end of step 10 to the "
                  "last (the master's ExecutionTime: MPI waits spin), serial and on 2 "
                  "processors alternated three times from fresh copies, and their ratio "
                  "(speed-up) in each repetition.\n\n"
                  % (result["date"], " ".join(result["load"])))
        out.write("| ores | simulated s | contact | serial s | 2 processors s | speed-up | "
                  "most clustered | outside-pipe reports |\n|---|---|---|---|---|---|---|---|\n")
        for r in rows:
            out.write("| %d | %g | %s | %s | %s | %s | %d | %d |\n"
                      % (r["N"], r["simulated_s"], r["variant"],
                         " ".join("%.1f" % t for t in r["serial_s"]),
                         " ".join("%.1f" % t for t in r["np2_s"]),
                         " ".join("%.2f" % x for x in r["speedup"]), r["max_clustered"],
                         r["outside_pipe_reports"]))


def decompose(case):
    """case split into 2 processors along z"""
    ff.write_dictionary(os.path.join(case, "system/decomposeParDict"),
                        "numberOfSubdomains 2;\nmethod simple;\n"
                        "simpleCoeffs { n (1 1 2); delta 0.001; }\n")
    cases.run(["decomposePar", "-force", "-case", case], os.path.join(case, "log.decomposePar"))


def parallel(case):
    return ["mpirun", "--allow-run-as-root", "--oversubscribe", "-np", "2",
            "riserParcelFoam", "-parallel", "-case", case]


def exchange_per_step(text):
    """mean over the steps of a parallel log of the particle copies and the
    bytes riserContact sent between the processors (its plan's and its
    sub-steps' lines, summed per step), and of the most exchanges of the
    sub-steps' states by one processor"""
    copies, sent, exchanges = [], [], []
    for step in text.split("\nTime = ")[1:]:
        lines = re.findall(r"sent copies of (\d+) particle\(s\)[^\n]*?, (\S+) bytes", step)
        copies.append(sum(int(c) for c, _ in lines))
        sent.append(sum(float(b) for _, b in lines))
        exchanges.append(sum(int(k) for k in re.findall(r"at most (\d+) exchanges of states", step)))
    return float(np.mean(copies[9:])), float(np.mean(sent[9:])), float(np.mean(exchanges[9:]))


def dense(args, work):
    """the wall-and-pair scene in its dense phase (see above)"""
    Cv, spinUp, dt = 0.05, 0.08, 1e-4
    rows = []
    for N in ((1000, 3000) if args.quick else (1000, 10000, 100000)):
        # (steps enough that the measured ones take about a second: the
        # log's times count in 10 ms)
        steps = max(30, int(3e5 / N))
        L = section_length(N, Cv)
        base = os.path.join(work, "dense", "N%d" % N)
        collision, pairs, alone = VARIANTS["wall+pairs"]
        make(base, spinUp, 0.2, 4.0, collision, pairs, alone,
             L=L, n=4, nz=max(4, int(round(L / 0.025))), Cv=Cv)
        decompose(base)
        t0 = time.perf_counter()
        cases.run(parallel(base), os.path.join(base, "log.spinUp"))
        spun = time.perf_counter() - t0
        cases.run(["reconstructPar", "-latestTime", "-lagrangianFields", "(\".*\")", "-case", base],
                  os.path.join(base, "log.reconstructPar"))
        control = os.path.join(base, "system", "controlDict")
        end = spinUp + steps * dt
        for entry, value in (("startFrom", "latestTime"), ("endTime", repr(end)),
                             ("writeInterval", repr(1.0))):
            ff.set_nested(control, entry, value)
        row = {"N": N, "L_m": L, "spin_up_s": spinUp, "steps": steps, "spin_up_wall_s": spun,
               "serial_s": [], "np2_s": []}
        for repeat in range(3):
            for key, np_ in (("serial_s", 1), ("np2_s", 2)):
                case = base + "_np%d" % np_
                shutil.rmtree(case, ignore_errors=True)
                shutil.copytree(base, case)
                log = os.path.join(case, "log.riserParcelFoam")
                if np_ == 1:
                    with open(log, "w") as out:
                        t0 = time.perf_counter()
                        subprocess.run(["/usr/bin/time", "-v", "riserParcelFoam", "-case", case],
                                       stdout=out, stderr=subprocess.STDOUT, check=True)
                    text = open(log).read()
                    row["peak_rss_MB"] = int(re.search(
                        r"Maximum resident set size \(kbytes\): (\d+)", text).group(1)) / 1024
                else:
                    text = cases.run(parallel(case), log)
                    (row["copies_per_step"], row["bytes_per_step"],
                     row["exchanges_per_step"]) = exchange_per_step(text)
                row[key].append(steps_time(text))
                clustered = [int(c) for c in
                             re.findall(r"(\d+) particle\(s\) in clusters or alone", text)] or [0]
                row["clustered_fraction"] = min(clustered) / N
                substeps = [int(k) for k in re.findall(r"alone at the wall: (?:at most )?(\d+) contact sub-steps", text)]
                row["substeps_per_step"] = float(np.mean(substeps)) if substeps else 0.0
                row["parcels"] = int(re.findall(r"Current number of parcels\s*=\s*(\d+)", text)[-1])
                row["outside_pipe_reports"] = text.count("outside the pipe")
        row["us_per_particle_step"] = 1e6 * min(row["serial_s"]) / ((steps - 10) * N)
        row["speedup"] = [a / b for a, b in zip(row["serial_s"], row["np2_s"])]
        rows.append(row)
        print(row)
    for r in rows:
        r["cost_ratio_to_first"] = r["us_per_particle_step"] / rows[0]["us_per_particle_step"]
    memory_growth(rows)
    result = stamped(rows=rows)
    with saved(args, "oreDense", result) as out:
        out.write("# Ores with wall and pair contact in the dense phase "
                  "(benchmarks/oreCloud.py --dense%s)\n\n" % (" --quick" if args.quick else ""))
        out.write("Measured %s, load average %s. C_v = 0.05, A = 0.2 m, f = 4 Hz, dt = 1e-4 s, "
                  "riserMesh -n 4 with 2.5 cm cells along the section, whose length grows with "
                  "the number of ores; shaken %g s on 2 processors, then 30 steps (300 for 1e3 ores, "
                  "3e5/N for fewer than 1e4) from that state "
                  "serially and on 2 processors (split along z), alternated three times from "
                  "fresh copies. Time: the master's time from step 10 to the last (its ExecutionTime: CPU "
                  "time, MPI waits spin); cost: the serial time per particle-step (least of "
                  "the three) and its ratio to the first row; speed-up: serial over 2 processors, "
                  "repeat by repeat; clustered: the least fraction of the ores in clusters "
                  "or alone at the wall in a step; sent: riserContact's particle copies and bytes "
                  "sent between the processors per step (mean of the steps); memory: the serial "
                  "run's peak resident set and its growth per particle from the previous row (the "
                  "mesh's growth included).\n\n"
                  % (result["date"], " ".join(result["load"]), spinUp))
        out.write("| ores | section [m] | clustered | us/particle-step | ratio | serial s | "
                  "2 processors s | speed-up | copies sent per step | bytes per step | "
                  "bytes per copy | peak RSS [MB] | bytes per particle | parcels at the end | "
                  "outside-pipe reports |\n|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n")
        for r in rows:
            out.write("| %d | %.2f | %.2f | %.2f | %.2f | %s | %s | %s | %.0f | %.0f | %.0f | %.0f | %s | %d | %d |\n"
                      % (r["N"], r["L_m"], r["clustered_fraction"], r["us_per_particle_step"],
                         r["cost_ratio_to_first"],
                         " ".join("%.1f" % t for t in r["serial_s"]),
                         " ".join("%.1f" % t for t in r["np2_s"]),
                         " ".join("%.2f" % x for x in r["speedup"]),
                         r["copies_per_step"], r["bytes_per_step"],
                         r["bytes_per_step"] / max(r["copies_per_step"], 1),
                         r["peak_rss_MB"],
                         "%.0f" % r["bytes_per_particle"] if "bytes_per_particle" in r else "",
                         r["parcels"], r["outside_pipe_reports"]))


def simulated(log):
    """the simulated time of a log: its last time less the first step's start"""
    times = [float(t) for t in re.findall(r"^Time = (\S+)", log, flags=re.M)]
    dt = times[1] - times[0] if len(times) > 1 else 0.0
    return times[-1] - times[0] + dt


def run(case):
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.perf_counter()
    log = os.path.join(case, "log.riserParcelFoam")
    cases.run(["riserParcelFoam", "-case", case], log)
    wall = time.perf_counter() - t0
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    text = open(log).read()
    counts = [int(c) for c in re.findall(r"Current number of parcels\s*=\s*(\d+)", text)]
    near = [int(c) for c in re.findall(r"(\d+) particle\(s\) near", text)] or [0]
    sub = [int(c) for c in re.findall(r"(\d+) move-collide subCycles", text)] or [1]
    clustered = re.findall(r"(\d+) particle\(s\) in clusters or alone at the wall: (?:at most )?(\d+)"
                           r" contact sub-steps", text)
    contacts = os.path.join(case, "postProcessing/lagrangian/kinematicCloud/riserContact",
                            "contacts.dat")
    restitution = None
    if os.path.exists(contacts):
        rows = cases.wall_contacts(case)
        if len(rows):
            # weighted by the approach speed (a mean of the ratios is ruled
            # by the contacts of ores pushed at the wall at ~1e-3 m/s)
            restitution = float(np.sum(rows["UnOut"]) / np.sum(rows["UnIn"]))
    overlap = re.findall(r"largest pair overlap in this run (\S+)", text)
    placed = re.search(r"riserFill: placed (\d+) ores, solids fraction C_v = (\S+)", text)
    return {
        "cpu_s": (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime),
        "wall_s": wall,
        "placed": int(placed.group(1)) if placed else None,
        "Cv": float(placed.group(2)) if placed else None,
        "parcels_end": counts[-1] if counts else None,
        "outside_pipe_reports": text.count("outside the pipe"),
        "max_near": max(near),
        "max_subcycles": max(sub),
        "max_clustered": max([int(c) for c, _ in clustered] or [0]),
        "max_contact_substeps": max([int(k) for _, k in clustered] or [0]),
        "largest_pair_overlap_of_d": float(overlap[-1]) if overlap else None,
        "wall_contacts": len(cases.wall_contacts(case)) if restitution is not None else 0,
        # the time average of the ores in wall contact, as a fraction
        "in_wall_contact": (float(np.sum(cases.wall_contacts(case)["duration"]))
                            / (counts[-1] * simulated(text))
                            if restitution is not None and counts else 0.0),
        "mean_wall_restitution": restitution,
    }


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--scaling", action="store_true")
    ap.add_argument("--processors", action="store_true")
    ap.add_argument("--dense", action="store_true")
    ap.add_argument("--build", required=True)
    ap.add_argument("--results", required=True)
    args = ap.parse_args()
    end = 0.05 if args.quick else 0.5
    work = os.path.join(os.path.abspath(args.build), "oreCloud")
    os.makedirs(args.results, exist_ok=True)
    if args.scaling:
        scaling(args, work)
        return
    if args.processors:
        processors(args, work)
        return
    if args.dense:
        dense(args, work)
        return
    rows = {}
    for scene, (A, f) in SCENES.items():
        rows[scene] = {}
        for name, (collision, pairs, alone) in VARIANTS.items():
            case = os.path.join(work, scene, re.sub(r"[^A-Za-z0-9]+", "_", name))
            make(case, end, A, f, collision, pairs, alone)
            r = run(case)
            r["ratio_to_none"] = r["cpu_s"]/rows[scene]["none"]["cpu_s"] if name != "none" else 1.0
            rows[scene][name] = r
            print("%-8s %-10s %s" % (scene, name, r))
    result = stamped(quick=args.quick, simulated_s=end, scenes=rows)
    with saved(args, "oreCloud", result) as out:
        out.write("# 1,000 shaken ores in riserParcelFoam (benchmarks/oreCloud.py%s)\n\n"
                  % (" --quick" if args.quick else ""))
        out.write("Measured %s, %g s simulated, load average %s; CPU seconds of the solver, "
                  "and their ratio to the same scene without contact, run in the same "
                  "command.\n\n" % (result["date"], end, " ".join(result["load"])))
        out.write("| scene | contact | ores placed (C_v) | CPU s | ratio to no contact | "
                  "ores at the end | outside-pipe reports | most near a contact | "
                  "most tracked sub-cycles | most sub-stepped without the mesh (contact sub-steps) | "
                  "largest pair overlap / d | wall contacts | ores in wall contact (time "
                  "average) | mean wall restitution (sum UnOut / sum UnIn) |\n"
                  "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n")
        for scene, variants in rows.items():
            for name, r in variants.items():
                out.write("| %s | %s | %s (%s) | %.1f | %.2f | %s | %d | %d | %d | %d (%d) | %s "
                          "| %d | %.2f %% | %s |\n"
                          % (scene.replace("_", ", ").replace("A", "A = ").replace("f", "f = "),
                             name, r["placed"], r["Cv"], r["cpu_s"], r["ratio_to_none"],
                             r["parcels_end"], r["outside_pipe_reports"], r["max_near"],
                             r["max_subcycles"], r["max_clustered"], r["max_contact_substeps"],
                             "-" if r["largest_pair_overlap_of_d"] is None
                             else "%.4f" % r["largest_pair_overlap_of_d"],
                             r["wall_contacts"], 100 * r["in_wall_contact"],
                             "-" if r["mean_wall_restitution"] is None
                             else "%.4f" % r["mean_wall_restitution"]))


if __name__ == "__main__":
    main()
