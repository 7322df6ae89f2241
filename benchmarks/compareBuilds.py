"""Measure a proposed change of riserFoam without touching the tree: two
private builds of the library and solver (a snapshot of src/ and
applications/solvers/riserParcelFoam, unchanged in A, changed in B, each
built with wmake outside the project, RISER_DIR/RISER_LIBBIN/RISER_APPBIN
pointing there), run alternately on the same cases; the final particle
states of A and B must be identical.

usage: compareBuilds.py <build A> <build B> [--quick] [--out file.json]

License: GPL-3.0-or-later
"""
import argparse
import json
import os
import shutil

import bench
from riserfoam import cases, foamfields


def env_for(build):
    env = dict(os.environ)
    env["PATH"] = os.path.join(build, "bin") + ":" + env["PATH"]
    env["LD_LIBRARY_PATH"] = os.path.join(build, "lib") + ":" + env.get("LD_LIBRARY_PATH", "")
    return env


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("A")
    ap.add_argument("B")
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--reps", type=int, default=3)
    ap.add_argument("--work", default=os.path.join(os.environ["RISER_DIR"], "build", "benchmarks", "compareBuilds"))
    ap.add_argument("--out", default=None)
    ap.add_argument("--parts", default="cases,flagship")
    args = ap.parse_args()
    b = bench.Bench(args.work, args.quick)
    b.make_mesh()
    n_lab = 2000 if args.quick else 10000
    n_static = 2000 if args.quick else 10000
    plan = [  # (suite, variant, N, steps)
        ("lab", "riserLabBasset", 1, 25), ("lab", "riserLabBasset", n_lab, 25),
        ("lab", "riserLab", n_lab, 25),
        ("static", "riserFrameBasset", 1, 60), ("static", "riserFrameBasset", n_static, 60),
        ("static", "riserFrame", n_static, 60),
    ]
    envs = {"A": env_for(args.A), "B": env_for(args.B)}
    out = {"A": args.A, "B": args.B, "machine": bench.machine(), "runs": []}
    for suite, key, n, steps in (plan if "cases" in args.parts else []):
        runs = {}
        for tag in ("A", "B"):
            runs[tag] = b.case("%s_%s" % (suite, tag), key, n, steps, write_at_end=True)
        times = {"A": [], "B": []}
        for rep in range(args.reps):
            for tag in (("A", "B") if rep % 2 == 0 else ("B", "A")):
                r = bench.run_solver(runs[tag], "riserParcelFoam", env=envs[tag])
                times[tag].append(bench.per_step(r["cpuStamps"], 3, steps - 1))
        diff = bench.compare_clouds(runs["A"], runs["B"], steps * bench.DT, n) \
            if n > 1 else "n/a"
        if n == 1:
            a, bb = (foamfields.read_vectors(os.path.join(bench.time_dir(runs[tag], steps * bench.DT),
                                                          "lagrangian", "kinematicCloud", "positions"))
                     for tag in ("A", "B"))
            diff = {"identical": a == bb}
        row = {"suite": suite, "variant": key, "N": n, "steps": steps,
               "A": min(times["A"]), "B": min(times["B"]), "allA": times["A"], "allB": times["B"],
               "ratio": min(times["B"]) / min(times["A"]), "sameResults": diff}
        out["runs"].append(row)
        b.say("%-6s %-18s N = %-6d A %8.3f ms/step, B %8.3f ms/step, B/A %.3f, %s"
              % (suite, key, n, 1e3 * row["A"], 1e3 * row["B"], row["ratio"], diff))
    if "flagship" in args.parts:
        # the flagship, whole run, as the tutorial runs it
        flag = {}
        for tag in ("A", "B"):
            path = os.path.join(args.work, "flagship_%s" % tag)
            cases.copy_tutorial("riser/oscillatingContact", path, root=os.environ["RISER_DIR"])
            cases.riser_mesh(path, 0.1, 0.2, 12, root=os.environ["RISER_DIR"])
            flag[tag] = path
        ft = {"A": [], "B": []}
        for rep in range(args.reps):
            for tag in (("A", "B") if rep % 2 == 0 else ("B", "A")):
                # from the start (startFrom latestTime): the tutorial's Allclean
                for d in os.listdir(flag[tag]):
                    if d == "postProcessing" or (d != "0" and d.replace(".", "").replace("e-", "").isdigit()):
                        shutil.rmtree(os.path.join(flag[tag], d))
                r = bench.run_solver(flag[tag], "riserParcelFoam", env=envs[tag])
                if len(r["cpuStamps"]) < 3000 or None in (r["cpuStamps"][0], r["cpuStamps"][-2]):
                    raise RuntimeError("flagship run incomplete or not timed")
                ft[tag].append(r["cpuStamps"][-2] - r["cpuStamps"][0])
        table = lambda t: open(os.path.join(flag[t], "postProcessing", "lagrangian", "kinematicCloud",
                                            "riserParticleTable", "particles.dat")).read()
        row = {"suite": "flagship", "variant": "tutorials/riser/oscillatingContact (3,334 steps, CPU of steps 2..end)",
               "A": min(ft["A"]), "B": min(ft["B"]), "allA": ft["A"], "allB": ft["B"],
               "ratio": min(ft["B"]) / min(ft["A"]), "sameResults": {"identicalTable": table("A") == table("B")}}
        out["runs"].append(row)
        b.say("flagship A %.2f s, B %.2f s, B/A %.3f, %s" % (row["A"], row["B"], row["ratio"], row["sameResults"]))
    if args.out:
        with open(args.out, "w") as f:
            json.dump(out, f, indent=1)


if __name__ == "__main__":
    main()
