#!/usr/bin/python3
"""Writes the initial carrier 0/U of a riserCoupledFoam case relative to the
riser (riser frame): a fully developed axial profile at the cell centres.

usage: initCarrier.py poiseuille|powerLaw     (in the case folder)

poiseuille: the laminar Poiseuille flow u_cm (1 - r^2/R^2) of
constant/riserProperties (D, uCentre), the analytic carrier of
riserParcelFoam, scaled to the bulk velocity u_cm/2 on the mesh, and the
drive's gradient of that flow in 0/uniform/riserDrive
(riserfoam.cases.poiseuille_start, which also writes the cell centres);
powerLaw: the 1/7 power law of a turbulent pipe flow
(riserfoam.pipeflow.power_law) at the drive's bulkVelocity (default
uCentre/2), at the cell centres that `postProcess -func writeCellCentres
-time 0` writes to 0/C; and where the case has 0/k and 0/omega, their
uniform start and wall values from that bulk velocity and D
(riserfoam.pipeflow.turbulence_estimates: intensity 5 %, length 0.07 D), so
that D and the bulk velocity are given in riserProperties alone. The wall
is noSlip, the ends cyclic (a periodic riser section from bin/riserMesh
-ends cyclic), the riser frame; the
Poiseuille profile also in the lab frame (riserProperties' frame lab: the
flow moves with the riser, its wall is movingWallVelocity).
"""
from riserfoam.cli import help_requested  # noqa: E402

help_requested(__doc__)

import os
import re
import sys

from riserfoam import cases
from riserfoam import foamfields as ff
from riserfoam import pipeflow
from riserfoam.carrier import Riser


def main():
    profile = sys.argv[1] if len(sys.argv) == 2 else None
    riser = Riser.of_case(".")
    R = 0.5 * riser.D
    if profile == "poiseuille":
        transport = os.path.join("constant", "transportProperties")
        mu = ff.read_entry(transport, "nu") * ff.read_entry(transport, "rhoInf")
        text = open(os.path.join("constant", "riserProperties")).read()
        lab = re.search(r"^\s*frame\s+lab\s*;", text, re.M) is not None
        cases.poiseuille_start(".", riser, "lab" if lab else "riser",
                               "movingWallVelocity" if lab else "noSlip", mu)
        print("initCarrier: 0/U, the Poiseuille profile, and 0/uniform/riserDrive")
        return
    if profile == "powerLaw":
        ub = ff.read_entry(os.path.join("constant", "riserProperties"), "bulkVelocity")
        ub = 0.5 * riser.u_cm if ub is None else ub

        def axial(r):
            return pipeflow.power_law(r, R, ub)
    else:
        sys.exit("usage: initCarrier.py poiseuille|powerLaw")
    centres = ff.read_vectors(os.path.join("0", "C"), "internalField")
    ff.write_vector_field(
        os.path.join("0", "U"), centres,
        {"riserWall": "type noSlip;", "bottom": "type cyclic;", "top": "type cyclic;"},
        lambda x, y, z: (0.0, 0.0, axial(riser.axis_distance(x, y))), precision=12,
        note="the %s profile relative to the riser, written by initCarrier.py" % profile)
    print("initCarrier: 0/U, the %s profile at %d cell centres" % (profile, len(centres)))
    if profile == "powerLaw":
        k, omega, _ = pipeflow.turbulence_estimates(ub, riser.D)
        for name, value in (("k", k), ("omega", omega)):
            path = os.path.join("0", name)
            if os.path.exists(path):
                for entry in ("internalField", "boundaryField/riserWall/value"):
                    ff.set_nested(path, entry, "uniform %.6g" % value)
                print("initCarrier: 0/%s, uniform %.6g" % (name, value))


main()
