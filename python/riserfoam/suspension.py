"""Homogeneous suspensions of ores in a periodic riser section, computed by
riserCoupledFoam: the case (ores filled at a solids fraction, the carrier's
flow rate held by the drive, the coarse-particle kernel, contacts), what is
measured from it (the mean slip, the pressure gradient, the solids
fraction), and the closed forms it is compared with: the terminal velocity
of a drag law and the hindered-settling correlations of Richardson & Zaki
(1954) and Garside & Al-Dibouni (1977).

Slip form. In a suspension at voidage eps = 1 - C_v the correlations give
the superficial velocity U = u_i eps^n (fluidisation: the fluid's flow rate
over the column's area with the particles at rest; batch settling: the
particles' speed where the volume flux of the mixture is zero). Either way
the particles' mean velocity relative to the carrier's interstitial mean
velocity (the slip) is U / eps:
    u_s = u_i eps^(n - 1).

SPDX-License-Identifier: GPL-3.0-or-later
"""
import math
import os

from . import cases, foamfields, tables

G, RHO_F, NU = 9.81, 1000.0, 1e-6
ORE_DENSITY = 2000.0    # the ores of cases.coupled_pipe_case [kg/m^3]


# ------------------------------------------------- closed forms

def wen_yu_cdre(Re):
    """C_D Re of the single sphere in the drag law of Wen & Yu (1966) as
    the stock WenYuDrag writes it: Schiller & Naumann (1933) below
    Re = 1000, Newton's C_D = 0.44 above"""
    return 0.44 * Re if Re > 1000.0 else 24.0 * (1.0 + 0.15 * Re ** 0.687)


def clift_gauvin_cdre(Re):
    """C_D Re of the standard drag curve of Clift & Gauvin (1970), the
    unbounded limit of wallCorrectedDrag's law continuous"""
    return 24.0 * (1.0 + 0.15 * Re ** 0.687) + 0.42 * Re / (1.0 + 42500.0 * Re ** -1.16)


def terminal_velocity(d, rho_p, cdre, rho=RHO_F, nu=NU, g=G):
    """The terminal velocity in unbounded fluid of a sphere whose drag has
    C_D Re = cdre(Re)"""
    mu = rho * nu
    weight = (rho_p - rho) * g * math.pi * d ** 3 / 6
    return _root(lambda u: math.pi * d * mu / 8 * cdre(u * d / nu) * u - weight, 0.0, 100.0)


def _root(f, lo, hi):
    """the root of f, increasing from f(lo) < 0 to f(hi) > 0, by bisection
    to the last bit"""
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if f(mid) < 0 else (lo, mid)
    return 0.5 * (lo + hi)


def chi_wen_yu(eps, ReS):
    """The exponent of Wen & Yu's (1966) voidage function eps^-chi: 3.65"""
    return 3.65


def chi_rong(eps, ReS):
    """The exponent of the voidage function eps^-chi of Rong, Dong & Yu
    (2013) at voidage eps and Re_s = eps Re (the superficial slip's),
        chi = 2.65 (eps + 1) - (5.3 - 3.5 eps) eps^2 exp(-(1.5 - log10 Re_s)^2 / 2),
    the dip vanishing at Re_s = 0 (riser::voidageExponent, Voidage::rong)"""
    dip = math.exp(-0.5 * (1.5 - math.log10(ReS)) ** 2) if ReS > 0 else 0.0
    return 2.65 * (eps + 1) - (5.3 - 3.5 * eps) * eps ** 2 * dip


def slip_homogeneous(d, rho_p, eps=1.0, cdre=wen_yu_cdre, chi=chi_wen_yu, rho=RHO_F, nu=NU,
                     g=G):
    """The slip at which the drag with the voidage function eps^-chi on an
    ore in a homogeneous suspension at voidage eps carries its buoyant
    weight,
        (pi d mu / 8) (C_D Re)(Re_s) eps^-chi(eps, Re_s) u_s = (rho_p - rho) g pi d^3 / 6,
    Re = u_s d / nu, Re_s = eps Re, C_D Re of the single sphere cdre and
    chi(eps, Re_s) the voidage function's exponent (chi_wen_yu, chi_rong).
    That is the drag of WenYuDrag (cdre wen_yu_cdre, chi_wen_yu) and of
    wallCorrectedDrag with a voidage function without its wall factors
    (clift_gauvin_cdre): both hold the pressure gradient's share,
    WenYuDrag without a fluid stress force, wallCorrectedDrag with
    riserFluidStress, zero in a suspension at rest. eps = 1 gives the
    terminal velocity u_t of the single ore in unbounded fluid"""
    return terminal_velocity(d, rho_p, lambda Re: cdre(eps * Re) * eps ** -chi(eps, eps * Re),
                             rho, nu, g)


def slip_wen_yu(d, rho_p, eps=1.0, cdre=wen_yu_cdre, rho=RHO_F, nu=NU, g=G):
    """The Wen & Yu balance of a homogeneous suspension, slip_homogeneous
    with chi = 3.65:
        (pi d mu / 8) (C_D Re)(eps Re) eps^-3.65 u_s = (rho_p - rho) g pi d^3 / 6"""
    return slip_homogeneous(d, rho_p, eps, cdre, chi_wen_yu, rho, nu, g)


def slip_rong(d, rho_p, eps=1.0, cdre=clift_gauvin_cdre, rho=RHO_F, nu=NU, g=G):
    """The balance of a homogeneous suspension with Rong, Dong & Yu's
    voidage function (slip_homogeneous with chi_rong), by default on the
    Clift-Gauvin sphere of wallCorrectedDrag's law continuous"""
    return slip_homogeneous(d, rho_p, eps, cdre, chi_rong, rho, nu, g)


def n_richardson_zaki(Re_t, a):
    """Richardson & Zaki's (1954) exponent n(Re_t, d/D = a)"""
    if Re_t < 0.2:
        return 4.65 + 19.5 * a
    if Re_t < 1:
        return (4.35 + 17.5 * a) * Re_t ** -0.03
    if Re_t < 200:
        return (4.45 + 18 * a) * Re_t ** -0.1
    if Re_t < 500:
        return 4.45 * Re_t ** -0.1
    return 2.39


def richardson_zaki(eps, Re_t, a):
    """u_s / u_t of Richardson & Zaki (1954), slip form, u_t the terminal
    velocity in unbounded fluid: u_i = u_t 10^(-d/D) (their wall
    correction, log10 u_i = log10 u_t - d/D) and n(Re_t, d/D)"""
    return 10 ** -a * eps ** (n_richardson_zaki(Re_t, a) - 1)


def n_garside_al_dibouni(Re_t):
    """Garside & Al-Dibouni's (1977) exponent: (5.1 - n)/(n - 2.7) = 0.1 Re_t^0.9"""
    x = 0.1 * Re_t ** 0.9
    return (5.1 + 2.7 * x) / (1 + x)


def garside_al_dibouni(eps, Re_t):
    """u_s / u_t of Garside & Al-Dibouni (1977), slip form, u_i = u_t"""
    return eps ** (n_garside_al_dibouni(Re_t) - 1)


# the least width of the band between the two correlations, over its
# midpoint: where they cross, the band is taken 5 % wide about its middle
BAND_FLOOR = 0.05


def band_excess(value, bounds):
    """How far value lies outside the band [min(bounds), max(bounds)], over
    its width (0 inside); the width is at least BAND_FLOOR of the band's
    midpoint. Returns (excess, width, floored)"""
    lo, hi = min(bounds), max(bounds)
    width = max(hi - lo, BAND_FLOOR * 0.5 * (lo + hi))
    return max(lo - value, value - hi, 0.0) / width, width, width > hi - lo


# ------------------------------------------------- the case

# the drag of Wen & Yu (1966) as the stock WenYuDrag writes it: the single
# sphere's drag at the superficial slip times eps^-4.65 (per ore; eps^-3.65
# in the form of Anderson & Jackson's model A, divided by eps): it holds the
# pressure gradient's share, so it goes without the fluid stress force
WEN_YU_FORCES = """        WenYuDrag { alphac alphac; }
        riserFrame;
        gravity;"""


def riser_forces(voidage):
    """the riser's own forces in a suspension: wallCorrectedDrag with the
    voidage function voidage (model B, with riserFluidStress's
    rho_f V Du/Dt)"""
    return """        wallCorrectedDrag { law continuous; voidage %s; }
        riserFluidStress;
        riserFrame;
        gravity;""" % voidage


# with the voidage functions of Wen & Yu (1966) and Rong, Dong & Yu (2013)
RISER_WEN_YU_FORCES = riser_forces("wenYu")
RISER_RONG_FORCES = riser_forces("rong")

CONTACTS = """    collisionModel riserContact;
    riserContactCoeffs
    {
        wall { youngsModulus 2e11; poissonsRatio 0.3; }
        normalRestitution 0.76; tangentialRestitution 0.7; friction 0.2;
        normalForce tensionAllowed; rotation off; stepsPerContact 10;
        pairs { normalRestitution 0.5; tangentialRestitution 0.5; friction 0.5; }
    }"""


def settling_case(case, d, D, L, n, nz, cv, dt, end, write_every, kernel, seed=1,
                  E=1e8, forces=WEN_YU_FORCES, collision=CONTACTS):
    """A periodic riser section (O-grid of n cells across the core, nz
    along L) filled with ores of diameter d and ORE_DENSITY at the solids
    fraction cv (riserFill, at rest with the carrier), water at rest, the
    carrier's flow rate held at zero by the drive, no-slip wall; the ores'
    forces (default: the Wen & Yu drag and the buoyant weight), contacts
    (default: riserContact with pairs, ores of Young's modulus E) and
    kernel (text of the kernel's entries); written every write_every
    steps"""
    injection = cases.fill_injection(cv, d, seed)
    cases.coupled_pipe_case(case, n, nz, L=L, D=D, nu=NU, rho=RHO_F, dt=dt, end=end,
                            drive="bulkVelocity 0;", coupled=True, write_every=write_every,
                            injection=injection, kernel=kernel, forces=forces,
                            collision=collision, E=E)
    return case


def _times(case):
    """the written times of case, ascending"""
    found = []
    for name in os.listdir(case):
        try:
            found.append((float(name), name))
        except ValueError:
            pass
    return sorted(found)


def measure(case, t0, rho_p=ORE_DENSITY, rho=RHO_F, g=G):
    """Over the written times after t0: the solids fraction C_v (the ores'
    volume over the mesh's), the ores' mean axial velocity w (the mean over
    the times of the mean over the ores), the carrier's interstitial mean
    axial velocity u_b / (1 - C_v) (u_b the drive's bulk velocity, the
    carrier's flow rate over the area), the slip u_s = that minus w, the
    drive's -dp/dz averaged over (t0, end] and the same over the ores'
    buoyant weight per volume, C_v (rho_p - rho) g; the ores' count; the
    RMS over the cells (volume-weighted) of the carrier's axial velocity at
    the end, a measure of the structure the suspension has developed. Also
    each time's (t, w) for the run's history."""
    times = _times(case)
    last = times[-1][1]
    cells = foamfields.read_scalars(os.path.join(case, last, "V"), "internalField")
    V = sum(cells)
    Uc = foamfields.read_vectors(os.path.join(case, last, "U"), "internalField")
    uzRms = math.sqrt(sum(u[2] ** 2 * v for u, v in zip(Uc, cells)) / V)
    history = []
    for t, name in times:
        path = os.path.join(case, name, "lagrangian/kinematicCloud/U")
        if t > 0 and os.path.exists(path):
            Up = foamfields.read_vectors(path)
            history.append((t, sum(u[2] for u in Up) / len(Up), len(Up)))
    count = history[-1][2]
    diameter = float(foamfields.read_scalars(
        os.path.join(case, last, "lagrangian/kinematicCloud/d"))[0])
    cv = count * math.pi / 6 * diameter ** 3 / V
    w = [h[1] for h in history if h[0] > t0]
    w_mean = sum(w) / len(w)
    drive = tables.read(os.path.join(case, "postProcessing/riserDrive/0/drive.dat"))
    window = drive["t"] > t0
    ub = drive[drive.names[2]][window].mean()
    dpdz = -drive["dpdz"][window].mean()
    carrier = ub / (1 - cv)
    return {"cv": cv, "count": count, "w": w_mean, "carrier": carrier, "slip": carrier - w_mean,
            "dpdz": dpdz, "dpdzRatio": dpdz / (cv * (rho_p - rho) * g), "uzRms": uzRms,
            "history": [(h[0], h[1]) for h in history]}


# ------------------------------------------------- the hindered-settling scenes

# validation/hinderedSettling and the test hinderedSettling, two scenes,
# each of core cells of h = d, in water, ores of 2000 kg/m^3, dt = 1 ms,
# no-slip wall, measured over (t0, end], after the ores have reached their
# hindered speed:
# - "1mm": ores of d = 1 mm in a section of D = 25 mm (d/D = 0.04) and
#   L = 10 mm, 10 cells across the core and along, kernel width 6 d (more
#   than the largest cell, a ring cell at the wall);
# - "10mm": the riser's ore, d = 10 mm, in D = 0.1 m (d/D = 0.1) and
#   L = 0.1 m, 4 cells across the core, 10 along, kernel width 3 d (a ring
#   cell's arc at the wall is 20 mm; 6 d would smear the whole section)
SCENES = {
    "1mm": {"d": 0.001, "D": 0.025, "L": 0.01, "n": 10, "nz": 10, "width": 6,
            "t0": 0.15, "end": 0.45},
    "10mm": {"d": 0.01, "D": 0.1, "L": 0.1, "n": 4, "nz": 10, "width": 3,
             "t0": 0.3, "end": 0.9},
}
SCENE_DT = 1e-3


def hindered_case(case, cv, end, forces=WEN_YU_FORCES, scene="1mm"):
    """the hindered-settling scene (a key of SCENES) at the solids fraction
    cv, run to end, written every 10 steps"""
    sc = SCENES[scene]
    kernel = "type diffusion; width %d; widthUnit diameters;" % sc["width"]
    return settling_case(case, sc["d"], sc["D"], sc["L"], sc["n"], sc["nz"], cv, SCENE_DT, end,
                         10, kernel, forces=forces)


# the single sphere's drag of each drag law of the scenes
SINGLE_SPHERE = {"WenYuDrag": wen_yu_cdre, "wallCorrectedDrag": clift_gauvin_cdre,
                 "wallCorrectedDrag_wenYu": clift_gauvin_cdre,
                 "wallCorrectedDrag_rong": clift_gauvin_cdre}


def hindered_reference(cv, scene="1mm", drag="WenYuDrag"):
    """the closed forms at the achieved solids fraction cv of the scene:
    {ut, Re_t, a (d/D), richardsonZaki, garsideAlDibouni, wenYu, rong} (the
    last four as u_s / u_t; wenYu and rong the balances of a homogeneous
    suspension with Wen & Yu's and with Rong, Dong & Yu's voidage
    function), u_t the terminal velocity in unbounded water by the single
    sphere's drag of the drag law drag (a key of SINGLE_SPHERE), which the
    balances use too"""
    d = SCENES[scene]["d"]
    a = d / SCENES[scene]["D"]
    ut = terminal_velocity(d, ORE_DENSITY, SINGLE_SPHERE[drag])
    Re_t = ut * d / NU
    eps = 1 - cv
    return {"ut": ut, "Re_t": Re_t, "a": a, "richardsonZaki": richardson_zaki(eps, Re_t, a),
            "garsideAlDibouni": garside_al_dibouni(eps, Re_t),
            "wenYu": slip_wen_yu(d, ORE_DENSITY, eps, SINGLE_SPHERE[drag]) / ut,
            "rong": slip_rong(d, ORE_DENSITY, eps, SINGLE_SPHERE[drag]) / ut}


# ------------------------------------------------- the kernel's mesh scene

# validation/kernelMeshIndependence and the test riserCoupledKernelCoarse:
# the 1 mm ores of SCENES at C_v = 0.1 in a wider section, D = 40 mm and
# L = 8 mm, so that an O-grid of 4 cells across the core has core cells of
# h = 4 d; n cells across the core, n/2 along (core cells cubes of
# h = 0.4 D / n); the kernel's width 8 d on every grid (it must be at least
# the largest cell: the coarsest grid's ring cells span pi D/16 = 7.9 mm of
# the wall); dt = 2 ms (an ore moves at most 0.4 of the finest cell,
# h = 0.5 d, in a step); 0.3 s, measured over (0.15, 0.3] s
MESH_SCENE = {"d": 0.001, "D": 0.04, "L": 0.008, "cv": 0.1, "dt": 2e-3, "t0": 0.15,
              "end": 0.3}
MESH_KERNELS = {"diffusion": "type diffusion; width 8; widthUnit diameters;",
                "none": "type none;"}


def mesh_case(case, n, kernel, end=MESH_SCENE["end"]):
    """the kernel's mesh scene on the O-grid of n cells across the core with
    the kernel kernel (a key of MESH_KERNELS), written every 5 steps"""
    sc = MESH_SCENE
    return settling_case(case, sc["d"], sc["D"], sc["L"], n, n // 2, sc["cv"], sc["dt"], end, 5,
                         MESH_KERNELS[kernel])
