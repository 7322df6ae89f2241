"""The motion models' cost in riserParticle per force evaluation and per
particle-step, as ratios to the sinusoid's measured in the same round (see
Allrun). The steps differ between the motions (the adaptive integrator
follows each riser's physics), so both are given."""
import math
import os
import re
import statistics
import sys

from riserfoam import cases, foamfields as ff

work = os.path.abspath(sys.argv[1])
os.makedirs(work, exist_ok=True)
END, L, A, F = 60.0, 100.0, 0.1, 0.5
MOTIONS = {
    "sinusoid": "{ type sinusoid; A %r; f %r; }" % (A, F),
    "modes": "{ type modes; foot 0; length %r; x ((3 %r %r 0)); }" % (L, A, F),
    "table": '{ type table; file "constant/riserMotion.csv"; }',
}


def write_table(case):
    heights = [0.5 * i for i in range(201)]
    with open(os.path.join(case, "constant/riserMotion.csv"), "w") as out:
        out.write("t z x y\n")
        for j in range(3001):
            t = 0.02 * j
            for z in heights:
                x = A * math.sin(3 * math.pi * z / L) * math.sin(2 * math.pi * F * t)
                out.write("%.10g %.10g %.17g 0\n" % (t, z, x))


def make(name):
    case = os.path.join(work, name)
    cases.copy_tutorial("riser/oscillatingNoContact", case)
    riser = cases.set_motion(case, MOTIONS[name])
    ff.set_nested(riser, "frame", "lab")
    # the ore 25 m up the riser (where mode 3 moves: 0.1 |sin(3 pi z/L)|)
    ff.write_dictionary(os.path.join(case, "constant/kinematicCloudPositions"),
                        "((0.02 0.02 25))\n", "vectorField")
    ff.set_entry(os.path.join(case, "system/controlDict"), "endTime", repr(END))
    ff.set_entry(os.path.join(case, "system/controlDict"), "deltaT", "0.1")
    if name == "table":
        write_table(case)
    return case


def run(case):
    log = cases.run(["riserParticle", "-case", case], os.path.join(case, "log.run"))
    m = re.search(r"(\d+) steps \(\d+ rejected, \d+ in contact\), (\d+) force evaluations,"
                  r" \S+ s \((\S+) s integrating", log)
    return int(m.group(1)), int(m.group(2)), float(m.group(3))


folders = {name: make(name) for name in MOTIONS}
ratios = {name: [] for name in MOTIONS}
stepRatios = {name: [] for name in MOTIONS}
counts = {}
for round_ in range(5):
    perEvaluation, perStep = {}, {}
    for name in MOTIONS:
        steps, n, t = run(folders[name])
        counts[name] = (steps, n)
        perEvaluation[name] = t / n
        perStep[name] = t / steps
    for name in MOTIONS:
        ratios[name].append(perEvaluation[name] / perEvaluation["sinusoid"])
        stepRatios[name].append(perStep[name] / perStep["sinusoid"])
    print("round %d: per evaluation %s" % (round_, ", ".join(
        "%s %.3g us" % (k, 1e6 * v) for k, v in perEvaluation.items())))
os.makedirs("results", exist_ok=True)
with open("results/cost.dat", "w") as out:
    out.write("# riserParticle, one ore, 60 s: integration time per force evaluation and per"
              " step as ratios to the sinusoid's of the same round (5 rounds)\n"
              "# motion steps force_evaluations per_evaluation(median min max)"
              " per_step(median min max)\n")
    for name in MOTIONS:
        r, q = ratios[name], stepRatios[name]
        out.write("%s %d %d %.3f %.3f %.3f %.3f %.3f %.3f\n"
                  % ((name,) + counts[name] + (statistics.median(r), min(r), max(r),
                                               statistics.median(q), min(q), max(q))))
print(open("results/cost.dat").read())
