"""riserCoupledFoam, two-way coupled, with the riser at rest: the lab
frame's moving-mesh path gives the riser frame's run.

With A = 0 the frames differ only in their code: the lab frame moves its
mesh through riserOscillation's solidBody motion (standing still: the mesh
flux is zero, the cells' old volumes are the new ones), keeps the
carrier's flux relative to the mesh, takes the wall as movingWallVelocity
and the face velocity Uf, and builds the particles' Du/Dt with the
convection relative to the mesh's velocity (zero); the riser frame has a
static mesh and its fictitious force is zero. Both compute the same
arithmetic, so the carrier and the ore must agree to round-off.

The scene: the laminar periodic section of riserCoupledCarrierAcceleration
(D = L = 0.1 m, an O-grid of 8 cells across the core and 8 along L,
water), started as the developed Poiseuille flow of u_cm = 1 m/s, with a
neutrally buoyant ore (d = 10 mm, rho_p = rho_f; drag, added mass, fluid
stress, buoyant weight) released at (0.005, 0, 0.05) m with 0.68 m/s
upward (slower than the carrier there: its wake disturbs the carrier), two-way
coupled through the diffusion kernel (3 d), one period of f = 3 Hz at the
flagship's step (5e-4 s, 667 steps).

Checked at the end and, for the ore, at every step:
- the carrier's velocity, lab against riser frame, within 1e-10 m/s
  (1e-10 of u_cm: the two runs' arithmetic differs by round-off, which
  667 steps of the linear solvers (tolerance 1e-12) keep at ~1e-12 m/s;
  measured 1e-12, the written precision);
- the ore's velocity within 1e-4 m/s over the period (the slip to the
  carrier, which agrees to round-off, then agrees as well; measured
  1e-12).
When the inner product (U - U_mesh) & grad(U) of carrierFlow's Du/Dt on a
moving mesh was taken on a temporary, it wrote its components over the
velocity it was reading (OpenFOAM's loops declare their pointers not to
alias): the lab frame's Du/Dt took half the convection of the ore's wake
in the axial component: the carrier parted by 2.1e-6 m/s and the ore by
1.9e-4 m/s within the period, and the mean axial fluid-stress force on
the ore was 7.2e-7 N in the lab frame against 5.3e-8 N in the riser
frame (both checks failed).

Figures from the run are printed.
"""
import os

import numpy as np

from riserfoam import cases, foamfields, tables
from riserfoam.checks import Checks

checks = Checks(width=70)
D, L, NU, RHO, UCM = 0.1, 0.1, 1e-6, 1000.0, 1.0
F, DT = 3.0, 5e-4
T = 1 / F
STEPS = round(T / DT)
END = STEPS * DT

FORCES = """        wallCorrectedDrag { law continuous; }
        riserAddedMass { CA 0.5; }
        riserFluidStress;
        gravity;"""


def make(frame):
    case = os.path.abspath(frame)
    cases.coupled_pipe_case(
        case, 8, 8, L=L, D=D, nu=NU, rho=RHO, uCentre=UCM, A=0.0, f=F, frame=frame,
        dt=DT, end=END, U0="poiseuille", coupled=True,
        injection=cases.single_release(0.01, (0.0, 0.0, 0.68)), forces=FORCES,
        kernel="type diffusion; width 3; widthUnit diameters;",
        cloud_functions="table { type riserParticleTable; }", tolerances=cases.ROUND_OFF_SOLVES)
    foamfields.edit(os.path.join(case, "constant/kinematicCloudProperties"),
                    r"rho0 2000;", "rho0 %r;" % RHO)
    foamfields.write_dictionary(os.path.join(case, "constant/kinematicCloudPositions"),
                                "((0.005 0 0.05))\n", "vectorField")
    if frame == "lab":
        # the riser's moving mesh, standing still (A = 0), and its moving wall
        foamfields.write_dictionary(os.path.join(case, "constant/dynamicMeshDict"), """
dynamicFvMesh   dynamicMotionSolverFvMesh;
motionSolverLibs (fvMotionSolvers);
motionSolver    solidBody;
solidBodyMotionFunction riserOscillation;
""")
        foamfields.edit(os.path.join(case, "0/U"), "noSlip", "movingWallVelocity")
    log = cases.run(["riserCoupledFoam", "-case", case],
                    os.path.join(case, "log.riserCoupledFoam"))
    if frame == "lab" and "Selecting dynamicFvMesh dynamicMotionSolverFvMesh" not in log:
        raise RuntimeError("the lab frame's case did not move its mesh")
    return case


def velocities(case):
    times = [d for d in os.listdir(case) if d != "0" and d.replace(".", "").isdigit()]
    last = max(times, key=float)
    return np.array(foamfields.read_vectors(os.path.join(case, last, "U"), "internalField"))


def table(case):
    return tables.read(os.path.join(case, "postProcessing/lagrangian/kinematicCloud/"
                                    "riserParticleTable/particles.dat"))


lab, rsr = make("lab"), make("riser")

print("carrier after one period (%d steps)" % STEPS)
checks.near("  largest velocity difference, lab against riser frame [m/s]",
            abs(velocities(lab) - velocities(rsr)).max(), 0, 1e-10, 1.0)

print("the ore over the period")
tl, tr = table(lab), table(rsr)
if len(tl["t"]) != STEPS or len(tr["t"]) != STEPS:
    checks.failures += 1
    print("  FAILED: %d and %d rows, expected %d" % (len(tl["t"]), len(tr["t"]), STEPS))
n = min(len(tl["t"]), len(tr["t"]))
velocity = np.hypot(np.hypot(np.array(tl["Ux"][:n]) - np.array(tr["Ux"][:n]),
                             np.array(tl["Uy"][:n]) - np.array(tr["Uy"][:n])),
                    np.array(tl["Uz"][:n]) - np.array(tr["Uz"][:n]))
print("  ore's rise in the period: %.4f m; mean fluid-stress force (axial): lab %.4e N,"
      " riser %.4e N" % (tr["lift"][n - 1], np.mean(tl["F_riserFluidStress_z"][:n]),
                         np.mean(tr["F_riserFluidStress_z"][:n])))
checks.near("  largest velocity difference of the ore [m/s]", velocity.max(), 0, 1e-4, 1.0)
checks.exit()
