"""The grain engine (src/riserCore/granular) against LIGGGHTS 3.8 on the same
pure-DEM scene: ores of 9-11 mm poured into a closed vertical riser section
(D = 0.1 m, floor at z = 0, no fluid) with the same Hertz–Mindlin law and
parameters as the test granularBedAgainstLiggghts (E = 1e7 Pa, nu = 0.3,
e_n = 0.5, mu = 0.5, rotation, dt = 2e-5 s), N = 1,000 and 5,000 ores, the
first 0.2 s of the pour: the column falls, its lowest layers reach the
floor and pile up while the grains above are still falling (so contacts are
fewer than in a settled bed). The grains start on a jittered lattice, 1.25 d
apart, at rest.

Both programs run alternately (LIGGGHTS 1 rank, LIGGGHTS 2 ranks, ours,
repeated) in this one command, so that the shared machine's load falls on
all alike; CPU time (user + sys of the child processes, all ranks) per
simulated second, and the ratio ours / LIGGGHTS per repeat (median
reported). The engine runs in one process: it has no domain decomposition.

With --dense instead: the bed settled, every grain in contact. LIGGGHTS
pours each column for 0.5 s (its lowest grains at rest on the floor, the
rest piled on them); both programs then start from its final positions, at
rest, and run 0.1 s, alternated three times: CPU seconds per grain-step of
each and their ratio per repeat (the target: ours at most 1.5 times
LIGGGHTS on one rank), with the mean number of contacts a grain has at the
end (LIGGGHTS' contact/atom).

usage: granular.py [--quick] [--dense] --build DIR --results DIR
writes <results>/granular.json and <results>/granular.md (--dense:
granularDense.json and granularDense.md)
License: GPL-3.0-or-later
"""
import argparse
import datetime
import json
import math
import os
import random
import resource
import statistics
import subprocess
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
TEST = os.path.join(ROOT, "tests", "cases", "granularBedAgainstLiggghts")
E, NU, EN, MU, DT, R = 1e7, 0.3, 0.5, 0.5, 2e-5, 0.05


def lattice(n, seed, path):
    """n ores on a jittered lattice inside the riser section, at rest"""
    rnd = random.Random(seed)
    a = 1.25*0.011
    ring = [(x*a, y*a) for x in range(-5, 6) for y in range(-5, 6)
            if math.hypot(x*a, y*a) < R - 0.6*a]
    grains, layer = [], 0
    while len(grains) < n:
        for (x, y) in ring:
            if len(grains) == n:
                break
            j = 0.1*a
            grains.append((x + rnd.uniform(-j, j), y + rnd.uniform(-j, j),
                           0.01 + layer*a, 0.01*rnd.uniform(0.9, 1.1)))
        layer += 1
    top = max(g[2] for g in grains) + 0.02
    with open(path, "w") as f:
        f.write("ores on a lattice\n\n%d atoms\n1 atom types\n\n" % n)
        f.write("-0.06 0.06 xlo xhi\n-0.06 0.06 ylo yhi\n-0.01 %g zlo zhi\n\nAtoms\n\n" % top)
        for i, (x, y, z, d) in enumerate(grains):
            f.write("%d 1 %.17g 2500 %.17g %.17g %.17g\n" % (i + 1, d, x, y, z))


def timed(cmd, cwd, stdin=None):
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.perf_counter()
    subprocess.run(cmd, cwd=cwd, stdin=stdin, stdout=subprocess.DEVNULL, check=True)
    wall = time.perf_counter() - t0
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return cpu, wall


def liggghts(ranks, data, steps, out, cwd):
    args = ["liggghts", "-echo", "none", "-log", "none"]
    for k, v in dict(data=data, skin=0.002, E=E, nu=NU, e=EN, mu=MU, dt=DT, R=R,
                     steps=steps, out=out).items():
        args += ["-var", k, str(v)]
    if ranks > 1:
        args = ["mpirun", "--allow-run-as-root", "--oversubscribe", "-np", str(ranks)] + args
    with open(os.path.join(TEST, "in.pour")) as inp:
        return timed(args, cwd, stdin=inp)


def saved(args, stem, rows):
    """<results>/<stem>.json written (the rows, the date); <results>/<stem>.md
    opened for the table; and the result"""
    result = {"date": datetime.datetime.now().isoformat(timespec="seconds"),
              "quick": args.quick, "rows": rows}
    with open(os.path.join(args.results, stem + ".json"), "w") as f:
        json.dump(result, f, indent=1)
    return open(os.path.join(args.results, stem + ".md"), "w"), result


def settled(n, work):
    """the data file of n ores poured for 0.5 s by LIGGGHTS (their final
    positions, at rest), and the mean number of contacts of a grain then"""
    data = os.path.join(work, "ores%d.data" % n)
    lattice(n, 1, data)
    dump = "settle%d.dump" % n
    liggghts(1, data, int(round(0.5/DT)), dump, work)
    with open(os.path.join(work, dump)) as f:
        lines = f.read().splitlines()
    start = next(i for i, l in enumerate(lines) if l.startswith("ITEM: ATOMS")) + 1
    rows = [l.split() for l in lines[start:start + n]]
    top = max(float(r[4]) for r in rows) + 0.02
    bed = os.path.join(work, "bed%d.data" % n)
    with open(bed, "w") as f:
        f.write("a settled bed of ores\n\n%d atoms\n1 atom types\n\n" % n)
        f.write("-0.06 0.06 xlo xhi\n-0.06 0.06 ylo yhi\n-0.01 %g zlo zhi\n\nAtoms\n\n" % top)
        for r in rows:
            f.write("%s 1 %.17g 2500 %s %s %s\n" % (r[0], 2*float(r[1]), r[2], r[3], r[4]))
    return bed, statistics.mean(float(r[5]) for r in rows)


def dense(args, work, engine):
    """ours against LIGGGHTS 1 rank on the settled bed (see above)"""
    sizes = [1000] if args.quick else [1000, 5000]
    simulated = 0.02 if args.quick else 0.1
    steps = int(round(simulated/DT))
    rows = []
    for n in sizes:
        bed, contacts = settled(n, work)
        runs = {"liggghts1": [], "ours": []}
        for r in range(3):
            runs["liggghts1"].append(liggghts(1, bed, steps, "dense1.dump", work))
            runs["ours"].append(timed([engine, bed, str(E), str(NU), str(EN), str(MU), str(DT),
                                       str(steps), str(R), "dense.txt"], work))
        per = {k: [1e9*cpu/(n*steps) for cpu, _ in v] for k, v in runs.items()}
        ratios = [o/l for o, l in zip(per["ours"], per["liggghts1"])]
        row = {"N": n, "simulated_s": simulated, "steps": steps, "contacts_per_grain": contacts,
               "ns_per_grain_step": per, "ratio_ours_to_liggghts1": ratios,
               "ratio_median": statistics.median(ratios)}
        rows.append(row)
        print(row)
    out, result = saved(args, "granularDense", rows)
    with out as f:
        f.write("# Grain engine against LIGGGHTS 3.8 on a settled bed (pure DEM)\n\n")
        f.write("Measured %s by `benchmarks/granular.py --dense%s`: ores of 9-11 mm poured by "
                "LIGGGHTS for 0.5 s into a closed riser section (D = 0.1 m), then both programs "
                "from those positions at rest for %g s (dt = %g s, the same Hertz-Mindlin law and "
                "parameters, rotation), alternated three times; CPU nanoseconds per grain-step and "
                "the ratio ours / LIGGGHTS of each repeat. Target: at most 1.5.\n\n"
                % (result["date"], " --quick" if args.quick else "", simulated, DT))
        f.write("| N | contacts per grain | LIGGGHTS 1 rank [ns] | ours [ns] | ours / LIGGGHTS |\n"
                "|---|---|---|---|---|\n")
        for r in rows:
            p = r["ns_per_grain_step"]
            f.write("| %d | %.1f | %s | %s | %s |\n"
                    % (r["N"], r["contacts_per_grain"],
                       " ".join("%.0f" % x for x in p["liggghts1"]),
                       " ".join("%.0f" % x for x in p["ours"]),
                       " ".join("%.2f" % x for x in r["ratio_ours_to_liggghts1"])))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--dense", action="store_true")
    ap.add_argument("--build", required=True)
    ap.add_argument("--results", required=True)
    args = ap.parse_args()
    work = os.path.join(os.path.abspath(args.build), "granular")
    os.makedirs(work, exist_ok=True)
    os.makedirs(args.results, exist_ok=True)
    engine = os.path.join(work, "granularBed")
    subprocess.run(["g++", "-O2", "-std=c++17", "-DNDEBUG", "-I", os.path.join(ROOT, "src", "riserCore"),
                    "-I", "/usr/include/eigen3", os.path.join(TEST, "granularBed.cpp"), "-o", engine],
                   check=True)
    if args.dense:
        dense(args, work, engine)
        return
    sizes = [1000] if args.quick else [1000, 5000]
    simulated = 0.05 if args.quick else 0.2
    steps = int(round(simulated/DT))
    repeats = 2
    rows = []
    for n in sizes:
        data = os.path.join(work, "ores%d.data" % n)
        lattice(n, 1, data)
        runs = {"liggghts1": [], "liggghts2": [], "ours": []}
        for r in range(repeats):
            runs["liggghts1"].append(liggghts(1, data, steps, "l1.dump", work))
            runs["liggghts2"].append(liggghts(2, data, steps, "l2.dump", work))
            runs["ours"].append(timed([engine, data, str(E), str(NU), str(EN), str(MU), str(DT),
                                       str(steps), str(R), "ours.txt"], work))
        per = {k: [cpu/simulated for cpu, _ in v] for k, v in runs.items()}
        row = {
            "N": n, "simulated_s": simulated, "steps": steps,
            "cpu_per_simulated_second": per,
            "wall_s": {k: [w for _, w in v] for k, v in runs.items()},
            "ratio_ours_to_liggghts1": statistics.median(
                o/l for o, l in zip(per["ours"], per["liggghts1"])),
            "ratio_ours_to_liggghts2": statistics.median(
                o/l for o, l in zip(per["ours"], per["liggghts2"])),
            "ns_per_particle_step_ours": 1e9*statistics.median(per["ours"])*simulated/(n*steps),
            "ns_per_particle_step_liggghts1": 1e9*statistics.median(per["liggghts1"])*simulated/(n*steps),
        }
        rows.append(row)
        print("N = %d: CPU s per simulated s: LIGGGHTS 1 rank %.1f, 2 ranks %.1f, ours %.1f;"
              " ours / LIGGGHTS %.2f (1 rank), %.2f (2 ranks)"
              % (n, statistics.median(per["liggghts1"]), statistics.median(per["liggghts2"]),
                 statistics.median(per["ours"]), row["ratio_ours_to_liggghts1"],
                 row["ratio_ours_to_liggghts2"]))
    out, result = saved(args, "granular", rows)
    with out as f:
        f.write("# Grain engine against LIGGGHTS 3.8 (pure DEM, poured riser section)\n\n")
        f.write("Measured %s by `benchmarks/granular.py%s`; CPU seconds per simulated second, "
                "median of %d alternated repeats. Target: ours within 3 times LIGGGHTS.\n\n"
                % (result["date"], " --quick" if args.quick else "", repeats))
        f.write("| N | LIGGGHTS 1 rank | LIGGGHTS 2 ranks | ours (1 process) | ours / LIGGGHTS 1 | "
                "ours / LIGGGHTS 2 | ns per particle-step ours / LIGGGHTS |\n|---|---|---|---|---|---|---|\n")
        for r in rows:
            p = r["cpu_per_simulated_second"]
            f.write("| %d | %.1f | %.1f | %.1f | %.2f | %.2f | %.0f / %.0f |\n"
                    % (r["N"], statistics.median(p["liggghts1"]), statistics.median(p["liggghts2"]),
                       statistics.median(p["ours"]), r["ratio_ours_to_liggghts1"],
                       r["ratio_ours_to_liggghts2"], r["ns_per_particle_step_ours"],
                       r["ns_per_particle_step_liggghts1"]))


if __name__ == "__main__":
    main()
