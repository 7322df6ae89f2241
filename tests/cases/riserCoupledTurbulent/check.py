"""riserCoupledFoam with a RAS model (kEpsilon, standard wall functions):
the turbulent periodic riser against the stock solver, Prandtl's
friction law and the log law.

D = L = 0.1 m, water (nu = 1e-6 m^2/s), bulk velocity 1 m/s: Re = 1e5;
O-grid of 16 cells across the core, 2 along; from a plug flow, dt =
0.05 s to t = 30 s (dp/dz then changes by 3e-11 per second; at 15 s
still by 3e-6). RAS kEpsilon with kqRWallFunction, epsilonWallFunction,
nutkWallFunction (Launder & Spalding 1974: u_tau from k, the log law
kappa = 0.41, E = 9.8 at the wall cell's centre). The wall cells' centres
lie at y+ = 40 to 53 (y: the distance to the mesh's wall, 64 chords of
the circle; y+ = u_tau y / nu, u_tau from the wall stress that balances
dp/dz): in the log layer, where the wall function holds.

- The same case under the stock pimpleFoam driven by the fvOption
  meanVelocityForce (Ubar 1 m/s) gives the same pressure gradient: within
  1e-8 (measured 1e-11 and less). Without particles (alpha_c = 1)
  riserCoupledFoam's equations are pimpleFoam's, with the turbulence model
  built for DPMFoam's carrier (PhaseIncompressibleTurbulenceModel with
  alpha_c), and the drive reaches the steady gradient that
  meanVelocityForce reaches.
- Darcy's friction factor lambda = -dp/dz D / (rho u_b^2 / 2) against
  Prandtl's smooth-pipe law 1/sqrt(lambda) = 2.0 log10(Re sqrt(lambda))
  - 0.8 (0.0180 at Re = 1e5; Blasius 0.316 Re^-1/4 = 0.0178): within 5 %
  (the requirement). Measured -3.1 % (-2.8, -3.4 % with 12, 24 cells
  across: wall cells at y+ of about 53-68 and 26-36).
- The mean profile in the log region, y+ >= 30 (the classical lower
  bound) and y/R <= 0.12 (the upper bound of the Superpipe's log law,
  McKeon et al. 2004, J. Fluid Mech. 501), every cell (all around the
  wall): u+ = U/u_tau between the lowest and the highest of the
  published log laws u+ = ln(y+)/kappa + B of Coles (1956: kappa = 0.41,
  B = 5.0), Nikuradse's pipes (as in Schlichting: 0.40, 5.5) and the
  Superpipe (McKeon et al. 2004: 0.421, 5.60): the band their scatter
  spans, 0.75 to 0.85 in u+ at y+ = 50 to 300. Measured: u+ - ln(y+)/0.41
  = 5.49 to 5.72 at y+ = 40 to 278 (the wall function's B, 5.57, at the
  wall cells), inside the band. Not met further out: up to y/R = 0.15
  (the bound of Marusic et al. 2013, J. Fluid Mech. 716 R3) the cells at
  y/R = 0.14 (y+ = 330, where the O-grid's ring is thinnest) have 5.87,
  0.03 above the band (Nikuradse's law; printed, not checked): the start
  of the wake, where the model's profile rises above the log law.

Why kEpsilon and not kOmegaSST (measured on this grid, same case):
kOmegaSST with nutkWallFunction gives -5.9 % (-5.1, -6.8, -7.7 % with 12,
20, 24 cells across), with nutUSpaldingWallFunction -2.2 % but a profile
that jumps by 0.7 in B between the first and the second cell. Its eddy
viscosity a1 k / max(a1 omega, F2 S) is limited by the cell's strain rate
S, which in a wall cell is that of the jump to the no-slip wall, about
three times the log law's u_tau/(kappa y): the wall cell's nu_t is 0.31
kappa u_tau y (kEpsilon's Cmu k^2/epsilon: 1.02 kappa u_tau y), the
velocity rises too steeply between the first two cells (B from 5.5 to
6.2) and the core runs too fast for its wall stress. realizableKE
(nutkWallFunction): -7.3 % (-6.3 to -8.8 % on 12 to 24 cells).
kEpsilon with nutUSpaldingWallFunction: +0.8 % (+0.2 to +2.4 %, rising
as the wall cell moves to smaller y+, where Spalding's law lies below the
log law).

- The library's analytic turbulent carrier against this profile (below):
  within 3 % at r/R = 0.4, 0.6, 0.8 (measured 2.2, 0.06, 0.8 %).
"""
import math
import os
import re
import shutil

import numpy as np

from riserfoam import cases, foamfields, pipeflow, tables
from riserfoam.checks import Checks

checks = Checks(width=60)
D, NU, RHO, UB, N, END = 0.1, 1e-6, 1000.0, 1.0, 16, 30.0
LOG_LAWS = ((0.41, 5.0), (0.40, 5.5), (0.421, 5.60))  # Coles, Nikuradse, McKeon et al.

case = os.path.abspath("coupled")
cases.coupled_pipe_case(case, N, 2, D=D, nu=NU, rho=RHO, uCentre=1.25,
                        drive="bulkVelocity %r;" % UB, dt=0.05, end=END)
cases.coupled_pipe_RAS(case, UB, D, "kEpsilon", "nutkWallFunction")

stock = os.path.abspath("stock")
shutil.copytree(case, stock)
foamfields.set_entry(os.path.join(stock, "system/controlDict"), "application", "pimpleFoam")
schemes = os.path.join(stock, "system/fvSchemes")
foamfields.write_file(schemes, open(schemes).read().replace("div(alphaPhi,", "div(phi,"))
foamfields.write_dictionary(os.path.join(stock, "constant/fvOptions"), """
drive
{
    type meanVelocityForce;
    active yes;
    meanVelocityForceCoeffs { selectionMode all; fields (U); Ubar (0 0 %r); relaxation 1; }
}
""" % UB)

cases.run(["riserCoupledFoam", "-case", case], os.path.join(case, "log.riserCoupledFoam"))
log = cases.run(["pimpleFoam", "-case", stock], os.path.join(stock, "log.pimpleFoam"))

dpdz = tables.read(os.path.join(case, "postProcessing/riserDrive/0/drive.dat"))["dpdz"][-1]
stock_dpdz = -RHO * float([l for l in log.splitlines()
                           if "pressure gradient =" in l][-1].split("=")[-1])
checks.near("dp/dz [Pa/m] against pimpleFoam + meanVelocityForce", dpdz, stock_dpdz, 1e-8)

lam = -dpdz * D / (0.5 * RHO * UB ** 2)
prandtl = pipeflow.prandtl_friction(UB * D / NU)
checks.near("friction factor against Prandtl's law (Re = 1e5)", lam, prandtl, 5e-2)

# The profile: the distance of each cell centre to the mesh's wall, the
# chord of its quarter's n equal arcs (riserMesh: from -45 degrees), and
# u_tau from the wall stress that balances dp/dz over the polygon's
# area/perimeter
cases.run(["postProcess", "-func", "writeCellCentres", "-time", "0", "-case", case],
          os.path.join(case, "log.writeCellCentres"))
C = np.array(foamfields.read_vectors(os.path.join(case, "0/C"), "internalField"))
U = np.array(foamfields.read_vectors(os.path.join(case, "%g/U" % END), "internalField"))
R = 0.5 * D
arc = 0.5 * math.pi / N
theta = np.arctan2(C[:, 1], C[:, 0])
middle = -0.25 * math.pi + (np.floor((theta + 0.25 * math.pi) / arc) + 0.5) * arc
apothem = R * math.cos(0.5 * arc)
y = apothem - np.hypot(C[:, 0], C[:, 1]) * np.cos(theta - middle)
u_tau = math.sqrt(-dpdz / RHO * 0.5 * apothem)
yp, up = y * u_tau / NU, U[:, 2] / u_tau
print("wall cells at y+ = %.0f to %.0f" % (yp.min(), yp[yp < 1.5 * yp.min()].max()))


def against_log_laws(label, cells, checked):
    """the cells' u+ against the band of the published log laws"""
    low = np.min([np.log(yp[cells]) / k + b for k, b in LOG_LAWS], axis=0)
    high = np.max([np.log(yp[cells]) / k + b for k, b in LOG_LAWS], axis=0)
    outside = np.maximum(low - up[cells], up[cells] - high).max()
    B = up[cells] - np.log(yp[cells]) / 0.41
    ok = outside <= 0
    if checked:
        checks.failures += not ok
    print("%s: %d cells at y+ = %.0f to %.0f, u+ - ln(y+)/0.41 = %.2f to %.2f; largest "
          "excursion from the published laws' band %+.3f %s"
          % (label, cells.sum(), yp[cells].min(), yp[cells].max(), B.min(), B.max(), outside,
             ("ok" if ok else "FAILED") if checked else "(not checked)"))


against_log_laws("log law, y+ >= 30, y/R <= 0.12", (yp >= 30) & (y <= 0.12 * R), True)
against_log_laws("beyond, 0.12 < y/R <= 0.15", (y > 0.12 * R) & (y <= 0.15 * R), False)

# The library's analytic turbulent carrier (profile turbulent, theory guide
# section 2.7) against this computed profile: the cells about five radii,
# their mean axial velocity against the analytic one's mean over the same
# cells, within 3 % in the outer half of the radius. The core is printed,
# not checked: there kEpsilon's profile is flatter than pipe flow's
# (u_c/U_b 1.164 against Nikuradse's 1.22 at this Re; the analytic profile
# is within 0.5 % of Nikuradse's, core.TurbulentPipeProfile), measured
# 4.7 % below the analytic one on the axis and 4.0 % at r/R = 0.2.
analytic = pipeflow.turbulent_profile(UB, D, NU)
r = np.hypot(C[:, 0], C[:, 1])
for rk in (0.0, 0.2, 0.4, 0.6, 0.8):
    cells = np.abs(r / R - rk) < (0.1 if rk == 0 else 0.05)
    label = "analytic profile at r/R = %.1f (%d cells) / RAS" % (rk, cells.sum())
    if rk >= 0.4:
        checks.near(label, analytic(r[cells]).mean(), U[cells, 2].mean(), 3e-2)
    else:
        print("%s: %.4f against %.4f m/s (not checked: the RAS core)"
              % (label, analytic(r[cells]).mean(), U[cells, 2].mean()))
print("u_c/U_b: analytic %.4f, RAS centre cells %.4f (Nikuradse, n = 7: 1.2245)"
      % (analytic(0.0) / UB, U[r < 0.1 * R, 2].mean() / UB))

# riserCarrierProfile writes this computed flow as the samples of 'profile
# tabulated' (rows r w k nu_t). Each bin's row against the volume-weighted
# means of its cells binned here, independently (the cells' volumes from
# writeCellVolumes), within the file's twelve printed digits (1e-9
# relative, the sums' order differing); the axis' row the even
# continuation a + b r^2 of the first two bins; the wall's row no-slip.
# The samples' speed about r/R = 0.4, 0.6, 0.8 (the nearest bins) against
# the analytic profile within the 3 % above; and the mesh-free engine
# reads the file (profile tabulated) and runs an ore in it.
cases.run(["postProcess", "-func", "writeCellVolumes", "-time", "0", "-case", case],
          os.path.join(case, "log.writeCellVolumes"))
V = np.array(foamfields.read_scalars(os.path.join(case, "0/V"), "internalField"))
k = np.array(foamfields.read_scalars(os.path.join(case, "%g/k" % END), "internalField"))
nut = np.array(foamfields.read_scalars(os.path.join(case, "%g/nut" % END), "internalField"))
BINS = 10
cases.run(["riserCarrierProfile", "-latestTime", "-bins", str(BINS), "-case", case],
          os.path.join(case, "log.riserCarrierProfile"))
number = r"([-+0-9.eE]+)"
text = foamfields._body(os.path.join(case, "constant/riserCarrierProfile"))
rows = np.array([[float(v) for v in m.groups()] for m in re.finditer(
    r"\(\s*%s\s+%s\s+%s\s+%s\s*\)" % ((number,) * 4), text[text.index("rows"):])])
bins = np.minimum((r / R * BINS).astype(int), BINS - 1)
expected = []
for b in range(BINS):
    cells = bins == b
    if cells.any():
        w = V[cells] / V[cells].sum()
        expected.append([(w * q[cells]).sum() for q in (r, U[:, 2], k, nut)])
expected = np.array(expected)
inner = rows[1:-1]
same = inner.shape == expected.shape and np.allclose(inner, expected, rtol=1e-9, atol=1e-15)
print("riserCarrierProfile: %d bins' rows against their cells' means: %s"
      % (len(inner), "ok" if same else "FAILED\n%s\n%s" % (inner, expected)))
checks.failures += not same
(r1, r2), (a1, a2) = expected[:2, 0] ** 2, (expected[0, 1:], expected[1, 1:])
axis = (r2 * a1 - r1 * a2) / (r2 - r1)
checks.near("riserCarrierProfile: the axis' speed (a + b r^2 of two bins)", rows[0, 1], axis[0], 1e-9)
checks.near("riserCarrierProfile: the wall's radius", rows[-1, 0], R, 1e-12)
ok = rows[0, 0] == 0 and (rows[-1, 1:] == 0).all()
print("riserCarrierProfile: the axis at r = 0, the wall's row no-slip: %s" % ("ok" if ok else "FAILED"))
checks.failures += not ok
for rk in (0.4, 0.6, 0.8):
    near = np.argmin(np.abs(rows[:, 0] / R - rk))
    checks.near("the samples at r/R = %.3f against the analytic profile" % (rows[near, 0] / R),
                rows[near, 1], analytic(np.array([rows[near, 0]]))[0], 3e-2)
oneWay = os.path.abspath("oneWay")
cases.copy_tutorial("riser/oscillatingNoContact", oneWay)
foamfields.set_entry(os.path.join(oneWay, "system/controlDict"), "endTime", "0.02")
props = os.path.join(oneWay, "constant/riserProperties")
foamfields.remove_entry(props, "uCentre")
with open(props, "a") as out:
    out.write('profile tabulated;\nprofileFile "%s";\n'
              % os.path.join(case, "constant/riserCarrierProfile"))
text = cases.run(["riserParticle", "-case", oneWay], os.path.join(oneWay, "log.riserParticle"))
ok = "1 inside the pipe to the end" in text
print("riserParticle reads the profile (profile tabulated) and runs an ore in it: %s"
      % ("ok" if ok else "FAILED"))
checks.failures += not ok
checks.exit()
