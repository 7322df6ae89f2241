"""The mesh-free engine's accuracy against its tolerance on eight scenes of the
paper's (A, f) grid: (A/D, f D/u_cm) in {(1, .05), (1, .3), (.5, .05),
(2, .05), (1, .15), (1, .4), (.5, .3), (2, .3)}, 40 s each, the flagship's
particle and wall contact (tutorial riser/oscillatingContact without the
Basset force, which riserParticle has not), rows every 2 ms. Each scene is run
with the adaptive integrator at the tolerances below and compared with its run
at 1e-12 (the reference): the lift at 40 s and the largest distance of the lab
trajectory from the reference's over the rows, in D. A scene whose reference
itself moves by more than the goal when the release point moves by 1e-10 D
(sensitive: nearby paths part over its hundreds of contacts) is marked so: no
tolerance can meet a trajectory goal there.

Goal of the default: lift within 0.5 % and trajectory within 1e-3 D.

usage: eightScenes.py <project root> <scratch folder> <results folder>
"""
import os
import subprocess
import sys
import time

import numpy as np
from riserfoam import tables
from riserfoam.carrier import D
from riserfoam.cases import RiserCase

root, scratch, results = sys.argv[1:4]
SCENES = [(1, .05), (1, .3), (.5, .05), (2, .05), (1, .15), (1, .4), (.5, .3), (2, .3)]
TOLERANCES = ["1e-6", "1e-8", "1e-9", "1e-10", "default"]
REFERENCE = "1e-12"
T, ROWS = 40.0, 2e-3


def run(A, f, tol, shift=0.0):
    name = "A%g_f%g_%s%s" % (A, f, tol, "_shifted" if shift else "")
    case = (RiserCase(root, scratch, name, tutorial="oscillatingContact")
            .without_force("riserBasset").riser(A=A, f=f)
            .run_for(T, ROWS).releases([(0.2 + shift, 0.2)]))
    if tol != "default":
        case.engine_settings("integrator adaptive; adaptiveCoeffs { tolerance %s; }" % tol)
    start = time.perf_counter()
    with open(os.path.join(case.path, "log.riserParticle"), "w") as log:
        subprocess.run(["riserParticle", "-case", case.path], stdout=log,
                       stderr=subprocess.STDOUT, check=True)
    wall = time.perf_counter() - start
    out = os.path.join(case.path, "postProcessing/riserParticle")
    t = tables.read(os.path.join(out, "particles.dat"))
    c = tables.read(os.path.join(out, "contacts.dat"))
    x = t.matrix("x", "y", "z")
    os.remove(os.path.join(out, "particles.dat"))
    return x, float(t["lift"][-1]), len(c["start"]) if "start" in c.names else 0, wall


lines = ["# eightScenes.py: the mesh-free engine (adaptive) against its tolerance, T = 40 s,",
         "# reference tolerance %s; lift error [%%] and largest trajectory distance [D] from"
         " the reference;" % REFERENCE,
         "# sensitive: the reference moves by more than 1e-3 D when the release moves by 1e-10 D",
         "A/D f tolerance lift_m liftError_percent trajectory_D contacts wall_s meets sensitive"]
for A, f in SCENES:
    xr, liftr, nr, wr = run(A, f, REFERENCE)
    xs, _, _, _ = run(A, f, REFERENCE, shift=1e-10)
    n = min(len(xs), len(xr))
    sensitive = np.linalg.norm(xs[:n] - xr[:n], axis=1).max() / D > 1e-3
    lines.append("%g %g %s %.9g 0 0 %d %.2f reference %s" % (A, f, REFERENCE, liftr, nr, wr,
                                                              "yes" if sensitive else "no"))
    for tol in TOLERANCES:
        x, lift, nc, wall = run(A, f, tol)
        n = min(len(x), len(xr))
        traj = np.linalg.norm(x[:n] - xr[:n], axis=1).max() / D
        err = 100 * abs(lift - liftr) / abs(liftr)
        meets = err <= 0.5 and traj <= 1e-3
        lines.append("%g %g %s %.9g %.3g %.3g %d %.2f %s %s"
                     % (A, f, tol, lift, err, traj, nc, wall, "yes" if meets else "no",
                        "yes" if sensitive else "no"))
    print("\n".join(lines[-len(TOLERANCES) - 1:]), flush=True)
os.makedirs(results, exist_ok=True)
with open(os.path.join(results, "eightScenes.dat"), "w") as fh:
    fh.write("\n".join(lines) + "\n")
# the default on every scene that is not sensitive
bad = [l for l in lines[4:] if l.split()[2] == "default" and l.split()[-2:] == ["no", "no"]]
print("default misses the goal on %d scene(s) that are not sensitive" % len(bad))
sys.exit(1 if bad else 0)
