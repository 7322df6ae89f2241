"""Head-on impacts of two particles through riserContact's pair contact;
see run."""
import math
import os
import sys

from riserfoam import cases, foamfields
from riserfoam.checks import Checks

checks = Checks()
check = checks.near




def final_velocities(case, end):
    """U of the two parcels at the end, ordered by origId"""
    for app in ("blockMesh", "icoUncoupledKinematicParcelFoam"):
        cases.run([app, "-case", case], os.path.join(case, "log." + app))
    log = open(os.path.join(case, "log.icoUncoupledKinematicParcelFoam")).read()
    if "outside the pipe" in log:
        sys.exit("FAILED: a particle left the pipe in %s" % case)
    folder = os.path.join(case, "%g" % end, "lagrangian", "kinematicCloud")
    U = foamfields.read_vectors(os.path.join(folder, "U"))
    ids = foamfields.read_scalars(os.path.join(folder, "origId"))
    return [u for _, u in sorted(zip(ids, U))]


# two ores, soft (E = 1e8 Pa) so that a contact (~0.5 ms) spans a few flow
# steps of 1e-4 s; no fluid forces, no gravity; they meet on the x axis
# inside a static riser of D = 0.1 m, far from its wall
E, nu, rho, dt, end = 1e8, 0.3, 2500.0, 1e-4, 0.03
start = [(-0.012, 0.0, 0.02), (0.012, 0.0, 0.02)]


def impact(name, d0, d1, v0, v1, pairs):
    cases.wall_contact_case(name, D=0.1, radius=0.5 * d0, rho=rho, E=E, nu=nu,
                            wall_E=E, wall_nu=nu, e_n=0.5, e_t=1.0, mu=0.0,
                            velocities=[(v0, 0.0), (v1, 0.0)], positions=start,
                            dt=dt, end=end, pairs=pairs, diameters=[d0, d1])
    return final_velocities(name, end)


print("head-on, like spheres (d = 10 mm) at +-0.5 m/s: rebound at e_n times the speed")
for e in (0.3, 0.76, 1.0):
    U = impact("like_e%g" % e, 0.01, 0.01, 0.5, -0.5, (e, 1.0, 0.0))
    check("  e_n = %g: particle 0 after/before" % e, -U[0][0] / 0.5, e, 5e-3)
    check("  e_n = %g: particle 1 after/before" % e, U[1][0] / 0.5, e, 5e-3)

print("head-on, 10 mm against 6 mm at +0.5 and -0.2 m/s: momentum and e_n")
m0, m1 = (rho * math.pi / 6 * d ** 3 for d in (0.01, 0.006))
v0, v1 = 0.5, -0.2
for e in (0.3, 1.0):
    U = impact("unlike_e%g" % e, 0.01, 0.006, v0, v1, (e, 1.0, 0.0))
    w0 = (m0 * v0 + m1 * v1 - m1 * e * (v0 - v1)) / (m0 + m1)
    w1 = w0 + e * (v0 - v1)
    # errors relative to the approach speed v0 - v1
    check("  e_n = %g: particle 0 after [m/s]" % e, U[0][0], w0, 5e-3, v0 - v1)
    check("  e_n = %g: particle 1 after [m/s]" % e, U[1][0], w1, 5e-3, v0 - v1)

print("across the ends of a periodic section (cyclic bottom and top): they rebound too")
name = "periodic"
cases.wall_contact_case(name, D=0.1, radius=0.005, rho=rho, E=E, nu=nu, wall_E=E, wall_nu=nu,
                        e_n=0.5, e_t=1.0, mu=0.0, velocities=[(0.0, -0.5), (0.0, 0.5)],
                        positions=[(0.0, 0.0, 0.008), (0.0, 0.0, 0.092)], dt=dt, end=end,
                        pairs=(0.76, 1.0, 0.0))
mesh = os.path.join(name, "system", "blockMeshDict")
text = open(mesh).read().replace(
    "walls { type wall; faces ( (0 3 2 1) (4 5 6 7) (0 1 5 4) (1 2 6 5) (2 3 7 6) (3 0 4 7) ); }",
    "walls { type wall; faces ( (0 1 5 4) (1 2 6 5) (2 3 7 6) (3 0 4 7) ); }\n"
    "    bottom { type cyclic; neighbourPatch top; faces ( (0 3 2 1) ); }\n"
    "    top { type cyclic; neighbourPatch bottom; faces ( (4 5 6 7) ); }")
assert "cyclic" in text
open(mesh, "w").write(text)
path = os.path.join(name, "0", "U")
text = open(path).read().replace(
    "boundaryField { walls { type noSlip; } }",
    "boundaryField { walls { type noSlip; } bottom { type cyclic; } top { type cyclic; } }")
open(path, "w").write(text)
U = final_velocities(name, end)
check("  e_n = 0.76: particle 0 after/before", U[0][2] / 0.5, 0.76, 5e-3)
check("  e_n = 0.76: particle 1 after/before", -U[1][2] / 0.5, 0.76, 5e-3)

print("without pairs the two pass through each other")
U = impact("noPairs", 0.01, 0.01, 0.5, -0.5, None)
check("  particle 0 keeps its velocity", U[0][0], 0.5, 1e-9)

checks.exit()
