"""The one-way turbulent carriers against the two-way coupled RAS run (see
Allrun).

usage: oneWay.py <work folder>"""
import os
import shutil
import subprocess
import sys

from riserfoam.cli import help_requested  # noqa: E402

help_requested(__doc__)

import numpy as np

from riserfoam import cases, foamfields as ff, tables

root = os.path.abspath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
work = os.path.abspath(sys.argv[1])
CV, START, END = 0.01, 2.5, 4.5
STATS = "postProcessing/lagrangian/kinematicCloud/riserTransportStatistics/transport.dat"


def coupled(name="coupled", hindered=True):
    """the tutorial at C_v (kept from an earlier run); without hindered,
    its drag without the suspension's voidage function"""
    case = os.path.join(work, name)
    if os.path.isfile(os.path.join(case, STATS)):
        return case
    shutil.rmtree(case, ignore_errors=True)
    shutil.copytree(os.path.join(root, "tutorials/riser/oreTransportCoupled"), case)
    subprocess.run([os.path.join(case, "Allclean")], check=True)
    cloud = os.path.join(case, "constant/kinematicCloudProperties")
    ff.set_nested(cloud, "subModels/injectionModels/ores/solidsFraction", repr(CV))
    if not hindered:
        ff.remove_entry(cloud, "subModels/particleForces/wallCorrectedDrag/voidage")
    done = subprocess.run([os.path.join(case, "Allrun")], stdout=subprocess.DEVNULL,
                          stderr=subprocess.STDOUT)
    if done.returncode != 0 or not os.path.isfile(os.path.join(case, STATS)):
        sys.exit("oneWay.py: the coupled run failed (%s/log.riserCoupledFoam)" % case)
    return case


def one_way(name, source, carrier, dispersion):
    case = os.path.join(work, name)
    shutil.rmtree(case, ignore_errors=True)
    os.makedirs(case)
    for folder in ("constant", "system"):
        shutil.copytree(os.path.join(source, folder), os.path.join(case, folder))
    shutil.copytree(os.path.join(source, "0"), os.path.join(case, "0"))
    for dictionary in ("fvSolution", "fvSchemes"):   # the one-way solver's: no carrier to solve
        shutil.copy(os.path.join(root, "tutorials/riser/oreTransport/system", dictionary),
                    os.path.join(case, "system", dictionary))
    for extra in ("turbulenceProperties",):
        os.remove(os.path.join(case, "constant", extra))
    for field in os.listdir(os.path.join(case, "0")):
        if field not in ("U",):
            path = os.path.join(case, "0", field)
            shutil.rmtree(path) if os.path.isdir(path) else os.remove(path)
    riser = os.path.join(case, "constant/riserProperties")
    for key in ("drive", "uCentre", "carrier"):
        ff.remove_entry(riser, key)
    with open(riser, "a") as out:
        out.write("carrier exact;\n%s\n" % carrier)
    cloud = os.path.join(case, "constant/kinematicCloudProperties")
    ff.set_nested(cloud, "solution/coupled", "false")
    for key in ("solution/sourceTerms", "kernel",
                "subModels/particleForces/wallCorrectedDrag/voidage"):
        ff.remove_entry(cloud, key)
    ff.set_nested(cloud, "subModels/dispersionModel", dispersion)
    control = os.path.join(case, "system/controlDict")
    ff.set_entry(control, "application", "riserParcelFoam")
    ff.set_nested(control, "libs", '("libriserLagrangian.so")')
    ff.remove_entry(control, "functions")
    cases.run(["riserParcelFoam", "-case", case], os.path.join(case, "log.riserParcelFoam"))
    return case


def means(case):
    t = tables.read(os.path.join(case, STATS))
    late = (np.asarray(t["t"]) >= START - 1e-9) & (np.asarray(t["t"]) <= END + 1e-9)
    return float(np.mean(np.asarray(t["Urz"])[late])), float(np.mean(np.asarray(t["slipz"])[late]))


os.makedirs(work, exist_ok=True)
source = coupled()
cases.run(["riserCarrierProfile", "-time", "1.5", "-case", source],
          os.path.join(source, "log.riserCarrierProfile"))
profile = os.path.join(source, "constant/riserCarrierProfile")
runs = {"coupled": source,
        "turbulent": one_way("turbulent", source, "profile turbulent;\nuBulk 1;", "none")}
tab = one_way("tabulated", source,
              'profile tabulated;\nprofileFile "%s";' % profile, "langevinDispersionRAS")
runs["tabulated"] = tab
runs["coupledNoVoidage"] = coupled("coupledNoVoidage", hindered=False)
rows = {name: means(case) for name, case in runs.items()}
os.makedirs("results", exist_ok=True)
with open("results/oneWay.dat", "w") as out:
    out.write("# the scene of oreTransportCoupled at C_v = %g, Re = 1e5: means over %g to %g s"
              " of riserTransportStatistics' transport.dat\n"
              "# run Urz[m/s] slipz[m/s] Urz/coupled slipz/coupled\n" % (CV, START, END))
    for name, (u, s) in rows.items():
        out.write("%s %.4f %.4f %.4f %.4f\n" % (name, u, s, u / rows["coupled"][0], s / rows["coupled"][1]))
print(open("results/oneWay.dat").read())
