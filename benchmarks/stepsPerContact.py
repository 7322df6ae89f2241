"""The contact sub-cycles' resolution against their cost: stepsPerContact of
riserContact from 10 to 640, on dry impacts of the flagship's ore (d = 10 mm,
2000 kg/m^3, E = 60 GPa, nu = 0.26) on its steel riser wall (200 GPa, 0.3;
e_n = 0.76, e_t = 0.7, mu_c = 0.2) with no fluid force, so that the rebound
has a closed form: UnOut/UnIn = e_n (the damping is calibrated to it).
Impacts at 0.1, 0.5 and 2 m/s normal, and 1 m/s normal with 0.5 m/s along
the wall (cases.wall_contact_case; icoUncoupledKinematicParcelFoam, dt =
1e-4 s). For each stepsPerContact: the largest |UnOut/UnIn - e_n| / e_n of
the impacts, the contact time's sub-cycles, and the solver's time of the
whole run. The cost is measured on a scene where contacts are a large
share of the work: oreCloud.py's 1,000 shaken ores (C_v 0.05, A = 0.2 m,
f = 4 Hz, wall contact, ores alone at the wall tracked through the mesh),
0.05 s, the solver's time from the end of step 10 to the last, relative to
stepsPerContact 40 (the default); the values alternated, three
repetitions, the least taken.

With the fluid forces: the flagship (tutorials/riser/oscillatingContact:
riserParcelFoam, the paper's forces with the Basset force, five periods,
11 wall contacts) at each stepsPerContact, against itself at 640 (no
closed form there): the largest difference of the rebound's normal speed
UnOut over the contacts, in units of u_cm, of the restitution UnOut/UnIn,
and of the lift after five periods.

usage: stepsPerContact.py --build DIR --results DIR
       stepsPerContact.py --fluid --build DIR --results DIR
                             (the fluid-force rows alone, merged into a
                             finished run's results)
       stepsPerContact.py --plot --results DIR   (the chart of a finished run)
Writes results/stepsPerContact.{md,json,png}.
"""
import argparse
import json
import os
import shutil
import sys
import time

from riserfoam import cases

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import oreCloud  # noqa: E402  (its shaken scene)
from riserfoam import tables  # noqa: E402

E_N = 0.76
U_CM = 1.0      # the flagship's centre-line speed [m/s]
STEPS = (10, 14, 20, 28, 40, 57, 80, 113, 160, 320, 640)
IMPACTS = [(0.1, 0.0), (0.5, 0.0), (2.0, 0.0), (1.0, 0.5)]


def make(case, steps):
    cases.wall_contact_case(case, D=0.1, radius=0.005, rho=2000.0, E=6e10, nu=0.26,
                            wall_E=2e11, wall_nu=0.3, e_n=E_N, e_t=0.7, mu=0.2,
                            velocities=IMPACTS, dt=1e-4, end=2e-3, steps_per_contact=steps)
    cases.run(["blockMesh", "-case", case], os.path.join(case, "log.blockMesh"))


def run_copy(base, case, steps):
    """base copied to case with stepsPerContact steps, run by riserParcelFoam;
    returns the log's text"""
    shutil.rmtree(case, ignore_errors=True)
    shutil.copytree(base, case)
    oreCloud.ff.set_nested(os.path.join(case, "constant/kinematicCloudProperties"),
                           "subModels/riserContactCoeffs/stepsPerContact", str(steps))
    return cases.run(["riserParcelFoam", "-case", case], os.path.join(case, "log.riserParcelFoam"))


def fluid_rows(work):
    """The flagship with its fluid forces at each stepsPerContact, against
    stepsPerContact 640: one row per value"""
    base = os.path.join(work, "flagship")
    cases.copy_tutorial("riser/oscillatingContact", base)
    cases.riser_mesh(base, 0.1, 0.2, 12)
    runs = {}
    for n in STEPS:
        case = os.path.join(work, "flagship%d" % n)
        run_copy(base, case, n)
        c = cases.wall_contacts(case)
        table = tables.read(os.path.join(case, "postProcessing/lagrangian/kinematicCloud/"
                                         "riserParticleTable/particles.dat"))
        runs[n] = (c["UnIn"], c["UnOut"], table["lift"][-1])
    ref_in, ref_out, ref_lift = runs[STEPS[-1]]
    rows = []
    for n in STEPS:
        u_in, u_out, lift = runs[n]
        if len(u_out) != len(ref_out):
            raise SystemExit("stepsPerContact %d: %d contacts, %d at %d"
                             % (n, len(u_out), len(ref_out), STEPS[-1]))
        rows.append({
            "steps": n, "contacts": len(u_out),
            "unout_error": max(abs(a - b) for a, b in zip(u_out, ref_out)) / U_CM,
            "restitution_error": max(abs(a / i - b / j)
                                     for a, i, b, j in zip(u_out, u_in, ref_out, ref_in)),
            "lift": lift, "lift_error": abs(lift - ref_lift) / ref_lift})
    return rows


def write_md(result, results):
    """results/stepsPerContact.md"""
    rows = result["rows"]
    with open(os.path.join(results, "stepsPerContact.md"), "w") as out:
        out.write("# Contact sub-cycles against their resolution (benchmarks/stepsPerContact.py)\n\n"
                  "Measured %s, load average %s. Resolution: dry impacts of the flagship's ore "
                  "on its riser wall at (normal, tangential) speeds %s m/s, no fluid force: the "
                  "rebound's closed form is UnOut/UnIn = e_n = 0.76. Cost: 1,000 shaken ores "
                  "(oreCloud.py's scene, wall contact, tracked), 0.05 s, the solver's time from "
                  "step 10 (least of three, the values alternated), relative to "
                  "stepsPerContact 40.\n\n"
                  "| stepsPerContact | largest restitution error | restitutions | time s | "
                  "time / time at 40 |\n|---|---|---|---|---|\n"
                  % (result["date"], " ".join(result["load"]),
                     ", ".join("(%g, %g)" % v for v in IMPACTS)))
        for r in rows:
            out.write("| %d | %.2e | %s | %.2f | %.2f |\n"
                      % (r["steps"], r["error"], " ".join("%.5f" % x for x in r["restitution"]),
                         min(r["time_s"]), r["cost_vs_40"]))
        if "fluid" in result:
            out.write("\n## With the fluid forces\n\n"
                      "Measured %s. The flagship (tutorials/riser/oscillatingContact: "
                      "riserParcelFoam, the paper's forces and the Basset force, riser frame, "
                      "five periods, %d wall contacts) against itself at stepsPerContact %d: the "
                      "largest difference over the contacts of the rebound's normal speed UnOut "
                      "(in units of u_cm = 1 m/s) and of the restitution UnOut/UnIn, and the "
                      "lift after five periods.\n\n"
                      "| stepsPerContact | largest UnOut difference / u_cm | largest restitution "
                      "difference | lift after five periods m | lift difference |\n"
                      "|---|---|---|---|---|\n"
                      % (result["fluid_date"], result["fluid"][0]["contacts"], STEPS[-1]))
            for r in result["fluid"]:
                out.write("| %d | %.2e | %.2e | %.6f | %.2e |\n"
                          % (r["steps"], r["unout_error"], r["restitution_error"], r["lift"],
                             r["lift_error"]))


def plot(results):
    """results/stepsPerContact.png: the restitution error and the cost
    against stepsPerContact"""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    rows = json.load(open(os.path.join(results, "stepsPerContact.json")))["rows"]
    n = [r["steps"] for r in rows]
    fig, ax = plt.subplots(figsize=(6.4, 4.2))
    ax.loglog(n, [r["error"] for r in rows], "o-", label="largest |e - e_n| / e_n (dry impacts)")
    fluid = json.load(open(os.path.join(results, "stepsPerContact.json"))).get("fluid")
    if fluid:
        ax.loglog([r["steps"] for r in fluid[:-1]], [r["unout_error"] for r in fluid[:-1]], "^-",
                  color="tab:green",
                  label="largest UnOut difference / u_cm (flagship, fluid forces; vs 640)")
    ax.set_xlabel("stepsPerContact")
    ax.set_ylabel("restitution error")
    ax.axvline(40, color="grey", lw=0.8, ls=":")
    cost = ax.twinx()
    cost.semilogx(n, [r["cost_vs_40"] for r in rows], "s--", color="tab:red",
                  label="time / time at 40 (1,000 shaken ores)")
    cost.set_ylabel("cost relative to stepsPerContact 40")
    lines = ax.get_legend_handles_labels()[0] + cost.get_legend_handles_labels()[0]
    labels = ax.get_legend_handles_labels()[1] + cost.get_legend_handles_labels()[1]
    ax.legend(lines, labels, fontsize=8, loc="upper center")
    ax.set_title("riserContact: sub-cycles per contact time, resolution and cost", fontsize=10)
    fig.tight_layout()
    fig.savefig(os.path.join(results, "stepsPerContact.png"), dpi=120)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build")
    ap.add_argument("--results", required=True)
    ap.add_argument("--plot", action="store_true", help="only the chart of a finished run")
    ap.add_argument("--fluid", action="store_true",
                    help="only the fluid-force rows, merged into a finished run's results")
    args = ap.parse_args()
    if args.plot:
        plot(args.results)
        return
    if not args.build:
        ap.error("--build is required")
    work = os.path.join(args.build, "stepsPerContact")
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    if args.fluid:
        result = json.load(open(os.path.join(args.results, "stepsPerContact.json")))
        result["fluid"] = fluid_rows(work)
        result["fluid_date"] = time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime())
        json.dump(result, open(os.path.join(args.results, "stepsPerContact.json"), "w"),
                  indent=1)
        write_md(result, args.results)
        plot(args.results)
        for r in result["fluid"]:
            print("stepsPerContact %4d: UnOut %.2e u_cm, restitution %.2e, lift %.2e"
                  % (r["steps"], r["unout_error"], r["restitution_error"], r["lift_error"]))
        return
    rows = {n: {"steps": n, "time_s": []} for n in STEPS}
    # the resolution: dry impacts, closed form
    for n in STEPS:
        case = os.path.join(work, "impacts%d" % n)
        make(case, n)
        text = cases.run(["icoUncoupledKinematicParcelFoam", "-case", case],
                         os.path.join(case, "log.solver"))
        c = cases.wall_contacts(case)
        e = [o / i for i, o in zip(c["UnIn"], c["UnOut"])]
        if len(e) != len(IMPACTS) or "outside the pipe" in text:
            raise SystemExit("stepsPerContact %d: %d contacts, expected %d"
                             % (n, len(e), len(IMPACTS)))
        rows[n]["error"] = max(abs(x - E_N) / E_N for x in e)
        rows[n]["restitution"] = e
    # the cost: the shaken scene, the values alternated
    scene = os.path.join(work, "scene")
    # (1,000 ores at C_v 0.05, the section as oreCloud.py --processors makes it)
    Cv = 0.05
    L = oreCloud.section_length(1000, Cv)
    oreCloud.make(scene, 0.05, 0.2, 4.0, *oreCloud.VARIANTS["wall"], L=L, n=6,
                  nz=max(4, int(round(L / 0.02))), Cv=Cv)
    for repeat in range(3):
        for n in STEPS:
            text = run_copy(scene, os.path.join(work, "scene%d" % n), n)
            rows[n]["time_s"].append(oreCloud.steps_time(text))
    base = min(rows[40]["time_s"])
    for r in rows.values():
        r["cost_vs_40"] = min(r["time_s"]) / base
    os.makedirs(args.results, exist_ok=True)
    result = {"date": time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime()),
              "load": open("/proc/loadavg").read().split()[:3], "rows": list(rows.values())}
    result["fluid"] = fluid_rows(work)
    result["fluid_date"] = result["date"]
    json.dump(result, open(os.path.join(args.results, "stepsPerContact.json"), "w"), indent=1)
    write_md(result, args.results)
    plot(args.results)
    for r in rows.values():
        print("stepsPerContact %4d: error %.2e, time %.2f s (%.2f of 40's)"
              % (r["steps"], r["error"], min(r["time_s"]), r["cost_vs_40"]))


if __name__ == "__main__":
    main()
