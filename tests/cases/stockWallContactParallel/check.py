"""The stock colliding cloud's wall contacts across a processor boundary;
see run."""
import glob
import math
import os

from riserfoam import cases, tables
from riserfoam.checks import Checks

checks = Checks()
SOLVER = "icoUncoupledKinematicParcelFoam"
D, L, R, dt, end = 0.1, 0.1, 0.005, 1e-4, 0.004
vx, vz, gap = 0.3, 0.5, 1e-4
zBoundary = 0.5 * L     # simple decomposition, 10 equal cells along z

# five ores side by side along y, each a gap from the wall along its
# path (+x); each starts lower by its own share of its contact's duration
# (Hertz's, for the normal speed at the wall: t_c = 2.87 (m*^2 / (R E*^2
# v_n))^(1/5), about 0.6 ms) so that the boundary is crossed early, midway
# and late in the contacts
ys = (-0.030, -0.015, 0.0, 0.012, 0.027)
shares = (0.1, 0.3, 0.5, 0.7, 0.9)
E, nu, rho = 1e8, 0.3, 2500.0
mass = rho * 4.0 / 3.0 * math.pi * R ** 3
Estar = E / (2.0 * (1.0 - nu ** 2))
rWall = 0.5 * D - R
positions, velocities = [], []
for y, share in zip(ys, shares):
    x = math.sqrt(rWall ** 2 - y ** 2) - gap
    touch = gap / vx
    vn = vx * math.sqrt(1.0 - (y / rWall) ** 2)
    tc = 2.87 * (mass ** 2 / (R * Estar ** 2 * vn)) ** 0.2
    positions.append((x, y, zBoundary - vz * (touch + share * tc)))
    velocities.append((vx, vz))


def make(case):
    cases.wall_contact_case(case, D=D, radius=R, rho=rho, E=E, nu=nu,
                            wall_E=E, wall_nu=nu, e_n=0.5, e_t=1.0, mu=0.0,
                            velocities=velocities, positions=positions,
                            dt=dt, end=end, pairs=None)
    cases.on_riser_grid(case, SOLVER, D=D, L=L)


def rows(case):
    files = glob.glob(os.path.join(case, "postProcessing/lagrangian/kinematicCloud/"
                                         "riserContact/contacts*.dat"))
    table = []
    for f in files:
        t = tables.read(f)
        table += [list(r) for r in t.matrix(*t.names)]
    return sorted(table, key=lambda r: (r[2], r[3]))


make("serial")
log = cases.run([SOLVER, "-case", "serial"], "serial/log." + SOLVER)
make("parallel")
plog = cases.run_parallel(os.path.abspath("parallel"), SOLVER, (1, 1, 2))
for name, text in (("serial", log), ("parallel", plog)):
    if "outside the pipe" in text:
        print("FAILED: an ore left the pipe in the %s run" % name)
        checks.failures += 1

a, b = rows("serial"), rows("parallel")
print("completed wall contacts: serial %d, parallel %d" % (len(a), len(b)))
if len(a) != len(positions) or len(b) != len(a):
    print("FAILED: one wall contact an ore expected in each run")
    checks.failures += 1
else:
    # each contact runs across the boundary: its ore (constant v_z, no
    # friction) is below it at the contact's start and above it at its end
    for r in a:
        k = int(r[1])
        z0 = positions[k][2]
        below, above = z0 + vz * r[2] < zBoundary, z0 + vz * r[3] > zBoundary
        print("  ore %d: contact %.4g..%.4g s, crosses z = %g at %.4g s"
              % (k, r[2], r[3], zBoundary, (zBoundary - z0) / vz))
        if not (below and above):
            print("FAILED: ore %d's contact does not run across the boundary: the check is blind" % k)
            checks.failures += 1
    # the same rows to round-off (the parallel run's origIds are its
    # processors' numbering: the rows compared from tStart on) (the same arithmetic; an ore tracked on
    # another processor: ~1e-13 in the single-particle parallel test); a
    # contact restarted at the crossing would change tStart by ~1e-4 s and
    # UnIn by ~0.3 m/s
    worst = max(abs(x - y) for ra, rb in zip(a, b) for x, y in zip(ra[2:], rb[2:]))
    checks.near("largest difference of a row's number, parallel against serial",
                worst, 0.0, 1e-10, 1.0)
checks.exit()
