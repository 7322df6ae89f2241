"""The two frames of the cloud solvers against each other and against the
mesh-free engine as the step falls.

Two-way (riserCoupledFoam): the scene of tutorials/riser/coupledFrames, the
coupled flagship's ore (tutorials/riser/oscillatingContactCoupled:
d = 10 mm, 2000 kg/m^3, released with the carrier's 0.68 m/s upward; paper
drag law, Saffman-Mei lift, added mass, Basset history, fluid stress;
two-way coupled through the diffusion kernel) in a laminar periodic section
(D = L = 0.1 m, 8 cells across the core) without wall contact, the riser
oscillating at A = 0.01 m, for five periods, at the steps dt, dt/2, dt/4 of
the flagship's dt = 5e-4 s. Each case is run in the riser frame (static
mesh, the frame force) and in the lab frame (the mesh moving with the
riser, riserOscillation; the ore released with the riser's velocity added).
The two frames are the same physics, so the difference of the ore's lift
after five periods is the discretisation's. Scenes: 3 Hz and 10 Hz with the
flagship's release 0.2 D off the axis in x and y, and 10 Hz released on
the axis. At 10 Hz the riser's 39 m/s^2 flings the off-axis ore against
the wall within a period: without a contact model it runs into it until
the stock rebound turns it at the wall's face (one-way, with the exact
carrier, it grazes it), an impact no step of the flow resolves the same
way; the ore released on the axis stays 14 mm off the wall. Written to results/convergence.dat (f, release, dt, the two lifts,
their difference over the riser frame's lift, the ore's nearest approach
to the wall over both frames).

One-way (riserParcelFoam, exact carrier): the ore of
tutorials/riser/oscillatingNoContact (drag, lift, added mass, fluid
stress) at 10 Hz, A = 0.01 m, for five periods in both frames at
dt = 5e-4 s to 6.25e-5 s, against riserParticle (lab frame, integrator
tolerance 1e-11): the largest difference of the lift over the run, for
both releases. Written to results/oneWay.dat.

usage: frames.py <work folder> [twoWay] [oneWay]    (default both)
One solver run at a time (about 45 minutes for the two-way runs).
"""
import math
import os
import shutil
import sys

from riserfoam import cases, tables
from riserfoam import foamfields as ff

HERE = os.path.dirname(os.path.abspath(__file__))
TUTORIALS = os.path.join(cases.ROOT, "tutorials", "riser")
SOURCE = os.path.join(TUTORIALS, "oscillatingContactCoupled")
DYNAMIC_MESH = os.path.join(TUTORIALS, "coupledFrames", "constant", "dynamicMeshDict")
A, PERIODS, DT, D = 0.01, 5, 5e-4, 0.1
TABLE = "postProcessing/lagrangian/kinematicCloud/riserParticleTable/particles.dat"
RELEASES = {"offAxis": (0.02, 0.02, 0.05), "axis": (0.0, 0.0, 0.05)}
TWO_WAY_SCENES = ((3.0, "offAxis"), (10.0, "offAxis"), (10.0, "axis"))


def set_scene(case, frame, f, dt, release):
    """riser motion, frame, release and run length of a copied case"""
    riser = os.path.join(case, "constant", "riserProperties")
    ff.set_nested(riser, "A", "[0 1 0 0 0 0 0] %r" % A)
    ff.set_nested(riser, "f", "[0 0 -1 0 0 0 0] %r" % f)
    ff.set_nested(riser, "frame", frame)
    cloud = os.path.join(case, "constant", "kinematicCloudProperties")
    Ux = A * 2 * math.pi * f if frame == "lab" else 0.0
    ff.set_nested(cloud, "subModels/injectionModels/release/U0", "(%.17g 0 0.68)" % Ux)
    if frame == "lab":
        ff.remove_entry(cloud, "subModels/particleForces/riserFrame")
        shutil.copy(DYNAMIC_MESH, os.path.join(case, "constant"))
    else:
        dynamic = os.path.join(case, "constant", "dynamicMeshDict")
        if os.path.exists(dynamic):
            os.remove(dynamic)
    ff.write_dictionary(os.path.join(case, "constant", "kinematicCloudPositions"),
                        "((%r %r %r))\n" % RELEASES[release], "vectorField")
    control = os.path.join(case, "system", "controlDict")
    end = PERIODS / f
    for entry, value in (("deltaT", "%r" % dt), ("endTime", "%.17g" % end),
                         ("writeInterval", "%.17g" % end)):
        ff.set_nested(control, entry, value)
    ff.remove_entry(control, "functions")


def make_two_way(case, frame, f, dt, release):
    """the two-way scene in one frame"""
    shutil.rmtree(case, ignore_errors=True)
    os.makedirs(case)
    for folder in ("0.orig", "constant", "system"):
        shutil.copytree(os.path.join(SOURCE, folder), os.path.join(case, folder))
    set_scene(case, frame, f, dt, release)
    cloud = os.path.join(case, "constant", "kinematicCloudProperties")
    ff.set_nested(cloud, "subModels/collisionModel", "none")
    ff.set_nested(cloud, "cloudFunctions", "{ table { type riserParticleTable; } }")
    cases.riser_mesh(case, D, 0.1, 8, nz=8, ends="cyclic")
    shutil.copytree(os.path.join(case, "0.orig"), os.path.join(case, "0"))
    cases.run([sys.executable, os.path.join(TUTORIALS, "common", "initCarrier.py"),
               "poiseuille"], os.path.join(case, "log.initCarrier"), cwd=case)


def make_one_way(case, frame, f, dt, release):
    """the one-way scene (exact carrier) in one frame"""
    shutil.rmtree(case, ignore_errors=True)
    cases.copy_tutorial("riser/oscillatingNoContact", case)
    set_scene(case, frame, f, dt, release)
    cases.riser_mesh(case, D, 0.1, 6, ends="cyclic")


def track(case, engine=False):
    """{t: (lift, gap to the wall)} of the ore"""
    path = "postProcessing/riserParticle/particles.dat" if engine else TABLE
    rows = tables.read(os.path.join(case, path))
    reach = 0.5 * D - 0.005
    return {round(t, 9): (lift, reach - math.hypot(x, y))
            for t, x, y, lift in zip(rows["t"], rows["xr"], rows["yr"], rows["lift"])}


def two_way(work):
    rows = []
    for f, release in TWO_WAY_SCENES:
        for k in (1, 2, 4):
            dt = DT / k
            lifts, gap = {}, D
            for frame in ("riser", "lab"):
                case = os.path.join(work, "twoWay_f%g_%s_dt%d_%s" % (f, release, k, frame))
                make_two_way(case, frame, f, dt, release)
                cases.run(["riserCoupledFoam", "-case", case],
                          os.path.join(case, "log.riserCoupledFoam"))
                ore = track(case)
                lifts[frame] = ore[max(ore)][0]
                gap = min(gap, min(g for _, g in ore.values()))
            apart = (lifts["lab"] - lifts["riser"]) / lifts["riser"]
            rows.append((f, release, dt, lifts["riser"], lifts["lab"], apart, gap))
            print("f = %g Hz, %s, dt = %g s: lift riser %.6f m, lab %.6f m, apart %+.4f %%,"
                  " nearest the wall %.2e m" % (f, release, dt, lifts["riser"], lifts["lab"],
                                                100 * apart, gap), flush=True)
    with open(os.path.join(HERE, "results", "convergence.dat"), "w") as out:
        out.write("# riserCoupledFoam, lab frame against riser frame: the ore's lift after"
                  " %d periods, A = %g m\n# f[Hz] release dt[s] liftRiser[m] liftLab[m]"
                  " (lab-riser)/riser nearestWallGap[m]\n" % (PERIODS, A))
        for row in rows:
            out.write("%g %s %g %.9g %.9g %.4e %.3e\n" % row)


def one_way(work):
    f = 10.0
    rows = []
    for release in ("offAxis", "axis"):
        engine = os.path.join(work, "oneWay_%s_engine" % release)
        make_one_way(engine, "lab", f, 1e-4, release)
        ff.write_dictionary(os.path.join(engine, "system", "riserParticleDict"),
                            "adaptiveCoeffs { tolerance 1e-11; }\n")
        cases.run(["riserParticle", "-case", engine], os.path.join(engine, "log.riserParticle"))
        reference = track(engine, engine=True)
        for k in (1, 2, 4, 8):
            dt = DT / k
            worst = {}
            for frame in ("riser", "lab"):
                case = os.path.join(work, "oneWay_%s_dt%d_%s" % (release, k, frame))
                make_one_way(case, frame, f, dt, release)
                cases.run(["riserParcelFoam", "-case", case],
                          os.path.join(case, "log.riserParcelFoam"))
                ore = track(case)
                common = [t for t in ore if t in reference]
                worst[frame] = max(abs(ore[t][0] - reference[t][0]) for t in common)
            gap = min(g for _, g in reference.values())
            rows.append((release, dt, worst["riser"], worst["lab"], gap))
            print("one-way, %s, dt = %g s: lift's largest difference from the engine: riser"
                  " frame %.3e m, lab frame %.3e m (engine's nearest approach to the wall"
                  " %.2e m)" % rows[-1], flush=True)
    with open(os.path.join(HERE, "results", "oneWay.dat"), "w") as out:
        out.write("# riserParcelFoam (exact carrier) against riserParticle, f = %g Hz,"
                  " A = %g m, %d periods: the lift's largest difference over the run\n"
                  "# release dt[s] riserFrame[m] labFrame[m] engineNearestWallGap[m]\n"
                  % (f, A, PERIODS))
        for row in rows:
            out.write("%s %g %.4e %.4e %.3e\n" % row)


def main():
    work = os.path.abspath(sys.argv[1])
    parts = sys.argv[2:] or ["oneWay", "twoWay"]
    os.makedirs(os.path.join(HERE, "results"), exist_ok=True)
    for part in parts:
        {"oneWay": one_way, "twoWay": two_way}[part](work)


if __name__ == "__main__":
    main()
