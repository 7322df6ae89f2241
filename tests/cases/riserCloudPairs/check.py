"""Particle-particle contact in the riser cloud (riserParcelFoam: clusters
sub-stepped without the mesh) against closed forms and the stock colliding
cloud; see run."""
import math
import os
import re
import shutil
import sys

from riserfoam import cases, foamfields
from riserfoam.checks import Checks

checks = Checks()
check = checks.near
RISER, STOCK = "riserParcelFoam", "icoUncoupledKinematicParcelFoam"




# two ores, soft (E = 1e8 Pa) so that a contact (~0.5 ms) spans a few flow
# steps of 1e-4 s; no fluid forces, no gravity; inside a static periodic
# riser O-grid of D = 0.1 m and L = 0.1 m, far from its wall
E, nu, rho, dt, end = 1e8, 0.3, 2500.0, 1e-4, 0.03


def make(case, solver, positions, velocities, pairs, diameters=None, end=end):
    """wall_contact_case's dictionaries on the riser O-grid, for solver"""
    cases.wall_contact_case(case, D=0.1, radius=0.005, rho=rho, E=E, nu=nu,
                            wall_E=E, wall_nu=nu, e_n=0.5, e_t=1.0, mu=0.0,
                            velocities=velocities, positions=positions,
                            dt=dt, end=end, pairs=pairs, diameters=diameters)
    cases.on_riser_grid(case, solver)


def solve(case, solver, until=None):
    if until:
        foamfields.set_entry(os.path.join(case, "system/controlDict"), "endTime", until)
    log = cases.run([solver, "-case", case], os.path.join(case, "log.%s.%s" % (solver, until)))
    if "outside the pipe" in log:
        print("FAILED: a particle left the pipe in %s" % case)
        sys.exit(1)
    return log


def velocities(case, time):
    """U of the parcels at time, ordered by origId"""
    folder = os.path.join(case, time, "lagrangian", "kinematicCloud")
    U = foamfields.read_vectors(os.path.join(folder, "U"))
    ids = foamfields.read_scalars(os.path.join(folder, "origId"))
    return [u for _, u in sorted(zip(ids, U))]


def impact(name, solver, d0, d1, v0, v1, e):
    make(name, solver, [(-0.012, 0.0, 0.02), (0.012, 0.0, 0.02)], [(v0, 0.0), (v1, 0.0)],
         (e, 1.0, 0.0), [d0, d1])
    log = solve(name, solver)
    return velocities(name, "%g" % end), log


print("head-on, like spheres (d = 10 mm) at +-0.5 m/s: rebound at e_n times the speed")
for e in (0.3, 0.76, 1.0):
    U, log = impact("like_e%g" % e, RISER, 0.01, 0.01, 0.5, -0.5, e)
    # 400 sub-steps per contact resolve the Hertz impact to ~1e-4
    check("  e_n = %g: particle 0 after/before" % e, -U[0][0] / 0.5, e, 5e-3)
    check("  e_n = %g: particle 1 after/before" % e, U[1][0] / 0.5, e, 5e-3)
    if "without the mesh" not in log:
        print("FAILED: the contact was not sub-stepped without the mesh")
        checks.failures += 1

print("head-on, 10 mm against 6 mm at +0.5 and -0.2 m/s: momentum and e_n")
m0, m1 = (rho * math.pi / 6 * d ** 3 for d in (0.01, 0.006))
v0, v1 = 0.5, -0.2
for e in (0.3, 1.0):
    U, _ = impact("unlike_e%g" % e, RISER, 0.01, 0.006, v0, v1, e)
    w0 = (m0 * v0 + m1 * v1 - m1 * e * (v0 - v1)) / (m0 + m1)
    w1 = w0 + e * (v0 - v1)
    check("  e_n = %g: particle 0 after [m/s]" % e, U[0][0], w0, 5e-3, v0 - v1)
    check("  e_n = %g: particle 1 after [m/s]" % e, U[1][0], w1, 5e-3, v0 - v1)

print("across the cyclic ends of the riser: they rebound too")
make("periodic", RISER, [(0.0, 0.0, 0.008), (0.0, 0.0, 0.092)], [(0.0, -0.5), (0.0, 0.5)],
     (0.76, 1.0, 0.0))
solve("periodic", RISER)
U = velocities("periodic", "%g" % end)
check("  e_n = 0.76: particle 0 after/before", U[0][2] / 0.5, 0.76, 5e-3)
check("  e_n = 0.76: particle 1 after/before", -U[1][2] / 0.5, 0.76, 5e-3)

print("wet pairs in a liquid of 0.02 Pa s: e = e_n exp(-35/St*) of the pair, none below St* 10")
# St* = M* v / (6 pi mu R*^2) with the reduced inertia M* of m_p + m_f/2 and
# the reduced radius R* (Yang & Hunt, Phys. Fluids 18, 121506, 2006), e of
# Legendre et al. (Chem. Eng. Sci. 61, 3543, 2006), written out here; the
# added mass (C_A = 1/2) the wet restitution needs gives no force in still
# liquid. Tolerance 5e-3 of the approach speed, as above (the engine's
# velocity Verlet at 400 sub-steps a contact).
muL, rhoL, d = 0.02, 1000.0, 0.01


def wet_pairs(case):
    """wet pairs in case, with the added mass (C_A = 1/2) they need"""
    props = os.path.join(case, "constant/kinematicCloudProperties")
    foamfields.edit(props, r"particleForces \{\}", "particleForces { riserAddedMass { CA 0.5; } }")
    foamfields.set_nested(props, "subModels/riserContactCoeffs/pairs/wet", "{ type stokesRestitution; }")


for v in (0.25, 0.05, 0.01):
    name = "wet_v%g" % v
    make(name, RISER, [(-0.0055, 0.0, 0.02), (0.0055, 0.0, 0.02)], [(v, 0.0), (-v, 0.0)],
         (0.76, 1.0, 0.0), end=0.15)
    wet_pairs(name)
    foamfields.set_entry(os.path.join(name, "constant/transportProperties"), "nu", muL / rhoL)
    solve(name, RISER)
    U = velocities(name, "0.15")
    mL = (rho + 0.5 * rhoL) * math.pi / 6 * d ** 3
    St = (mL / 2) * 2 * v / (6 * math.pi * muL * (d / 4) ** 2)
    e = 0.76 * math.exp(-35 / St) if St >= 10 else 0.0
    check("  St* = %.1f: relative speed after/before (Legendre: %.4f)" % (St, e),
          (U[1][0] - U[0][0]) / (2 * v), e, 5e-3, 1.0)

# an oblique contact that sticks (mu = 1), from about t = 0.0143 to 0.0147 s
SPLIT = "0.0146"
oblique = dict(positions=[(-0.012, 0.0, 0.02), (0.012, 0.0, 0.02445)],
               velocities=[(0.5, 0.05), (-0.5, -0.05)], pairs=(0.76, 0.5, 1.0))
print("an oblique sticking contact: restart mid-contact, and the stock cloud")
make("whole", RISER, **oblique)
solve("whole", RISER)
make("split", RISER, **oblique)
foamfields.set_entry("split/system/controlDict", "writeInterval", "0.0002")
foamfields.set_entry("split/system/controlDict", "startFrom", "latestTime")
solve("split", RISER, SPLIT)
records = os.path.join("split", SPLIT, "lagrangian", "kinematicCloud", "collisionRecordsPairData")
kept = open(records).read()
if not re.search(r"\n1\(\(", kept):
    sys.exit("FAILED: no pair contact in progress at the restart time %s" % SPLIT)
shutil.copytree("split", "forgotten")
solve("split", RISER, "%g" % end)
path = os.path.join("forgotten", SPLIT, "lagrangian", "kinematicCloud", "collisionRecordsPairData")
open(path, "w").write(re.sub(r"\(\(([^()]*)\)\)", "((0 0 0))", kept))
solve("forgotten", RISER, "%g" % end)
make("stock", STOCK, **oblique)
solve("stock", STOCK)


def difference(a, b):
    return max(math.dist(u, v) / math.hypot(*u) for u, v in zip(a, b))


whole = velocities("whole", "%g" % end)
restarted = difference(whole, velocities("split", "%g" % end))
forgotten = difference(whole, velocities("forgotten", "%g" % end))
stock = difference(whole, velocities("stock", "%g" % end))
# a restart starts the next step from the written state (positions,
# velocities, springs, contact forces at 15 digits): round-off
check("  restarted mid-contact against uninterrupted", restarted, 0.0, 1e-9, 1.0)
if not forgotten > 1e-4:
    print("FAILED: forgetting the springs changes the result by %.2e < 1e-4: the check is blind"
          % forgotten)
    checks.failures += 1
else:
    print("  the springs forgotten at the restart: %.2e (> 1e-4: the check sees them)" % forgotten)


def trace(case, name):
    """a field of the contact trace at the end, ordered by origId"""
    folder = os.path.join(case, "%g" % end, "lagrangian", "kinematicCloud")
    ids = foamfields.read_scalars(os.path.join(folder, "origId"))
    return [v for _, v in sorted(zip(ids, foamfields.read_scalars(os.path.join(folder, name))))]


# the contact trace across the restart: the contact in progress is completed
# once; its approach speed, kept in the model from one flow step to the next
# but not stored, is the one found at the restart's first sub-step; and the
# forces of its last evaluation are derived from the state read, which
# changes the first sub-step's dissipation by O(h^2) (velocities at the end
# of the step instead of the half-step ones: the damping forces differ by
# eta h/2 a): 1e-4 of the contact's dissipation is allowed
energy = sum(trace("whole", "pairEnergy"))
check("  pairEnergy restarted mid-contact against uninterrupted [J]",
      sum(trace("split", "pairEnergy")), energy, 1e-4)
if trace("whole", "pairContacts") != [1, 1] or trace("split", "pairContacts") != [1, 1]:
    print("FAILED: pairContacts %s (whole), %s (split): one each expected"
          % (trace("whole", "pairContacts"), trace("split", "pairContacts")))
    checks.failures += 1
# the approach speed: the normal relative speed when the straight paths
# bring the centres to d = 10 mm apart: relative position (0.024 - t, 0,
# 0.00445 - 0.1 t) m, relative velocity (1, 0, 0.1) m/s; the engine takes it
# at its first sub-step with an overlap, within a sub-step's turn of the
# normal (~ U h/d, 1e-4 here)
a, b = 1.01, -2 * (0.024 + 0.1 * 0.00445)
c = 0.024 ** 2 + 0.00445 ** 2 - 1e-4
t = (-b - math.sqrt(b * b - 4 * a * c)) / (2 * a)
approach = ((0.024 - t) + 0.1 * (0.00445 - 0.1 * t)) / 0.01
for i, speed in enumerate(trace("whole", "pairImpactSpeed")):
    check("  pairImpactSpeed of particle %d, uninterrupted [m/s]" % i, speed, approach, 1e-4)
print("  pairImpactSpeed after the restart mid-contact: %s m/s (the speed at the restart)"
      % trace("split", "pairImpactSpeed"))
# the stock cloud moves each sub-cycle through the mesh with the same law;
# its cycle (velocity half step, move, collide, velocity half step) is
# velocity Verlet too, so with no fluid forces the two integrate the same
# sequence of states: equal up to round-off (other summation orders)
check("  riser cloud against the stock colliding cloud", stock, 0.0, 1e-9, 1.0)

print("on 2 processors split at x = 0: rows of touching ores across the boundary")
# four rows of six ores along x, centred on the processor boundary x = 0,
# 0.2 mm apart; in each row the end ores are thrown inwards (some with a
# vertical component: oblique contacts with friction), so that contacts
# run along the rows and across the boundary; dry and deterministic, so
# the parallel run must equal the serial one to round-off
rows = []
for r, (vLeft, vRight, vz) in enumerate([(0.5, 0.0, 0.0), (0.4, -0.3, 0.0),
                                          (0.3, -0.3, 0.05), (0.0, -0.5, -0.05)]):
    for k in range(6):
        x = (k - 2.5) * 0.0102
        v = vLeft if k == 0 else vRight if k == 5 else 0.0
        rows.append(((x, 0.0, 0.015 + 0.02 * r), (v, vz if k in (0, 5) else 0.0)))
for name in ("rowsSerial", "rowsParallel"):
    make(name, RISER, [p for p, _ in rows], [v for _, v in rows], (0.76, 0.5, 0.5))
foamfields.write_dictionary("rowsParallel/system/decomposeParDict",
                            "numberOfSubdomains 2;\nmethod simple;\ncoeffs { n (2 1 1); }\n")
solve("rowsSerial", RISER)
cases.run(["decomposePar", "-case", "rowsParallel"], "rowsParallel/log.decomposePar")
log = cases.run(["mpirun", "--allow-run-as-root", "--oversubscribe", "-np", "2",
                 RISER, "-parallel", "-case", "rowsParallel"], "rowsParallel/log.parallel")
cases.run(["reconstructPar", "-latestTime", "-case", "rowsParallel"],
          "rowsParallel/log.reconstructPar")
across = [int(n) for n in re.findall(r"(\d+) across processor boundaries", log)]
steps = sum(1 for n in across if n)
print("  pairs in contact across the boundary: in %d steps, up to %d at once"
      % (steps, max(across or [0])))
if steps < 10:
    print("FAILED: fewer than 10 steps with pairs across the boundary: the check is blind")
    checks.failures += 1
if "outside the pipe" in log:
    print("FAILED: a particle left the pipe")
    checks.failures += 1


def state(case):
    """(position, velocity) of every parcel at the end, by position (the
    origIds differ: each processor numbers the parcels it injects)"""
    folder = os.path.join(case, "%g" % end, "lagrangian", "kinematicCloud")
    return sorted(zip(foamfields.read_vectors(os.path.join(folder, "positions")),
                      foamfields.read_vectors(os.path.join(folder, "U"))))


a, b = state("rowsSerial"), state("rowsParallel")
if len(a) != len(rows) or len(b) != len(rows):
    print("FAILED: %d parcels serial, %d parallel, %d injected" % (len(a), len(b), len(rows)))
    checks.failures += 1
else:
    dx = max(math.dist(p, q) for (p, _), (q, _) in zip(a, b))
    du = max(math.dist(u, v) for (_, u), (_, v) in zip(a, b))
    # round-off: the parcels that cross the boundary are tracked on another
    # processor (the single-particle parallel test measures ~5e-13); a
    # missed or doubled pair contact would change a velocity by ~0.1 m/s
    check("  largest position difference [m], parallel against serial", dx, 0.0, 1e-12, 1.0)
    check("  largest velocity difference [m/s], parallel against serial", du, 0.0, 1e-10, 1.0)

print("the stock colliding cloud with pairs on 2 processors: the rows again")
# the same rows under the stock solver, whose collision sub-cycles find the
# pairs across the boundary with copies of the other processor's
# particles: equal to its serial run to round-off
for name in ("stockSerial", "stockParallel"):
    make(name, STOCK, [p for p, _ in rows], [v for _, v in rows], (0.76, 0.5, 0.5))
foamfields.write_dictionary("stockParallel/system/decomposeParDict",
                            "numberOfSubdomains 2;\nmethod simple;\ncoeffs { n (2 1 1); }\n")
solve("stockSerial", STOCK)
cases.run(["decomposePar", "-case", "stockParallel"], "stockParallel/log.decomposePar")
log = cases.run(["mpirun", "--allow-run-as-root", "--oversubscribe", "-np", "2",
                 STOCK, "-parallel", "-case", "stockParallel"], "stockParallel/log.parallel")
cases.run(["reconstructPar", "-latestTime", "-case", "stockParallel"],
          "stockParallel/log.reconstructPar")
if "outside the pipe" in log:
    print("FAILED: a particle left the pipe")
    checks.failures += 1
a, b = state("stockSerial"), state("stockParallel")
if len(a) != len(rows) or len(b) != len(rows):
    print("FAILED: %d parcels serial, %d parallel, %d injected" % (len(a), len(b), len(rows)))
    checks.failures += 1
else:
    dx = max(math.dist(p, q) for (p, _), (q, _) in zip(a, b))
    du = max(math.dist(u, v) for (_, u), (_, v) in zip(a, b))
    # round-off, as for the riser cloud above; a pair across the boundary
    # missed (the serial rows' contacts run across x = 0) would change a
    # velocity by ~0.1 m/s
    check("  largest position difference [m], parallel against serial", dx, 0.0, 1e-12, 1.0)
    check("  largest velocity difference [m/s], parallel against serial", du, 0.0, 1e-10, 1.0)

print("wet pairs in the stock colliding cloud: refused (its pairs keep no approach speed)")
make("stockWet", STOCK, [(-0.0055, 0.0, 0.02), (0.0055, 0.0, 0.02)], [(0.05, 0.0), (-0.05, 0.0)],
     (0.76, 1.0, 0.0))
wet_pairs("stockWet")
refused = cases.run([STOCK, "-case", "stockWet"], "stockWet/log", may_fail=True) is None
text = open("stockWet/log").read()
if refused and "entry 'wet' of pairs in a stock colliding cloud" in text:
    print("  refused: " + next(l.strip() for l in text.splitlines() if "entry 'wet' of pairs" in l))
else:
    print("FAILED: the stock cloud ran wet pairs, or its error does not name 'wet'")
    checks.failures += 1

print("two ores released overlapping each other: refused, naming both")
make("overlapping", RISER, [(0.0, 0.0, 0.02), (0.0099, 0.0, 0.02)], [(0.0, 0.0), (0.0, 0.0)],
     (0.76, 0.5, 0.5))
refused = cases.run([RISER, "-case", "overlapping"], "overlapping/log", may_fail=True) is None
text = open("overlapping/log").read()
if refused and re.search(r"particles \d+ \(processor 0\) at .* and \d+ \(processor 0\)", text) \
        and "overlapping each other: overlap 0.0001" in text:
    print("  refused: " + next(l.strip() for l in text.splitlines() if "overlapping each" in l))
else:
    print("FAILED: overlapping ores at release were not refused with both named")
    checks.failures += 1

checks.exit()
