"""A riser case from its physical parameters; see run."""
import math
import os
import re
import subprocess
import sys

from riserfoam import foamfields as ff
from riserfoam.checks import Checks

root, work = sys.argv[1], sys.argv[2]
riser_case = os.path.join(root, "bin", "riserCase")
checks = Checks()

D, L, A, f, ub, dmin, dmax, rmin, rmax, N = 0.08, 0.4, 0.05, 2.0, 0.6, 0.006, 0.01, 2500.0, 3500.0, 60
case = os.path.join(work, "myRiser")
subprocess.run([riser_case, case, "-D", repr(D), "-L", repr(L), "-A", repr(A), "-f", repr(f),
                "-uBulk", repr(ub), "-dMin", repr(dmin), "-dMax", repr(dmax),
                "-rhoMin", repr(rmin), "-rhoMax", repr(rmax), "-N", str(N),
                "-periods", "1", "-n", "6"], check=True)
run = subprocess.run([os.path.join(case, "Allrun")], stdout=subprocess.PIPE,
                     stderr=subprocess.STDOUT, text=True)
print(run.stdout.strip())
if run.returncode != 0:
    print("FAILED: the case's Allrun exited with %d" % run.returncode)
    checks.failures += 1
    checks.exit()

log = open(os.path.join(case, "log.riserParcelFoam")).read()
if not log.rstrip().endswith("End") or not os.path.isdir(os.path.join(case, "0.5")):
    print("FAILED: the run did not reach the end of its period, 0.5 s")
    checks.failures += 1
written = [t for t in ("0.0625", "0.125", "0.1875", "0.25", "0.3125", "0.375", "0.4375", "0.5")
           if os.path.isdir(os.path.join(case, t))]
print("eight writes in the period: %s" % ("ok" if len(written) == 8 else "FAILED: %s" % written))
checks.failures += len(written) != 8

# the given values, as the case holds them (exact: written from them)
riser = os.path.join(case, "constant", "riserProperties")
cloud = os.path.join(case, "constant", "kinematicCloudProperties")
# Re = 0.6 * 0.08 / 1e-6 = 4.8e4: the turbulent carrier at the bulk velocity
for name, expected in (("D", D), ("uBulk", ub), ("roughness", 0.0), ("A", A), ("f", f)):
    value = ff.read_entry(riser, name)
    checks.near("riserProperties %s" % name, value, expected, 1e-12, scale=1.0)
profile = open(riser).read()
if not re.search(r"^profile\s+turbulent;", profile, re.M) or "uCentre" in profile:
    print("FAILED: the case at Re 4.8e4 is not given the turbulent profile")
    checks.failures += 1
# -laminar keeps Poiseuille's above Re 2,300, and says so; below, laminar anyway
for name, args, says in (("laminarAsked", ["-laminar"], "above 2,300 as asked by -laminar"),
                         ("laminarSlow", ["-uBulk", "0.02"], "laminar Poiseuille (Re 1600")):
    other = os.path.join(work, name)
    out = subprocess.run([riser_case, other, "-D", repr(D), "-L", repr(L), "-N", "5"]
                         + (["-uBulk", repr(ub)] if "-uBulk" not in args else []) + args,
                         stdout=subprocess.PIPE, text=True, check=True).stdout
    u = ub if "-uBulk" not in args else 0.02
    text = open(os.path.join(other, "constant", "riserProperties")).read()
    ok = (says in out and re.search(r"^profile\s+laminar;", text, re.M) is not None
          and abs(ff.read_entry(os.path.join(other, "constant", "riserProperties"), "uCentre")
                  - 2 * u) < 1e-12)
    print("riserCase %s: laminar Poiseuille, uCentre = 2 uBulk, said: %s"
          % (" ".join(args), "ok" if ok else "FAILED\n" + out))
    checks.failures += 0 if ok else 1
drag = subprocess.run(["foamDictionary", "-entry",
                       "subModels/particleForces/wallCorrectedDrag/pipeDiameter", "-value", cloud],
                      stdout=subprocess.PIPE, text=True, check=True).stdout
checks.near("wallCorrectedDrag pipeDiameter", float(drag), D, 1e-12)

# the fill: -N 60 places exactly 60 ores (riserFill's number); the C_v it
# reports is their volume over the section's (checked against the
# diameters written at the end, below)
m = re.search(r"riserFill: placed (\d+) ores, solids fraction C_v = (\S+) \(requested (\d+) ores\)"
              r".* volume (\S+) m\^3", log)
placed, achieved, requested, volume = int(m.group(1)), float(m.group(2)), int(m.group(3)), float(m.group(4))
ok = placed == requested == N
print("-N %d: riserFill placed %d ores (requested %d): %s" % (N, placed, requested, "ok" if ok else "FAILED"))
checks.failures += not ok

final = os.path.join(case, "0.5", "lagrangian", "kinematicCloud")
d = ff.read_scalars(os.path.join(final, "d"))
rho = ff.read_scalars(os.path.join(final, "rho"))
checks.near("ores at the end of the period", len(d), placed, 0.5, scale=1.0)
# the log prints C_v to 6 significant digits
checks.near("C_v reported against the ores' diameters", achieved,
            sum(math.pi / 6 * x ** 3 for x in d) / volume, 1e-5)
inside = all(dmin <= x <= dmax for x in d) and all(rmin <= x <= rmax for x in rho)
print("diameters in [%g, %g]: %g..%g; densities in [%g, %g]: %g..%g: %s"
      % (dmin, dmax, min(d), max(d), rmin, rmax, min(rho), max(rho), "ok" if inside else "FAILED"))
checks.failures += not inside

# the contact choices, in the dictionaries written
for contacts, model, pairs in (("wall", "riserContact", False), ("none", "none", False),
                               ("pairs", "riserContact", True)):
    other = os.path.join(work, "contacts_" + contacts)
    subprocess.run([riser_case, other, "-contacts", contacts], check=True, stdout=subprocess.DEVNULL)
    text = open(os.path.join(other, "constant", "kinematicCloudProperties")).read()
    got_model = re.search(r"\bcollisionModel\s+(\w+);", text).group(1)
    got_pairs = re.search(r"\bpairs\s*\{", text) is not None
    ok = got_model == model and got_pairs == pairs
    print("-contacts %-5s: collisionModel %s, pairs %s: %s" % (contacts, got_model, got_pairs,
                                                              "ok" if ok else "FAILED"))
    checks.failures += not ok


def stops_naming(cases):
    """each (args, option): riserCase stops naming the option, writing nothing"""
    for args, named in cases:
        bad = subprocess.run([riser_case, os.path.join(work, "bad")] + args,
                             stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        ok = bad.returncode != 0 and named in bad.stdout and not os.path.exists(os.path.join(work, "bad"))
        print("riserCase %-40s stops naming %-9s: %s" % (" ".join(args), named, "ok" if ok else "FAILED"))
        if not ok:
            print(bad.stdout)
        checks.failures += not ok


# hostile input: stops, naming the option
stops_naming((
        (["-D", "-0.1"], "-D"),
        (["-D", "nan"], "-D"),
        (["-d", "0.06"], "-d"),
        (["-d", "0.01", "-dMin", "0.005", "-dMax", "0.01"], "-d"),
        (["-dMin", "0.01"], "-dMax"),
        (["-dMin", "0.01", "-dMax", "0.005"], "-dMin"),
        (["-rhoMin", "3000", "-rhoMax", "2000"], "-rhoMin"),
        (["-rho", "-5"], "-rho"),
        (["-Cv", "0.03", "-N", "10"], "-N"),
        (["-Cv", "0.5"], "-Cv"),
        (["-roughness", "-1e-5"], "-roughness"),
        (["-roughness", "0.05"], "-roughness"),
        (["-roughness", "1e-4", "-laminar"], "-roughness"),
        (["-nu", "0"], "-nu"),
        (["-uBulk", "0.03"], "-uBulk"),
        (["-N", "100000"], "-N"),
        (["-n", "5"], "-n"),
        (["-periods", "0"], "-periods"),
        (["-L", "0.01"], "-d"),
        (["-contacts", "wet"], "-contacts"),
        (["-uBulkk", "1"], "-uBulkk"),
        (["-period", "2"], "-period")))
# a riser that varies along its length: an open section fed at its foot
def run_open(name, args):
    """make and run an open-section case; its folder and solver log"""
    folder = os.path.join(work, name)
    made = subprocess.run([riser_case, folder] + args, stdout=subprocess.PIPE,
                          stderr=subprocess.STDOUT, text=True)
    print(made.stdout.strip())
    done = subprocess.run([os.path.join(folder, "Allrun")], stdout=subprocess.PIPE,
                          stderr=subprocess.STDOUT, text=True)
    if made.returncode != 0 or done.returncode != 0:
        print("FAILED: riserCase %s (or its Allrun)\n%s" % (" ".join(args), done.stdout[-2000:]))
        checks.failures += 1
        return folder, ""
    return folder, open(os.path.join(folder, "log.riserParcelFoam")).read()


def mesh_bottom(folder):
    return min(p[2] for p in ff.read_vectors(os.path.join(folder, "constant/polyMesh/points")))


def added(log):
    found = re.findall(r"- parcels added\s+= (\d+)", log)
    return int(found[-1]) if found else -1


# mode 3 of a 100 m riser, 0.2 m at 0.5 Hz; the 2 m section centred on the
# first antinode (z = 100/6 m) by default; 10 mm ores of 2000 kg/m^3 fed at
# C_v = 0.01 at the bulk velocity 1 m/s: 0.01 * 2000 * pi 0.1^2/4 * 1 =
# 0.1571 kg/s, 150 ores a second, 30 in 0.2 s (whole ores: within 1)
mode, ok_args = os.path.join(work, "modes"), ["-motion", "modes", "-mode", "3", "-riserLength", "100",
                                              "-A", "0.2", "-f", "0.5", "-L", "2", "-n", "4",
                                              "-uBulk", "1", "-Cv", "0.01", "-endTime", "0.2"]
folder, log = run_open("modes", ok_args)
if log:
    riser = os.path.join(folder, "constant", "riserProperties")
    text = open(riser).read()
    checks.near("modes: the section's bottom (the first antinode - L/2)", mesh_bottom(folder),
                100 / 6 - 1, 1e-6, scale=1.0)
    expected = 0.01 * 2000 * math.pi * 0.1 ** 2 / 4 * 1.0 * 0.2 / (2000 * math.pi / 6 * 0.01 ** 3)
    checks.near("modes: ores fed in 0.2 s", added(log), expected, 1.0, scale=1.0)
    ok = (re.search(r"type\s+modes;", text) and re.search(r"x\s+\(\s*\(\s*3 0.2 0.5 0\s*\)\s*\)", text)
          and log.rstrip().endswith("End") and os.path.getsize(os.path.join(folder, "riser_along.png")) > 0)
    print("modes: the motion written, the run ended, the chart drawn: %s" % ("ok" if ok else "FAILED"))
    checks.failures += not ok
# the same mode as a table, sampled every 0.05 s and 0.5 m, the section at z = 15 m
table = os.path.join(work, "mode3.csv")
with open(table, "w") as out:
    out.write("t z x y\n")
    for j in range(9):
        for i in range(81):
            out.write("%.10g %.10g %.17g 0\n" % (0.05 * j, 0.5 * i,
                      0.2 * math.sin(3 * math.pi * 0.5 * i / 100) * math.sin(math.pi * 0.05 * j)))
folder, log = run_open("table", ["-motion", "table", "-table", table, "-z0", "15", "-L", "2",
                                 "-n", "4", "-uBulk", "1", "-Cv", "0.01", "-endTime", "0.1"])
if log:
    ok = (os.path.isfile(os.path.join(folder, "constant", "riserMotion.csv"))
          and abs(mesh_bottom(folder) - 15) < 1e-9 and added(log) > 0 and log.rstrip().endswith("End"))
    print("table: the table copied, the section at z = 15 m, %d ores fed, the run ended: %s"
          % (added(log), "ok" if ok else "FAILED"))
    checks.failures += not ok
stops_naming((
        (["-mode", "3"], "-mode"),
        (["-motion", "modes"], "-riserLength"),
        (["-motion", "modes", "-riserLength", "100", "-z0", "99.5"], "-z0"),
        (["-motion", "modes", "-riserLength", "100", "-N", "10"], "-N"),
        (["-motion", "modes", "-riserLength", "100", "-A", "2", "-mode", "3"], "-A"),
        (["-motion", "modes", "-riserLength", "100", "-mode", "0"], "-mode"),
        (["-motion", "modes", "-riserLength", "100", "-table", table], "-table"),
        (["-motion", "table", "-z0", "15", "-endTime", "1"], "-table"),
        (["-motion", "table", "-table", table, "-endTime", "1"], "-z0"),
        (["-motion", "table", "-table", table, "-z0", "15"], "-endTime"),
        (["-motion", "table", "-table", os.path.join(work, "none.csv"), "-z0", "15", "-endTime", "1"], "-table"),
        (["-feed", "0.5"], "-feed"),
        (["-endTime", "1", "-periods", "2"], "-endTime"),
        (["-motion", "modes", "-riserLength", "100", "-feed", "-1"], "-feed")))
existing = subprocess.run([riser_case, case], stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
ok = existing.returncode != 0 and "exists" in existing.stdout
print("riserCase into an existing folder stops: %s" % ("ok" if ok else "FAILED"))
checks.failures += not ok
checks.exit()
