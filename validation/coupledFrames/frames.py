"""The two frames of riserCoupledFoam against each other as the step falls.

The scene of tutorials/riser/coupledFrames: the coupled flagship's ore
(tutorials/riser/oscillatingContactCoupled: d = 10 mm, 2000 kg/m^3,
released at (0.02, 0.02, 0.05) m with the carrier's 0.68 m/s upward; paper
drag law, Saffman-Mei lift, added mass, Basset history, fluid stress;
two-way coupled through the diffusion kernel) in a laminar periodic section
(D = L = 0.1 m, 8 cells across the core) without wall contact, the riser
oscillating at A = 0.01 m (the ore stays off the wall), for five periods, at
f = 3 and 10 Hz and the steps dt, dt/2, dt/4 of the flagship's
dt = 5e-4 s. Each case is run in the riser frame (static mesh, the frame
force) and in the lab frame (the mesh moving with the riser,
riserOscillation; the ore released with the riser's velocity added). The
two frames are the same physics, so the difference of the ore's lift after
five periods is the discretisation's: written to
results/convergence.dat (f, dt, the two lifts, their difference over the
riser frame's lift) and printed.

usage: frames.py <work folder> [frequencies...]    (default 3 10)
One solver run at a time.
"""
import math
import os
import shutil
import sys

from riserfoam import cases, tables
from riserfoam import foamfields as ff

HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE = os.path.join(cases.ROOT, "tutorials", "riser", "oscillatingContactCoupled")
DYNAMIC_MESH = os.path.join(cases.ROOT, "tutorials", "riser", "coupledFrames", "constant",
                            "dynamicMeshDict")
A, PERIODS, DT = 0.01, 5, 5e-4
TABLE = "postProcessing/lagrangian/kinematicCloud/riserParticleTable/particles.dat"


def make(case, frame, f, dt):
    """the scene in one frame at frequency f [Hz] and step dt [s]"""
    shutil.rmtree(case, ignore_errors=True)
    os.makedirs(case)
    for folder in ("0.orig", "constant", "system"):
        shutil.copytree(os.path.join(SOURCE, folder), os.path.join(case, folder))
    riser = os.path.join(case, "constant", "riserProperties")
    ff.set_nested(riser, "A", "[0 1 0 0 0 0 0] %r" % A)
    ff.set_nested(riser, "f", "[0 0 -1 0 0 0 0] %r" % f)
    ff.set_nested(riser, "frame", frame)
    cloud = os.path.join(case, "constant", "kinematicCloudProperties")
    ff.set_nested(cloud, "subModels/collisionModel", "none")
    ff.set_nested(cloud, "cloudFunctions", "{ table { type riserParticleTable; } }")
    if frame == "lab":
        ff.set_nested(cloud, "subModels/injectionModels/release/U0",
                      "(%.17g 0 0.68)" % (A * 2 * math.pi * f))
        ff.remove_entry(cloud, "subModels/particleForces/riserFrame")
        shutil.copy(DYNAMIC_MESH, os.path.join(case, "constant"))
    control = os.path.join(case, "system", "controlDict")
    end = PERIODS / f
    for entry, value in (("deltaT", "%r" % dt), ("endTime", "%.17g" % end),
                         ("writeInterval", "%.17g" % end)):
        ff.set_nested(control, entry, value)
    ff.remove_entry(control, "functions")
    cases.riser_mesh(case, 0.1, 0.1, 8, nz=8, ends="cyclic")
    shutil.copytree(os.path.join(case, "0.orig"), os.path.join(case, "0"))
    cases.run([sys.executable, os.path.join(cases.ROOT, "tutorials", "riser", "common",
                                            "initCarrier.py"), "poiseuille"],
              os.path.join(case, "log.initCarrier"), cwd=case)


def lift(case):
    return tables.read(os.path.join(case, TABLE))["lift"][-1]


def main():
    work = os.path.abspath(sys.argv[1])
    frequencies = [float(a) for a in sys.argv[2:]] or [3.0, 10.0]
    os.makedirs(os.path.join(HERE, "results"), exist_ok=True)
    rows = []
    for f in frequencies:
        for k in (1, 2, 4):
            dt = DT / k
            lifts = {}
            for frame in ("riser", "lab"):
                case = os.path.join(work, "f%g_dt%d_%s" % (f, k, frame))
                make(case, frame, f, dt)
                cases.run(["riserCoupledFoam", "-case", case],
                          os.path.join(case, "log.riserCoupledFoam"))
                lifts[frame] = lift(case)
            apart = (lifts["lab"] - lifts["riser"]) / lifts["riser"]
            rows.append((f, dt, lifts["riser"], lifts["lab"], apart))
            print("f = %g Hz, dt = %g s: lift riser %.6f m, lab %.6f m, apart %+.3f %%"
                  % (f, dt, lifts["riser"], lifts["lab"], 100 * apart), flush=True)
    with open(os.path.join(HERE, "results", "convergence.dat"), "w") as out:
        out.write("# riserCoupledFoam, lab frame against riser frame: the ore's lift after"
                  " %d periods, A = %g m\n# f[Hz] dt[s] liftRiser[m] liftLab[m]"
                  " (lab-riser)/riser\n" % (PERIODS, A))
        for row in rows:
            out.write("%g %g %.9g %.9g %.4e\n" % row)


if __name__ == "__main__":
    main()
