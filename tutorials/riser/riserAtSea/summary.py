"""The means of the riser-at-sea runs after their first period, one row a
carrier: the ores' mean axial velocity and slip relative to the riser, the
lifting efficiency (mean v_z over the carrier's own centre-line speed), the
wall and pair contact rates per ore (riserTransportStatistics'
transport.dat); written to summary.dat and printed.

usage: summary.py <case> ...     (in the tutorial's folder, after its runs)"""
from riserfoam.cli import help_requested  # noqa: E402

help_requested(__doc__)

import os
import sys

import numpy as np

from riserfoam import foamfields as ff
from riserfoam import tables

COLUMNS = ("Urz", "slipz", "liftingEfficiency", "contactRate", "pairContactRate")
if len(sys.argv) < 2:
    sys.exit(__doc__)
rows = []
for case in sys.argv[1:]:
    t = tables.read(os.path.join(
        case, "postProcessing/lagrangian/kinematicCloud/riserTransportStatistics/transport.dat"))
    period = 1 / ff.read_entry(os.path.join(case, "constant/riserProperties"), "f")
    after = np.asarray(t["t"]) >= period - 1e-9
    if not after.any():
        sys.exit("summary.py: %s has no sample after its first period (%g s)" % (case, period))
    rows.append((case,) + tuple(float(np.mean(np.asarray(t[c])[after])) for c in COLUMNS))
with open("summary.dat", "w") as out:
    out.write("# carrier Urz[m/s] slipz[m/s] liftingEfficiency[-] wallContactRate[1/s]"
              " pairContactRate[1/s] (means after the first period)\n")
    for r in rows:
        out.write("%s %.4f %.4f %.4f %.3f %.3f\n" % r)
        print("%-10s ore v_z %.3f m/s, slip %.3f m/s, lifting efficiency %.3f,"
              " %.2f wall and %.1f pair contacts a second per ore" % r)
