"""Case setup: commands run to a log, a tutorial copied to a scratch folder
and edited (RiserCase: the riser, the run length, the releases, the forces;
run by the mesh-free engine riserParticle or the solver riserParcelFoam,
its tables read back), the riser O-grid (bin/riserMesh + blockMesh), and the
wall-contact cases of the tests (particles thrown at a static riser wall,
no fluid forces).

SPDX-License-Identifier: GPL-3.0-or-later
"""
import os
import shutil
import subprocess

import numpy as np

from . import foamfields as ff
from . import pipeflow, tables
from .carrier import D, UCM, Riser

# the repository (this file is python/riserfoam/cases.py)
ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


class CaseError(RuntimeError):
    """A command of a case failed."""


def run(command, log, cwd=None, may_fail=False):
    """Run command (a list) with its output to the file log. Returns the
    log's text; when the command fails, None if may_fail, else CaseError
    with the log's tail."""
    with open(log, "w") as out:
        done = subprocess.run(command, cwd=cwd, stdout=out, stderr=subprocess.STDOUT)
    text = open(log).read()
    if done.returncode != 0:
        if may_fail:
            return None
        raise CaseError("%s failed (%s):\n%s" % (" ".join(command), log, text[-2000:]))
    return text



def run_parallel(case, solver, split=(2, 1, 1)):
    """Run solver on the case decomposed (simple, split cells along x, y,
    z; as many processors as their product) and reconstruct the latest
    time. Returns the solver's log."""
    ff.write_dictionary(os.path.join(case, "system/decomposeParDict"), """
numberOfSubdomains %d;
method simple;
simpleCoeffs { n (%d %d %d); delta 0.001; }
""" % ((split[0] * split[1] * split[2],) + tuple(split)))
    run(["decomposePar", "-case", case], os.path.join(case, "log.decomposePar"))
    log = run(["mpirun", "--allow-run-as-root", "--oversubscribe", "-np",
               str(split[0] * split[1] * split[2]), solver, "-parallel", "-case", case],
              os.path.join(case, "log." + solver))
    run(["reconstructPar", "-latestTime", "-case", case], os.path.join(case, "log.reconstructPar"))
    return log

def set_motion(case, motion):
    """The riser motion of case's constant/riserProperties: the dictionary
    text motion (e.g. "{ type modes; ... }") in place of the entries A, f,
    phi0 of the sinusoid; the file's path"""
    riser = os.path.join(case, "constant", "riserProperties")
    for key in ("A", "f", "phi0"):
        ff.remove_entry(riser, key)
    with open(riser, "a") as out:
        out.write("motion %s\n" % motion)
    return riser


def copy_tutorial(tutorial, case, root=ROOT):
    """A fresh copy of the tutorial (a folder under tutorials/, e.g.
    'riser/oscillatingNoContact') in case: its 0, constant and system,
    without a mesh (polyMesh, blockMeshDict)."""
    shutil.rmtree(case, ignore_errors=True)
    os.makedirs(case)
    source = os.path.join(root, "tutorials", tutorial)
    for sub in ("0", "constant", "system"):
        shutil.copytree(os.path.join(source, sub), os.path.join(case, sub),
                        ignore=shutil.ignore_patterns("polyMesh", "blockMeshDict"))


def riser_mesh(case, D, L, n, nz=None, ends="cyclic", root=ROOT):
    """The riser O-grid in case: bin/riserMesh (diameter D, length L [m],
    n cells across the core, nz along the riser) and blockMesh."""
    command = [os.path.join(root, "bin", "riserMesh"), "-D", repr(D), "-L", repr(L), "-n", str(n)]
    if nz:
        command += ["-nz", str(nz)]
    run(command + ["-ends", ends, "-case", case], os.path.join(case, "log.riserMesh"))
    run(["blockMesh", "-case", case], os.path.join(case, "log.blockMesh"))


# ------------------------------------------------- a tutorial, edited

class RiserCase:
    """A copy of a riser tutorial in scratch/name, in the paper's units
    (length D, velocity u_cm: carrier.D, carrier.UCM)."""

    def __init__(self, root, scratch, name, tutorial="oscillatingNoContact"):
        self.root = root
        self.path = os.path.join(scratch, name)
        copy_tutorial(os.path.join("riser", tutorial), self.path, root)

    def _file(self, relative):
        return os.path.join(self.path, relative)

    def riser(self, A=None, f=None, phi0=None):
        """amplitude [D], frequency [u_cm/D], phase (the paper's units)"""
        props = self._file("constant/riserProperties")
        if A is not None:
            ff.set_entry(props, "A", "[0 1 0 0 0 0 0] %r" % (A * D))
        if f is not None:
            ff.set_entry(props, "f", "[0 0 -1 0 0 0 0] %r" % (f * UCM / D))
        if phi0 is not None:
            ff.set_entry(props, "phi0", "%r" % phi0)
        return self

    def run_for(self, endTime, deltaT=None):
        """endTime and deltaT [s] (deltaT: the table's row interval)"""
        control = self._file("system/controlDict")
        ff.set_entry(control, "endTime", "%r" % endTime)
        ff.set_entry(control, "writeInterval", "%r" % endTime)
        if deltaT is not None:
            ff.set_entry(control, "deltaT", "%r" % deltaT)
        return self

    def releases(self, points, d=0.01):
        """one particle per (x, y) [D] at z = 0.5 D, released with the local
        carrier speed relative to the riser (the tutorials' riser frame)"""
        riser = Riser(D, UCM)
        blocks = []
        for i, (x, y) in enumerate(points):
            name = "kinematicCloudPositions%d" % i
            ff.write_dictionary(self._file("constant/" + name),
                                "((%r %r %r))\n" % (x * D, y * D, 0.5 * D), "vectorField")
            blocks.append(
                "        release%d\n        {\n"
                "            type manualInjection; massTotal 0; parcelBasisType fixed;\n"
                "            nParticle 1; SOI 0; positionsFile \"%s\";\n"
                "            U0 (0 0 %r);\n"
                "            sizeDistribution { type fixedValue; fixedValueDistribution { value %r; } }\n"
                "        }\n" % (i, name, riser.speed(riser.axis_distance(x * D, y * D)), d))
        ff.replace_block(self._file("constant/kinematicCloudProperties"), "injectionModels",
                         "".join(blocks))
        return self

    def without_force(self, name):
        """drop a particle force (a line 'name;' or a block 'name { ... }')"""
        props = self._file("constant/kinematicCloudProperties")
        try:
            ff.edit(props, r"^\s*%s\s*\{[^}]*\}\n" % name, "")
        except ValueError:
            ff.edit(props, r"^\s*%s;.*\n" % name, "")
        return self

    def with_basset(self, windowTime=0.01):
        props = self._file("constant/kinematicCloudProperties")
        if "riserBasset" not in open(props).read():
            ff.edit(props, r"^(\s*)riserFluidStress;",
                    r"\1riserBasset { coefficient michaelidesRoig; method windowTail; "
                    r"windowTime %r; }\n\1riserFluidStress;" % windowTime)
        return self

    def engine_settings(self, text):
        """system/riserParticleDict's entries (integrator, writeFrom, ...)"""
        ff.write_dictionary(self._file("system/riserParticleDict"), text + "\n")
        return self

    def engine(self, *args):
        """run riserParticle; returns self"""
        self.engine_log(*args)
        return self

    def engine_log(self, *args, may_fail=False):
        """run riserParticle; its log, or None if a particle's integration
        failed (a step too large) and may_fail"""
        log = run(["riserParticle", "-case", self.path] + list(args),
                  self._file("log.riserParticle"), cwd=self.path, may_fail=True)
        if log is None:
            text = open(self._file("log.riserParticle")).read()
            if not (may_fail and "failed: " in text):
                raise CaseError("riserParticle failed in %s:\n%s" % (self.path, text[-2000:]))
        return log

    def solver(self, cells=12, length=2.0):
        """mesh (O-grid, cyclic ends, length [D]) and run riserParcelFoam"""
        riser_mesh(self.path, D, length * D, cells, root=self.root)
        run(["riserParcelFoam", "-case", self.path], self._file("log.riserParcelFoam"),
            cwd=self.path)
        return self

    def sweep(self, As, fs, periods=20, liftTime=10):
        """riserParticle -sweep over the (A [m], f [Hz]) grid: sweep.dat's table"""
        ff.write_dictionary(self._file("system/riserSweepDict"),
                            "A (%s);\nf (%s);\nperiods %d;\nliftTime %g;\n"
                            % (" ".join("%.6g" % a for a in As), " ".join("%.6g" % f for f in fs),
                               periods, liftTime))
        self.engine("-sweep")
        return tables.read(self._file("postProcessing/riserParticle/sweep.dat"))

    def table(self, engine="riserParticle"):
        """{origId: Table of its rows}, the engine's or the solver's particle table"""
        name = ("postProcessing/riserParticle/particles.dat" if engine == "riserParticle" else
                "postProcessing/lagrangian/kinematicCloud/riserParticleTable/particles.dat")
        return tables.read(self._file(name)).group_by("origId")

    def contacts(self):
        """the engine's contacts (Table: origId start end side maxOverlap ...)"""
        return tables.read(self._file("postProcessing/riserParticle/contacts.dat"))

    def budget(self):
        """riserParticle -budget's rows: {force: (rms/W, max/W, lift change/D,
        trajectory change/D, cpu ratio)} (None where not dropped)"""
        self.engine("-budget")
        return {r["force"]: tuple(_number(r[k]) for k in (
                    "rms/W", "max/W", "dropped:liftChange/D", "dropped:largestTrajectoryChange/D",
                    "dropped:cpu/full"))
                for r in tables.read(self._file("postProcessing/riserParticle/budget.dat"))}


def _number(field):
    """a table's field as a float, None for '-' (not computed) and 'failed'"""
    return None if field in ("-", "failed") else float(field)


# ------------------------------------------------- wall-contact test cases

def wall_contact_case(case, D, radius, rho, E, nu, wall_E, wall_nu, e_n, e_t, mu,
                      velocities, rotation=False, dt=1e-5, end=2e-4,
                      steps_per_contact=400, normal_force="tensionAllowed", positions=None,
                      pairs=None, diameters=None):
    """A case in which particles fly at the riser wall of the riserContact
    model with no fluid forces (the sphere-wall benchmarks of Chung & Ooi
    2011 through the OpenFOAM wall model), run by icoUncoupledKinematicParcelFoam.

    The mesh is a box around a static riser of diameter D (the analytic
    wall, not the box, is what the particles hit); each particle starts
    three flow steps of its own normal motion away from the wall on the +x
    side, at its own height, with its own velocity (one manual injector per
    particle). The injection moves a parcel through the whole first step
    before the collision model sees it, so a smaller gap would start the
    contact already overlapped.

    velocities: list of (v_x, v_z) pairs, v_x towards the wall (> 0);
    positions: list of (x, y, z) to use instead of the default starts;
    pairs: (e_n, e_t, mu) of particle-particle contact, or None for none;
    diameters: one diameter per particle instead of 2 radius for all."""
    R = 0.5 * D
    half = 0.6 * D
    height = 0.4 * D * max(len(velocities), 1) + 4 * radius
    ff.write_dictionary(case + "/system/blockMeshDict", """
vertices
(
    (%(a)g %(a)g 0) (%(b)g %(a)g 0) (%(b)g %(b)g 0) (%(a)g %(b)g 0)
    (%(a)g %(a)g %(h)g) (%(b)g %(a)g %(h)g) (%(b)g %(b)g %(h)g) (%(a)g %(b)g %(h)g)
);
blocks ( hex (0 1 2 3 4 5 6 7) (6 6 %(nz)d) simpleGrading (1 1 1) );
boundary
(
    walls { type wall; faces ( (0 3 2 1) (4 5 6 7) (0 1 5 4) (1 2 6 5) (2 3 7 6) (3 0 4 7) ); }
);
""" % {"a": -half, "b": half, "h": height, "nz": max(6, 3 * len(velocities))})
    ff.write_dictionary(case + "/system/controlDict", """
application     icoUncoupledKinematicParcelFoam;
libs            ("libriserStockClouds.so");
startFrom       startTime;
startTime       0;
stopAt          endTime;
endTime         %g;
deltaT          %g;
writeControl    runTime;
writeInterval   %g;
writeFormat     ascii;
writePrecision  15;
timeFormat      general;
timePrecision   8;
runTimeModifiable no;
""" % (end, dt, end))
    ff.write_dictionary(case + "/system/fvSchemes", """
ddtSchemes { default none; } gradSchemes { default none; } divSchemes { default none; }
laplacianSchemes { default none; } interpolationSchemes { default linear; }
""")
    ff.write_dictionary(case + "/system/fvSolution", "solvers {}\n")
    ff.write_dictionary(case + "/0/U", """
dimensions [0 1 -1 0 0 0 0];
internalField uniform (0 0 0);
boundaryField { walls { type noSlip; } }
""", "volVectorField")
    ff.write_dictionary(case + "/constant/transportProperties",
                        "rhoInf 1000;\ntransportModel Newtonian;\nnu 1e-06;\n")
    ff.write_dictionary(case + "/constant/turbulenceProperties", "simulationType laminar;\n")
    ff.write_dictionary(case + "/constant/g", "dimensions [0 1 -2 0 0 0 0];\nvalue (0 0 0);\n",
                        "uniformDimensionedVectorField")
    ff.write_dictionary(case + "/constant/riserProperties",
                        "D %.17g;\nuCentre 0;\nA 0;\nf 0;\ncarrier exact;\n" % D)
    injectors = []
    for i, (vx, vz) in enumerate(velocities):
        start = (R - radius - 3 * dt * vx, 0.0, 0.4 * D * i + 2 * radius)
        if positions:
            start = positions[i]
        ff.write_dictionary(case + "/constant/positions%d" % i,
                            "((%.17g %.17g %.17g))\n" % start, "vectorField")
        injectors.append("""
        p%(i)d
        {
            type            manualInjection;
            massTotal       0;
            parcelBasisType fixed;
            nParticle       1;
            SOI             0;
            positionsFile   "positions%(i)d";
            U0              (%(vx).17g 0 %(vz).17g);
            sizeDistribution
            {
                type        fixedValue;
                fixedValueDistribution { value %(d).17g; }
            }
        }""" % {"i": i, "vx": vx, "vz": vz, "d": diameters[i] if diameters else 2 * radius})
    ff.write_dictionary(case + "/constant/kinematicCloudProperties", """
solution
{
    active true; coupled false; transient yes; cellValueSourceCorrection off; maxCo 0.3;
    interpolationSchemes { rho cell; U cellPoint; mu cell; }
    integrationSchemes { U Euler; }
}
constantProperties { rho0 %(rho).17g; youngsModulus %(E).17g; poissonsRatio %(nu).17g; }
subModels
{
    particleForces {}
    injectionModels
    {%(inj)s
    }
    dispersionModel none;
    patchInteractionModel standardWallInteraction;
    standardWallInteractionCoeffs { type rebound; }
    surfaceFilmModel none;
    stochasticCollisionModel none;
    collisionModel riserContact;
    riserContactCoeffs
    {
        wall { youngsModulus %(wE).17g; poissonsRatio %(wnu).17g; }
        normalRestitution %(en).17g;
        tangentialRestitution %(et).17g;
        friction %(mu).17g;
        normalForce %(nf)s;
        rotation %(rot)s;
        stepsPerContact %(spc)d;%(pairs)s
    }
}
cloudFunctions {}
""" % {"rho": rho, "E": E, "nu": nu, "inj": "".join(injectors), "wE": wall_E, "wnu": wall_nu,
       "en": e_n, "et": e_t, "mu": mu, "nf": normal_force, "rot": "on" if rotation else "off",
       "spc": steps_per_contact,
       "pairs": "" if pairs is None else
       "\n        pairs { normalRestitution %.17g; tangentialRestitution %.17g; friction %.17g; }"
       % pairs})


def on_riser_grid(case, solver, D=0.1, L=0.1):
    """Move a wall_contact_case (riser diameter D) from its box to the
    periodic riser O-grid of length L (riserMesh: 6 cells across the core,
    10 along, cyclic ends), the mesh riserParcelFoam needs (its points on
    the wall), and set its application to solver."""
    os.remove(os.path.join(case, "system", "blockMeshDict"))
    riser_mesh(case, D, L, 6, nz=10, ends="cyclic")
    ff.set_entry(os.path.join(case, "system/controlDict"), "application", solver)
    ff.write_dictionary(os.path.join(case, "0/U"), """
dimensions [0 1 -1 0 0 0 0];
internalField uniform (0 0 0);
boundaryField
{
    riserWall { type fixedValue; value uniform (0 0 0); }
    bottom { type cyclic; }
    top { type cyclic; }
}
""", "volVectorField")


def wall_contacts(case):
    """riserContact's completed contacts in case, in the order they
    ended (Table: origProc origId tStart tEnd duration overlapMax ...)"""
    return tables.read(os.path.join(case, "postProcessing/lagrangian/kinematicCloud/"
                                    "riserContact/contacts.dat"))


# ------------------------------------------------- the computed carrier

# the coupled cases' particle forces: drag without a voidage function, the
# fluid stress (the pressure gradient's share, Anderson & Jackson's model A),
# the riser frame's force and the buoyant weight
COUPLED_FORCES = """        wallCorrectedDrag { law continuous; }
        riserFluidStress;
        riserFrame;
        gravity;"""


# the linear solvers' absolute tolerances (p, U) of a coupled case that is
# compared with another run to round-off (frames, restarts, processors)
ROUND_OFF_SOLVES = (1e-12, 1e-12)


def coupled_pipe_case(case, n, nz, L=0.1, D=0.1, nu=1e-6, rho=1000.0, uCentre=0.01,
                      A=0.0, f=0.0, phi0=0.0, frame="riser", drive="", dt=100.0, end=4000.0,
                      U0=(0.0, 0.0, 0.0), nCorrectors=2, nOuterCorrectors=1, injection="",
                      coupled=False, write_every=None, kernel="type none;", forces=None,
                      collision=None, E=6e10, cloud_functions="", tolerances=(1e-9, 1e-10)):
    """A periodic riser section for riserCoupledFoam: the O-grid (n across
    the core, nz along L), a laminar carrier (nu, rho), at rest at the start
    unless U0 (a velocity, or "poiseuille": the developed laminar flow of
    uCentre, poiseuille_start); riserProperties of diameter D, uCentre,
    amplitude A [m], frequency f [Hz], phase phi0, frame (riser or lab: then
    the mesh and the wall move with the riser, riserOscillation) and the
    drive's entries drive (text); the riser cloud with the injectors
    injection (text), coupled true or false, the coarse-particle kernel's
    entries kernel (text; the default, type none, the one-cell deposit),
    the particle forces forces (text, default COUPLED_FORCES), the
    collision model collision (text, default none; flagship_contact() the
    flagship's wall contact), the ores' Young's modulus E [Pa] and the
    cloud functions cloud_functions (text); PIMPLE's nCorrectors and
    nOuterCorrectors; the absolute tolerances of the p and U solvers,
    tolerances (1e-9 and 1e-10: the cases' results agree with those at
    1e-12 to six digits, at 12 % less cost); written every write_every
    steps (default: at the end)."""
    dynamic = frame == "lab" and A * f > 0
    shutil.rmtree(case, ignore_errors=True)
    os.makedirs(os.path.join(case, "system"))
    ff.write_dictionary(os.path.join(case, "system/controlDict"), """
application     riserCoupledFoam;
libs            ("libriserLagrangian.so");
startFrom       latestTime;
startTime       0;
stopAt          endTime;
endTime         %r;
deltaT          %r;
writeControl    timeStep;
writeInterval   %d;
purgeWrite      0;
writeFormat     ascii;
writePrecision  12;
timeFormat      general;
timePrecision   8;
runTimeModifiable no;
""" % (end, dt, write_every or max(1, round(end / dt))))
    ff.write_dictionary(os.path.join(case, "system/fvSchemes"), """
ddtSchemes           { default Euler; }
gradSchemes          { default Gauss linear; }
divSchemes           { default Gauss linear; div(alphaPhi,U) Gauss linearUpwind grad(U); }
laplacianSchemes     { default Gauss linear corrected; }
interpolationSchemes { default linear; }
snGradSchemes        { default corrected; }
""")
    ff.write_dictionary(os.path.join(case, "system/fvSolution"), """
solvers
{
    p { solver PCG; preconditioner DIC; tolerance %r; relTol 0; }
    pFinal { $p; }
    "U.*" { solver smoothSolver; smoother symGaussSeidel; tolerance %r; relTol 0; }
}
PIMPLE
{
    nOuterCorrectors %d;
    nCorrectors %d;
    nNonOrthogonalCorrectors 1;
    momentumPredictor yes;
    pRefCell 0;
    pRefValue 0;
}
""" % (tolerances + (nOuterCorrectors, nCorrectors)))
    riser_mesh(case, D, L, n, nz=nz, ends="cyclic")
    ff.write_dictionary(os.path.join(case, "constant/riserProperties"), """
D           %r;
uCentre     %r;
A           %r;
f           %r;
phi0        %r;
frame       %s;
drive { %s }
""" % (D, uCentre, A, f, phi0, frame, drive))
    ff.write_dictionary(os.path.join(case, "constant/transportProperties"), """
transportModel  Newtonian;
nu              %r;
rhoInf          %r;
""" % (nu, rho))
    ff.write_dictionary(os.path.join(case, "constant/turbulenceProperties"),
                        "simulationType laminar;\n")
    ff.write_dictionary(os.path.join(case, "constant/g"),
                        "dimensions [0 1 -2 0 0 0 0];\nvalue (0 0 -9.81);\n",
                        "uniformDimensionedVectorField")
    if dynamic:
        ff.write_dictionary(os.path.join(case, "constant/dynamicMeshDict"), """
dynamicFvMesh   dynamicMotionSolverFvMesh;
motionSolverLibs (fvMotionSolvers);
motionSolver    solidBody;
solidBodyMotionFunction riserOscillation;
""")
    ff.write_dictionary(os.path.join(case, "constant/kinematicCloudProperties"), """
solution
{
    active          true;
    coupled         %s;
    transient       yes;
    cellValueSourceCorrection off;
    maxCo           0.3;
    sourceTerms { schemes { U semiImplicit 1; } }
    interpolationSchemes { rho cell; U cellPoint; mu cell; }
    integrationSchemes { U Euler; }
}
constantProperties { rho0 2000; youngsModulus %r; poissonsRatio 0.26; alphaMax 0.6; }
subModels
{
    particleForces
    {
%s
    }
    injectionModels
    {
%s
    }
    dispersionModel none;
    patchInteractionModel standardWallInteraction;
    standardWallInteractionCoeffs { type rebound; }
    surfaceFilmModel none;
    stochasticCollisionModel none;
%s
}
cloudFunctions { %s }
kernel { %s }
""" % ("true" if coupled else "false", E, forces or COUPLED_FORCES, injection,
       collision or "    collisionModel none;", cloud_functions, kernel))
    wall = "movingWallVelocity" if dynamic else "noSlip"
    ff.write_dictionary(os.path.join(case, "0/U"), """
dimensions [0 1 -1 0 0 0 0];
internalField uniform (%r %r %r);
boundaryField
{
    riserWall { type %s; value uniform (0 0 0); }
    bottom { type cyclic; }
    top { type cyclic; }
}
""" % (((0.0, 0.0, 0.0) if U0 == "poiseuille" else tuple(U0)) + (wall,)), "volVectorField")
    ff.write_dictionary(os.path.join(case, "0/p"), """
dimensions [0 2 -2 0 0 0 0];
internalField uniform 0;
boundaryField
{
    riserWall { type fixedFluxPressure; value uniform 0; }
    bottom { type cyclic; }
    top { type cyclic; }
}
""", "volScalarField")
    if U0 == "poiseuille":
        poiseuille_start(case, Riser(D, uCentre, A, f, phi0), frame, wall, rho * nu)


def poiseuille_start(case, riser, frame, wall, mu):
    """The developed laminar flow as the start of a coupled_pipe_case: 0/U
    the Poiseuille flow of the riser (carrier.Riser: u_cm (1 - r^2/R^2)
    at the cell centres, and in the lab frame the riser's velocity), its
    axial velocity scaled to the drive's default bulk velocity u_cm/2 on
    the mesh (the parabola at the cell centres of the O-grid, its wall a
    polygon, holds 1.2 % more on 8 cells across the core: the drive would
    take it off in the first step by a uniform shift and a spike of
    dp/dz), the wall at the riser's velocity, and the drive's gradient of
    that flow, dp/dz = -16 mu u_cm / D^2 (-32 mu u_b / D^2, u_b = u_cm/2),
    in 0/uniform/riserDrive: the carrier starts steady (up to the O-grid's
    discretisation error of the profile, riserCoupledPoiseuille)."""
    for function in ("writeCellCentres", "writeCellVolumes"):
        run(["postProcess", "-func", function, "-time", "0", "-case", case],
            os.path.join(case, "log." + function))
    centres = ff.read_vectors(os.path.join(case, "0", "C"), "internalField")
    volumes = ff.read_scalars(os.path.join(case, "0", "V"), "internalField")
    for name in ("C", "V"):
        os.remove(os.path.join(case, "0", name))
    bulk = sum(riser.speed(riser.axis_distance(x, y)) * V
               for (x, y, _), V in zip(centres, volumes)) / sum(volumes)
    scale = 0.5 * riser.u_cm / bulk

    def velocity(x, y, z):
        ux, uy, uz = riser.carrier(x, y, z, 0.0, frame)
        return ux, uy, scale * uz

    ff.write_vector_field(
        os.path.join(case, "0", "U"), centres,
        {"riserWall": "type %s; value uniform (%r 0 0);"
                      % (wall, riser.velocity(0.0) if frame == "lab" else 0.0),
         "bottom": "type cyclic;", "top": "type cyclic;"},
        velocity)
    ff.write_dictionary(os.path.join(case, "0", "uniform", "riserDrive"),
                        "dimensions [1 -2 -2 0 0 0 0];\nvalue %r;\n"
                        % (-16 * mu * riser.u_cm / riser.D ** 2),
                        "uniformDimensionedScalarField")


def flagship_contact():
    """The wall contact of the flagship tutorial (riser/oscillatingContact):
    its collisionModel line and riserContactCoeffs block, as text"""
    path = os.path.join(ROOT, "tutorials", "riser", "oscillatingContact", "constant",
                        "kinematicCloudProperties")
    text = open(path).read()
    start = text.index("collisionModel")
    return text[start:ff.matching(text, text.index("{", start)) + 1]



def dense_shaken_section(case, end, write_interval=None, alone_at_wall="meshFree", L=0.1):
    """The dense shaken periodic section of the contact tests, made in case
    (nothing run): the flagship tutorial on a section of D = 0.1 m and
    length L (riserMesh -n 6, cyclic ends) filled at C_v = 0.15 with 10 mm
    ores (riserFill: 225 in L = 0.1 m), A = 0.2 m, f = 4 Hz from the largest acceleration
    (phi0 = pi/2); soft ores and wall (E = 1e7 Pa: a contact lasts a few
    flow steps, so that contacts are in progress at the steps' ends),
    pairs (e_n 0.5, e_t 0.5, mu 0.3), every contact sub-stepped without
    the mesh (aloneAtWall meshFree; or an ore alone at the wall moved
    through the mesh in each sub-cycle: tracked), 10 sub-steps a contact
    time; dt =
    1e-4 s to end, written every write_interval (end by default) in ascii
    with 17 digits, no function objects."""
    copy_tutorial("riser/oscillatingContact", case)
    riser_mesh(case, D=0.1, L=L, n=6)
    props = os.path.join(case, "constant", "riserProperties")
    ff.set_nested(props, "A", "0.2")
    ff.set_nested(props, "f", "4")
    ff.set_nested(props, "phi0", "1.5707963267948966")
    control = os.path.join(case, "system", "controlDict")
    for entry, value in (("deltaT", "1e-4"), ("endTime", end),
                         ("writeInterval", write_interval or end), ("writePrecision", "17")):
        ff.set_nested(control, entry, value)
    ff.remove_entry(control, "functions")
    cloud = os.path.join(case, "constant", "kinematicCloudProperties")
    ff.set_nested(cloud, "cloudFunctions", "{}")
    ff.set_nested(cloud, "subModels/injectionModels", "{ %s }" % fill_injection(0.15, d=0.01))
    ff.set_nested(cloud, "constantProperties/youngsModulus", "1e7")
    coeffs = "subModels/riserContactCoeffs/"
    ff.set_nested(cloud, coeffs + "wall/youngsModulus", "1e7")
    ff.set_nested(cloud, coeffs + "stepsPerContact", "10")
    ff.set_nested(cloud, coeffs + "aloneAtWall", alone_at_wall)
    ff.set_nested(cloud, coeffs + "pairs",
                  "{ normalRestitution 0.5; tangentialRestitution 0.5; friction 0.3; }")


def fill_injection(cv, d=None, seed=1, sizes=None):
    """The injector 'ores' of a coupled_pipe_case, as text: the section
    filled at the start (riserFill) at the solids fraction cv with ores at
    rest with the carrier, of diameter d or of the size distribution sizes
    (the text of a sizeDistribution's entries)"""
    sizes = sizes or "type fixedValue; fixedValueDistribution { value %r; }" % d
    return """
        ores
        {
            type riserFill; SOI 0; massTotal 0; parcelBasisType fixed; nParticle 1;
            solidsFraction %r; seed %d; velocity carrier;
            sizeDistribution { %s }
        }""" % (cv, seed, sizes)


def single_release(d, velocity=(0.0, 0.0, 0.0)):
    """The injector 'release' of a cloud's injectionModels, as text: one
    particle of diameter d at each position of
    constant/kinematicCloudPositions, at the start, with the velocity
    velocity"""
    return """
        release
        {
            type manualInjection; massTotal 0; parcelBasisType fixed; nParticle 1;
            SOI 0; positionsFile "kinematicCloudPositions"; U0 (%r %r %r);
            sizeDistribution { type fixedValue; fixedValueDistribution { value %r; } }
        }""" % (tuple(velocity) + (d,))


def solve_coupled(case):
    """riserCoupledFoam on the case, then its cell volumes V at the latest
    time"""
    run(["riserCoupledFoam", "-case", case], os.path.join(case, "log.riserCoupledFoam"))
    run(["postProcess", "-func", "writeCellVolumes", "-latestTime", "-case", case],
        os.path.join(case, "log.writeCellVolumes"))
    return case

def cell_velocities(case, time):
    """The carrier's cell velocities U of a written time (numpy array)"""
    return np.array(ff.read_vectors(os.path.join(case, time, "U"), "internalField"))


def last_drive_gradient(case):
    """The drive's last dp/dz [Pa/m] (postProcessing/riserDrive/0/drive.dat)"""
    return tables.read(os.path.join(case, "postProcessing/riserDrive/0/drive.dat"))["dpdz"][-1]


def written_times(case):
    """The case's written times after 0, in order (folder names)"""
    return sorted((d for d in os.listdir(case)
                   if d != "0" and d.replace(".", "").isdigit()), key=float)


def coupled_rest_state(case, n, D, nu, rho, ub):
    """The periodic section of coupled_pipe_case (n cells across the core,
    4 along) driven at the bulk velocity ub to its steady state at rest
    (riserCoupledFoam, 20 steps of 100 s); its velocity field and last
    dp/dz"""
    coupled_pipe_case(case, n, 4, D=D, nu=nu, rho=rho, uCentre=2 * ub, dt=100.0, end=2000.0)
    run(["riserCoupledFoam", "-case", case], os.path.join(case, "log.riserCoupledFoam"))
    return cell_velocities(case, "2000"), last_drive_gradient(case)


def deviation_from_rest(case, U_rest, mesh_velocity):
    """Over the written times of a coupled run: the largest lateral
    velocity relative to the mesh (mesh_velocity(t): its (x, y) velocity
    over the step ending at t), the largest change of the axial velocity
    from U_rest; and the run's last dp/dz and velocity field"""
    lateral = axial = 0.0
    for t in written_times(case):
        U = cell_velocities(case, t)
        mx, my = mesh_velocity(float(t))
        lateral = max(lateral, abs(U[:, 0] - mx).max(), abs(U[:, 1] - my).max())
        axial = max(axial, abs(U[:, 2] - U_rest[:, 2]).max())
    return lateral, axial, last_drive_gradient(case), U


def coupled_pipe_RAS(case, ub, D=0.1, model="kOmegaSST", nutWall="nutkWallFunction"):
    """Make a coupled_pipe_case turbulent: the RAS model (kOmegaSST,
    kEpsilon, realizableKE) with wall functions (k, omega or epsilon, and
    nut by nutWall at the wall), its fields from a turbulence intensity of
    5 % of the bulk velocity ub and a length scale 0.07 D
    (pipeflow.turbulence_estimates), upwind
    convection of k and omega or epsilon; the carrier starts as a plug
    flow at ub."""
    ff.write_dictionary(os.path.join(case, "constant/turbulenceProperties"),
                        "simulationType RAS;\nRAS { RASModel %s; turbulence on; "
                        "printCoeffs off; }\n" % model)
    k, omega, epsilon = pipeflow.turbulence_estimates(ub, D, intensity=0.05, length=0.07)
    second = ("omega", "[0 0 -1 0 0 0 0]", omega, "omegaWallFunction") \
        if model == "kOmegaSST" else \
        ("epsilon", "[0 2 -3 0 0 0 0]", epsilon, "epsilonWallFunction")
    for name, dims, value, wall in (
            ("k", "[0 2 -2 0 0 0 0]", k, "kqRWallFunction"), second,
            ("nut", "[0 2 -1 0 0 0 0]", 0.0, nutWall)):
        ff.write_dictionary(os.path.join(case, "0", name), """
dimensions %s;
internalField uniform %r;
boundaryField
{
    riserWall { type %s; value uniform %r; }
    bottom { type cyclic; }
    top { type cyclic; }
}
""" % (dims, value, wall, value), "volScalarField")
    ff.edit(os.path.join(case, "0/U"), r"internalField uniform \([^)]*\);",
            "internalField uniform (0 0 %r);" % ub)
    schemes = os.path.join(case, "system/fvSchemes")
    ff.edit(schemes, r"^divSchemes .*$",
            "divSchemes           { default Gauss linear; div(alphaPhi,U) Gauss linearUpwind grad(U);"
            " div(alphaPhi,k) Gauss upwind; div(alphaPhi,%s) Gauss upwind; }" % second[0])
    with open(schemes, "a") as f:
        f.write("wallDist             { method meshWave; }\n")
    ff.edit(os.path.join(case, "system/fvSolution"), r'"U\.\*"', '"(U|k|%s).*"' % second[0])
