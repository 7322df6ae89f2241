"""The motion models' cost in a cloud (riserParcelFoam) per particle-step,
as ratios to the sinusoid's measured in the same round (see Allrun).

The section of tutorials/riser/wholeRiserCloud (10 m at z = 28 to 38 m, the
riser frame, the exact carrier, wall and pair contacts) filled with ores at
C_v = 0.01 (riserFill) and run for 1 s, the riser moving as
  sinusoid: A = 0.2 m at 0.5 Hz (rigid);
  modes:    mode 1 of a 20 km riser whose antinode is at the section's
            middle, 0.2 m at 0.5 Hz (its shape falls by 1e-6 over the
            section: the same scene through the sheared frame's code);
  table:    that mode sampled every 1 m and 0.025 s (the table's code).
The three scenes are the same to within a part in 1e5, so the particles
and their contacts are the same and the ratio is the motion's cost. The
cost is the solver's execution time from its first step to its last over
the sum of the particles in the cloud at each step (riserfoam.costs)."""
import math
import os
import sys

from riserfoam import cases, costs, foamfields as ff

work = os.path.abspath(sys.argv[1])
END = float(sys.argv[2]) if len(sys.argv) > 2 else 1.0
ROUNDS = int(sys.argv[3]) if len(sys.argv) > 3 else 3
A, F, BOTTOM, LENGTH = 0.2, 0.5, 28.0, 10.0
RISER_LENGTH = 20000.0
FOOT = BOTTOM + 0.5 * LENGTH - 0.5 * RISER_LENGTH
MOTIONS = {
    "sinusoid": "{ type sinusoid; A %r; f %r; }" % (A, F),
    "modes": "{ type modes; foot %r; length %r; x ((1 %r %r 0)); }" % (FOOT, RISER_LENGTH, A, F),
    "table": '{ type table; file "constant/riserMotion.csv"; }',
}
FILL = """{
    type            riserFill;
    SOI             0;
    massTotal       0;
    parcelBasisType fixed;
    nParticle       1;
    solidsFraction  0.01;
    seed            1;
    velocity        carrier;
    sizeDistribution
    {
        type        normal;
        normalDistribution { expectation 0.01; variance 1e-6; minValue 0.008; maxValue 0.012; }
    }
}"""


def write_table(case):
    with open(os.path.join(case, "constant/riserMotion.csv"), "w") as out:
        out.write("t z x y\n")
        for j in range(int(round((END + 0.2) / 0.025)) + 1):
            t = 0.025 * j
            for z in range(int(BOTTOM) - 2, int(BOTTOM + LENGTH) + 3):
                shape = math.sin(math.pi * (z - FOOT) / RISER_LENGTH)
                out.write("%.10g %d %.17g 0\n" % (t, z, A * shape * math.sin(2 * math.pi * F * t)))


def make(name):
    case = os.path.join(work, name)
    cases.copy_tutorial("riser/wholeRiserCloud", case)
    riser = os.path.join(case, "constant/riserProperties")
    ff.set_nested(riser, "motion", MOTIONS[name])
    cloud = os.path.join(case, "constant/kinematicCloudProperties")
    ff.set_nested(cloud, "subModels/injectionModels", "{ ores %s }" % FILL)
    ff.set_nested(cloud, "cloudFunctions", "{}")
    control = os.path.join(case, "system/controlDict")
    ff.set_entry(control, "endTime", repr(END))
    ff.set_entry(control, "writeInterval", repr(END))
    cases.riser_mesh(case, 0.1, LENGTH, 4, ends="wall")
    boundary = os.path.join(case, "constant/polyMesh/boundary")
    for patch in ("bottom", "top"):
        ff.set_nested(boundary, "entry0/%s/type" % patch, "patch")
        ff.remove_entry(boundary, "entry0/%s/inGroups" % patch)
    cases.run(["transformPoints", "-translate", "(0 0 %r)" % BOTTOM, "-case", case],
              os.path.join(case, "log.transformPoints"))
    if name == "table":
        write_table(case)
    return case


folders = {name: make(name) for name in MOTIONS}
ratios, parcels = costs.rounds(folders, "sinusoid", ROUNDS)
costs.write("results/cloudCost.dat",
            "# riserParcelFoam, a 10 m section at C_v = 0.01, %g s: execution time per"
            " particle-step as ratios to the sinusoid's of the same round (%d rounds)\n"
            "# motion parcels_at_end per_particle_step(median min max)\n" % (END, ROUNDS),
            ratios, parcels)
