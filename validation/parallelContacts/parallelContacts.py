"""1,000 shaken ores with wall and pair contact on 1, 2 and 4 processors.

1. The dense shaken section of the contact tests (cases.dense_shaken_section:
   10 mm ores filled at C_v = 0.15, soft ores and wall, E = 1e7 Pa, so that
   a contact lasts a few flow steps; A = 0.2 m, f = 4 Hz from the largest
   acceleration; every contact sub-stepped without the mesh), lengthened to
   0.45 m so that it holds about 1,000 ores: 200 steps from the fill
   serially, on 2 processors (the section split along z, across its cyclic
   ends) and on 4 (split along x and z, oversubscribed on a 2-core
   machine). Every ore's position, velocity and spin, its tangential
   springs (pair and wall: the collision records) and every completed wall
   contact's row of contacts.dat against the serial run's (the ores matched
   by position: each processor numbers the ores it injects). A run on N
   processors sums a particle's contact forces in another order, so the
   differences are of round-off; a pair missed or evaluated twice at a
   processor boundary would change a velocity by ~0.1 m/s.
2. The wall-and-pair scene of benchmarks/oreCloud.py (10 mm ores of
   2000 kg/m^3 at C_v = 0.05 in a section of D = 0.1 m that holds 1,000 of
   them, riserMesh -n 4 with 2.5 cm cells along; riser frame, exact
   carrier, the flagship's forces with Basset; A = 0.2 m, f = 4 Hz;
   dt = 1e-4 s; stepsPerContact 10; the ore's default stiffness), shaken
   serially for 0.08 s, by when most ores are in clusters or at the wall.
   Its contacts are stiff and many, so the flow itself amplifies a
   difference of round-off about tenfold a millisecond: from that state,
   one step serially and on 2 processors (the first step's differences:
   round-off), then 200 steps serially, on 2 processors and serially with
   the one ore that differed after the first step given that step's
   difference of velocity at the start. The parallel run's difference from
   the serial one grows as the perturbed serial run's does: it is
   round-off, amplified by the flow, not a contact missed.
3. The same state run 0.5 s serially and on 2 processors: the transport
   statistics (riserTransportStatistics, a sample every 5 ms), the steady
   mean of each column with its standard error (10 batch means,
   python/riserfoam/steady.py) and the difference of the two runs' means
   in units of their combined error (|z| < 3: the runs are two samples of
   the same flow).

In every run the ores are counted at its start and end (no ore may be
lost) and the log's reports of ores outside the pipe must be none.

usage: parallelContacts.py <work folder> <results folder>
writes <results>/parallelContacts.json and <results>/summary.md
License: GPL-3.0-or-later
"""
import datetime
import glob
import json
import math
import os
import re
import shutil
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "..", "benchmarks"))
import oreCloud  # noqa: E402  (the 1,000-ore scene)

from riserfoam import cases, steady, tables  # noqa: E402
from riserfoam import foamfields as ff  # noqa: E402

work, results = sys.argv[1:3]
os.makedirs(results, exist_ok=True)
N, CV, DT, SPIN_UP, STEPS, LONG, SAMPLE = 1000, 0.05, 1e-4, 0.08, 200, 0.5, 0.005
SOFT_LENGTH = 0.45
CLOUD = os.path.join("lagrangian", "kinematicCloud")
SPLITS = {"serial": None, "2 processors": (1, 1, 2), "4 processors": (2, 1, 2)}
COLUMNS = ("liftingEfficiency", "slipz", "contactRate", "pairContactRate", "pairImpactSpeedMean")
failures = []


def time_name(t):
    return "%g" % round(t, 10)


def parcels(log):
    return [int(n) for n in re.findall(r"Current number of parcels\s*=\s*(\d+)", log)]


def solve(case, split, end, expected=None):
    """the case run on from its latest time to end, serially or split (and
    reconstructed with its contacts in progress and collision records); the
    log. The ores at its first and last step must be expected (if given),
    and none outside the pipe."""
    ff.set_nested(os.path.join(case, "system", "controlDict"), "endTime", repr(end))
    if split:
        log = cases.run_parallel(case, "riserParcelFoam", split)
        cases.run(["reconstructPar", "-lagrangianFields", "(\".*\")", "-case", case],
                  os.path.join(case, "log.reconstructPar"))
    else:
        log = cases.run(["riserParcelFoam", "-case", case], os.path.join(case, "log.riserParcelFoam"))
    counts, outside = parcels(log), log.count("outside the pipe")
    name = os.path.basename(case)
    if outside:
        failures.append("%s: %d reports of ores outside the pipe" % (name, outside))
    if expected is not None and (counts[0] != expected or counts[-1] != expected):
        failures.append("%s: ores %d -> %d, %d expected" % (name, counts[0], counts[-1], expected))
    return log


def keys(folder):
    return list(zip((int(v) for v in ff.read_scalars(os.path.join(folder, "origProcId"))),
                    (int(v) for v in ff.read_scalars(os.path.join(folder, "origId")))))


def motion(case, t):
    """by ore (origProcId, origId): position and velocity at t"""
    folder = os.path.join(case, time_name(t), CLOUD)
    return dict(zip(keys(folder), zip(ff.read_vectors(os.path.join(folder, "positions")),
                                      ff.read_vectors(os.path.join(folder, "U")))))


def state(case, t):
    """by ore (origProcId, origId): position, velocity, spin, the pair
    springs by the other ore's key, the wall springs"""
    folder = os.path.join(case, time_name(t), CLOUD)
    x = ff.read_vectors(os.path.join(folder, "positions"))
    U = ff.read_vectors(os.path.join(folder, "U"))
    spin = ff.read_vectors(os.path.join(folder, "angularMomentum"))
    springs = ff.read_lists(os.path.join(folder, "collisionRecordsPairData"), 3)
    otherProc = ff.read_lists(os.path.join(folder, "collisionRecordsPairOrigProcOfOther"))
    otherId = ff.read_lists(os.path.join(folder, "collisionRecordsPairOrigIdOfOther"))
    wall = ff.read_lists(os.path.join(folder, "collisionRecordsWallData"), 3)
    ores = {}
    for i, key in enumerate(keys(folder)):
        pairs = {(int(p), int(q)): s for p, q, s in zip(otherProc[i], otherId[i], springs[i])}
        ores[key] = dict(x=x[i], U=U[i], spin=spin[i], pairs=pairs, wall=wall[i])
    return ores


def rows(case):
    """every processor's completed wall contacts (contacts*.dat)"""
    found = []
    for path in glob.glob(os.path.join(case, "postProcessing", CLOUD, "riserContact",
                                       "contacts*.dat")):
        t = tables.read(path)
        if len(t):
            found += [list(r) for r in t.matrix(*t.names)]
    return found


def largest(pairs):
    return max([math.dist(a, b) for a, b in pairs] or [0.0])


def renamed(ores, table, serial):
    """ores and rows of a parallel run under the serial run's keys (the ores
    matched by position: each processor numbers the ores it injects), or
    None when the positions do not match one to one"""
    mine = sorted(ores, key=lambda k: ores[k]["x"])
    theirs = sorted(serial, key=lambda k: serial[k]["x"])
    if len(mine) != len(theirs) or any(math.dist(ores[a]["x"], serial[b]["x"]) > 1e-9
                                       for a, b in zip(mine, theirs)):
        return None, None
    name = dict(zip(mine, theirs))
    out = {}
    for k, o in ores.items():
        out[name[k]] = dict(o, pairs={name[p]: s for p, s in o["pairs"].items()})
    table = sorted([list(name[(int(r[0]), int(r[1]))]) + r[2:] for r in table])
    return out, table


# 1. the soft dense section, 200 steps from the fill
soft = {}
end = STEPS * DT
for name, split in SPLITS.items():
    case = os.path.join(work, "soft_" + name.replace(" ", "_"))
    shutil.rmtree(case, ignore_errors=True)
    cases.dense_shaken_section(case, time_name(end), L=SOFT_LENGTH)
    log = solve(case, split, end)
    across = [int(m) for m in re.findall(r"(\d+) across processor", log)]
    soft[name] = dict(ores=state(case, end), rows=rows(case), injected=parcels(log)[-1],
                      across_max=max(across or [0]),
                      across_steps=sum(1 for n in across if n))
serial = soft["serial"]
serial["rows"] = sorted(serial["rows"])
result = dict(date=datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC"),
              load=open("/proc/loadavg").read().split()[:3],
              soft=dict(ores=serial["injected"], section_m=SOFT_LENGTH,
                        pair_contacts=sum(len(o["pairs"]) for o in serial["ores"].values()) // 2,
                        wall_contacts=sum(len(o["wall"]) for o in serial["ores"].values()),
                        rows=len(serial["rows"])))
print("soft section: %d ores, %d pair and %d wall contacts in progress at the end, %d rows"
      % (result["soft"]["ores"], result["soft"]["pair_contacts"], result["soft"]["wall_contacts"],
         result["soft"]["rows"]))
for name in ("2 processors", "4 processors"):
    run = soft[name]
    ores, table = renamed(run["ores"], run["rows"], serial["ores"])
    c = dict(across_max=run["across_max"], across_steps=run["across_steps"],
             injected=run["injected"])
    if ores is None:
        failures.append("soft section, %s: the ores' positions do not match the serial run's" % name)
    else:
        a = serial["ores"]
        same_pairs = all(sorted(a[k]["pairs"]) == sorted(ores[k]["pairs"]) for k in a)
        same_walls = all(len(a[k]["wall"]) == len(ores[k]["wall"]) for k in a)
        c.update(dx=largest((a[k]["x"], ores[k]["x"]) for k in a),
                 dU=largest((a[k]["U"], ores[k]["U"]) for k in a),
                 dspin=largest((a[k]["spin"], ores[k]["spin"]) for k in a),
                 same_pairs=same_pairs, same_walls=same_walls, rows=len(table),
                 same_rows=len(table) == len(serial["rows"]) and all(
                     r[:2] == q[:2] for r, q in zip(table, serial["rows"])))
        if same_pairs:
            c["dpair_spring"] = largest((a[k]["pairs"][o], ores[k]["pairs"][o])
                                        for k in a for o in a[k]["pairs"])
        if same_walls:
            c["dwall_spring"] = largest(p for k in a for p in zip(a[k]["wall"], ores[k]["wall"]))
        if c["same_rows"]:
            c["drow"] = max([abs(x - y) for r, q in zip(table, serial["rows"])
                             for x, y in zip(r[2:], q[2:])] or [0.0])
        # round-off: 1e-12 m and 1e-10 m/s, far below what a contact does
        # (~0.1 m/s) and above a reordered sum's (riserParallelPairs: 6e-17
        # m and 2e-14 m/s)
        if not (same_pairs and same_walls and c["same_rows"]):
            failures.append("soft section, %s: the contacts differ from the serial run's" % name)
        elif max(c["dx"], c["dpair_spring"], c["dwall_spring"]) > 1e-12 \
                or max(c["dU"], c["dspin"], c["drow"]) > 1e-10:
            failures.append("soft section, %s: differs from the serial run beyond round-off" % name)
        if run["across_steps"] < 10:
            failures.append("soft section, %s: pairs across processors in %d steps only: blind"
                            % (name, run["across_steps"]))
    result["soft"][name] = c
    print("soft section,", name, c)

# 2. the oreCloud scene: the dense state
base = os.path.join(work, "spunUp")
shutil.rmtree(base, ignore_errors=True)
L = oreCloud.section_length(N, CV)
collision, pairs, alone = oreCloud.VARIANTS["wall+pairs"]
oreCloud.make(base, SPIN_UP, 0.2, 4.0, collision, pairs, alone, L=L, n=4,
              nz=max(4, int(round(L / 0.025))), Cv=CV)
ff.set_nested(os.path.join(base, "constant", "kinematicCloudProperties"), "cloudFunctions",
              "{ statistics { type riserTransportStatistics; interval %g; } }" % SAMPLE)
ff.set_nested(os.path.join(base, "system", "controlDict"), "writePrecision", "17")
log = solve(base, None, SPIN_UP)
spun = parcels(log)[-1]
clustered = [int(c) for c in re.findall(r"(\d+) particle\(s\) in clusters or alone", log)]
result["stiff"] = dict(ores=spun, section_m=L, clustered=clustered[-1] if clustered else 0)
print("spun up: %d ores, %d in clusters or at the wall in the last step"
      % (spun, result["stiff"]["clustered"]))


def from_state(name, end, write):
    case = os.path.join(work, name.replace(" ", "_"))
    shutil.rmtree(case, ignore_errors=True)
    shutil.copytree(base, case)
    shutil.rmtree(os.path.join(case, "postProcessing"), ignore_errors=True)
    control = os.path.join(case, "system", "controlDict")
    ff.set_nested(control, "startFrom", "latestTime")
    ff.set_nested(control, "writeInterval", time_name(write))
    return case


def differences(a, b, t):
    A, B = motion(a, t), motion(b, t)
    return (max(math.dist(A[k][0], B[k][0]) for k in A),
            max(math.dist(A[k][1], B[k][1]) for k in A))


# the first step: which ore differs, by how much
first = SPIN_UP + DT
for name in ("serial", "2 processors"):
    solve(from_state("first " + name, first, DT), SPLITS[name], first, spun)
A = motion(os.path.join(work, "first_serial"), first)
B = motion(os.path.join(work, "first_2_processors"), first)
ore = max(A, key=lambda k: math.dist(A[k][1], B[k][1]))
dU = [b - a for a, b in zip(A[ore][1], B[ore][1])]
result["stiff"]["first_step"] = dict(dx=differences(os.path.join(work, "first_serial"),
                                                    os.path.join(work, "first_2_processors"),
                                                    first)[0],
                                     dU=math.dist(A[ore][1], B[ore][1]), ore=list(ore),
                                     ores_differing=sum(1 for k in A if A[k] != B[k]))
print("first step:", result["stiff"]["first_step"])
# round-off of a velocity of order 0.1-1 m/s, summed over a few contacts
if result["stiff"]["first_step"]["dU"] > 1e-11 or result["stiff"]["first_step"]["dx"] > 1e-14:
    failures.append("the first step on 2 processors differs from the serial one beyond round-off")

# 200 steps: serial, 2 processors, serial perturbed by the first step's difference
end = SPIN_UP + STEPS * DT
write = 10 * DT
cases_ = {}
for name in ("serial", "2 processors", "serial perturbed"):
    case = from_state("stiff " + name, end, write)
    if name == "serial perturbed":
        path = os.path.join(case, time_name(SPIN_UP), CLOUD, "U")
        folder = os.path.dirname(path)
        i = keys(folder).index(ore)
        U = ff.read_vectors(path)
        U[i] = tuple(u + d for u, d in zip(U[i], dU))
        text = open(path).read()
        start = text.index("(", text.index("FoamFile") + 200)
        open(path, "w").write(text[:start] + "(\n" + "".join(
            "(%.17g %.17g %.17g)\n" % u for u in U) + ")\n\n\n// " + "*" * 73 + " //\n")
    solve(case, SPLITS.get(name), end, spun)
    cases_[name] = case
growth = []
for k in range(1, STEPS // 10 + 1):
    t = SPIN_UP + 10 * k * DT
    growth.append(dict(t=round(t, 10),
                       parallel=differences(cases_["serial"], cases_["2 processors"], t),
                       perturbed=differences(cases_["serial"], cases_["serial perturbed"], t)))
result["stiff"]["growth"] = growth
last = growth[-1]
ratio = last["parallel"][0] / max(last["perturbed"][0], 1e-300)
result["stiff"]["ratio_at_end"] = ratio
print("after %d steps: parallel %.2e m, perturbed serial %.2e m" % (STEPS, last["parallel"][0],
                                                                    last["perturbed"][0]))
# two samples of chaotic growth over some twelve decades: their logs agree
# within two decades if the parallel run's difference is the round-off
# the flow amplifies (a contact missed would start at ~0.1 m/s)
if not 1e-2 < ratio < 1e2:
    failures.append("after %d steps the parallel difference is %.2g times the perturbed serial's"
                    % (STEPS, ratio))

# 3. 0.5 s
end = SPIN_UP + LONG
series, means = {}, {}
result["long"] = {}
for name in ("serial", "2 processors"):
    case = from_state("long " + name, end, LONG)
    solve(case, SPLITS[name], end, spun)
    t = tables.read(os.path.join(case, "postProcessing", CLOUD, "riserTransportStatistics",
                                 "transport.dat"))
    series[name] = t
    means[name] = {c: steady.steady_mean(t.column("t"), t.column(c), start_time=SPIN_UP + SAMPLE)
                   for c in COLUMNS}
    result["long"][name] = {c: dict(mean=m["mean"], se=m["se"], lag1=m["lag1"],
                                    samples=m["samples"]) for c, m in means[name].items()}
# the runs share the riser's forcing, which makes most of each series' swing
# over two of its periods: the difference of the two series sample by
# sample is what the runs' parting leaves, and its mean over its batch
# means' error is the test (paired); the unpaired difference is reported
result["long"]["z"], result["long"]["paired"] = {}, {}
a_t, b_t = series["serial"].column("t"), series["2 processors"].column("t")
if len(a_t) != len(b_t) or np.max(np.abs(a_t - b_t)) > 1e-9:
    failures.append("the two runs' transport statistics were not sampled at the same times")
else:
    for c in COLUMNS:
        a, b = means["serial"][c], means["2 processors"][c]
        result["long"]["z"][c] = (b["mean"] - a["mean"]) / math.hypot(a["se"], b["se"])
        d = series["2 processors"].column(c)[1:] - series["serial"].column(c)[1:]
        mean, se, lag1, _ = steady.batch_means(d)
        z = mean / se if se > 0 else (0.0 if mean == 0 else math.inf)
        result["long"]["paired"][c] = dict(mean=mean, se=se, lag1=lag1, z=z)
        if not abs(z) < 3:
            failures.append("%s: the 2 processors' series less the serial one: mean %.3g, "
                            "%.1f times its error" % (c, mean, z))
result["failures"] = failures

with open(os.path.join(results, "parallelContacts.json"), "w") as out:
    json.dump(result, out, indent=1)
with open(os.path.join(results, "summary.md"), "w") as out:
    out.write("# 1,000 shaken ores with wall and pair contact on 1, 2 and 4 processors\n\n")
    out.write("Measured %s (validation/parallelContacts; load average %s).\n\n"
              % (result["date"], " ".join(result["load"])))
    s = result["soft"]
    out.write("## 1. The soft dense section: %d steps from the fill\n\n" % STEPS)
    out.write("%d ores in %.2f m at C_v = 0.15, E = 1e7 Pa. The serial run at the end: %d pair and "
              "%d wall contacts in progress, %d completed wall contacts. Largest differences from "
              "the serial run:\n\n" % (s["ores"], SOFT_LENGTH, s["pair_contacts"],
                                        s["wall_contacts"], s["rows"]))
    out.write("| run | steps with pairs across processors (most at once) | position [m] | "
              "velocity [m/s] | spin | pair springs [m] | wall springs [m] | rows of "
              "contacts.dat |\n|---|---|---|---|---|---|---|---|\n")
    for name in ("2 processors", "4 processors"):
        c = s[name]
        out.write("| %s | %d (%d) | %.1e | %.1e | %.1e | %.1e | %.1e | %s, %.1e |\n"
                  % (name, c["across_steps"], c["across_max"], c.get("dx", math.nan),
                     c.get("dU", math.nan), c.get("dspin", math.nan),
                     c.get("dpair_spring", math.nan), c.get("dwall_spring", math.nan),
                     c.get("rows", "-"), c.get("drow", math.nan)))
    t = result["stiff"]
    out.write("\n## 2. The oreCloud scene in its dense phase: %d steps\n\n" % STEPS)
    out.write("%d ores in %.3f m at C_v = %g, shaken %g s serially: %d in clusters or at the wall. "
              "After one step %d ores differ between serial and 2 processors, by at most %.1e m/s "
              "(positions %.1e m). The serial run perturbed by that difference of that ore's "
              "velocity, "
              "against the 2 processors' run, both against the serial run (largest position "
              "difference [m]):\n\n" % (t["ores"], L, CV, SPIN_UP, t["clustered"],
                                         t["first_step"]["ores_differing"],
                                         t["first_step"]["dU"], t["first_step"]["dx"]))
    out.write("| t [s] | 2 processors | serial perturbed |\n|---|---|---|\n")
    for g in growth[1::2]:
        out.write("| %.3f | %.1e | %.1e |\n" % (g["t"], g["parallel"][0], g["perturbed"][0]))
    out.write("\n## 3. Transport statistics over %g s, serial and 2 processors\n\n" % LONG)
    out.write("Means of the samples after the start (the state is already dense), standard "
              "errors by 10 batch means. Over two riser periods most of each series' error is "
              "the riser's own swing, which both runs share: paired, the mean of the 2 "
              "processors' series less the serial one, over its own error (z).\n\n")
    out.write("| column | serial | 2 processors | unpaired z | paired difference | z |\n"
              "|---|---|---|---|---|---|\n")
    for c in COLUMNS:
        a, b = means["serial"][c], means["2 processors"][c]
        p = result["long"]["paired"].get(c, dict(mean=math.nan, se=math.nan, z=math.nan))
        out.write("| %s | %.5g +- %.2g | %.5g +- %.2g | %+.2f | %.2g +- %.2g | %+.2f |\n"
                  % (c, a["mean"], a["se"], b["mean"], b["se"], result["long"]["z"].get(c, math.nan),
                     p["mean"], p["se"], p["z"]))
    out.write("\nEvery run kept its ores (counted at its first and last step) and reported none "
              "outside the pipe.\n" if not any("ores" in f or "outside" in f for f in failures)
              else "\n")
    out.write("\n%s\n" % ("All checks hold." if not failures else
                          "Failed:\n\n" + "\n".join("- " + f for f in failures)))
print("\n".join(failures) if failures else "all checks hold")
sys.exit(1 if failures else 0)
