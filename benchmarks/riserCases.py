"""riserFoam benchmarks: the cases.

Writes OpenFOAM case directories for the benchmarks of benchmarks/Allrun:
one riser mesh (bin/riserMesh O-grid, cyclic ends), copied into every case,
the same particles (a seeded list of positions) and the same number of
steps, for

  - stock solvers (icoUncoupledKinematicParcelFoam on the static mesh,
    icoUncoupledKinematicParcelDyMFoam on the moving mesh) with stock
    sphereDrag + gravity, optionally the stock SaffmanMeiLiftForce,
    virtualMass and pressureGradient, collisionModel none;
  - riserParcelFoam with the paper's forces (wallCorrectedDrag,
    riserSaffmanMeiLift, riserAddedMass, riserFluidStress, riserFrame,
    gravity), optionally riserBasset (windowTail), and the wall contact
    riserContact, in the lab frame (moving mesh) or the riser frame
    (static mesh).

No per-particle output: no cloud function objects in any case.

License: GPL-3.0-or-later
"""
import math
import os
import random
import shutil

from riserfoam import cases
from riserfoam import foamfields as ff
from riserfoam.carrier import Riser

# The riser of the tutorials (constant/riserProperties): D = 0.1 m,
# u_cm = 1 m/s, A = 0.1 m, f = 3 Hz, phi0 = 0.
RISER = Riser(D=0.1, u_cm=1.0, A=0.1, f=3.0, phi0=0.0)
D = RISER.D
R = 0.5 * D
RISER_SPEED0 = RISER.velocity(0.0)        # wall velocity at t = 0 (lab)

# The particles: the tutorials' ore
PARTICLE_D = 0.01
PARTICLE_RHO = 2000.0

NOTE = "written by benchmarks/riserCases.py"


def write_dictionary(path, body, cls="dictionary"):
    ff.write_dictionary(path, body, cls, NOTE)


# ---------------------------------------------------------------- the mesh

def make_mesh(folder, length, n, nz):
    """The riser O-grid (cyclic ends) with blockMesh, and the cell and wall
    face centres (for the stock solvers' U field). Returns the cell count."""
    os.makedirs(os.path.join(folder, "constant"), exist_ok=True)
    write_system(folder, "icoUncoupledKinematicParcelFoam", steps=1, dt=1e-4,
                 write_at_end=False)
    cases.riser_mesh(folder, D, length, n, nz, root=os.environ["RISER_DIR"])
    os.makedirs(os.path.join(folder, "0"), exist_ok=True)
    cases.run(["postProcess", "-func", "writeCellCentres", "-time", "0", "-case", folder],
              os.path.join(folder, "log.writeCellCentres"))
    return len(ff.read_vectors(os.path.join(folder, "0", "C"), "internalField"))


def write_U(case, mesh, frame):
    """0/U: the carrier at t = 0 on the cells, the wall's velocity on the
    wall. riserParcelFoam overwrites it at every step; the stock solvers
    keep it (on the moving mesh it moves with the cells)."""
    centres = ff.read_vectors(os.path.join(mesh, "0", "C"), "internalField")
    wall = (RISER_SPEED0 if frame == "lab" else 0.0, 0.0, 0.0)
    ff.write_vector_field(
        os.path.join(case, "0", "U"), centres,
        {"riserWall": "type fixedValue; value uniform (%.12g %.12g %.12g);" % wall,
         "bottom": "type cyclic;", "top": "type cyclic;"},
        lambda x, y, z: RISER.carrier(x, y, z, 0.0, frame), precision=12, note=NOTE)


# ------------------------------------------------------------ the particles

def positions(n, seed=1912, margin=0.005, length=0.5):
    """n positions, uniform over the cross-section r <= R - d/2 - margin and
    along the riser (away from its ends by one diameter): the same list
    (and the same first n) for every case. The margin keeps the particles
    off the wall during a benchmark's few milliseconds."""
    rng = random.Random(seed)
    rmax = R - 0.5 * PARTICLE_D - margin
    out = []
    for _ in range(n):
        r = rmax * math.sqrt(rng.random())
        t = 2.0 * math.pi * rng.random()
        z = 0.01 + (length - 0.02) * rng.random()
        out.append((r * math.cos(t), r * math.sin(t), z))
    return out


def write_positions(case, n, length, extra=()):
    lines = ["("]
    lines += ["(%.12g %.12g %.12g)" % p for p in positions(n, length=length)]
    lines += ["(%.12g %.12g %.12g)" % p for p in extra]
    lines.append(")")
    write_dictionary(os.path.join(case, "constant", "kinematicCloudPositions"),
                     "\n".join(lines) + "\n", "vectorField")


# --------------------------------------------------------------- the models

STOCK_FORCES = """        sphereDrag;
        gravity;
"""

STOCK_CARRIER_FORCES = """        SaffmanMeiLiftForce { U U; }
        virtualMass { Cvm 0.5; }
        pressureGradient { U U; }
"""

RISER_FORCES = """        wallCorrectedDrag { law paper; pipeDiameter 0.1; }
        riserSaffmanMeiLift;
        riserAddedMass { CA 0.5; }
        riserFluidStress;
        riserFrame;
        gravity;
"""

RISER_BASSET = """        riserBasset
        {
            coefficient     michaelidesRoig;
            method          windowTail;
            windowTime      0.01;
        }
"""

STOCK_COLLISION = "    collisionModel  none;\n"

# stock particle-particle and particle-wall contact (the hopper tutorial's
# models, constants of the ore and the steel wall)
STOCK_PAIR_COLLISION = """    collisionModel  pairCollision;
    pairCollisionCoeffs
    {
        maxInteractionDistance  0.01;
        writeReferredParticleCloud no;
        pairModel pairSpringSliderDashpot;
        pairSpringSliderDashpotCoeffs
        {
            useEquivalentSize   no;
            alpha               0.12;
            b                   1.5;
            mu                  0.2;
            cohesionEnergyDensity 0;
            collisionResolutionSteps 12;
        }
        wallModel    wallSpringSliderDashpot;
        wallSpringSliderDashpotCoeffs
        {
            useEquivalentSize   no;
            collisionResolutionSteps 12;
            youngsModulus   2e11;
            poissonsRatio   0.3;
            alpha           0.12;
            b               1.5;
            mu              0.2;
            cohesionEnergyDensity 0;
        }
    }
"""

RISER_COLLISION = """    collisionModel  riserContact;
    riserContactCoeffs
    {
        wall { youngsModulus 2e11; poissonsRatio 0.3; }
        normalRestitution       0.76;
        tangentialRestitution   0.7;
        friction                0.2;
        normalForce             tensionAllowed;
        rotation                off;
        stepsPerContact         40;
    }
"""

CLOUD = """solution
{
    active          true;
    coupled         false;
    transient       yes;
    cellValueSourceCorrection off;
    maxCo           0.3;

    interpolationSchemes
    {
        rho             cell;
        U               cellPoint;
        mu              cell;
        curlUcDt        cellPoint;
        DUcDt           cellPoint;
    }

    integrationSchemes
    {
        U               Euler;
    }
}

constantProperties
{
    rho0            %(rho)g;
    youngsModulus   6e10;
    poissonsRatio   0.26;
}

subModels
{
    particleForces
    {
%(forces)s    }

    injectionModels
    {
        release
        {
            type            manualInjection;
            massTotal       0;
            parcelBasisType fixed;
            nParticle       1;
            SOI             0;
            positionsFile   "kinematicCloudPositions";
            U0              (%(U0x).12g 0 0.68);
            sizeDistribution
            {
                type        fixedValue;
                fixedValueDistribution { value %(d)g; }
            }
        }
    }

    dispersionModel none;
    patchInteractionModel standardWallInteraction;
    standardWallInteractionCoeffs { type rebound; }
    surfaceFilmModel none;
    stochasticCollisionModel none;
%(collision)s}

// no cloud functions: no per-particle output (riserParticleTable,
// particleForceFields) in a benchmark
cloudFunctions {}
"""


def write_system(case, application, steps, dt, write_at_end):
    write_dictionary(os.path.join(case, "system", "controlDict"), """
application     %s;
libs            ("%s");
startFrom       startTime;
startTime       0;
stopAt          endTime;
endTime         %.10g;
deltaT          %g;
writeControl    timeStep;
writeInterval   %d;
purgeWrite      0;
writeFormat     ascii;
writePrecision  17;
writeCompression off;
timeFormat      general;
timePrecision   10;
runTimeModifiable no;
""" % (application,
       # the riser solvers link the riser library; the stock ones load the
       # riser submodels registered for their clouds
       "libriserLagrangian.so" if application.startswith("riser") else "libriserStockClouds.so",
       steps * dt, dt, steps if write_at_end else 100000000))
    write_dictionary(os.path.join(case, "system", "fvSchemes"), """
ddtSchemes           { default Euler; }
gradSchemes          { default Gauss linear; }
divSchemes           { default none; }
laplacianSchemes     { default none; }
interpolationSchemes { default linear; }
""")
    write_dictionary(os.path.join(case, "system", "fvSolution"), "\nsolvers {}\nPIMPLE {}\n")


class Variant:
    """One solver with one set of models, in one frame.

    collision: None (riserContact for ours, none for stock) or "pair"
               (stock pairCollision: particle-particle and wall contact)

    solver:  'stock' or 'riser'
    frame:   'lab' (moving mesh) or 'riser' (static mesh)
    forces:  'drag' (stock sphereDrag + gravity), 'dragCarrier' (plus the
             stock lift, virtual mass and pressure gradient), 'paper' (the
             riser forces without Basset), 'paperBasset' (with riserBasset)
    """

    def __init__(self, key, solver, frame, forces, label, collision=None):
        self.key, self.solver, self.frame, self.forces = key, solver, frame, forces
        self.label = label
        self.collision = collision      # None: the solver's default; "pair": stock pairCollision

    @property
    def application(self):
        if self.solver == "riser":
            return "riserParcelFoam"
        return ("icoUncoupledKinematicParcelDyMFoam" if self.frame == "lab"
                else "icoUncoupledKinematicParcelFoam")

    def cloud_properties(self):
        forces = {
            "drag": STOCK_FORCES,
            "dragCarrier": STOCK_FORCES + STOCK_CARRIER_FORCES,
            "paper": RISER_FORCES,
            "paperBasset": RISER_FORCES + RISER_BASSET,
        }[self.forces]
        collision = RISER_COLLISION if self.solver == "riser" else STOCK_COLLISION
        if self.collision == "pair":
            collision = STOCK_PAIR_COLLISION
        return "\n" + CLOUD % {
            "rho": PARTICLE_RHO, "d": PARTICLE_D, "forces": forces,
            "collision": collision,
            # released with the riser's velocity in the lab, at rest
            # relative to it in the riser frame; 0.68 m/s upward
            "U0x": RISER_SPEED0 if self.frame == "lab" else 0.0,
        }


def make_case(case, variant, mesh, n, steps, dt, length, write_at_end=False, extra=()):
    """A case directory for variant with n particles (and the positions
    extra besides) and steps steps of dt."""
    if os.path.isdir(case):
        shutil.rmtree(case)
    os.makedirs(os.path.join(case, "constant"))
    shutil.copytree(os.path.join(mesh, "constant", "polyMesh"),
                    os.path.join(case, "constant", "polyMesh"))
    write_system(case, variant.application, steps, dt, write_at_end)
    write_U(case, mesh, variant.frame)
    write_positions(case, n, length, extra)
    c = os.path.join(case, "constant")
    write_dictionary(os.path.join(c, "kinematicCloudProperties"), variant.cloud_properties())
    write_dictionary(os.path.join(c, "g"), "dimensions [0 1 -2 0 0 0 0];\nvalue (0 0 -9.8);\n",
                     "uniformDimensionedVectorField")
    write_dictionary(os.path.join(c, "transportProperties"),
                     "rhoInf 1000;\ntransportModel Newtonian;\nnu 1e-06;\n")
    write_dictionary(os.path.join(c, "turbulenceProperties"), "simulationType laminar;\n")
    # the riser (read by riserParcelFoam and by the mesh motion riserOscillation)
    write_dictionary(os.path.join(c, "riserProperties"), """
D           %g;
uCentre     %g;
A           %g;
f           %g;
phi0        %g;
carrier     exact;
frame       %s;
""" % (RISER.D, RISER.u_cm, RISER.A, RISER.f, RISER.phi0, variant.frame))
    if variant.frame == "lab":
        # the same solid-body motion for both solvers: riserOscillation
        # (libriserLagrangian, loaded through controlDict's libs), x_c(t)
        # of constant/riserProperties
        write_dictionary(os.path.join(c, "dynamicMeshDict"), """
dynamicFvMesh           dynamicMotionSolverFvMesh;
motionSolverLibs        (fvMotionSolvers);
motionSolver            solidBody;
solidBodyMotionFunction riserOscillation;
""")
