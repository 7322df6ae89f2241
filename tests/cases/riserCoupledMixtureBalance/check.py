"""riserCoupledFoam: the axial momentum balance of the mixture in a
periodic riser with ores in upward transport.

DOCSTRING-TBD
"""
import concurrent.futures
import math
import os

import numpy as np

from riserfoam import cases, foamfields, tables
from riserfoam.checks import Checks

checks = Checks(width=66)
D, L, RHO, RHO_P, G, d = 0.1, 0.1, 1000.0, 2000.0, 9.81, 0.01
UCM, A, F, CV = 2.0, 0.1, 2.5, 0.01
DT, T0, END, WRITE = 1e-3, 0.4, 1.2, 0.02
ORES = """
        ores
        {
            type riserFill; SOI 0; massTotal 0; parcelBasisType fixed; nParticle 1;
            solidsFraction %r; seed 1; velocity carrier;
            sizeDistribution { type fixedValue; fixedValueDistribution { value %r; } }
        }""" % (CV, d)
PAIRS = "pairs { normalRestitution 0.5; tangentialRestitution 0.5; friction 0.3; }"
WALL_SHEAR = """
functions
{
    alphac { type readFields; libs ("libfieldFunctionObjects.so"); fields (alphac); }
    wallShearStress
    {
        type wallShearStress; libs ("libfieldFunctionObjects.so"); patches (riserWall);
    }
    wallShear
    {
        type surfaceFieldValue; libs ("libfieldFunctionObjects.so");
        regionType patch; name riserWall; operation weightedAreaIntegrate;
        weightField alphac; fields (wallShearStress); writeFields false;
    }
}
"""


def transport(name, pairs):
    """the run, the carrier's wall shear over the window (pimpleFoam's
    wallShearStress from the written U) and the cells' volumes"""
    case = os.path.abspath(name)
    cases.coupled_pipe_case(case, 8, 10, L=L, D=D, rho=RHO, uCentre=UCM, A=A, f=F,
                            frame="riser", dt=DT, end=END, U0="poiseuille", injection=ORES,
                            coupled=True, contact=True, write_every=round(WRITE / DT),
                            kernel="type diffusion; width 3; widthUnit diameters;")
    if pairs:
        foamfields.edit(os.path.join(case, "constant/kinematicCloudProperties"),
                        r"(stepsPerContact\s+\d+;)", r"\1\n        " + PAIRS)
    cases.run(["riserCoupledFoam", "-case", case], os.path.join(case, "log.riserCoupledFoam"))
    foamfields.write_dictionary(os.path.join(case, "system/wallShearDict"), WALL_SHEAR)
    cases.run(["pimpleFoam", "-postProcess", "-dict", "system/wallShearDict",
               "-time", "%r:%r" % (T0, END), "-case", case], os.path.join(case, "log.wallShear"))
    cases.run(["postProcess", "-func", "writeCellVolumes", "-time", "%r" % END, "-case", case],
              os.path.join(case, "log.writeCellVolumes"))
    return case


def ores(case, t):
    """the ores' diameters and axial velocities at t"""
    cloud = os.path.join(case, "%g" % t, "lagrangian/kinematicCloud")
    return (np.array(foamfields.read_scalars(os.path.join(cloud, "d"))),
            np.array([u[2] for u in foamfields.read_vectors(os.path.join(cloud, "U"))]))


def wall_shear_force(case):
    """(t, sum alpha_c tau_z |S_f| over the riserWall faces [m^4/s^2]: the
    wall's axial force on the carrier over rho_f) at the write times of the
    window"""
    # (the function object's folder is named by the last time processed)
    folder = os.path.join(case, "postProcessing/wallShear")
    path = os.path.join(folder, os.listdir(folder)[0], "surfaceFieldValue.dat")
    rows = [line.replace("(", " ").replace(")", " ").split()
            for line in open(path) if not line.startswith("#")]
    return np.array([float(r[0]) for r in rows]), np.array([float(r[3]) for r in rows])


def balance(case):
    """the terms of the balance over the window, per unit volume [Pa/m]"""
    T = END - T0
    volume = sum(foamfields.read_scalars(os.path.join(case, "%g" % END, "V"), "internalField"))
    diameters, w0 = ores(case, T0)
    _, w1 = ores(case, END)
    mass = RHO_P * math.pi / 6 * diameters ** 3
    cv = sum(math.pi / 6 * diameters ** 3) / volume
    drive = tables.read(os.path.join(case, "postProcessing/riserDrive/0/drive.dat"))
    steps = (drive["t"] > T0 + 0.5 * DT) & (drive["t"] < END + 0.5 * DT)
    ts, tau = wall_shear_force(case)
    contacts = cases.wall_contacts(case)
    ended = (contacts["tEnd"] > T0) & (contacts["tEnd"] <= END)
    terms = {"dpdz": -drive["dpdz"][steps].mean(),
             "weight": cv * (RHO_P - RHO) * G,
             "fluidWall": -RHO * np.trapz(tau, ts) / T / volume,
             "oreWall": -contacts["J_z"][ended].sum() / T / volume,
             "inertia": (sum(mass * w1) - sum(mass * w0)) / (T * volume)}
    print("%s: %d ores, C_v %.5f, mean ore velocity %.3f m/s; %d wall contacts in the window,"
          " longest %.3g s" % (os.path.basename(case), len(diameters), cv,
                               0.5 * (w0.mean() + w1.mean()), ended.sum(),
                               contacts["duration"][ended].max()))
    print("  -dp/dz %(dpdz).4f Pa/m = C_v (rho_p - rho_f) g %(weight).4f + carrier's wall shear"
          " %(fluidWall).4f + ores' wall friction %(oreWall).4f + ores' momentum change"
          " %(inertia).4f" % terms)
    return terms


with concurrent.futures.ThreadPoolExecutor(max_workers=2) as pool:
    runs = list(pool.map(lambda args: transport(*args), (("alone", False), ("pairs", True))))
for case in runs:
    terms = balance(case)
    checks.near("%s: -dp/dz [Pa/m] against the mixture's balance" % os.path.basename(case),
                terms["dpdz"], terms["weight"] + terms["fluidWall"] + terms["oreWall"]
                + terms["inertia"], 2e-2)
checks.exit()
