"""The classical and the finite-Re history kernel in riserParcelFoam: the
flagship's lift and the cost per particle-step (see Allrun).

usage: historyKernel.py <work folder> [cost rounds, default 5]

Writes results/lift.dat (per scene and kernel: the lift after the run and
its change against the classical kernel) and
results/cost.dat (per particle-step as ratios to the classical kernel's of
the same round: median, min, max)."""
import os
import sys

from riserfoam.cli import help_requested  # noqa: E402

help_requested(__doc__)

from riserfoam import cases, costs, foamfields as ff, tables

work = os.path.abspath(sys.argv[1])
ROUNDS = int(sys.argv[2]) if len(sys.argv) > 2 else 5
BASSET = "subModels/particleForces/riserBasset"
KERNELS = {
    "classical": "{ coefficient classical; method windowTail; windowTime 0.01; }",
    "michaelidesRoig": "{ coefficient michaelidesRoig; method windowTail; windowTime 0.01; }",
    "meiAdrian": "{ coefficient classical; kernel meiAdrian; method windowTail; windowTime 0.01; }",
}
TABLE = "postProcessing/lagrangian/kinematicCloud/riserParticleTable/particles.dat"


def flagship(name, kernel, still):
    """the flagship with the kernel's Basset entry; still: the riser at rest, 1 s"""
    case = os.path.join(work, name)
    cases.copy_tutorial("riser/oscillatingContact", case)
    ff.set_nested(os.path.join(case, "constant/kinematicCloudProperties"), BASSET, KERNELS[kernel])
    if still:
        ff.set_entry(os.path.join(case, "constant/riserProperties"), "A", "[0 1 0 0 0 0 0] 0")
        control = os.path.join(case, "system/controlDict")
        ff.set_entry(control, "endTime", "1")
        ff.set_entry(control, "writeInterval", "1")
    cases.riser_mesh(case, 0.1, 0.2, 12, ends="cyclic")
    cases.run(["riserParcelFoam", "-case", case], os.path.join(case, "log.riserParcelFoam"))
    return tables.read(os.path.join(case, TABLE))



def lift_runs():
    os.makedirs("results", exist_ok=True)
    rows = []
    for scene, still in (("flagship", False), ("still", True)):
        base = None
        for kernel in KERNELS:
            name = "%s_%s" % (scene, kernel)
            t = flagship(name, kernel, still)
            lift = float(t["lift"][-1])
            base = lift if kernel == "classical" else base
            rows.append("%s %s %.6f %+.3f" % (scene, kernel, lift, 100 * (lift / base - 1)))
            print(rows[-1], flush=True)
    with open("results/lift.dat", "w") as out:
        out.write("# riserParcelFoam, the flagship's ore (10 mm, 2000 kg/m^3) in the riser of D = 0.1 m,"
                  " u_c 1 m/s: shaken (A 0.1 m, 3 Hz, 5 periods) and at rest (1 s)\n"
                  "# scene kernel lift_at_end[m] change_against_classical[%]\n")
        out.write("\n".join(rows) + "\n")


def cost_runs():
    folders = {}
    for kernel in KERNELS:
        case = os.path.join(work, "cost_" + kernel)
        ff.set_nested(costs.ore_transport_section(case, 0.3), BASSET, KERNELS[kernel])
        folders[kernel] = case
    ratios, parcels = costs.rounds(folders, "classical", ROUNDS)
    costs.write("results/cost.dat",
                "# riserParcelFoam, a 1 m periodic section of oreTransport (D = 0.1 m) at C_v = 0.01,"
                " 0.3 s: execution time per particle-step as ratios to the classical kernel's of the"
                " same round (%d rounds)\n"
                "# history parcels_at_end per_particle_step(median min max)\n" % ROUNDS,
                ratios, parcels)


lift_runs()
cost_runs()
