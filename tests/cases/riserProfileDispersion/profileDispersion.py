"""riserProfileDispersion: see ./run for what is checked and why the bounds.
usage: profileDispersion.py <scratch folder>

SPDX-License-Identifier: GPL-3.0-or-later
"""
import math
import os
import sys

from riserfoam import cases
from riserfoam import foamfields as ff

work = sys.argv[1]
D, SIGMA, TL, SCT, N = 0.5, 0.08, 0.05, 0.7, 2000
K, NUT = 1.5 * SIGMA ** 2, SCT * SIGMA ** 2 * TL
failures = 0


def check(ok, text):
    global failures
    failures += not ok
    print("%-78s %s" % (text, "ok" if ok else "FAILED"))


def make_case(case, carrier, dispersion):
    cases.copy_tutorial("riser/oscillatingNoContact", case)
    cases.riser_mesh(case, D, 0.25, 8, ends="cyclic")
    rows = "\n".join("    (%r 0 %r %r)" % (r, K, NUT) for r in (0.0, 0.125, 0.25))
    ff.write_dictionary(os.path.join(case, "constant/riserCarrierProfile"), "rows\n(\n%s\n);\n" % rows)
    ff.write_dictionary(os.path.join(case, "constant/riserProperties"), (
        "D [0 1 0 0 0 0 0] %r;\nA 0;\nf 0;\nprofile tabulated;\n"
        "profileFile \"constant/riserCarrierProfile\";\ncarrier %s;\nframe riser;\n") % (D, carrier))
    ff.write_dictionary(os.path.join(case, "constant/kinematicCloudPositions"),
                        "(\n%s\n)\n" % "\n".join(["(0 0 0.125)"] * N), cls="vectorField")
    ff.write_dictionary(os.path.join(case, "constant/kinematicCloudProperties"), """
solution
{
    active true; coupled false; transient yes; cellValueSourceCorrection off;
    maxCo 0.3;
    interpolationSchemes { rho cell; U cellPoint; mu cell; }
    integrationSchemes { U Euler; }
}
constantProperties { rho0 1000; }
subModels
{
    particleForces { wallCorrectedDrag { law paper; pipeDiameter %r; } }
    injectionModels
    {%s
    }
    dispersionModel %s;
    patchInteractionModel standardWallInteraction;
    standardWallInteractionCoeffs { type rebound; }
    surfaceFilmModel none;
    stochasticCollisionModel none;
    collisionModel none;
}
cloudFunctions {}
""" % (D, cases.single_release(2e-5), dispersion))
    control = os.path.join(case, "system/controlDict")
    for key, value in (("endTime", 10 * TL), ("deltaT", TL / 50), ("writeControl", "adjustableRunTime"),
                       ("writeInterval", TL), ("writePrecision", 12)):
        ff.set_entry(control, key, str(value))


def taylor(t):
    return 2 * SIGMA ** 2 * TL ** 2 * (t / TL - 1 + math.exp(-t / TL))


def positions(case, n):
    return ff.read_vectors(os.path.join(case, "%g/lagrangian/kinematicCloud/positions" % (n * TL)))


for carrier in ("exact", "interpolated"):
    case = os.path.join(work, carrier)
    make_case(case, carrier, "langevinDispersionRAS")
    cases.run(["riserParcelFoam", "-case", case], os.path.join(case, "log.riserParcelFoam"))
    at = {n: positions(case, n) for n in (1, 3, 5, 10)}
    check(all(len(p) == N for p in at.values()),
          "%s: %s of %d tracers at t = T, 3T, 5T, 10T" % (carrier, [len(p) for p in at.values()], N))
    bound = 4 * math.sqrt(2.0 / (2 * N))
    for n in (1, 3, 10):
        var = sum(x * x + y * y for x, y, _ in at[n]) / (2 * N)
        check(abs(var / taylor(n * TL) - 1) < bound,
              "%s, t = %2d T: variance/Taylor = %.4f (bound 1 +- %.3f)"
              % (carrier, n, var / taylor(n * TL), bound))
    growth = [(a[0] ** 2 + a[1] ** 2) - (b[0] ** 2 + b[1] ** 2) for a, b in zip(at[10], at[5])]
    mean = sum(growth) / N
    se = math.sqrt(sum((g - mean) ** 2 for g in growth) / (N - 1) / N)
    expected = 2 * (taylor(10 * TL) - taylor(5 * TL))
    diffusive = 4 * NUT / SCT * 5 * TL
    check(abs(mean - expected) < 4 * se and abs(mean / diffusive - 1) < 0.15,
          "%s: growth of r^2 5T..10T / Taylor's = %.4f (4 s.e. %.3f), / 4 D_t t = %.4f"
          % (carrier, mean / expected, 4 * se / expected, mean / diffusive))

case = os.path.join(work, "none")
make_case(case, "exact", "none")
cases.run(["riserParcelFoam", "-case", case], os.path.join(case, "log.riserParcelFoam"))
spread = max(math.hypot(x, y) for x, y, _ in positions(case, 10))
check(spread < 1e-9, "blind check, dispersionModel none: the tracers stay on the axis (%.2g m)" % spread)

print("riserProfileDispersion: %s" % ("all checks passed" if not failures else "%d FAILED" % failures))
sys.exit(1 if failures else 0)
