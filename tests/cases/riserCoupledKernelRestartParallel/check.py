"""riserCoupledFoam with the coarse-particle kernel, a RAS model and ores
of mixed sizes, restarted and on 2 processors: the uninterrupted serial
run's results.

A periodic riser section (D = L = 0.1 m, O-grid of 6 cells across the
core, 6 along: cells up to 17 mm), water driven up at a bulk velocity of
0.5 m/s (drive relaxation 0.5, so that a restart needs the gradient it
read back), RAS kOmegaSST with wall functions from a plug flow; filled at
the start with ores (riserFill, C_v = 0.01, 2000 kg/m^3, diameters drawn
uniformly from 3 to 6 mm: 144 ores, two-way coupled) whose volume
and reaction the kernel spreads:
    kernel { type diffusion; width 5; widthUnit diameters; }
(b = 5 times the largest diameter, about 30 mm: at least the largest
cell). dt = 5 ms, 40 steps to 0.2 s, written every 20 steps in ascii with
17 digits (a restart reads back exactly what was written). Runs:

- whole: 0 to 0.2 s;
- restarted: 0 to 0.1 s, then (startFrom latestTime) 0.1 to 0.2 s;
- parallel: decomposePar (simple split at x = 0), mpirun -np 2
  riserCoupledFoam -parallel, reconstructPar.

Checked against the whole run at 0.2 s: the carrier's U, k and omega
(largest difference over the largest magnitude), each ore's position and
velocity (matched by diameter, each drawn once; relative to the section's
length and the bulk velocity), and every row of the drive's dp/dz
(relative to the last); the same ores and rows.

- Restart: within 1e-12. It reads back exactly what was written (17
  digits); the old-time volume fraction of its first step is that of the
  ores read back, as the uninterrupted run's is that of the step before
  (without it, ddt(alpha_c) of that step was zero: 5e-5 off the whole
  run's gradient, and growing). Measured: 0 (identical digits).
- 2 processors: within 1e-5. Not round-off alone: OpenFOAM's turbulence
  model with wall functions differs between 1 and 2 processors where the
  processor boundary meets the wall, the same in the stock pimpleFoam
  (with meanVelocityForce, this case without ores, 10 steps: U 1.4e-8,
  k 9.3e-7, omega 2.8e-6, nu_t 2e-5 of their largest values, the
  gradient 8e-9 and growing by about 1e-9 a step; riserCoupledFoam's
  gradient without ores the same, 8e-9; laminar, with or without ores,
  1e-11 and less).
  With the ores the kernel adds its own share: each processor's
  incomplete-Cholesky factor differs, so its solves stop at another
  iterate within the kernel's default tolerance (1e-4; the spread fields
  within 2 N 1e-4 of the converged ones, kernelConservation). Measured
  after 40 steps: U 2.7e-6, k 1.7e-6, omega 1.2e-6, positions 5e-7,
  velocities 1.5e-6, dp/dz 1.6e-6. A kernel that did not
  spread across the processor boundary, or a largest diameter not taken
  over both processors, would move the ores' reaction by cells (one-cell
  deposits are 35 % off in riserCoupledKernel): far above 1e-5.
- 2 processors, laminar (no RAS model) with the kernel solved to 1e-14,
  to 0.1 s: the carrier's U and the ores' velocities within 1e-10 of the
  serial run's (round-off of sums in another order, 20 steps). This
  checks what the default tolerance hides: the deposits shared between a
  particle's cell and its tet's points (pointShares) summed over both
  processors at the points of the processor boundary. Measured 4.6e-13
  and 4.0e-13.
"""
import os

import numpy as np

from riserfoam import cases, foamfields, tables
from riserfoam.checks import Checks

checks = Checks(width=64)
UB, END, HALF = 0.5, 0.2, 0.1
CLOUD = "lagrangian/kinematicCloud"
ORES = cases.fill_injection(0.01, sizes="type uniform; uniformDistribution { minValue 0.003; maxValue 0.006; }")


def make(name, laminar=False):
    case = os.path.abspath(name)
    cases.coupled_pipe_case(case, 6, 6, uCentre=1.25 * UB, drive="bulkVelocity %r; relaxation 0.5;" % UB,
                            dt=5e-3, end=END, write_every=20, injection=ORES, coupled=True,
                            kernel="type diffusion; width 5; widthUnit diameters;%s"
                            % (" tolerance 1e-14;" if laminar else ""),
                            tolerances=cases.ROUND_OFF_SOLVES)
    if not laminar:
        cases.coupled_pipe_RAS(case, UB)
    foamfields.set_entry(os.path.join(case, "system/controlDict"), "writePrecision", "17")
    return case


def solve(case, end=END):
    foamfields.set_entry(os.path.join(case, "system/controlDict"), "endTime", repr(end))
    return cases.run(["riserCoupledFoam", "-case", case],
                     os.path.join(case, "log.riserCoupledFoam.%g" % end))


def state(case):
    """the carrier's fields, the ores' (positions, velocities) by diameter, dp/dz's rows"""
    time = os.path.join(case, "%g" % END)
    carrier = {f: np.array(read(os.path.join(time, f), "internalField"))
               for f, read in (("U", foamfields.read_vectors), ("k", foamfields.read_scalars),
                               ("omega", foamfields.read_scalars))}
    d = np.array(foamfields.read_scalars(os.path.join(time, CLOUD, "d")))
    order = np.argsort(d)
    ores = {f: np.array(foamfields.read_vectors(os.path.join(time, CLOUD, f)))[order]
            for f in ("positions", "U")}
    return carrier, d[order], ores, tables.read(os.path.join(case, "postProcessing/riserDrive/0/drive.dat"))


whole = make("whole")
solve(whole)
restarted = make("restarted")
solve(restarted, HALF)
log = solve(restarted)
ok = "Time = %g" % (HALF + 5e-3) in log and "Time = 0.005\n" not in log
checks.failures += not ok
print("the second run continued from %g s %s" % (HALF, "ok" if ok else "FAILED"))

parallel = make("parallel")
cases.run_parallel(parallel, "riserCoupledFoam")

carrier, d, ores, drive = state(whole)
print("whole run: %d ores of %.2f to %.2f mm, dp/dz %.6g Pa/m at %g s"
      % (len(d), 1e3 * d.min(), 1e3 * d.max(), drive["dpdz"][-1], END))
for name, case, tol in (("restart", restarted, 1e-12), ("2 processors", parallel, 1e-5)):
    c, dd, o, dr = state(case)
    ok = len(dd) == len(d) and np.array_equal(dd, d) and list(dr["t"]) == list(drive["t"])
    checks.failures += not ok
    print("%s: the same %d ores (diameters) and %d drive rows %s"
          % (name, len(dd), len(dr), "ok" if ok else "FAILED"))
    if not ok:
        continue
    for f in ("U", "k", "omega"):
        checks.near("%s: carrier %s, largest difference / largest value" % (name, f),
                    abs(c[f] - carrier[f]).max(), 0, tol, abs(carrier[f]).max())
    checks.near("%s: ore positions, largest difference / L" % name,
                abs(o["positions"] - ores["positions"]).max(), 0, tol, 0.1)
    checks.near("%s: ore velocities, largest difference / u_b" % name,
                abs(o["U"] - ores["U"]).max(), 0, tol, UB)
    checks.near("%s: dp/dz, largest difference over the rows / last" % name,
                abs(dr["dpdz"] - drive["dpdz"]).max(), 0, tol, abs(drive["dpdz"][-1]))

# laminar, the kernel solved to 1e-14: serial against 2 processors to 0.1 s
laminar = {}
for name in ("laminarSerial", "laminarParallel"):
    case = make(name, laminar=True)
    foamfields.set_entry(os.path.join(case, "system/controlDict"), "endTime", repr(HALF))
    if name == "laminarSerial":
        cases.run(["riserCoupledFoam", "-case", case], os.path.join(case, "log.riserCoupledFoam"))
    else:
        cases.run_parallel(case, "riserCoupledFoam")
    time = os.path.join(case, "%g" % HALF)
    d = np.array(foamfields.read_scalars(os.path.join(time, CLOUD, "d")))
    laminar[name] = (np.array(foamfields.read_vectors(os.path.join(time, "U"), "internalField")),
                     np.array(foamfields.read_vectors(os.path.join(time, CLOUD, "U")))[np.argsort(d)])
(Us, us), (Up, up) = laminar["laminarSerial"], laminar["laminarParallel"]
checks.near("laminar, 2 processors: carrier U, largest difference / largest value",
            abs(Up - Us).max(), 0, 1e-10, abs(Us).max())
ok = len(up) == len(us)
checks.failures += not ok
if ok:
    checks.near("laminar, 2 processors: ore velocities, largest difference / u_b",
                abs(up - us).max(), 0, 1e-10, UB)
else:
    print("laminar, 2 processors: %d ores against %d serially FAILED" % (len(up), len(us)))
checks.exit()
