"""particleKernel::alphac and particleKernel::SU on a coupled cloud.

Three ores (d = 10 mm, 2000 kg/m^3, on the riser O-grid, D = 0.1 m, 12
cells across the core, cyclic ends: a core cell of 3.3 x 3.3 x 8.3 mm has
a sixth of an ore's volume) released at rest in
water rising at 0.5 m/s, a two-way coupled stock colliding cloud
(sphereDrag, gravity, semi-implicit momentum source) moved one step of
1 ms; the deposits spread with the cloud's kernel b = 3 d (d the largest
diameter). Checked against the stock cloud's own theta and SU (vector
sums compared by their norms, their only non-zero component being z):

- the largest diameter is 10 mm;
- solids: sum (1 - alpha_c) V equals sum theta V (the ores' volume),
  relative 1e-12 (conservation, see kernelConservation; alphaMin 0);
- the largest spread theta is below 1 (alpha_c does not clip) where the
  stock one-cell theta is 5.65 (printed, checked above 1);
- the momentum source: its explicit part sum(source) and implicit part
  sum(diag) equal the stock's, relative 1e-12 (UTrans and UCoeff spread
  by the same conservative operator; the carrier uniform, so the
  explicit counterpart UCoeff U sums alike). The explicit part is the
  small difference of two sums each kept to round-off, UTrans and the
  counterpart sum(diag) U_c (the ores' weight against their drag:
  5.2e-5 against 0.025): its error is measured relative to the
  counterpart's size;
- type none: the source equals the stock's (relative 1e-15), and alpha_c
  is the stock's max(1 - theta, 0), clipped where an ore fills more
  than its cell: 1 - alpha_c reaches 1 and its sum over the cells is
  less than the ores' volume (printed: the share the carrier sees).
"""
import math
import os
import re

from riserfoam import foamfields as ff
from riserfoam.cases import riser_mesh, run
from riserfoam.checks import Checks
from riserfoam import kernel

checks = Checks(width=64)
U_CARRIER = 0.5     # m/s, the water, uniform
work = os.getcwd()

CLOUD = """
solution
{
    active          true;
    coupled         true;
    transient       yes;
    cellValueSourceCorrection off;
    maxCo           0.3;
    sourceTerms { schemes { U semiImplicit 1; } }
    interpolationSchemes { rho cell; U cellPoint; mu cell; }
    integrationSchemes { U Euler; }
}
constantProperties { rho0 2000; youngsModulus 6e10; poissonsRatio 0.26; }
subModels
{
    particleForces { sphereDrag; gravity; }
    injectionModels
    {
        ores
        {
            type            manualInjection;
            massTotal       0;
            parcelBasisType fixed;
            nParticle       1;
            SOI             0;
            positionsFile   "kinematicCloudPositions";
            U0              (0 0 0);
            sizeDistribution
            {
                type        fixedValue;
                fixedValueDistribution { value 0.01; }
            }
        }
    }
    dispersionModel none;
    patchInteractionModel standardWallInteraction;
    standardWallInteractionCoeffs { type rebound; }
    surfaceFilmModel none;
    stochasticCollisionModel none;
    collisionModel  none;
}
cloudFunctions {}
kernel { %s }
"""


def case(name, kernel_body):
    path = os.path.join(work, name)
    kernel.system(path)
    riser_mesh(path, 0.1, 0.2, 12, ends="cyclic")
    ff.set_entry(os.path.join(path, "system/controlDict"), "deltaT", "0.001")
    ff.write_dictionary(os.path.join(path, "0/U"), """
dimensions [0 1 -1 0 0 0 0];
internalField uniform (0 0 %r);
boundaryField
{
    riserWall { type fixedValue; value uniform (0 0 0); }
    bottom { type cyclic; }
    top { type cyclic; }
}
""" % U_CARRIER, "volVectorField")
    ff.write_dictionary(os.path.join(path, "constant/g"),
                        "dimensions [0 1 -2 0 0 0 0];\nvalue (0 0 -9.81);\n",
                        "uniformDimensionedVectorField")
    ff.write_dictionary(os.path.join(path, "constant/transportProperties"),
                        "transportModel Newtonian;\nrhoInf 1000;\nnu 1e-06;\n")
    ff.write_dictionary(os.path.join(path, "constant/kinematicCloudProperties"),
                        CLOUD % kernel_body)
    ff.write_dictionary(os.path.join(path, "constant/kinematicCloudPositions"),
                        "((0.003 0.003 0.103) (0.005 0.005 0.105) (0.02 -0.01 0.05))",
                        "vectorField")
    text = run(["riserKernel", "-cloud", "kinematicCloud", "-case", path],
               os.path.join(path, "log.riserKernel"))

    def pair(name):
        """stock and spread values: numbers, or the vectors' norms"""
        line = re.search(r"^%s stock (.*) spread (.*)$" % name, text, re.M)
        return tuple(math.sqrt(sum(float(c) ** 2 for c in v.strip("()").split()))
                     for v in line.groups())
    parcels = int(re.search(r"^parcels (\d+)", text, re.M).group(1))
    largest = float(re.search(r"largestDiameter (\S+)", text).group(1))
    return parcels, largest, {k: pair(k) for k in ("solids", "largestTheta", "explicit", "implicit")}


parcels, largest, sums = case("diffusion", "type diffusion; width 3; widthUnit diameters;")
print("%d parcels, largest diameter %g m" % (parcels, largest))
if parcels != 3:
    print("FAILED: %d parcels injected, 3 expected" % parcels)
    checks.failures += 1
checks.near("largest diameter [m]", largest, 0.01, 1e-12)
stock_theta, spread_theta = sums["largestTheta"]
print("largest theta: one-cell %.4f, spread %.4f" % (stock_theta, spread_theta))
if not (stock_theta > 1 > spread_theta):
    print("FAILED: expected the one-cell theta above 1 and the spread one below")
    checks.failures += 1
for name in ("solids", "explicit", "implicit"):
    stock, spread = sums[name]
    scale = sums["implicit"][0] * U_CARRIER if name == "explicit" else None
    checks.near("diffusion: %s, spread against stock" % name, spread, stock, 1e-12, scale)

_, _, sums = case("none", "type none;")
for name in ("explicit", "implicit"):
    stock, spread = sums[name]
    checks.near("none: %s, against stock" % name, spread, stock, 1e-15)
checks.near("none: largest 1 - alpha_c (clipped)", sums["largestTheta"][1], 1, 1e-15)
stock, clipped = sums["solids"]
print("none: the carrier sees %.3f of the ores' volume (clipped)" % (clipped / stock))
if not clipped < stock:
    print("FAILED: the one-cell deposit was expected to clip")
    checks.failures += 1
checks.exit()
