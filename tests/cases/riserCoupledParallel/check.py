"""riserCoupledFoam in parallel: the laminar periodic riser of
riserCoupledPoiseuille (O-grid of 8 cells across the core, 4 along, from
rest, 10 steps of 100 s) on 2 processors (decomposePar, simple split at
x = 0) against the serial run: the drive's table (written by the master
only, one row a step) and the velocity (reconstructPar) equal the serial
run's within 1e-9 (sums in another order: measured 6e-12)."""
import os

import numpy as np

from riserfoam import cases, foamfields, tables
from riserfoam.checks import Checks

checks = Checks(width=60)


def make(name):
    case = os.path.abspath(name)
    cases.coupled_pipe_case(case, 8, 4, dt=100.0, end=1000.0,
                            tolerances=cases.ROUND_OFF_SOLVES)
    return case


serial = make("serial")
cases.run(["riserCoupledFoam", "-case", serial], os.path.join(serial, "log.riserCoupledFoam"))
parallel = make("parallel")
cases.run_parallel(parallel, "riserCoupledFoam")

drive = {case: tables.read(os.path.join(case, "postProcessing/riserDrive/0/drive.dat"))
         for case in (serial, parallel)}
ok = list(drive[serial]["t"]) == list(drive[parallel]["t"])
checks.failures += not ok
print("drive.dat: %d rows on 2 processors, the serial run's times %s"
      % (len(drive[parallel]), "ok" if ok else "FAILED"))
worst = max(abs(a / b - 1) for a, b in zip(drive[parallel]["dpdz"], drive[serial]["dpdz"]))
checks.near("largest relative difference of dp/dz", worst, 0, 1e-9, 1)
U = {case: np.array(foamfields.read_vectors(os.path.join(case, "1000", "U"), "internalField"))
     for case in (serial, parallel)}
checks.near("largest velocity difference / u_max", abs(U[parallel] - U[serial]).max(), 0,
            1e-9, abs(U[serial]).max())
checks.exit()
