"""tracerDispersion: see ./run for what is checked and why the bounds.
usage: tracerDispersion.py <scratch folder> <this folder>

SPDX-License-Identifier: GPL-3.0-or-later
"""
import math
import os
import shutil
import sys

from riserfoam import foamfields as ff
from riserfoam.cases import run

work, here = sys.argv[1], sys.argv[2]
stock = os.path.join(here, "..", "uncoupledSettling")
Sct, Cmu = 0.7, 0.09
failures = 0


def check(ok, text):
    global failures
    failures += not ok
    print("%-76s %s" % (text, "ok" if ok else "FAILED"))


def scalar_field(name, dims, values, patches):
    body = "dimensions %s;\ninternalField nonuniform List<scalar> %d(\n%s\n);\n" % (
        dims, len(values), "\n".join("%.12g" % v for v in values))
    body += "boundaryField\n{\n%s}\n" % "".join(
        "    %s { type %s;%s }\n" % (p, t, " value uniform 0;" if t == "calculated" else "")
        for p, t in patches)
    ff.write_dictionary(name, body, cls="volScalarField")


def make_case(case, box, cells, cyclic_x, sigma_at, TL, releases, deltaT, endTime,
              writeInterval, dispersion="langevinDispersionRAS", coeffs="", laminar=False):
    """A frozen carrier at rest in a box (x0 x1 y0 y1 z0 z1), walls or, with
    cyclic_x, periodic in all three directions; sigma_at(x): the rms
    fluctuation at a cell centre's x; T_L uniform."""
    os.makedirs(case + "/system")
    os.makedirs(case + "/constant")
    os.makedirs(case + "/0")
    for f in ("system/fvSchemes", "system/fvSolution", "constant/thermophysicalProperties",
              "0/T", "0/p"):
        shutil.copy(os.path.join(stock, f), os.path.join(case, f))
    x0, x1, y0, y1, z0, z1 = box
    nx, ny, nz = cells
    if cyclic_x:
        patches = [("left", "right", "(0 4 7 3)", "(1 2 6 5)"),
                   ("front", "back", "(0 1 5 4)", "(3 7 6 2)"),
                   ("bottom", "top", "(0 3 2 1)", "(4 5 6 7)")]
        boundary = "".join(
            "    %s { type cyclic; neighbourPatch %s; faces (%s); }\n"
            "    %s { type cyclic; neighbourPatch %s; faces (%s); }\n" % (a, b, fa, b, a, fb)
            for a, b, fa, fb in patches)
        names = [n for a, b, _, _ in patches for n in (a, b)]
        bc = lambda t: [(n, "cyclic") for n in names]
    else:
        boundary = ("    walls { type wall; faces ((0 3 2 1) (4 5 6 7) (0 1 5 4) (1 2 6 5)"
                    " (2 3 7 6) (3 0 4 7)); }\n")
        bc = lambda t: [("walls", t)]
    ff.write_dictionary(case + "/system/blockMeshDict", (
        "vertices ((%g %g %g) (%g %g %g) (%g %g %g) (%g %g %g)"
        " (%g %g %g) (%g %g %g) (%g %g %g) (%g %g %g));\n"
        % (x0, y0, z0, x1, y0, z0, x1, y1, z0, x0, y1, z0,
           x0, y0, z1, x1, y0, z1, x1, y1, z1, x0, y1, z1))
        + "blocks (hex (0 1 2 3 4 5 6 7) (%d %d %d) simpleGrading (1 1 1));\n" % (nx, ny, nz)
        + "boundary\n(\n%s);\n" % boundary)
    ff.write_dictionary(case + "/system/controlDict", (
        "application uncoupledKinematicParcelFoam;\nlibs (\"libriserStockClouds.so\");\n"
        "startFrom startTime;\nstartTime 0;\nstopAt endTime;\nendTime %g;\ndeltaT %g;\n"
        "writeControl adjustableRunTime;\nwriteInterval %g;\nwriteFormat ascii;\n"
        "writePrecision 12;\ntimeFormat general;\ntimePrecision 6;\nrunTimeModifiable no;\n"
        % (endTime, deltaT, writeInterval)))
    ff.write_dictionary(case + "/constant/turbulenceProperties",
                        "simulationType laminar;\n" if laminar else
                        "simulationType RAS;\nRAS { RASModel kEpsilon; turbulence on; printCoeffs off; }\n")
    ff.write_dictionary(case + "/constant/g", "dimensions [0 1 -2 0 0 0 0];\nvalue (0 0 0);\n",
                        cls="uniformDimensionedVectorField")
    # the cell centres' x of the uniform block
    xs = [x0 + (i + 0.5)*(x1 - x0)/nx for k in range(nz) for j in range(ny) for i in range(nx)]
    sig = [sigma_at(x) for x in xs]
    k = [1.5*s*s for s in sig]
    nut = [Sct*s*s*TL for s in sig]
    eps = [Cmu*kk*kk/n for kk, n in zip(k, nut)]
    scalar_field(case + "/0/k", "[0 2 -2 0 0 0 0]", k, bc("zeroGradient"))
    scalar_field(case + "/0/epsilon", "[0 2 -3 0 0 0 0]", eps, bc("zeroGradient"))
    scalar_field(case + "/0/nut", "[0 2 -1 0 0 0 0]", nut, bc("calculated"))
    scalar_field(case + "/0/alphat", "[1 -1 -1 0 0 0 0]", [0.0]*len(xs), bc("calculated"))
    ff.write_dictionary(case + "/0/U",
                        "dimensions [0 1 -1 0 0 0 0];\ninternalField uniform (0 0 0);\n"
                        "boundaryField\n{\n%s}\n" % "".join(
                            "    %s { type %s; }\n" % (p, "cyclic" if t == "cyclic" else "noSlip")
                            for p, t in bc("wall")), cls="volVectorField")
    for f in ("0/T", "0/p"):
        text = open(case + "/" + f).read()
        start = text.index("boundaryField")
        open(case + "/" + f, "w").write(text[:start] + "boundaryField\n{\n%s}\n" % "".join(
            "    %s { type %s; }\n" % (p, "cyclic" if t == "cyclic" else "zeroGradient")
            for p, t in bc("wall")))
    ff.write_dictionary(case + "/constant/kinematicCloudPositions",
                        "(\n%s\n)\n" % "\n".join("(%.12g %.12g %.12g)" % p for p in releases),
                        cls="vectorField")
    ff.write_dictionary(case + "/constant/kinematicCloudProperties", """
solution
{
    active true; coupled false; transient yes; cellValueSourceCorrection off;
    maxCo 0.3;
    interpolationSchemes { rho cell; U cellPoint; thermo:mu cell; }
    integrationSchemes { U analytical; }
}
constantProperties { rho0 1000; }
subModels
{
    particleForces { wallCorrectedDrag { law paper; pipeDiameter 1; } }
    injectionModels
    {
        tracers
        {
            type manualInjection; massTotal 0; parcelBasisType fixed; nParticle 1;
            SOI 0; positionsFile "kinematicCloudPositions"; U0 (0 0 0);
            sizeDistribution { type fixedValue; fixedValueDistribution { value 2e-5; } }
        }
    }
    dispersionModel %s;
    %s
    patchInteractionModel standardWallInteraction;
    standardWallInteractionCoeffs { type rebound; }
    surfaceFilmModel none;
    stochasticCollisionModel none;
}
cloudFunctions {}
""" % (dispersion, coeffs))


def solve(case, may_fail=False):
    run(["blockMesh"], case + "/log.blockMesh", cwd=case)
    return run(["timeout", "600", "uncoupledKinematicParcelFoam"],
               case + "/log.uncoupledKinematicParcelFoam", cwd=case, may_fail=may_fail)


def positions(case, time):
    return ff.read_vectors("%s/%s/lagrangian/kinematicCloud/positions" % (case, time))


def taylor(sigma, T, t):
    return 2*sigma*sigma*T*T*(t/T - 1 + math.exp(-t/T))


# --- homogeneous turbulence: Taylor's spreading ---------------------------
sigma, TL, N = 0.08, 0.2, 3000
bound = 4*math.sqrt(2.0/(3*N))
# with dt = T/100, the spread at t = T, 3T and 10T against Taylor's form;
# with dt = T/2, the diffusivity: the growth of each tracer's squared
# displacement from 5T to 10T, against the form's, within 4 of its standard
# errors (estimated from the tracers' own spread of that growth)
for label, deltaT, coeffs in (
        ("dt = T/100", TL/100, ""),
        ("dt = T/2, beta 0", TL/2, "langevinDispersionRASCoeffs { beta 0; }")):
    case = work + "/homogeneous_" + label.replace(" ", "").replace("/", "").replace(",", "_")
    make_case(case, (-0.5, 0.5, -0.5, 0.5, -0.5, 0.5), (5, 5, 5), False, lambda x: sigma, TL,
              [(0.0, 0.0, 0.0)]*N, deltaT, 10*TL, TL, coeffs=coeffs)
    solve(case)
    at = {}
    for n in (1, 3, 5, 10):
        at[n] = positions(case, "%g" % (n*TL))
        check(len(at[n]) == N, "%s: %d of %d tracers at t = %g T" % (label, len(at[n]), N, n))
    if deltaT < 0.1*TL:
        for n in (1, 3, 10):
            var = sum(a*a + b*b + c*c for a, b, c in at[n])/(3*N)
            expected = taylor(sigma, TL, n*TL)
            check(abs(var/expected - 1) < bound,
                  "%s, t = %2d T: variance/Taylor = %.4f (bound 1 +- %.3f)"
                  % (label, n, var/expected, bound))
    growth = [sum(c*c for c in p10) - sum(c*c for c in p5) for p5, p10 in zip(at[5], at[10])]
    mean = sum(growth)/N
    se = math.sqrt(sum((g - mean)**2 for g in growth)/(N - 1)/N)
    expected = 3*(taylor(sigma, TL, 10*TL) - taylor(sigma, TL, 5*TL))
    check(abs(mean - expected) < 4*se,
          "%s: growth 5T..10T / Taylor's = %.4f (bound 1 +- %.3f: 4 standard errors)"
          % (label, mean/expected, 4*se/expected))

# --- inhomogeneous turbulence: well mixed ----------------------------------
L, sigma0, TL, N, bins = 0.025, 0.05, 0.1, 4000, 10
sig = lambda x: sigma0*(1 + 0.6*math.sin(2*math.pi*x/L))
releases = [((i + 0.5)*L/N, 0.5e-3, 0.5e-3) for i in range(N)]
chi = {}
for model in ("langevinDispersionRAS", "stochasticDispersionRAS"):
    case = work + "/wellMixed_" + model
    make_case(case, (0, L, 0, 1e-3, 0, 1e-3), (50, 1, 1), True, sig, TL, releases,
              TL/50, 40*TL, 40*TL, dispersion=model)
    solve(case)
    x = [p[0] % L for p in positions(case, "%g" % (40*TL))]
    check(len(x) == N, "%s: %d of %d tracers at the end" % (model, len(x), N))
    count = [0]*bins
    for xi in x:
        count[min(bins - 1, int(xi/L*bins))] += 1
    mean = len(x)/bins
    chi[model] = sum((c - mean)**2/mean for c in count)
    print("%s: counts %s, chi-square %.1f" % (model, count, chi[model]))
check(chi["langevinDispersionRAS"] < 27.9,
      "well mixed: chi-square %.1f < 27.9" % chi["langevinDispersionRAS"])
check(chi["stochasticDispersionRAS"] > 27.9,
      "blind check, the stock random walk: chi-square %.1f > 27.9" % chi["stochasticDispersionRAS"])

# --- bad input -------------------------------------------------------------
bad = (("Sct", "langevinDispersionRASCoeffs { Sct 0.05; }", "'Sct'", False),
       ("beta", "langevinDispersionRASCoeffs { beta -1; }", "'beta'", False),
       ("Sct nan", "langevinDispersionRASCoeffs { Sct nan; }",
        "entry 'Sct' = nan is not a finite number", False),
       ("beta nan", "langevinDispersionRASCoeffs { beta nan; }",
        "entry 'beta' = nan is not a finite number", False),
       ("misspelt", "langevinDispersionRASCoeffs { Sc 0.7; }", "unknown entry 'Sc'", False),
       ("laminar", "", "the carrier is laminar", True))
for name, coeffs, expected, laminar in bad:
    case = work + "/bad_" + name.replace(" ", "_")
    make_case(case, (-0.5, 0.5, -0.5, 0.5, -0.5, 0.5), (2, 2, 2), False, lambda x: sigma, TL,
              [(0.1, 0.1, 0.1)], 0.01, 0.02, 0.02, coeffs=coeffs, laminar=laminar)
    log = solve(case, may_fail=True)
    text = open(case + "/log.uncoupledKinematicParcelFoam").read()
    check(log is None and expected in text and "FOAM FATAL" in text,
          "refused: %s (the message names %s)" % (name, expected))

print("tracerDispersion: %s" % ("all checks passed" if not failures else "%d FAILED" % failures))
sys.exit(1 if failures else 0)
