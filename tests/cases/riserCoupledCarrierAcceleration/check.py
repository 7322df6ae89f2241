"""riserCoupledFoam: the particles feel the carrier's acceleration, in
either frame.

The particles move in the carrier of the flow step they move in, and the
fluid stress and the added mass take its material derivative Du/Dt from
the carrier's change over that step (carrierFlow). In the lab frame the
carrier of an oscillating riser is accelerated with the riser (A omega^2),
and a particle that moves with it must be accelerated by the fluid as the
riser is.

The laminar periodic riser of riserCoupledFrames (D = L = 0.1 m, an O-grid
of 8 cells across the core, water), started as the developed Poiseuille
flow of u_cm (cases.poiseuille_start, moving with the riser in the lab
frame), the riser oscillating at A = 0.1 m, f = 3 Hz (wall speed A omega =
1.9 m/s, acceleration A omega^2 = 36 m/s^2).

1. A neutrally buoyant sphere (d = 10 mm, rho_p = rho_f; drag, added
   mass, fluid stress, buoyant weight, and in the riser frame the frame
   force), released near the axis with the carrier's velocity, one-way
   (coupled false: the carrier does not see it), u_cm = 0.1 m/s, two
   periods of 160 steps (the cloud's maxCo 0.3: sub-steps of at most 0.3
   of a step). With rho_p = rho_f its equation, (m_p + C_A m_f) dv/dt =
   (1 + C_A) m_f Du/Dt + drag, keeps v = u: checked, each step, its
   lateral velocity against the riser's within 1e-3 A omega (the
   requirement; in the lab frame against the riser's velocity A omega
   cos(omega t): the computed carrier moves with the mesh's velocity over
   the step, (x_c(t) - x_c(t - dt))/dt (riserCoupledFrames), but
   carrierFlow gives the particles the carrier relative to its wall plus
   the riser's velocity at their time and its velocity change over their
   step, as the riser frame does; relative to the riser, zero, in the riser
   frame). Measured 2.6e-4 (lab, in the first steps) and 3e-18 (riser);
   with the riser's acceleration at the end of each sub-step in place of
   its change over the sub-step, 5.6e-3 (the first-order error of the
   particle's Euler step). Before the solver moved the
   particles in the carrier of their step, the lab frame's particle was
   0.67 m/s (0.36 A omega) off within 0.05 s; with the carrier's
   end-of-step velocity seen throughout a step tracked in sub-steps, a
   1 mm sphere was 1.4e-2 A omega off (carrierFlow's velocity at the
   particle's time mends it); with the one-way carrier displaced by the
   sphere (alpha_c < 1 about it) 1.7e-4 (lab) and 9.6e-5 (riser).
2. The flagship's ore (d = 10 mm, 2000 kg/m^3; drag, added mass, fluid
   stress, buoyant weight, the frame force in the riser frame), released
   at (0.005, 0, 0.05) m relative to the axis with 0.68 m/s upward, in the
   flagship's carrier (u_cm = 1 m/s), two-way coupled through the kernel
   of oscillatingContactCoupled (type diffusion, width 3 d; 8 cells along
   L), the riser oscillating at A = 0.01 m (so that the ore stays off the
   wall: at 0.1 m it reaches it within half a period, and its contacts
   then magnify any difference), five periods of 320 steps: the two
   frames are the same physics, so the ore's lift and its track relative
   to the riser agree, the lift within 1 % and the track within 0.01 D.
   The lab frame's discrete riser is first order in time (the carrier
   moves with the mesh's velocity over the step, the riser's at
   t - dt/2). Measured, lift and track apart: after one period 0.45 %,
   0.17 %, 0.10 % and 0.0041, 0.0022, 0.0013 D at 160, 320, 640 steps a
   period; after five 0.95 %, 0.77 % and 0.0043, 0.0072 D at 320, 640
   steps (one-way, coupled false: 0.96 %, 0.50 % and 0.0057, 0.0025 D).
   Those were with the lab frame's particles in the carrier's wall
   kinematics and the added mass's reaction frame-dependent
   (riserCoupledFramesAtRest); now, after five periods, 0.20 % and
   0.00090 D at 320 steps (the test's), 0.11 % and 0.00055 D at 640:
   first order, five and eleven times inside the tolerances.
3. The same two runs: the ore's axial velocity has no one-step dips (a
   drop over a step undone over the next, min(-dw_k, dw_(k+1)) > 0), the
   mark of a carrier that jumps as the ore crosses a cell face (the
   fluid stress and added mass take the jump's Du/Dt). Checked: the
   largest dip within 0.1 of g dt (the velocity gravity gives in a step,
   1.0e-2 m/s at 320 steps a period): the ore's smooth dynamics reverse
   its acceleration within a step by at most |da/dt| dt^2 ~ (A omega^2 +
   g) omega dt^2 ~ 2.8e-4 m/s, 0.027 g dt. Measured: 4.7e-6 m/s (lab) and
   6.2e-6 m/s (riser), 4.6e-4 and 6.1e-4 g dt (at 640 steps 3.5e-4 and
   2.8e-4). Before the kernel's deposits were continuous
   in the ore's position (particleKernel, pointShares), each face
   crossing gave a dip of 0.035-0.040 m/s, 7-8 g dt (measured in the
   riser frame of tutorials/riser/coupledFrames, 667 steps a period).

Figures from the run are printed.
"""
import concurrent.futures
import math
import os

import numpy as np

from riserfoam import cases, foamfields, tables
from riserfoam.checks import Checks

checks = Checks(width=70)
D, L, NU, RHO, G = 0.1, 0.1, 1e-6, 1000.0, 9.81
A, F = 0.1, 3.0
OMEGA, T = 2 * math.pi * F, 1 / F
STEPS = 160
DT = T / STEPS
ORE_STEPS, ORE_A, PERIODS = 320, 0.01, 5

FORCES = """        wallCorrectedDrag { law continuous; }
        riserAddedMass { CA 0.5; }
        riserFluidStress;
%s        gravity;"""


def make(name, frame, rho_p, d, uCentre, position, u_axial, periods, collision=None,
         coupled=False, kernel="type none;", nz=2, steps=STEPS, amplitude=A):
    case = os.path.abspath(name)
    lab = frame == "lab"
    cases.coupled_pipe_case(
        case, 8, nz, L=L, D=D, nu=NU, rho=RHO, uCentre=uCentre, A=amplitude, f=F,
        frame=frame,
        dt=T / steps, end=periods * T, U0="poiseuille",
        injection=cases.single_release(d, (amplitude * OMEGA if lab else 0.0, 0.0, u_axial)),
        forces=FORCES % ("" if lab else "        riserFrame;\n"),
        collision=collision, coupled=coupled, kernel=kernel, cloud_functions="table { type riserParticleTable; }")
    foamfields.edit(os.path.join(case, "constant/kinematicCloudProperties"),
                    r"rho0 2000;", "rho0 %r;" % rho_p)
    foamfields.write_dictionary(os.path.join(case, "constant/kinematicCloudPositions"),
                                "((%r %r %r))\n" % tuple(position), "vectorField")
    return case


def solve(case):
    cases.run(["riserCoupledFoam", "-case", case], os.path.join(case, "log.riserCoupledFoam"))


def table(case):
    return tables.read(os.path.join(case, "postProcessing/lagrangian/kinematicCloud/"
                                    "riserParticleTable/particles.dat"))


# the release speeds are near the carrier's (the slip they leave is axial)
NEAR_AXIS = (0.001, 0.002, 0.05)
ORE = (0.005, 0.0, 0.05)
KERNEL = "type diffusion; width 3; widthUnit diameters;"
runs = {
    ("tracer", "lab"): make("tracerLab", "lab", RHO, 0.01, 0.1, NEAR_AXIS, 0.1, 2),
    ("tracer", "riser"): make("tracerRiser", "riser", RHO, 0.01, 0.1, NEAR_AXIS, 0.1, 2),
    ("ore", "lab"): make("oreLab", "lab", 2000.0, 0.01, 1.0, ORE, 0.68, PERIODS,
                           None, True, KERNEL, 8, ORE_STEPS, ORE_A),
    ("ore", "riser"): make("oreRiser", "riser", 2000.0, 0.01, 1.0, ORE, 0.68, PERIODS,
                           None, True, KERNEL, 8, ORE_STEPS, ORE_A),
}
with concurrent.futures.ThreadPoolExecutor(max_workers=2) as pool:
    list(pool.map(solve, runs.values()))

print("1. a neutrally buoyant particle follows the riser's carrier")
for frame in ("lab", "riser"):
    t = table(runs[("tracer", frame)])
    time = np.array(t["t"])
    if frame == "lab":
        # the riser's velocity (x_c = A sin(omega t)), which the particles
        # see the carrier move with at their time
        riser = A * OMEGA * np.cos(OMEGA * time)
        lateral = np.hypot(np.array(t["Ux"]) - riser, np.array(t["Uy"]))
    else:
        lateral = np.hypot(np.array(t["Urx"]), np.array(t["Ury"]))
    worst = int(np.argmax(lateral))
    print("  %s frame: %d steps to t = %.4f s; largest lateral velocity relative to the"
          " riser %.3e m/s at t = %.4f s" % (frame, len(time), time[-1], lateral[worst],
                                               time[worst]))
    checks.near("  %s frame: largest lateral slip from the riser / (A omega)" % frame,
                lateral.max(), 0, 1e-3, A * OMEGA)

print("2. the ore moves alike in both frames (%d steps a period)" % ORE_STEPS)
lab, rsr = table(runs[("ore", "lab")]), table(runs[("ore", "riser")])
for name, tab in (("lab", lab), ("riser", rsr)):
    r = np.hypot(np.array(tab["xr"]), np.array(tab["yr"]))
    gap = D / 2 - 0.01 / 2 - r
    print("  %s frame: lift %.5f m after %d periods; largest distance from the axis %.4f D;"
          " least gap to the wall %.2f mm" % (name, tab["lift"][-1], PERIODS, r.max() / D,
                                               1e3 * gap.min()))
    if gap.min() <= 0:
        checks.failures += 1
        print("  FAILED: the ore reached the wall in the %s frame" % name)
n = min(len(lab["t"]), len(rsr["t"]))
track = np.hypot(np.array(lab["xr"][:n]) - np.array(rsr["xr"][:n]),
                 np.array(lab["yr"][:n]) - np.array(rsr["yr"][:n]))
checks.near("  lift after %d periods [m], lab frame against riser frame" % PERIODS,
            lab["lift"][n - 1], rsr["lift"][n - 1], 1e-2)
checks.near("  largest distance between the tracks relative to the riser / D",
            track.max() / D, 0, 1e-2, 1)

print("3. no one-step dips of the ore's axial velocity at cell faces")
for name, tab in (("lab", lab), ("riser", rsr)):
    dw = np.diff(np.array(tab["Urz"]))
    dips = np.maximum(np.minimum(-dw[:-1], dw[1:]), 0)
    worst = int(np.argmax(dips))
    print("  %s frame: largest dip %.3e m/s at t = %.4f s" % (name, dips[worst],
                                                          tab["t"][worst + 1]))
    checks.near("  %s frame: largest one-step dip of the axial velocity / (g dt)" % name,
                dips.max(), 0, 0.1, G * T / ORE_STEPS)
checks.exit()
