"""riserCoupledFoam restarted: the same run as the uninterrupted one.

The laminar periodic riser of riserCoupledPoiseuille on a coarse O-grid
(8 cells across the core), from rest, 12 steps of 50 s (the flow still
developing, the drive's gradient changing), written every 3 steps. The
drive's relaxation is 0.5: with 1 its first correction of a step sets
the gradient whatever it was, and a restart would not need it back. The
run is repeated from t = 300 s twice (the second restart as if the first
had been stopped at 450 s and rerun from 300 s). Checked:

- the velocity at 600 s and the drive's last dp/dz equal the
  uninterrupted run's within 1e-9 (the fields are written with 12
  digits);
- the restart read the gradient back (its log names the gradient of
  300 s), and postProcessing/riserDrive/0/drive.dat holds each step's
  time once, its rows those of the uninterrupted run (to 1e-9);
- a blind check: with the gradient in uniform/riserDrive set to 0 the
  restart ends elsewhere (more than 1e-6). (Without the file the restart
  is refused: checkStartTime.H finds the time incomplete.)
"""
import os
import shutil

import numpy as np

from riserfoam import cases, foamfields, tables
from riserfoam.checks import Checks

checks = Checks(width=60)


def make(name):
    case = os.path.abspath(name)
    cases.coupled_pipe_case(case, 8, 2, dt=50.0, end=600.0, write_every=3,
                            drive="relaxation 0.5;", tolerances=cases.ROUND_OFF_SOLVES)
    return case


def solve(case, start=None, log="log.riserCoupledFoam"):
    if start is not None:
        foamfields.set_entry(os.path.join(case, "system/controlDict"), "startFrom", "startTime")
        foamfields.set_entry(os.path.join(case, "system/controlDict"), "startTime", start)
    return cases.run(["riserCoupledFoam", "-case", case], os.path.join(case, log))


def result(case):
    U = np.array(foamfields.read_vectors(os.path.join(case, "600", "U"), "internalField"))
    return U, tables.read(os.path.join(case, "postProcessing/riserDrive/0/drive.dat"))


whole = make("whole")
solve(whole)
U_whole, drive_whole = result(whole)

restarted = make("restarted")
solve(restarted)
for t in ("450", "600"):
    shutil.rmtree(os.path.join(restarted, t))
log = solve(restarted, "300", "log.restart1")
log = solve(restarted, "300", "log.restart2")
U, drive = result(restarted)
dpdz300 = drive_whole["dpdz"][np.argmin(abs(drive_whole["t"] - 300))]
scale = abs(U_whole).max()
checks.near("largest velocity difference at 600 s / u_max", abs(U - U_whole).max(), 0, 1e-9, scale)
checks.near("last dp/dz [Pa/m]", drive["dpdz"][-1], drive_whole["dpdz"][-1], 1e-9)
read_back = "dp/dz = %s Pa/m at the start" % foamfields.read_entry(
    os.path.join(restarted, "300", "uniform", "riserDrive"), "value")
ok = read_back in log and abs(foamfields.read_entry(
    os.path.join(restarted, "300", "uniform", "riserDrive"), "value") / dpdz300 - 1) < 1e-9
checks.failures += not ok
print("the restart read dp/dz of 300 s back (%s) %s" % (read_back, "ok" if ok else "FAILED"))
ok = list(drive["t"]) == list(drive_whole["t"]) and \
    np.allclose(drive["dpdz"], drive_whole["dpdz"], rtol=1e-9, atol=0)
checks.failures += not ok
print("drive.dat: %d rows, each time once, the uninterrupted run's %s"
      % (len(drive), "ok" if ok else "FAILED"))

blind = make("blind")
solve(blind)
shutil.rmtree(os.path.join(blind, "450"))
shutil.rmtree(os.path.join(blind, "600"))
foamfields.set_entry(os.path.join(blind, "300", "uniform", "riserDrive"), "value", "0")
solve(blind, "300", "log.restart")
_, drive_blind = result(blind)
change = abs(drive_blind["dpdz"][-1] / drive_whole["dpdz"][-1] - 1)
ok = change > 1e-6
checks.failures += not ok
print("blind: uniform/riserDrive set to 0, the last dp/dz changes by %.2e (> 1e-6) %s"
      % (change, "ok" if ok else "FAILED"))
checks.exit()
