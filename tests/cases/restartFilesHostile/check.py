"""Restart files that lie, or that a stopped run left cut; see run."""
import json
import os
import re
import shutil
import subprocess

import numpy as np

from riserfoam import cases, foamfields as ff
from riserfoam.checks import Checks

checks = Checks()
here = os.path.dirname(os.path.abspath(__file__))
MID, LATE, END, STEP = "0.007", "0.008", "0.009", "0.001"
CLOUD = "lagrangian/kinematicCloud"
SERIES = "postProcessing/vtkCloud/kinematicCloud.vtp.series"
PAIR_IDS = "collisionRecordsPairOrigIdOfOther"
PAIR_FIELDS = ("collisionRecordsPairAccessed", "collisionRecordsPairOrigProcOfOther",
               PAIR_IDS, "collisionRecordsPairData")
HISTORIES = ("historySteps", "historySlip0", "historyWindow", "historyTail")


def ok(condition, label):
    """a check of one's own: printed, counted when it fails"""
    print("%s: %s" % (label, "ok" if condition else "FAILED"))
    checks.failures += not condition


def control(case, entry, value):
    ff.set_nested(os.path.join(case, "system", "controlDict"), entry, value)


def solve(case, log):
    """riserParcelFoam on the case: (exit status 0, the log's text)"""
    path = os.path.join(case, log)
    text = cases.run(["riserParcelFoam", "-case", case], path, may_fail=True)
    return text is not None, open(path).read()


def copy(name, last=MID):
    """the whole run's case with its times up to last, to restart from the
    latest of them"""
    case = os.path.abspath(name)
    shutil.copytree(whole, case, ignore=lambda d, names: [
        n for n in names if d == whole and re.fullmatch(r"[0-9.e-]+", n)
        and float(n) > float(last)])
    control(case, "startFrom", "latestTime")
    return case


def refused(name, case, texts, log="log.restart"):
    """the restart of case must stop with an error holding every one of texts"""
    ran, text = solve(case, log)
    missing = [t for t in texts if t not in text]
    ok(not ran and not missing and "stack trace" not in text.lower(),
       "%s: refused%s" % (name, " lacking %s" % missing if missing else ""))
    for line in text.splitlines():
        if texts[0] in line:
            print("    " + line.strip()[:300])
            break
    if ran or missing:
        print("\n".join(text.splitlines()[-15:]))


# ------------------------------------------------------------ fields of fields
def field_items(path):
    """the text of a lagrangian field of fields in ascii: (its text, the
    offsets of the list's brackets, each particle's list as written)"""
    text = open(path).read()
    start = re.search(r"^\d+\s*\n\(", text, re.M).end() - 1
    end = ff.matching(text, start)
    body, items, k = text[start + 1:end], [], 0
    while True:
        while k < len(body) and body[k].isspace():
            k += 1
        if k >= len(body):
            break
        j = k
        while body[j].isdigit():
            j += 1
        e = ff.matching(body, j)
        items.append(body[k:e + 1])
        k = e + 1
    return text, start, end, items


def read_items(case, name):
    return field_items(os.path.join(case, MID, CLOUD, name))[3]


def write_items(case, name, items):
    path = os.path.join(case, MID, CLOUD, name)
    text, start, end, _ = field_items(path)
    open(path, "w").write(text[:start + 1] + "\n" + "\n".join(items) + "\n" + text[end:])


def elements(item):
    """the elements (as written) of one particle's list: n(a b ...) or n{a}"""
    n = int(re.match(r"\d+", item).group())
    inner = item[len(str(n)) + 1:-1]
    if item[len(str(n))] == "{":
        return [inner.strip()] * n
    return re.findall(r"\([^()]*\)|[^\s()]+", inner)


def list_of(values):
    return "%d(%s)" % (len(values), " ".join(values))


def ids(case):
    return [int(v) for v in ff.read_scalars(os.path.join(case, MID, CLOUD, "origId"))]


def particle(case, i):
    return "particle %d (origProcId 0, origId %d)" % (i, ids(case)[i])


# ------------------------------------------------------------------ the run
whole = os.path.abspath("whole")
cases.dense_shaken_section(whole, END, write_interval=STEP)
control(whole, "functions",
        '{ vtkCloud { type vtkCloud; libs ("liblagrangianFunctionObjects.so");'
        ' cloud kinematicCloud; writeControl writeTime; } }')
ran, log = solve(whole, "log.riserParcelFoam")
ok(ran, "whole: ran 0 -> %s s" % END)
partners = [elements(item) for item in read_items(whole, PAIR_IDS)]
inProgress = [elements(item) for item in read_items(whole, "pairContactsInProgress")]
nRecords = sum(len(p) for p in partners)
ok(nRecords > 0 and sum(len(p) for p in inProgress) == 6 * nRecords,
   "whole: at %s s %d pair collision records, each with its record in progress"
   % (MID, nRecords))

# ------------------------------------------------------- contact records
origIds = ids(whole)
withPairs = [i for i, p in enumerate(partners) if p]
first = withPairs[0]

case = copy("partner9999")
spoilt = read_items(case, PAIR_IDS)
spoilt[first] = list_of(["9999"] + partners[first][1:])
write_items(case, PAIR_IDS, spoilt)
refused("partner9999", case,
        [particle(case, first), PAIR_IDS,
         "holds a pair collision record with the particle (origProcId 0, origId 9999),"
         " which is not in the cloud (its %d particles at this time" % len(origIds)])

# two ores that touch neither each other nor each other's partners swap
# their records
first_partners = {int(v) for v in partners[first]}
other = next(j for j in withPairs[1:]
             if origIds[j] not in first_partners
             and not {int(v) for v in partners[j]} & (first_partners | {origIds[first]}))
ok(True, "swapped: the records of %s and %s" % (particle(whole, first), particle(whole, other)))
case = copy("swapped")
for name in PAIR_FIELDS + ("pairContactsInProgress",):
    spoilt = read_items(case, name)
    spoilt[first], spoilt[other] = spoilt[other], spoilt[first]
    write_items(case, name, spoilt)
refused("swapped", case,
        ["Cloud kinematicCloud at time %s: particle " % MID, PAIR_IDS,
         "which holds none with it: both particles of a contact keep its record"])

case = copy("shortened")
spoilt = read_items(case, "collisionRecordsPairData")
data = elements(spoilt[first])
spoilt[first] = list_of(data[:-1])
write_items(case, "collisionRecordsPairData", spoilt)
refused("shortened", case,
        [particle(case, first),
         'collisionRecordsPairData" holds %d pair collision records, but %d in %s'
         % (len(data) - 1, len(data), PAIR_IDS)])

walls = [elements(item) for item in read_items(whole, "collisionRecordsWallPRel")]
atWall = next((i for i, w in enumerate(walls) if w), None)
ok(atWall is not None, "whole: a wall collision record at %s s" % MID)
if atWall is not None:
    case = copy("wallShortened")
    spoilt = read_items(case, "collisionRecordsWallPRel")
    spoilt[atWall] = list_of(walls[atWall][:-1])
    write_items(case, "collisionRecordsWallPRel", spoilt)
    refused("wallShortened", case,
            [particle(case, atWall),
             'collisionRecordsWallPRel" holds %d wall collision records, but %d in'
             " collisionRecordsWallAccessed" % (len(walls[atWall]) - 1, len(walls[atWall]))])

# a pair contact in progress named after an ore the particle keeps no
# record with
stranger = next(k for k in origIds if k != origIds[first] and k not in first_partners)
case = copy("inProgress")
spoilt = read_items(case, "pairContactsInProgress")
numbers = list(inProgress[first])
numbers[1] = str(stranger)
spoilt[first] = list_of(numbers)
write_items(case, "pairContactsInProgress", spoilt)
refused("inProgress", case,
        [particle(case, first), "pairContactsInProgress",
         "holds a pair contact in progress with the particle (origProcId 0, origId %d),"
         " but no pair collision record with it" % stranger])

# ------------------------------------------------------------------ the fill
for entry, value, was in (("seed", "2", "1"), ("solidsFraction", "0.1", "0.15")):
    case = copy("fill-" + entry)
    ff.set_nested(os.path.join(case, "constant", "kinematicCloudProperties"),
                  "subModels/injectionModels/ores/" + entry, value)
    refused("fill-" + entry, case,
            ["entry '%s' changed at a restart: %s here, %s in the fill made in the step"
             " that holds SOI = 0 (%d ores" % (entry, value, was, len(origIds)),
             "Restore the entry as it was, or start from a time before SOI"])

# ------------------------------------------------ warm: a stopped write
warm = copy("warm", last=LATE)
cut = os.path.join(warm, LATE, CLOUD, "U")
os.truncate(cut, os.path.getsize(cut) // 2)
wholeSeries = open(os.path.join(whole, SERIES)).read()
listed = json.loads(wholeSeries)["files"]
for entry in listed:
    if entry["time"] > float(LATE) + 1e-9:
        os.remove(os.path.join(warm, os.path.dirname(SERIES), entry["name"]))
# the series cut inside the name of its second file, as a stop in its
# rewrite at 0.003 s leaves it
second = wholeSeries.index('"name" : "', wholeSeries.index(listed[1]["name"]) - 12)
open(os.path.join(warm, SERIES), "w").write(wholeSeries[:second + 15])
refused("warm: from the half-written %s s" % LATE, warm,
        ["Time %s of " % LATE, "is incomplete", "The latest complete time is %s" % MID],
        log="log.refused")
shutil.rmtree(os.path.join(warm, LATE))
ran, text = solve(warm, "log.restart")
ok(ran, "warm: restarted from %s s with %s removed" % (MID, LATE))
ok("was cut short" in text and "placed" not in text and "nothing more to place" in text,
   "warm: the log says the series was written anew and the fill kept, not made")
if ran:
    for field, tol in (("positions", 1e-12), ("U", 1e-10)):
        a = np.array(ff.read_vectors(os.path.join(whole, END, CLOUD, field)))
        b = np.array(ff.read_vectors(os.path.join(warm, END, CLOUD, field)))
        ok(a.shape == b.shape, "warm: %d ores at %s s, whole run %d" % (len(b), END, len(a)))
        if a.shape == b.shape:
            checks.near("warm: largest %s difference" % field,
                        float(np.max(np.linalg.norm(a - b, axis=1))), 0.0, tol, 1.0)
    # (the restart's times are those of the time folders, the whole run's
    # the sums of its steps: equal to round-off)
    series = json.loads(open(os.path.join(warm, SERIES)).read())["files"]
    ok([e["name"] for e in series] == [e["name"] for e in listed]
       and all(abs(a["time"] - b["time"]) < 1e-12 for a, b in zip(series, listed)),
       "warm: %s lists the whole run's %d files at its times" % (SERIES, len(listed)))

# ------------------------------------------- cold: the histories removed
cold = copy("cold")
for name in HISTORIES:
    os.remove(os.path.join(cold, MID, CLOUD, name))
ran, text = solve(cold, "log.restart")
ok(ran and "no Basset histories written at %s; they start at the next step" % MID in text,
   "cold: restarted from %s s without the histories, the log says they start anew" % MID)
if ran:
    steps = round(float(MID) / 1e-4)
    def history_steps(case):
        path = os.path.join(case, END, CLOUD)
        return dict(zip(ff.read_scalars(os.path.join(path, "origId")),
                        ff.read_scalars(os.path.join(path, "historySteps"))))
    w, c = history_steps(whole), history_steps(cold)
    ok(w.keys() == c.keys() and all(w[k] - c[k] == steps for k in w),
       "cold: every ore's historySteps at %s s is the whole run's less %d (%d ores)"
       % (END, steps, len(c)))
partial = copy("coldInPart")
os.remove(os.path.join(partial, MID, CLOUD, "historyTail"))
refused("coldInPart: historyTail alone removed", partial,
        ["Time %s of " % MID, "is incomplete: file %s/historyTail of time %s is missing"
         % (CLOUD, ("%g" % (float(MID) - float(STEP))))])

# ------------------------------- escaped: contacts with ores that left
# an open riser (oreCase.sh: D = 0.1 m, L = 0.2 m, the ends open, ores
# escaping through them) filled at C_v = 0.2 with soft 8-12 mm ores, the
# carrier at 3 m/s carrying them out of the outlet, some in contact
escaped = os.path.abspath("escaped")
ESCAPE_END = "0.01"
subprocess.run(["bash", "-c", """
. "$1/oreCase.sh"
ore_case "$2" 6 'D 0.1; uCentre 3; A 0; f 0; carrier exact; frame riser;' \
    'wallCorrectedDrag { law paper; } riserAddedMass { CA 0.5; } riserFluidStress; gravity;' \
    'type riserFill; solidsFraction 0.2; seed 1; velocity carrier; gap 1e-4;
     sizeDistribution { type uniform; uniformDistribution { minValue 0.008; maxValue 0.012; } }' open
""", "-", os.path.join(here, ".."), escaped], check=True)
props = os.path.join(escaped, "constant", "kinematicCloudProperties")
for entry, value in (("constantProperties/youngsModulus", "1e7"),
                     ("subModels/riserContactCoeffs/stepsPerContact", "10"),
                     ("subModels/riserContactCoeffs/aloneAtWall", "meshFree"),
                     ("subModels/riserContactCoeffs/pairs",
                      "{ normalRestitution 0.5; tangentialRestitution 0.5; friction 0.3; }"),
                     ("cloudFunctions", "{}")):
    ff.set_nested(props, entry, value)
for entry, value in (("deltaT", "1e-4"), ("endTime", ESCAPE_END), ("writeControl", "timeStep"),
                     ("writeInterval", "1"), ("writeFormat", "ascii"), ("writePrecision", "17")):
    control(escaped, entry, value)
ran, text = solve(escaped, "log.riserParcelFoam")
# the steps (their end times) in which records were dropped
dropped = re.findall(r"^Time = (\S+)\n(?:(?!^Time = ).*\n)*?.*record\(s\) with particles that"
                     r" left the mesh dropped", text, re.M)
ok(ran and dropped, "escaped: records with ores that left dropped in the steps to %s"
   % ", ".join(dropped))
dangling = []
for time in sorted((t for t in os.listdir(escaped) if re.fullmatch(r"[0-9.e-]+", t)
                    and os.path.exists(os.path.join(escaped, t, CLOUD, "origId"))), key=float):
    folder = os.path.join(escaped, time, CLOUD)
    present = set(ff.read_scalars(os.path.join(folder, "origId")))
    dangling += [(time, o) for r in ff.read_lists(os.path.join(folder, PAIR_IDS))
                 for o in r if o not in present]
ok(not dangling, "escaped: every pair record of every written time names an ore of"
                 " that time%s" % (": not %s" % dangling[:3] if dangling else ""))
if ran and dropped:
    restart = os.path.abspath("escapedRestart")
    shutil.copytree(escaped, restart, ignore=lambda d, names: [
        n for n in names if d == escaped and re.fullmatch(r"[0-9.e-]+", n)
        and float(n) > float(dropped[0])])
    control(restart, "startFrom", "latestTime")
    ran, text = solve(restart, "log.restart")
    ok(ran, "escapedRestart: restarted from %s s, right after the drop" % dropped[0])
    if ran:
        def state(case, field):
            folder = os.path.join(case, ESCAPE_END, CLOUD)
            order = np.argsort(ff.read_scalars(os.path.join(folder, "origId")))
            return np.array(ff.read_vectors(os.path.join(folder, field)))[order]
        for field, tol in (("positions", 1e-12), ("U", 1e-10)):
            a, b = state(escaped, field), state(restart, field)
            ok(a.shape == b.shape, "escapedRestart: %d ores at %s s, whole run %d"
               % (len(b), ESCAPE_END, len(a)))
            if a.shape == b.shape:
                checks.near("escapedRestart: largest %s difference" % field,
                            float(np.max(np.linalg.norm(a - b, axis=1))), 0.0, tol, 1.0)
checks.exit()
