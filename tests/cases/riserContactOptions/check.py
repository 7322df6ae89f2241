"""riserContact's options aloneAtWall and wallContact in the riser cloud
(riserParcelFoam); see run."""
import math
import os

from riserfoam import cases, foamfields
from riserfoam.checks import Checks

checks = Checks()
check = checks.near
RISER = "riserParcelFoam"
COEFFS = "subModels/riserContactCoeffs"


def add_coeff(case, entry, value):
    cases.run(["foamDictionary", "-entry", "%s/%s" % (COEFFS, entry), "-add", value,
               os.path.join(case, "constant", "kinematicCloudProperties")],
              os.path.join(case, "log.foamDictionary"))


def remove_coeff(case, entry):
    cases.run(["foamDictionary", "-entry", "%s/%s" % (COEFFS, entry), "-remove",
               os.path.join(case, "constant", "kinematicCloudProperties")],
              os.path.join(case, "log.foamDictionary"))


def solve(case, may_fail=False):
    log = cases.run([RISER, "-case", case], os.path.join(case, "log.solver"), may_fail=may_fail)
    if log and "outside the pipe" in log:
        print("FAILED: a particle left the pipe in %s" % case)
        checks.failures += 1
    return log


def last_state(case, end):
    """(position, U) of the parcels at end, ordered by origId"""
    folder = os.path.join(case, "%g" % end, "lagrangian", "kinematicCloud")
    ids = foamfields.read_scalars(os.path.join(folder, "origId"))
    x = foamfields.read_vectors(os.path.join(folder, "positions"))
    U = foamfields.read_vectors(os.path.join(folder, "U"))
    return [(p, u) for _, p, u in sorted(zip(ids, x, U))]


# dry: one ore (d = 10 mm, soft: E = 1e8 Pa, a contact of ~0.5 ms spans
# several flow steps) thrown obliquely at the wall of a static periodic
# riser O-grid, friction 0.3: it slides, and the tangential spring matters
E, nu, rho, dt, end = 1e8, 0.3, 2500.0, 1e-4, 0.03
print("aloneAtWall: a dry oblique impact, tracked and meshFree")
for mode in ("tracked", "meshFree"):
    case = "dry_" + mode
    cases.wall_contact_case(case, D=0.1, radius=0.005, rho=rho, E=E, nu=nu, wall_E=E,
                            wall_nu=nu, e_n=0.76, e_t=0.5, mu=0.3,
                            velocities=[(0.5, 0.3)], positions=[(0.04, 0.0, 0.05)],
                            dt=dt, end=end)
    cases.on_riser_grid(case, RISER)
    add_coeff(case, "aloneAtWall", mode)
    log = solve(case)
    if mode == "meshFree" and "alone at the wall" not in log:
        print("FAILED: the meshFree run did not sub-step the particle without the mesh")
        checks.failures += 1
rows = [cases.wall_contacts("dry_" + mode) for mode in ("tracked", "meshFree")]
if len(rows[0]) != 1 or len(rows[1]) != 1:
    print("FAILED: %d and %d contacts, one each expected" % (len(rows[0]), len(rows[1])))
    checks.failures += 1
else:
    check("  normal restitution of the tracked contact", rows[0][0]["UnOut"] / rows[0][0]["UnIn"],
          0.76, 5e-3)
(xa, ua), = last_state("dry_tracked", end)
(xb, ub), = last_state("dry_meshFree", end)
# both integrate by velocity Verlet over the same sub-cycles with no fluid
# force, but not the same sequence of states: they differ from the step
# the contact begins in, by an amount that vanishes with the sub-step
# (a normal impact at E = 1e10 Pa: 2.4e-6, 1.0e-6 and 2.7e-7 m/s at 100,
# 400 and 1600 sub-steps per contact time), far inside the contact's own
# discretisation error (its rebound speed moves by 7e-5 m/s between those
# sub-steps; 2.5e-4 of e_n above): 1e-5 of the impact speed allowed, so
# that a wrong force, spring or hand-over (errors of 1e-2 and more) fails
check("  position difference [m]", math.dist(xa, xb), 0.0, 1e-5 * 0.5 * end, 1.0)
check("  velocity difference [m/s]", math.dist(ua, ub), 0.0, 1e-5 * 0.5, 1.0)

# wet: the flagship (one 10 mm ore, the paper's forces with the Basset
# force, the riser frame at A = 0.1 m, f = 3 Hz), up to its third contact
print("aloneAtWall: the flagship's ore, tracked and meshFree, 3 wall contacts")
wet = {}
for mode in ("tracked", "meshFree"):
    case = "wet_" + mode
    cases.copy_tutorial("riser/oscillatingContact", case)
    cases.riser_mesh(case, 0.1, 0.2, 12)
    foamfields.set_entry(os.path.join(case, "system/controlDict"), "endTime", "0.34")
    foamfields.set_entry(os.path.join(case, "system/controlDict"), "writeInterval", "0.34")
    add_coeff(case, "aloneAtWall", mode)
    solve(case)
    contacts = cases.wall_contacts(case)
    table = os.path.join(case, "postProcessing/lagrangian/kinematicCloud/riserParticleTable",
                         "particles.dat")
    last = open(table).read().split("\n")[-2].split()
    wet[mode] = ([row["UnOut"] / row["UnIn"] for row in contacts], float(last[5]))
(ea, za), (eb, zb) = wet["tracked"], wet["meshFree"]
if len(ea) != 3 or len(eb) != 3:
    print("FAILED: %d and %d contacts, 3 expected" % (len(ea), len(eb)))
    checks.failures += 1
else:
    # meshFree freezes the fluid force's coefficients over the flow step
    # (the drag's rate with its wall factor, taken at the gap of the step's
    # start; the velocity is not frozen); the drag's impulse over a contact
    # is ~ rate t_c ~ 1e-2 of the particle's momentum at the wall, of which
    # the frozen coefficients change a part: each contact's restitution
    # within 1 % (measured: 0.15 % at most) and the lift, which the
    # restitutions set, within 1 % (measured 0.16 %)
    for k in range(3):
        check("  restitution of contact %d, meshFree against tracked" % (k + 1), eb[k], ea[k],
              1e-2)
    check("  height at t = 0.34 s, meshFree against tracked [m]", zb, za, 1e-2)

# an ore pressed at the wall (dry: gravity 99 m/s^2 across the riser, with
# buoyancy 49.5 m/s^2) bounces ever lower and comes to rest: slow contacts
# that often span a flow step. The mesh-free sub-steps must hand such a
# contact from one flow step to the next without a jump (a shift of the
# particle by the track's share of a dt^2/2, ~1e-7 m, as large as the
# overlap, made it bounce at e_n > 1 and never settle: 381 contacts against
# the tracked run's 16)
print("aloneAtWall: an ore pressed at the wall comes to rest, tracked and meshFree")
pressed = {}
for mode in ("tracked", "meshFree"):
    case = "pressed_" + mode
    cases.copy_tutorial("riser/oscillatingContact", case)
    cases.riser_mesh(case, 0.1, 0.2, 12)
    control = os.path.join(case, "system/controlDict")
    for entry, value in (("endTime", "0.2"), ("writeInterval", "0.2"), ("deltaT", "1e-4")):
        foamfields.set_entry(control, entry, value)
    foamfields.set_entry(os.path.join(case, "constant/riserProperties"), "A", "0")
    foamfields.edit(os.path.join(case, "constant/g"), r"^value .*;", "value (99 0 -9.81);")
    cloud = os.path.join(case, "constant/kinematicCloudProperties")
    for force in ("riserBasset", "wallCorrectedDrag", "riserSaffmanMeiLift", "riserAddedMass",
                  "riserFluidStress", "riserFrame"):
        cases.run(["foamDictionary", "-entry", "subModels/particleForces/" + force, "-remove",
                   cloud], os.path.join(case, "log.foamDictionary"))
    cases.run(["foamDictionary", "-entry", "subModels/injectionModels/release/U0", "-set",
               "(0 0 0)", cloud], os.path.join(case, "log.foamDictionary"))
    cases.run(["foamDictionary", "-entry", COEFFS + "/stepsPerContact", "-set", "10", cloud],
              os.path.join(case, "log.foamDictionary"))
    foamfields.write_file(os.path.join(case, "constant/kinematicCloudPositions"),
                          foamfields.header("vectorField", "kinematicCloudPositions")
                          + "(\n(0.044 0 0.05)\n)\n")
    add_coeff(case, "aloneAtWall", mode)
    solve(case)
    pressed[mode] = cases.wall_contacts(case)
a, b = pressed["tracked"], pressed["meshFree"]
print("  wall contacts: %d tracked, %d meshFree" % (len(a), len(b)))
# the bounces decay alike (a few more or fewer before rest: the slowest
# ones are at the contact's resolution)
if not abs(len(b) - len(a)) <= 3:
    print("FAILED: %d contacts meshFree against %d tracked" % (len(b), len(a)))
    checks.failures += 1
# the restitution of the whole sequence, sum(UnOut)/sum(UnIn): each
# contact's within the 1 % above
check("  sum(UnOut)/sum(UnIn), meshFree against tracked", float(sum(b["UnOut"]) / sum(b["UnIn"])),
      float(sum(a["UnOut"]) / sum(a["UnIn"])), 1e-2)

print("wallContact off: pairs alone, the wall left to the patchInteractionModel")
pair = dict(D=0.1, radius=0.005, rho=rho, E=E, nu=nu, wall_E=E, wall_nu=nu, e_n=0.5,
            e_t=1.0, mu=0.0, velocities=[(0.5, 0.0), (-0.5, 0.0)],
            positions=[(-0.012, 0.0, 0.02), (0.012, 0.0, 0.02)], dt=dt, end=end,
            pairs=(0.76, 1.0, 0.0))
for name in ("pairWallOn", "pairWallOff"):
    cases.wall_contact_case(name, **pair)
    cases.on_riser_grid(name, RISER)
for entry in ("wall", "normalRestitution", "tangentialRestitution", "friction"):
    remove_coeff("pairWallOff", entry)
add_coeff("pairWallOff", "wallContact", "off")
solve("pairWallOn")
log = solve("pairWallOff")
if "wall contact off" not in log:
    print("FAILED: the log does not say that the wall contact is off")
    checks.failures += 1
on, off = last_state("pairWallOn", end), last_state("pairWallOff", end)
# the pair is 4 cm from the wall: with the wall on nothing touches it, so
# the two runs integrate the same states
check("  pair rebound, wall off against wall on [m/s]",
      max(math.dist(a[1], b[1]) for a, b in zip(on, off)), 0.0, 1e-12, 1.0)
check("  e_n = 0.76: particle 0 after/before", -off[0][1][0] / 0.5, 0.76, 5e-3)
# the ores then fly to the wall: standardWallInteraction rebound reflects
# their velocity about the normal of the mesh face their centres reach (a
# facet of the O-grid, not radial where it is hit), its magnitude kept
final = 0.21   # a write time (every 0.03 s)
foamfields.set_entry("pairWallOff/system/controlDict", "endTime", "%g" % final)
foamfields.set_entry("pairWallOff/system/controlDict", "startFrom", "latestTime")
solve("pairWallOff")
(xa, ua), (xb, ub) = last_state("pairWallOff", final)
if not (ua[0] > 0 and ub[0] < 0):
    print("FAILED: the ores did not rebound from the mesh's wall: U = %s, %s" % (ua, ub))
    checks.failures += 1
else:
    for i, u in enumerate((ua, ub)):
        # the pair's rebound speed, 0.760143 x 0.5 m/s, kept to round-off
        check("  speed after the rebound from the mesh wall, particle %d [m/s]" % i,
              math.hypot(*u), 0.760143 * 0.5, 1e-5)
if len(cases.wall_contacts("pairWallOff")):
    print("FAILED: contacts with the wall recorded with wallContact off")
    checks.failures += 1

print("wallContact off: refused without pairs and with the wall's entries")


for name, entry, value, expected in [
        ("offWithoutPairs", "pairs", None, "entry 'wallContact' = off without 'pairs'"),
        ("offWithFriction", "friction", "0.2", "entry 'friction' with wallContact off")]:
    cases.wall_contact_case(name, **pair)
    cases.on_riser_grid(name, RISER)
    for wallEntry in ("wall", "normalRestitution", "tangentialRestitution", "friction"):
        remove_coeff(name, wallEntry)
    add_coeff(name, "wallContact", "off")
    if value is None:
        remove_coeff(name, entry)
    else:
        add_coeff(name, entry, value)
    refused = solve(name, may_fail=True) is None
    text = open(os.path.join(name, "log.solver")).read()
    if refused and expected in text:
        print("  refused: " + next(l.strip() for l in text.splitlines() if expected in l))
    else:
        print("FAILED: %s: not refused with '%s'" % (name, expected))
        checks.failures += 1

checks.exit()
