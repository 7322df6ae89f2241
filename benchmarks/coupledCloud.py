"""What the two-way coupling costs riserCoupledFoam, and its speed-up on two
processors, on one ore-transport scene.

The scene: a periodic riser section (D = 0.1 m, L = 0.5 m, riserMesh -n 12
-nz 44 -ends cyclic: 21,120 cells), water driven upward at the bulk
velocity 1.5 m/s (twice the terminal speed of the ores, about 0.55 m/s), the
turbulent carrier of kOmegaSST with wall functions
(cases.coupled_pipe_RAS); the riser oscillates at A = 0.1 m, f = 3 Hz
(riser frame); ores of d = 10 mm (2000 kg/m^3) fill the section at C_v =
0.05 (riserFill, seed 1, at rest relative to the carrier: about 375 ores),
forces wallCorrectedDrag, riserFluidStress, riserFrame and gravity, wall
and pair contact (riserContact with pairs, the coefficients of the
tutorial riser/oreTransport, stepsPerContact 10); dt = 5e-4 s; PIMPLE with
1 outer and 2 pressure correctors, p by PCG/DIC to 1e-7 (relTol 0.01 in the
first corrector), U, k, omega by symGaussSeidel to 1e-7 (relTol 0.1 in the
first). The kernel is that of the tutorial riser/oreTransportCoupled:
diffusion over 3 largest diameters (b = 30 mm) in 2 pseudo-steps, the
solves to the default tolerance (1e-4), unless said.

Suite 'cost' (serial): the CPU time per step of seven variants of the
scene, run alternately (A B ... G, then G ... B A, ...) in this one command,
so that the shared machine's load falls on all alike:

    fluid       no ores (the carrier alone)
    oneWay      coupled false: the ores move in the computed carrier, which
                feels their volume (alpha_c, spread by the kernel) but not
                their force
    oneWayNone  the same with kernel none (alpha_c from one-cell deposits)
    twoWay      coupled true, kernel diffusion
    twoWayNone  coupled true, kernel none
    oneWayN4, twoWayN4  oneWay and twoWay with the kernel's default 4
                pseudo-steps (the same width, a shape nearer the
                Gaussian, see particleKernel.H)

Reported: the time per step of each (median and least over the repeats);
the ratio twoWay / oneWayNone, the coupled solver against the fluid solve
plus the one-way cloud in one run (the ores' volume kept in their cells,
no kernel, no reaction: the target, at most 1.3), computed repeat by
repeat, its median and range; the ratios twoWay / oneWay (what the
reaction and its spreading add to a run whose carrier already feels the
spread volume), twoWayNone / oneWayNone and twoWayN4 / oneWayN4 alike; and
the breakdown of the twoWay step:
fluid; cloud = oneWayNone - fluid; the spread alpha_c = oneWay -
oneWayNone; the reaction with one-cell deposits = twoWayNone -
oneWayNone; the kernel's spreading of the reaction = (twoWay -
twoWayNone) - (oneWay - oneWayNone). Then one more twoWay run with the
debug switch particleKernel 1 counts the kernel's pseudo-steps and
conjugate-gradient iterations (per field: theta, and UTrans x, y, z and
UCoeff in lock-step) and the pressure's solves and iterations, and times
the kernel's calls against the step in the same process: its share of
the step and twoWay / (twoWay - kernel), a reading of the ratio that the
machine's varying load does not move (the variants' times, minutes
apart, scatter by up to a fifth on a shared machine).

Suite 'ranks': the twoWay and twoWayNone scenes on one and on two
processors (decomposePar, simple, split along the riser's axis z),
alternately, each run started once the machine's other work has dropped
below 0.3 cores or after 60 s: the wall time per step (median over the
measured steps of a run) and the speed-up, repeat by repeat and of the
least wall times (the quietest runs), the CPU time per step of the busiest
rank, with the other work measured before and during each run and the
load average. Two ranks on two cores that other work also uses wait for
each other: mpirun's ranks poll while they wait, so a rank descheduled
for another process stalls both.

Timing as in bench.py (run_solver): the CPU time of the solver's threads
read at each ExecutionTime line, over steps 3 .. steps - 1 (step 1 injects
the ores, the last one writes).

usage: coupledCloud.py [--quick] [--suites cost,ranks] [--repeats N]
                       --build DIR --results DIR
writes <results>/coupledCloud.json and <results>/coupledCloud.md
License: GPL-3.0-or-later
"""
import argparse
import glob
import json
import os
import re
import shutil
import statistics

import bench
from riserfoam import cases
from riserfoam import foamfields as ff
from riserfoam.suspension import CONTACTS

D, L, N_CORE, NZ = 0.1, 0.5, 12, 44
UB, DT, CV, ORE_D = 1.5, 5e-4, 0.05, 0.01
KERNEL = "type diffusion; width 3; widthUnit diameters; pseudoSteps 2;"
ORES = cases.fill_injection(CV, ORE_D)
SOLVERS = """
solvers
{
    p { solver PCG; preconditioner DIC; tolerance 1e-7; relTol 0.01; }
    pFinal { $p; relTol 0; }
    "(U|k|omega)" { solver smoothSolver; smoother symGaussSeidel; tolerance 1e-7; relTol 0.1; }
    "(U|k|omega)Final" { $U; relTol 0; }
}
"""
# variant: (ores, coupled, kernel)
VARIANTS = {
    "fluid": (False, False, KERNEL),
    "oneWay": (True, False, KERNEL),
    "oneWayNone": (True, False, "type none;"),
    "twoWay": (True, True, KERNEL),
    "twoWayNone": (True, True, "type none;"),
    "oneWayN4": (True, False, KERNEL.replace("pseudoSteps 2", "pseudoSteps 4")),
    "twoWayN4": (True, True, KERNEL.replace("pseudoSteps 2", "pseudoSteps 4")),
}
# on one and two processors; each run waits this long at most [s] for the
# other work on the machine to drop below 0.3 cores
RANK_VARIANTS = ("twoWay", "twoWayNone")
QUIET_WAIT = 60.0


def make(case, variant, steps):
    """the scene (see above) as variant, run for steps steps"""
    ores, coupled, kernel = VARIANTS[variant]
    cases.coupled_pipe_case(case, N_CORE, NZ, L=L, D=D, nu=1e-6, rho=1000.0, uCentre=2 * UB,
                            A=0.1, f=3.0, drive="bulkVelocity %r;" % UB, dt=DT,
                            end=steps * DT, injection=ORES if ores else "",
                            coupled=coupled, kernel=kernel, collision=CONTACTS)
    cases.coupled_pipe_RAS(case, UB, D)
    ff.edit(os.path.join(case, "system/fvSolution"), r"^solvers\n\{(.|\n)*?\n\}\n", SOLVERS)
    # every repeat from the start time
    ff.set_entry(os.path.join(case, "system/controlDict"), "startFrom", "startTime")
    return case


def timed(case, np=1):
    """run_solver on case, the output of an earlier run removed"""
    for folder in [case] + glob.glob(os.path.join(case, "processor*")):
        shutil.rmtree(os.path.join(folder, "postProcessing"), ignore_errors=True)
        for entry in os.listdir(folder):
            try:
                if float(entry) > 0:
                    shutil.rmtree(os.path.join(folder, entry))
            except ValueError:
                pass
    return bench.run_solver(case, "riserCoupledFoam", np)


def iterations(case):
    """Linear-solver iterations per flow step of one more run of case with
    the kernel's debug switch (each pseudo-step printed with its fields'
    iterations): the kernel's pseudo-steps, field solves and iterations;
    the pressure's solves and iterations (steps 3 .. the last)"""
    control = os.path.join(case, "system/controlDict")
    text = open(control).read()
    with open(control, "a") as out:
        out.write("DebugSwitches { particleKernel 1; }\n")
    try:
        timed(case)
    finally:
        with open(control, "w") as out:
            out.write(text)
    log = open(os.path.join(case, "log.riserCoupledFoam")).read()
    steps = log.split("\nTime = ")[3:]
    kernel = [[int(n) for its in re.findall(r"particleKernel: pseudo-step \d+, iterations of "
                                             r"the \d+ fields:([0-9 ]+)", s)
               for n in its.split()] for s in steps]
    pseudo = [len(re.findall(r"particleKernel: pseudo-step", s)) for s in steps]
    p = [[int(n) for n in re.findall(r"Solving for p, .* No Iterations (\d+)", s)] for s in steps]
    mean = lambda xs: sum(xs) / len(xs)
    # CPU times of the same run: the kernel's calls and the whole step
    # (ExecutionTime, cumulative), so that the machine's load falls on both
    spread = [sum(float(t) for t in re.findall(r"particleKernel: \d+ field\(s\) spread in (\S+) s", s))
              for s in steps]
    clock = [float(re.search(r"ExecutionTime = (\S+) s", s).group(1)) for s in log.split("\nTime = ")[2:]]
    step_cpu = [b - a for a, b in zip(clock, clock[1:])]
    return {"steps": len(steps),
            "kernelCpuPerStep": mean(spread[:-1]),
            "stepCpuPerStep": mean(step_cpu[:-1]),
            "kernelPseudoStepsPerStep": mean(pseudo),
            "kernelSolvesPerStep": mean([len(k) for k in kernel]),
            "kernelIterationsPerStep": mean([sum(k) for k in kernel]),
            "pressureSolvesPerStep": mean([len(x) for x in p]),
            "pressureIterationsPerStep": mean([sum(x) for x in p])}


def suite_cost(args, work):
    steps = 8 if args.quick else 25
    names = list(VARIANTS)
    paths = {k: make(os.path.join(work, "cost", k), k, steps) for k in names}
    runs = {k: [] for k in names}
    for rep in range(args.repeats):
        for k in (names if rep % 2 == 0 else names[::-1]):
            r = timed(paths[k])
            r["cpuPerStep"] = bench.per_step(r["cpuStamps"], 3, steps - 1)
            r["wallPerStep"] = bench.per_step(r["wallStamps"], 3, steps - 1)
            runs[k].append({key: r[key] for key in
                            ("cpuPerStep", "wallPerStep", "parcels", "backgroundCores",
                             "peakRssKB", "totalWall")})
            print("%-11s rep %d: %8.2f ms/step CPU, %8.2f ms wall, %s parcels, other work "
                  "%.2f cores" % (k, rep + 1, 1e3 * r["cpuPerStep"], 1e3 * r["wallPerStep"],
                                  r["parcels"], r["backgroundCores"]), flush=True)
    med = statistics.median
    t = {k: med(r["cpuPerStep"] for r in runs[k]) for k in names}
    tmin = {k: min(r["cpuPerStep"] for r in runs[k]) for k in names}
    def paired(a, b):
        return [x["cpuPerStep"] / y["cpuPerStep"] for x, y in zip(runs[a], runs[b])]
    ratios_target = paired("twoWay", "oneWayNone")
    ratios = paired("twoWay", "oneWay")
    ratios_none = paired("twoWayNone", "oneWayNone")
    ratios_n4 = paired("twoWayN4", "oneWayN4")
    breakdown = {}
    for label, which in (("median", t), ("least", tmin)):
        breakdown[label] = {
            "fluid": which["fluid"],
            "cloud": which["oneWayNone"] - which["fluid"],
            "spread alpha_c": which["oneWay"] - which["oneWayNone"],
            "reaction, one-cell": which["twoWayNone"] - which["oneWayNone"],
            "spread reaction": (which["twoWay"] - which["twoWayNone"])
                               - (which["oneWay"] - which["oneWayNone"]),
        }
    return {"ores": runs["twoWay"][0]["parcels"], "iterations": iterations(paths["twoWay"]),
            "steps": steps, "measuredSteps": [3, steps - 1], "repeats": args.repeats,
            "runs": runs, "cpuPerStep": t, "cpuPerStepLeast": tmin,
            "ratioTarget": med(ratios_target), "ratioTargetAllRepeats": ratios_target,
            "ratioTargetOfLeast": tmin["twoWay"] / tmin["oneWayNone"],
            "ratioTwoWayOneWay": med(ratios), "ratioTwoWayOneWayAllRepeats": ratios,
            "ratioTwoWayOneWayOfLeast": tmin["twoWay"] / tmin["oneWay"],
            "ratioKernelNone": med(ratios_none), "ratioKernelNoneAllRepeats": ratios_none,
            "ratioPseudoSteps4": med(ratios_n4), "ratioPseudoSteps4AllRepeats": ratios_n4,
            "breakdown": breakdown}


def suite_ranks(args, work):
    steps = 10 if args.quick else 30
    out = {"steps": steps, "repeats": args.repeats,
           "decomposition": "simple (1 1 2): split along the riser's axis", "variants": {}}
    paths = {}
    for variant in RANK_VARIANTS:
        for np in (1, 2):
            paths[variant, np] = make(os.path.join(work, "ranks", "%s_np%d" % (variant, np)),
                                      variant, steps)
        ff.write_dictionary(os.path.join(paths[variant, 2], "system/decomposeParDict"),
                            "numberOfSubdomains 2;\nmethod simple;\n"
                            "simpleCoeffs { n (1 1 2); delta 0.001; }\n")
        cases.run(["decomposePar", "-case", paths[variant, 2]],
                  os.path.join(paths[variant, 2], "log.decomposePar"))
    runs = {key: [] for key in paths}
    for rep in range(args.repeats):
        order = [(v, np) for v in RANK_VARIANTS for np in (1, 2)]
        for variant, np in (order if rep % 2 == 0 else order[::-1]):
            quiet = bench.wait_for_quiet(limit=QUIET_WAIT)
            load = open("/proc/loadavg").read().split()[:3]
            r = timed(paths[variant, np], np)
            w = statistics.median(bench.step_costs(r["wallStamps"])[2:steps - 2])
            if np == 1:
                c = bench.per_step(r["cpuStamps"], 4, steps - 1)
            else:
                # the busiest rank's CPU time (ranks poll while they wait)
                c = max(bench.per_step([x[i] if x else None for x in r["rankCpuStamps"]],
                                       4, steps - 1) for i in range(np))
            runs[variant, np].append({"wall": w, "cpu": c, "otherBefore": quiet,
                                      "otherDuring": r["backgroundCores"], "loadAverage": load})
            out["ores"] = r["parcels"]
            print("%-10s np %d rep %d: %8.2f ms/step wall (median), %8.2f ms/step CPU (busiest "
                  "rank), %s parcels, other work %.2f cores before, %.2f during"
                  % (variant, np, rep + 1, 1e3 * w, 1e3 * c, r["parcels"], quiet,
                     r["backgroundCores"]), flush=True)
    for variant in RANK_VARIANTS:
        ratios = [a["wall"] / b["wall"] for a, b in zip(runs[variant, 1], runs[variant, 2])]
        least = {np: min(runs[variant, np], key=lambda r: r["wall"]) for np in (1, 2)}
        out["variants"][variant] = {
            "runs": {str(np): runs[variant, np] for np in (1, 2)},
            "speedup": statistics.median(ratios), "speedupAllRepeats": ratios,
            "speedupOfLeast": least[1]["wall"] / least[2]["wall"],
            "otherDuringLeast": [least[1]["otherDuring"], least[2]["otherDuring"]]}
    return out


def write(args, result):
    with open(os.path.join(args.results, "coupledCloud.json"), "w") as out:
        json.dump(result, out, indent=1)
    ms = lambda s: "%.1f" % (1e3 * s)
    lines = ["# What the two-way coupling costs riserCoupledFoam (benchmarks/coupledCloud.py%s)\n"
             % (" --quick" if args.quick else ""),
             "Measured %s on %d cores (%s), load average %s at the start. The scene: "
             "benchmarks/coupledCloud.py's docstring (%d ores of 10 mm, C_v = %g, kOmegaSST, "
             "riser frame, wall and pair contact, 21,120 cells, dt = %g s).\n"
             % (result["date"], result["machine"]["nproc"], result["machine"]["cpu"],
                " ".join(result["machine"]["loadAverageAtStart"]),
                next(s["ores"] for s in result["suites"].values()), CV, DT)]
    cost = result["suites"].get("cost")
    if cost:
        t, tmin = cost["cpuPerStep"], cost["cpuPerStepLeast"]
        lines.append("## Cost per step, serial\n\nCPU time of the solver per step, steps %d..%d "
                     "of %d, %d repeats run alternately; median and least over the repeats.\n"
                     % (cost["measuredSteps"][0], cost["measuredSteps"][1], cost["steps"],
                        cost["repeats"]))
        lines.append("| variant | ms/step (median) | ms/step (least) | all repeats |\n"
                     "|---|---|---|---|")
        for k in VARIANTS:
            lines.append("| %s | %s | %s | %s |" % (k, ms(t[k]), ms(tmin[k]), ", ".join(
                ms(r["cpuPerStep"]) for r in cost["runs"][k])))
        ok = cost["ratioTarget"] <= 1.3
        lines.append("\n**twoWay / oneWayNone = %.2f** (the coupled solver against the fluid "
                     "solve plus the one-way cloud; median of the repeats' ratios; range %.2f "
                     "to %.2f; of the least times %.2f): target <= 1.3 %s.\n"
                     % (cost["ratioTarget"], min(cost["ratioTargetAllRepeats"]),
                        max(cost["ratioTargetAllRepeats"]), cost["ratioTargetOfLeast"],
                        "met" if ok else "NOT met"))
        lines.append("What the reaction and its spreading add to a run whose carrier already "
                     "feels the spread volume: twoWay / oneWay = %.2f (range %.2f to %.2f; of "
                     "the least times %.2f). With one-cell deposits (kernel none) twoWayNone / "
                     "oneWayNone = %.2f (range %.2f to %.2f); with the kernel in the default 4 "
                     "pseudo-steps twoWayN4 / oneWayN4 = %.2f (range %.2f to %.2f).\n"
                     % (cost["ratioTwoWayOneWay"], min(cost["ratioTwoWayOneWayAllRepeats"]),
                        max(cost["ratioTwoWayOneWayAllRepeats"]),
                        cost["ratioTwoWayOneWayOfLeast"],
                        cost["ratioKernelNone"], min(cost["ratioKernelNoneAllRepeats"]),
                        max(cost["ratioKernelNoneAllRepeats"]), cost["ratioPseudoSteps4"],
                        min(cost["ratioPseudoSteps4AllRepeats"]),
                        max(cost["ratioPseudoSteps4AllRepeats"])))
        lines.append("The twoWay step in parts, differences of the variants' times (see the "
                     "docstring); a part smaller than the repeats' spread, a few ms, is not "
                     "resolved and may come out negative.\n")
        lines.append("| part of the twoWay step | ms/step (from the medians) | share | "
                     "ms/step (from the least) |\n|---|---|---|---|")
        total = t["twoWay"]
        for part, v in cost["breakdown"]["median"].items():
            lines.append("| %s | %s | %.0f %% | %s |" % (part, ms(v), 100 * v / total,
                                                         ms(cost["breakdown"]["least"][part])))
        it = cost["iterations"]
        lines.append("\nLinear solves of a twoWay step (one more run with the debug switch "
                     "particleKernel 1, means over %d steps): the kernel %.0f pseudo-steps, "
                     "%.0f field solves of %.0f conjugate-gradient iterations in all (%.1f "
                     "each; theta, then UTrans x, y, z and UCoeff in lock-step, to the "
                     "kernel's default tolerance); the pressure %.0f solves of %.0f iterations "
                     "in all.\n"
                     % (it["steps"], it["kernelPseudoStepsPerStep"], it["kernelSolvesPerStep"],
                        it["kernelIterationsPerStep"],
                        it["kernelIterationsPerStep"] / it["kernelSolvesPerStep"],
                        it["pressureSolvesPerStep"], it["pressureIterationsPerStep"]))
        k, step = it["kernelCpuPerStep"], it["stepCpuPerStep"]
        lines.append("The kernel's own CPU time in that run (its calls timed by the debug "
                     "switch, against the step's ExecutionTime in the same process, so that "
                     "the machine's load falls on both alike): %s of %s ms a step (%.0f %%); "
                     "the step without it would take %s ms, and **twoWay / (twoWay - kernel) = "
                     "%.2f**: what the coupling costs if its other parts (the reaction's "
                     "assembly, the carrier's volume fraction in the equations) cost nothing, "
                     "as the one-cell variants find (twoWayNone / oneWayNone above).\n"
                     % (ms(k), ms(step), 100 * k / step, ms(step - k), step / (step - k)))
    ranks = result["suites"].get("ranks")
    if ranks:
        lines.append("## One and two processors\n\nThe twoWay and twoWayNone scenes, %d steps, "
                     "decomposePar %s; wall time per step (median over steps 4..%d of a run) "
                     "and CPU time per step of the busiest rank (mean over the same steps), %d "
                     "repeats alternately; each run waited (%.0f s at most) for the other work "
                     "to drop below 0.3 cores.\n" % (ranks["steps"], ranks["decomposition"],
                                                     ranks["steps"] - 1, ranks["repeats"],
                                                     QUIET_WAIT))
        lines.append("| scene | processors | ms/step wall, each repeat | ms/step CPU of the "
                     "busiest rank | other work before / during the run [cores] | load "
                     "average at the start |\n|---|---|---|---|---|---|")
        for variant, v in ranks["variants"].items():
            for np, rs in v["runs"].items():
                lines.append("| %s | %s | %s | %s | %s | %s |" % (
                    variant, np, ", ".join(ms(r["wall"]) for r in rs),
                    ", ".join(ms(r["cpu"]) for r in rs),
                    ", ".join("%.2f / %.2f" % (r["otherBefore"], r["otherDuring"]) for r in rs),
                    "; ".join(" ".join(r["loadAverage"]) for r in rs)))
        lines.append("")
        for variant, v in ranks["variants"].items():
            lines.append("**%s: speed-up np 1 / np 2 = %.2f** (wall; median of the repeats' "
                         "ratios: %s); of the least wall times %.2f (other work during those "
                         "runs %.2f and %.2f cores).\n"
                         % (variant, v["speedup"],
                            ", ".join("%.2f" % x for x in v["speedupAllRepeats"]),
                            v["speedupOfLeast"], v["otherDuringLeast"][0],
                            v["otherDuringLeast"][1]))
        lines.append("")
    with open(os.path.join(args.results, "coupledCloud.md"), "w") as out:
        out.write("\n".join(lines))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--suites", default="cost,ranks")
    ap.add_argument("--repeats", type=int, default=None)
    ap.add_argument("--build", required=True)
    ap.add_argument("--results", required=True)
    args = ap.parse_args()
    if args.repeats is None:
        args.repeats = 2 if args.quick else 3
    work = os.path.join(os.path.abspath(args.build), "coupledCloud")
    os.makedirs(args.results, exist_ok=True)
    result = {"machine": bench.machine(), "quick": args.quick, "suites": {}}
    result["date"] = result["machine"]["date"]
    for suite in args.suites.split(","):
        result["suites"][suite] = {"cost": suite_cost, "ranks": suite_ranks}[suite](args, work)
        result["suites"][suite]["loadAverageAtEnd"] = open("/proc/loadavg").read().split()[:3]
        write(args, result)


if __name__ == "__main__":
    main()
