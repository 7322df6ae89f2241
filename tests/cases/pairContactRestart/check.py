"""A pair contact in progress at a restart; see run."""
import math
import os
import re
import shutil
import sys

from riserfoam import cases, foamfields

SPLIT, END = "0.0146", "0.03"


def make(case):
    # two ores approach at 1 m/s, offset along z and moving past each other
    # at 0.1 m/s: an oblique contact from about t = 0.0143 to 0.0147 s that
    # sticks (mu = 1), so its tangential spring carries history (a sliding
    # contact's spring is reset to the Coulomb limit and would not)
    cases.wall_contact_case(case, D=0.1, radius=0.005, rho=2500.0, E=1e8, nu=0.3,
                            wall_E=1e8, wall_nu=0.3, e_n=0.5, e_t=1.0, mu=0.0,
                            velocities=[(0.5, 0.05), (-0.5, -0.05)],
                            positions=[(-0.012, 0.0, 0.02), (0.012, 0.0, 0.02445)],
                            dt=1e-4, end=float(END), pairs=(0.76, 0.5, 1.0))
    foamfields.set_entry(os.path.join(case, "system/controlDict"), "writeInterval", "0.0002")
    foamfields.set_entry(os.path.join(case, "system/controlDict"), "startFrom", "latestTime")
    cases.run(["blockMesh", "-case", case], os.path.join(case, "log.blockMesh"))


def solve(case, end):
    foamfields.set_entry(os.path.join(case, "system/controlDict"), "endTime", end)
    cases.run(["icoUncoupledKinematicParcelFoam", "-case", case],
              os.path.join(case, "log.solver.%s" % end))


def velocities(case):
    return foamfields.read_vectors(os.path.join(case, END, "lagrangian", "kinematicCloud", "U"))


def springs(case, time):
    path = os.path.join(case, time, "lagrangian", "kinematicCloud", "collisionRecordsPairData")
    return open(path).read()


def difference(a, b):
    return max(math.dist(u, v) / math.hypot(*u) for u, v in zip(a, b))


make("whole")
solve("whole", END)
make("split")
solve("split", SPLIT)
kept = springs("split", SPLIT)
if not re.search(r"\n1\(\(", kept):
    sys.exit("FAILED: no pair contact in progress at the restart time %s" % SPLIT)
shutil.copytree("split", "forgotten")
shutil.copytree("split", "lying")
solve("split", END)

# the same restart with the springs set to zero: the histories matter
path = os.path.join("forgotten", SPLIT, "lagrangian", "kinematicCloud", "collisionRecordsPairData")
open(path, "w").write(re.sub(r"\(\(([^()]*)\)\)", "((0 0 0))", kept))
solve("forgotten", END)

# the same restart with the first ore's record naming an ore that does not
# exist: refused before the stock cloud reads the records, naming the file,
# the ore and the rule
path = os.path.join("lying", SPLIT, "lagrangian", "kinematicCloud",
                    "collisionRecordsPairOrigIdOfOther")
records = open(path).read()
open(path, "w").write(re.sub(r"\n1\((\d+)\)\n", "\n1(9999)\n", records, count=1))
foamfields.set_entry(os.path.join("lying", "system/controlDict"), "endTime", END)
lying = cases.run(["icoUncoupledKinematicParcelFoam", "-case", "lying"],
                  os.path.join("lying", "log.solver." + END), may_fail=True)
refusal = open(os.path.join("lying", "log.solver." + END)).read()
expected = ("particle 0 (origProcId 0, origId 0) of", "collisionRecordsPairOrigIdOfOther",
            "with the particle (origProcId 0, origId 9999), which is not in the cloud")
lyingRefused = lying is None and all(t in refusal for t in expected)
print("a record naming the ore 9999 (there are 2), refused: %s"
      % ("yes" if lyingRefused else "NO"))

restarted = difference(velocities("whole"), velocities("split"))
forgotten = difference(velocities("whole"), velocities("forgotten"))
print("velocities after the contact, restarted mid-contact against uninterrupted: %.2e" % restarted)
print("the same with the springs forgotten at the restart:                        %.2e" % forgotten)
failures = 0
if not restarted < 1e-9:
    print("FAILED: the restarted run differs by more than 1e-9")
    failures += 1
if not forgotten > 1e-4:
    print("FAILED: forgetting the springs changes the result by less than 1e-4: the check is blind")
    failures += 1
if not lyingRefused:
    print("FAILED: the restart with a record naming a missing ore was not refused as"
          " expected:\n" + refusal[-1500:])
    failures += 1
print("%d check(s) failed" % failures)
sys.exit(1 if failures else 0)
