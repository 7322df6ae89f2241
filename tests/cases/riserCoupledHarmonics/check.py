"""riserCoupledFoam with a riser moving in x and y (motion { type harmonics;
x ((0.025 6 0)); y ((0.1 3 0)); }: in-line at twice the cross-flow
frequency, the figure-of-eight; wall speeds 0.94 and 1.9 m/s, accelerations
35.5 m/s^2 in each direction): the carrier moves with the riser and stays
the Poiseuille flow relative to it, in either frame, as riserCoupledFrames
checks for the sinusoid (same pipe, same state at rest, same tolerances):

- riser frame (static mesh, fictitious force -a_r on the carrier, both
  components): the pressure takes the uniform force whole, so the flow is
  that of the riser at rest: lateral velocities within the linear solvers'
  tolerance (1e-10 of u_max), the axial velocity and dp/dz to round-off
  (1e-12);
- lab frame (mesh and wall moving in x and y, riserOscillation, started
  with the carrier moving with the riser): the carrier's velocity less the
  mesh's ((axis(t) - axis(t - dt))/dt, both components) is the riser
  frame's; lateral within 1e-3 of the wall's largest speed, axial within
  2e-3 u_max, dp/dz within 1e-4, at 160 steps a period of the cross-flow
  harmonic (80 of the in-line one, the sinusoid's 80 in riserCoupledFrames;
  at 80 steps the axial difference was 2.5e-3 u_max), and halving the step
  from 80 to 160 steps a period shrinks the lateral and axial differences
  by more than 2 (measured at 40 and 80 steps: 4.0 and 3.2).
"""
import math
import os
import re
import shutil

import numpy as np

from riserfoam import cases, foamfields
from riserfoam.checks import Checks

checks = Checks(width=64)
D, NU, RHO, UB, N = 0.1, 1e-6, 1000.0, 0.005, 16
AX, WX, AY, WY = 0.025, 2 * math.pi * 6.0, 0.1, 2 * math.pi * 3.0
T = 2 * math.pi / WY
MOTION = "motion { type harmonics; x ((%r 6 0)); y ((%r 3 0)); }\n" % (AX, AY)
WALL_SPEED = math.hypot(AX * WX, AY * WY)


def axis(t):
    return np.array([AX * math.sin(WX * t), AY * math.sin(WY * t)])


# the steady state at rest
rest = os.path.abspath("rest")
U_rest, dpdz_rest = cases.coupled_rest_state(rest, N, D, NU, RHO, UB)


def oscillating(name, frame, steps, moving=True):
    """one period from the state at rest; the largest lateral velocity
    relative to the mesh, the largest change of the axial velocity, the last
    dp/dz, and the last velocity field"""
    case = os.path.abspath(name)
    dt = T / steps
    # a sinusoid first (the moving mesh's dictionaries), then its A, f, phi0
    # replaced by the harmonics
    cases.coupled_pipe_case(case, N, 4, D=D, nu=NU, rho=RHO, uCentre=2 * UB,
                            A=0.1 if moving else 0.0, f=3.0, frame=frame, dt=dt, end=T,
                            write_every=steps // 4)
    if moving:
        path = os.path.join(case, "constant/riserProperties")
        text = open(path).read()
        text = re.sub(r"^\s*(A|f|phi0)\s[^;]*;\s*$", "", text, flags=re.M)
        open(path, "w").write(text + MOTION)
    shutil.rmtree(os.path.join(case, "0"))
    shutil.copytree(os.path.join(rest, "2000"), os.path.join(case, "0"))
    os.remove(os.path.join(case, "0", "phi"))
    if frame == "lab":
        # the carrier moving with the riser, whose velocity is (AX WX, AY WY) at t = 0
        Ux, Uy = AX * WX, AY * WY
        rows = "\n".join("(%.17g %.17g %.17g)" % (u[0] + Ux, u[1] + Uy, u[2]) for u in U_rest)
        foamfields.write_dictionary(os.path.join(case, "0/U"), """
dimensions [0 1 -1 0 0 0 0];
internalField nonuniform List<vector> %d
(
%s
);
boundaryField
{
    riserWall { type movingWallVelocity; value uniform (%.17g %.17g 0); }
    bottom { type cyclic; }
    top { type cyclic; }
}
""" % (len(U_rest), rows, Ux, Uy), "volVectorField")
    cases.run(["riserCoupledFoam", "-case", case], os.path.join(case, "log.riserCoupledFoam"))
    return cases.deviation_from_rest(
        case, U_rest,
        lambda t: (axis(t) - axis(t - dt)) / dt if frame == "lab" else np.zeros(2))


print("riser frame, 20 steps a period: the flow of the riser at rest")
lateral, _, dpdz, U = oscillating("riser20", "riser", 20)
_, _, dpdz_still, U_still = oscillating("still20", "riser", 20, moving=False)
checks.near("  largest lateral velocity / u_max", lateral, 0, 1e-10, 2 * UB)
checks.near("  largest difference of the axial velocity / u_max",
            abs(U[:, 2] - U_still[:, 2]).max(), 0, 1e-12, 2 * UB)
checks.near("  dp/dz [Pa/m] against the riser at rest", dpdz, dpdz_still, 1e-12)

print("lab frame: the flow relative to the mesh is the flow at rest")
found = {}
for steps in (80, 160):
    found[steps] = oscillating("lab%d" % steps, "lab", steps)
lateral, axial, dpdz, _ = found[160]
checks.near("  160 steps: largest lateral relative velocity / wall speed", lateral, 0, 1e-3,
            WALL_SPEED)
checks.near("  160 steps: largest change of the axial velocity / u_max", axial, 0, 2e-3, 2 * UB)
checks.near("  160 steps: dp/dz [Pa/m] against the riser at rest", dpdz, dpdz_rest, 1e-4)
for k, label in ((0, "lateral"), (1, "axial")):
    ratio = found[80][k] / found[160][k]
    ok = ratio > 2
    checks.failures += not ok
    print("  %s difference, 80 against 160 steps a period: %.3e / %.3e = %.1f (> 2) %s"
          % (label, found[80][k], found[160][k], ratio, "ok" if ok else "FAILED"))
checks.exit()
