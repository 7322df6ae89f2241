"""riserCoupledFoam in the dilute limit: one ore, two-way coupled through
a wide enough coarse-particle kernel, moves as in the one-way run on the
same computed carrier.

The flagship's ore (d = 10 mm, 2000 kg/m^3, released at (0.02, 0.02,
0.05) m with 0.68 m/s upward) in the flagship's riser (D = 0.1 m, u_cm =
1 m/s, A = 0.1 m, f = 3 Hz, riser frame, its wall contact; forces drag,
fluid stress, buoyant weight and the frame force) on a computed laminar
carrier: a periodic section L = 0.2 m (O-grid of 8 cells across the core,
20 along), water, started as the Poiseuille flow of u_cm at the drive's
bulk velocity u_cm/2, with the drive's gradient of that flow
(cases.poiseuille_start: the carrier starts steady, and the riser frame's
oscillation leaves it so, riserCoupledFrames). One riser period, 1/3 s,
dt = 0.5 ms; the ore touches the wall three times. Two runs for each
kernel width b (kernel { type diffusion; width b; widthUnit diameters; }):
coupled false (one-way: the carrier does not see the ore, alpha_c = 1, no
reaction) and coupled true; their lifting distances (riserParticleTable's
lift) differ by what the ore does to the carrier: its reaction, and its
volume in alpha_c (whose effects the fluid stress's reaction balances).

Why they agree: the reaction takes from the carrier what the fluid
forces give the ore, on average its buoyant weight W = (rho_p - rho_f) g
pi d^3/6 = 5.1 mN, spread by the kernel over V_k = (pi b^2)^(3/2), the
Gaussian's volume (1/its peak). The self-induced disturbance is the
kernel's fluid accelerated at W/(rho_f V_k); at the ore's Reynolds number
(~5000) nothing viscous limits it over a run far shorter than the viscous
time b^2/nu (900 s; sqrt(nu T) = 0.6 mm). Were the ore held in the fluid
it pushes for the whole run T, it would slow its rise by
    Delta = W T^2 / (2 rho_f V_k),
1.9 mm at b = 3d (3.6 % of the 53 mm lift) and 0.24 mm at b = 6d
(0.45 %): an upper bound. Its slip (about 0.5 m/s) carries it out of that
fluid within b/0.5 m/s, 0.06 s at b = 3d, a fifth of the run, so the
measured slowing is a fraction of Delta, a larger one at the wider kernel
(0.12 s), and falls more slowly than b^-3. Checked:

- b = 6d: the lift over the run, two-way against one-way, within 1 %
  (the requirement). Measured -0.20 % (0.10 mm); the lateral track within
  0.07 % of D;
- both widths: the lift difference (one-way less two-way: the reaction
  pushes the fluid about the ore down) is a slowing, more than 0.05
  Delta (a reaction missing or of the wrong sign would leave none or a
  gain), and at most Delta (the bound), and it is smaller at b = 6d than
  at 3d. Measured 0.15 Delta (b = 3d: 0.28 mm, the lift 0.53 % off, the
  lateral track 0.14 % of D) and 0.45 Delta (b = 6d); 2.6 times smaller
  for b doubled. (The magnitude of the reaction itself is checked to
  1e-10 against the ores' deposits by riserCoupledKernel.) Those were
  with the deposits in the cell of the ore's centre; continuous in its
  position (particleKernel, pointShares): 0.17 Delta (b = 3d: 0.33 mm,
  -0.62 %, 0.12 % of D) and 0.43 Delta (b = 6d), 3.2 times smaller.
  With the volume continuous and the reaction still in the centre's
  cell, the b = 6d ore gained 0.09 mm (-0.37 Delta, which the check of a
  slowing caught: the reaction no longer balanced the displaced
  fluid). The test's
  earlier one-way run displaced the carrier by the ore without its
  reaction, which left the riser's acceleration (1 - alpha_c) a_r
  unbalanced where the ore was (an artefact scaling as b^-3, as Delta
  does); against it, and with the particles moved before the carrier,
  the difference had come out 0.69 and 0.78 Delta.

Figures from the run are printed; the ones above are those measured when
the test was written.
"""
import concurrent.futures
import math
import os

import numpy as np

from riserfoam import cases, foamfields, tables
from riserfoam.checks import Checks

checks = Checks(width=66)
D, L, RHO, RHO_P, G, d = 0.1, 0.2, 1000.0, 2000.0, 9.81, 0.01
A, F, UCM = 0.1, 3.0, 1.0
DT, END = 5e-4, 1 / 3.0
WIDTHS = (3, 6)
RELEASE = cases.single_release(d, (0.0, 0.0, 0.68))


def riser(name, coupled, width):
    case = os.path.abspath(name)
    cases.coupled_pipe_case(case, 8, 20, L=L, D=D, rho=RHO, uCentre=UCM, A=A, f=F,
                            frame="riser", dt=DT, end=END, U0="poiseuille", injection=RELEASE,
                            coupled=coupled, collision=cases.flagship_contact(),
                            kernel="type diffusion; width %d; widthUnit diameters;" % width,
                            cloud_functions="table { type riserParticleTable; }")
    foamfields.write_dictionary(os.path.join(case, "constant/kinematicCloudPositions"),
                                "((0.02 0.02 0.05))\n", "vectorField")
    return case


def solve(case):
    cases.run(["riserCoupledFoam", "-case", case], os.path.join(case, "log.riserCoupledFoam"))


def track(case):
    """the ore's lift and its position across the riser, step by step"""
    t = tables.read(os.path.join(case, "postProcessing/lagrangian/kinematicCloud/"
                                 "riserParticleTable/particles.dat"))
    return np.array(t["lift"]), np.array(t["xr"]), np.array(t["yr"])


runs = {b: (riser("oneWay%d" % b, False, b), riser("twoWay%d" % b, True, b)) for b in WIDTHS}
with concurrent.futures.ThreadPoolExecutor(max_workers=2) as pool:
    list(pool.map(solve, [case for pair in runs.values() for case in pair]))

weight = (RHO_P - RHO) * G * math.pi / 6 * d ** 3
found = {}
for b in WIDTHS:
    (lift1, x1, y1), (lift2, x2, y2) = track(runs[b][0]), track(runs[b][1])
    lateral = np.hypot(x2 - x1, y2 - y1).max()
    delta = weight * END ** 2 / (2 * RHO * (math.pi * (b * d) ** 2) ** 1.5)
    found[b] = lift1[-1] - lift2[-1]
    print("b = %d d: lift one-way %.5f m, two-way %.5f m (%+.2f %%); largest lateral"
          " difference %.3e m (%.2f %% of D); Delta %.3e m"
          % (b, lift1[-1], lift2[-1], 100 * (lift2[-1] / lift1[-1] - 1), lateral,
             100 * lateral / D, delta))
    if b == 6:
        checks.near("b = 6 d: lift over the run [m], two-way against one-way",
                    lift2[-1], lift1[-1], 1e-2)
    ratio = found[b] / delta
    ok = 0.05 < ratio <= 1
    checks.failures += not ok
    print("%-70s %13.7g (0.05 to 1) %s" % ("b = %d d: lift difference / Delta" % b, ratio,
                                            "ok" if ok else "FAILED"))
ok = found[3] > found[6]
checks.failures += not ok
print("lift difference at b = 3 d over that at b = 6 d: %.2f (> 1) %s"
      % (found[3] / found[6], "ok" if ok else "FAILED"))
checks.exit()
