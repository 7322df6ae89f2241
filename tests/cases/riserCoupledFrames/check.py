"""riserCoupledFoam in an oscillating riser: the carrier moves with the
riser and stays the Poiseuille flow relative to it, in either frame.

The laminar periodic riser of riserCoupledPoiseuille (D = L = 0.1 m,
Re = 500, no particles, O-grid of 16 cells across the core) is first
brought to its steady state with the riser at rest (dt = 100 s to
t = 2000 s). From that state, with the riser oscillating at A = 0.1 m,
f = 3 Hz (wall speed A omega = 1.9 m/s, acceleration A omega^2 = 36 m/s^2,
about 190 times the flow's centre-line speed and 2200 times the driving
acceleration), for one period:

- riser frame (static mesh, fictitious force -a_r on the carrier): the
  pressure takes the uniform force whole (p is the pressure less -a_r.x),
  so the flow is that of the same run with the riser at rest (A = 0; it
  still settles by 1e-9 in these steps): velocity and dp/dz equal to
  round-off (1e-12; the lateral velocity, zero at rest, within the
  linear solvers' tolerance, 1e-10 of u_max);
- lab frame (mesh and wall moving, riserOscillation, started with the
  carrier moving with the riser): the carrier's velocity less the mesh's
  (the mesh's velocity over the step, (x_c(t) - x_c(t - dt))/dt) is the
  riser frame's; lateral within 1e-3 A omega, axial within 2e-3 u_max,
  dp/dz within 1e-4, at 80 steps a period. The differences are the time
  discretisation's: measured at 20, 40, 80 steps a period, the largest
  lateral one 1.3e-2, 3.3e-3, 8.8e-4 m/s (7e-3, 1.7e-3, 4.7e-4 of A omega),
  the axial one 2.4e-4, 3.4e-5, 1.0e-5 m/s, dp/dz 4.5e-2, 7.6e-4, 1.5e-5
  relative; checked: halving the step from 40 to 80 steps a period shrinks
  the lateral and axial differences by more than 2.
"""
import math
import os
import shutil

from riserfoam import cases, foamfields
from riserfoam.checks import Checks

checks = Checks(width=64)
D, NU, RHO, UB, N = 0.1, 1e-6, 1000.0, 0.005, 16
A, F = 0.1, 3.0
OMEGA = 2 * math.pi * F
T = 1 / F


# the steady state at rest
rest = os.path.abspath("rest")
U_rest, dpdz_rest = cases.coupled_rest_state(rest, N, D, NU, RHO, UB)


def oscillating(name, frame, steps, amplitude=A):
    """one period from the state at rest (its U and its drive's gradient);
    the largest lateral velocity relative to the mesh, the largest change
    of the axial velocity, the last dp/dz, and the last velocity field"""
    case = os.path.abspath(name)
    dt = T / steps
    cases.coupled_pipe_case(case, N, 4, D=D, nu=NU, rho=RHO, uCentre=2 * UB, A=amplitude,
                            f=F, frame=frame, dt=dt, end=T, write_every=steps // 4,
                            tolerances=cases.ROUND_OFF_SOLVES)
    shutil.rmtree(os.path.join(case, "0"))
    shutil.copytree(os.path.join(rest, "2000"), os.path.join(case, "0"))
    os.remove(os.path.join(case, "0", "phi"))
    if frame == "lab":
        # the carrier moving with the riser, whose velocity is A omega at t = 0
        rows = "\n".join("(%.17g %.17g %.17g)" % (u[0] + A * OMEGA, u[1], u[2]) for u in U_rest)
        foamfields.write_dictionary(os.path.join(case, "0/U"), """
dimensions [0 1 -1 0 0 0 0];
internalField nonuniform List<vector> %d
(
%s
);
boundaryField
{
    riserWall { type movingWallVelocity; value uniform (%.17g 0 0); }
    bottom { type cyclic; }
    top { type cyclic; }
}
""" % (len(U_rest), rows, A * OMEGA), "volVectorField")
    cases.run(["riserCoupledFoam", "-case", case], os.path.join(case, "log.riserCoupledFoam"))
    return cases.deviation_from_rest(
        case, U_rest,
        lambda t: (A * (math.sin(OMEGA * t) - math.sin(OMEGA * (t - dt))) / dt
                   if frame == "lab" else 0, 0))


print("riser frame, 20 steps a period: the flow of the riser at rest")
lateral, _, dpdz, U = oscillating("riser20", "riser", 20)
_, _, dpdz_still, U_still = oscillating("still20", "riser", 20, amplitude=0.0)
checks.near("  largest lateral velocity / u_max", lateral, 0, 1e-10, 2 * UB)
checks.near("  largest difference of the axial velocity / u_max",
            abs(U[:, 2] - U_still[:, 2]).max(), 0, 1e-12, 2 * UB)
checks.near("  dp/dz [Pa/m] against the riser at rest", dpdz, dpdz_still, 1e-12)

print("lab frame: the flow relative to the mesh is the flow at rest")
found = {}
for steps in (40, 80):
    found[steps] = oscillating("lab%d" % steps, "lab", steps)
lateral, axial, dpdz, _ = found[80]
checks.near("  80 steps: largest lateral relative velocity / (A omega)", lateral, 0, 1e-3, A * OMEGA)
checks.near("  80 steps: largest change of the axial velocity / u_max", axial, 0, 2e-3, 2 * UB)
checks.near("  80 steps: dp/dz [Pa/m] against the riser at rest", dpdz, dpdz_rest, 1e-4)
for k, label in ((0, "lateral"), (1, "axial")):
    ratio = found[40][k] / found[80][k]
    ok = ratio > 2
    checks.failures += not ok
    print("  %s difference, 40 against 80 steps a period: %.3e / %.3e = %.1f (> 2) %s"
          % (label, found[40][k], found[80][k], ratio, "ok" if ok else "FAILED"))
checks.exit()
