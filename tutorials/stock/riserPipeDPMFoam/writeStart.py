#!/usr/bin/python3
"""The start of the pipe flow: 0/U.water the developed laminar (Poiseuille)
flow u = 2 u_b (1 - r^2/R^2) along z at the cell centres and on the inlet
(bottom), so the ores meet developed flow from the foot; the ores' release
points in constant/kinematicCloudPositions: N points (default 200, -N),
the first on the axis at z = L/4, the others uniform over the cross-section
inside r = R - d and over 0.01 m < z < L/2, from a fixed seed. D and L
are read from the comment riserMesh writes at the top of
system/blockMeshDict, u_b from -bulk [m/s].

usage: writeStart.py [-bulk 0.1] [-N 200] [-seed 1]   (in the case, after blockMesh)
"""
from riserfoam.cli import help_requested  # noqa: E402

help_requested(__doc__)

import argparse
import math
import os
import random
import re
import subprocess

from riserfoam import foamfields as ff

DIAMETER = 0.0005   # the ores' diameter in constant/kinematicCloudProperties [m]


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("-bulk", type=float, default=0.1, help="bulk velocity [m/s] (> 0)")
    ap.add_argument("-N", type=int, default=200, help="ores released (>= 0)")
    ap.add_argument("-seed", type=int, default=1)
    args = ap.parse_args()
    if not args.bulk > 0 or args.N < 0:
        ap.error("-bulk must be > 0 and -N >= 0")
    mesh = open("system/blockMeshDict").read()
    D, L = (float(v) for v in re.search(r"D = (\S+) m, L = (\S+) m", mesh).groups())
    R = 0.5 * D

    with open("log.writeCellCentres", "w") as log:
        subprocess.run(["postProcess", "-func", "writeCellCentres", "-time", "0"],
                       stdout=log, stderr=subprocess.STDOUT, check=True)
    centres = ff.read_vectors("0/C", "internalField")
    inlet = ff.read_vectors("0/C", "bottom")
    for name in ("C", "Cx", "Cy", "Cz"):
        if os.path.exists(os.path.join("0", name)):
            os.remove(os.path.join("0", name))

    def poiseuille(x, y, z):
        return 0.0, 0.0, 2 * args.bulk * max(0.0, 1 - (x * x + y * y) / (R * R))

    def values(points):
        return "\n".join("(0 0 %.12g)" % poiseuille(*p)[2] for p in points)

    ff.write_vector_field(
        "0/U.water", centres,
        {"riserWall": "type noSlip;",
         "bottom": "type fixedValue;\n        value nonuniform List<vector>\n%d\n(\n%s\n);"
                   % (len(inlet), values(inlet)),
         "top": "type zeroGradient;"},
        poiseuille, precision=12,
        note="Poiseuille flow of bulk velocity %g m/s (writeStart.py)" % args.bulk)

    rng = random.Random(args.seed)
    points = [(0.0, 0.0, 0.25 * L)][:args.N]
    while len(points) < args.N:
        x, y = (rng.uniform(-R, R) for _ in range(2))
        if math.hypot(x, y) < R - DIAMETER:
            points.append((x, y, rng.uniform(0.01, 0.5 * L)))
    ff.write_dictionary("constant/kinematicCloudPositions",
                        "(\n%s\n)\n" % "\n".join("(%.9g %.9g %.9g)" % p for p in points),
                        "vectorField")
    print("writeStart.py: Poiseuille flow of bulk velocity %g m/s (%g m/s on the axis), "
          "%d ores" % (args.bulk, 2 * args.bulk, len(points)))


main()
