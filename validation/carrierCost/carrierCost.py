"""The carrier profiles' cost in riserParcelFoam per particle-step, as ratios
to the laminar carrier's measured in the same round (see Allrun).

usage: carrierCost.py <work folder> [end time [s], default 0.3] [rounds, default 3]

The carriers, each of the bulk speed 1 m/s in the 0.1 m riser (Re 1e5):
  laminar:    Poiseuille flow, uCentre 2 m/s;
  turbulent:  the closed-form turbulent profile (profile turbulent);
  tabulated:  that profile sampled at 21 radii (profile tabulated, k and
              nu_t of the order of a RAS run's: 0.004 m^2/s^2, 2e-4 m^2/s);
  dispersed:  the tabulated one with dispersionModel langevinDispersionRAS.
The ores are filled at rest relative to each carrier, so the scenes differ
in their motion but not in their number: the ratio per particle-step is
the carrier's cost (with the contacts the different motions bring). The
cost is the solver's execution time from its first step to its last over
the sum of the particles in the cloud at each step (riserfoam.costs)."""
import os
import sys

from riserfoam.cli import help_requested  # noqa: E402

help_requested(__doc__)

from riserfoam import costs, foamfields as ff, pipeflow

work = os.path.abspath(sys.argv[1])
END = float(sys.argv[2]) if len(sys.argv) > 2 else 0.3
ROUNDS = int(sys.argv[3]) if len(sys.argv) > 3 else 3
D, UB, NU = 0.1, 1.0, 1e-6
CARRIERS = {
    "laminar": "profile laminar; uCentre %r;" % (2 * UB),
    "turbulent": "profile turbulent; uBulk %r;" % UB,
    "tabulated": 'profile tabulated; profileFile "constant/riserCarrierProfile";',
    "dispersed": 'profile tabulated; profileFile "constant/riserCarrierProfile";',
}


def write_profile(case):
    w = pipeflow.turbulent_profile(UB, D, NU)
    rows = []
    for i in range(21):
        r = 0.5 * D * i / 20
        rows.append("    (%r %r %r %r)" % (r, float(w(r)), 0.004 * (1 - 0.5 * (2 * r / D) ** 2),
                                          2e-4 * (1 - (2 * r / D) ** 2)))
    ff.write_dictionary(os.path.join(case, "constant/riserCarrierProfile"),
                        "rows\n(\n%s\n);\n" % "\n".join(rows))


def make(name):
    case = os.path.join(work, name)
    cloud = costs.ore_transport_section(case, END)
    riser = os.path.join(case, "constant/riserProperties")
    ff.remove_entry(riser, "uCentre")
    with open(riser, "a") as out:
        out.write(CARRIERS[name] + "\n")
    if name == "dispersed":
        ff.set_nested(cloud, "subModels/dispersionModel", "langevinDispersionRAS")
    if name in ("tabulated", "dispersed"):
        write_profile(case)
    return case


folders = {name: make(name) for name in CARRIERS}
ratios, parcels = costs.rounds(folders, "laminar", ROUNDS)
costs.write("results/carrierCost.dat",
            "# riserParcelFoam, a 1 m periodic section of D = 0.1 m at C_v = 0.01, %g s:"
            " execution time per particle-step as ratios to the laminar carrier's of the"
            " same round (%d rounds)\n"
            "# carrier parcels_at_end per_particle_step(median min max)\n" % (END, ROUNDS),
            ratios, parcels)
