"""Writes a case in which particles fly at the riser wall of the
riserWallContact model, with no fluid forces: the sphere-wall benchmarks of
Chung & Ooi (2011) run through the OpenFOAM wall model.

The mesh is a box around a static riser of diameter D (the analytic wall,
not the box, is what the particles hit); each particle starts three flow steps of
its own normal motion away from the wall on the +x side, at its own height,
with its own velocity (one manual injector per particle). The injection
moves a parcel through the whole first step before the collision model
sees it, so a smaller gap would start the contact already overlapped.
"""
import os


def header(cls, obj):
    return ("FoamFile\n{\n    version 2.0;\n    format ascii;\n    class %s;\n"
            "    object %s;\n}\n" % (cls, obj))


def write(path, text):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    open(path, "w").write(text)


def make_case(case, D, radius, rho, E, nu, wall_E, wall_nu, e_n, e_t, mu,
              velocities, rotation=False, dt=1e-5, end=2e-4,
              steps_per_contact=400, normal_force="tensionAllowed", positions=None):
    """velocities: list of (v_x, v_z) pairs, v_x towards the wall (> 0);
    positions: list of (x, y, z) to use instead of the default starts."""
    R = 0.5 * D
    half = 0.6 * D
    height = 0.4 * D * max(len(velocities), 1) + 4 * radius
    write(case + "/system/blockMeshDict", header("dictionary", "blockMeshDict") + """
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
    write(case + "/system/controlDict", header("dictionary", "controlDict") + """
application     icoUncoupledKinematicParcelFoam;
libs            ("libriserLagrangian.so");
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
    write(case + "/system/fvSchemes", header("dictionary", "fvSchemes") + """
ddtSchemes { default none; } gradSchemes { default none; } divSchemes { default none; }
laplacianSchemes { default none; } interpolationSchemes { default linear; }
""")
    write(case + "/system/fvSolution", header("dictionary", "fvSolution") + "solvers {}\n")
    write(case + "/0/U", header("volVectorField", "U") + """
dimensions [0 1 -1 0 0 0 0];
internalField uniform (0 0 0);
boundaryField { walls { type noSlip; } }
""")
    write(case + "/constant/transportProperties", header("dictionary", "transportProperties")
          + "rhoInf 1000;\ntransportModel Newtonian;\nnu 1e-06;\n")
    write(case + "/constant/turbulenceProperties", header("dictionary", "turbulenceProperties")
          + "simulationType laminar;\n")
    write(case + "/constant/g", header("uniformDimensionedVectorField", "g")
          + "dimensions [0 1 -2 0 0 0 0];\nvalue (0 0 0);\n")
    write(case + "/constant/riserProperties", header("dictionary", "riserProperties")
          + "D %.17g;\nuCentre 0;\nA 0;\nf 0;\ncarrier exact;\n" % D)
    injectors = []
    for i, (vx, vz) in enumerate(velocities):
        start = (R - radius - 3 * dt * vx, 0.0, 0.4 * D * i + 2 * radius)
        if positions:
            start = positions[i]
        write(case + "/constant/positions%d" % i, header("vectorField", "positions%d" % i)
              + "((%.17g %.17g %.17g))\n" % start)
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
        }""" % {"i": i, "vx": vx, "vz": vz, "d": 2 * radius})
    write(case + "/constant/kinematicCloudProperties", header("dictionary", "kinematicCloudProperties") + """
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
    collisionModel riserWallContact;
    riserWallContactCoeffs
    {
        wall { youngsModulus %(wE).17g; poissonsRatio %(wnu).17g; }
        normalRestitution %(en).17g;
        tangentialRestitution %(et).17g;
        friction %(mu).17g;
        normalForce %(nf)s;
        rotation %(rot)s;
        stepsPerContact %(spc)d;
    }
}
cloudFunctions {}
""" % {"rho": rho, "E": E, "nu": nu, "inj": "".join(injectors), "wE": wall_E, "wnu": wall_nu,
       "en": e_n, "et": e_t, "mu": mu, "nf": normal_force, "rot": "on" if rotation else "off",
       "spc": steps_per_contact})


def read_contacts(case):
    """Completed contacts in the order they ended: dicts of named columns."""
    path = case + "/postProcessing/lagrangian/kinematicCloud/riserWallContact/contacts.dat"
    names = None
    contacts = []
    for line in open(path):
        if line.startswith("# origProc"):
            names = line[2:].split()
        elif line.strip() and not line.startswith("#"):
            contacts.append(dict(zip(names, (float(v) for v in line.split()))))
    return contacts
