"""The cost of riserParcelFoam cases per particle-step, as ratios to a
baseline case measured in the same round, the cases run in turn (the
validations' cost benchmarks: riserMotionCost/cloudCost.py,
carrierCost/carrierCost.py). The cost of a run is the solver's execution
time from its first step to its last over the sum of the particles in the
cloud at each step.

SPDX-License-Identifier: GPL-3.0-or-later
"""
import os
import re
import shutil
import statistics

from riserfoam import cases
from riserfoam import foamfields as ff


def ore_transport_section(case, end):
    """the scene of the cloud cost benchmarks that vary a model of the
    tutorial oreTransport: its ores (about 10 mm, wall and pair contacts,
    riser frame, exact carrier, 0.1 m at 3 Hz) in a 1 m periodic section of
    D = 0.1 m filled at C_v = 0.01 (149 ores), no cloud functions, run to
    the end time end [s] and written there; the case's cloud properties
    file is returned for the benchmark's own edits"""
    cases.copy_tutorial("riser/oreTransport", case)
    cloud = os.path.join(case, "constant/kinematicCloudProperties")
    ff.set_nested(cloud, "subModels/injectionModels/ores/solidsFraction", "0.01")
    ff.set_nested(cloud, "cloudFunctions", "{}")
    control = os.path.join(case, "system/controlDict")
    ff.set_entry(control, "endTime", repr(end))
    ff.set_entry(control, "writeInterval", repr(end))
    cases.riser_mesh(case, 0.1, 1.0, 8, ends="cyclic")
    return cloud


def run(case):
    """riserParcelFoam on case from its start (later times removed): the
    seconds from the first step to the last, particle-steps, parcels"""
    for folder in os.listdir(case):
        if re.fullmatch(r"[0-9.e+-]+", folder) and float(folder) > 0:
            shutil.rmtree(os.path.join(case, folder))
    log = cases.run(["riserParcelFoam", "-case", case], os.path.join(case, "log.riserParcelFoam"))
    times = [float(x) for x in re.findall(r"^ExecutionTime = (\S+) s", log, re.M)]
    counts = [int(x) for x in re.findall(r"Current number of parcels\s+= (\d+)", log)]
    return times[-1] - times[0], sum(counts[1:]), counts[-1]


def rounds(folders, baseline, count):
    """count rounds of every case of folders ({name: case}) in turn: each
    case's cost per particle-step over the baseline's of the same round
    ({name: [ratios]}), and each case's parcels at its end"""
    ratios = {name: [] for name in folders}
    parcels = {}
    for round_ in range(count):
        perStep = {}
        for name, case in folders.items():
            seconds, particleSteps, parcels[name] = run(case)
            perStep[name] = seconds / particleSteps
        for name in folders:
            ratios[name].append(perStep[name] / perStep[baseline])
        print("round %d: per particle-step %s" % (round_, ", ".join(
            "%s %.3g us" % (k, 1e6 * v) for k, v in perStep.items())), flush=True)
    return ratios, parcels


def write(path, header, ratios, parcels):
    """the ratios' median, min and max per case under the header's lines,
    to path (its folder made), and printed"""
    os.makedirs(os.path.dirname(path) or ".", exist_ok=True)
    with open(path, "w") as out:
        out.write(header)
        for name, r in ratios.items():
            out.write("%s %d %.3f %.3f %.3f\n"
                      % (name, parcels[name], statistics.median(r), min(r), max(r)))
    print(open(path).read())
