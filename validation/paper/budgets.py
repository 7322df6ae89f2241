"""Force budgets of the paper's scenes (riserParticle -budget): each force's
RMS and largest magnitude against the buoyant weight W, and what dropping it
changes in the lifting distance and the relative trajectory, and saves in
CPU time. A force is needed when dropping it moves the lifting distance by
more than 1 % or the trajectory by more than 0.01 D. Writes
results/budgets.json (report.py puts the table in the report).

SPDX-License-Identifier: GPL-3.0-or-later
"""
import json
import os

from paperFigures import D, UCM, RiserCase, quick, results, root, scratch

scenes = [("stationary riser", "stationary", 0.0, 0.0, 5.0),
          ("A = 1, f = 0.05 (no contact)", "oscillatingNoContact", 1.0, 0.05, 4.0),
          ("A = 1, f = 0.15 (contacts)", "oscillatingNoContact", 1.0, 0.15, 4.0),
          ("A = 1, f = 0.3 (flagship, contacts)", "oscillatingNoContact", 1.0, 0.3, 5 / 3.0),
          ("A = 2, f = 0.4 (riser speed 5 u_cm)", "oscillatingNoContact", 2.0, 0.4, 1.25)]
out = []
for name, tutorial, A, f, T in scenes:
    case = (RiserCase(root, scratch, "budget_" + tutorial + "_%g_%g" % (A, f), tutorial)
            .riser(A=A, f=f).run_for(T / (2 if quick else 1), 2e-3).releases([(0.2, 0.2)]))
    budget = case.budget()
    lift = case.engine().table()[0]["lift"][-1] / D
    rows = {}
    for force, (rms, peak, dlift, dtraj, cpu) in budget.items():
        needed = None if dlift is None else bool(abs(dlift) > 0.01 * abs(lift) or dtraj > 0.01)
        rows[force] = {"rms": rms, "max": peak, "liftChange": dlift, "trajectoryChange": dtraj,
                       "cpu": cpu, "needed": needed}
    out.append({"scene": name, "duration": T * UCM / D, "lift": lift, "forces": rows})
    print("%s: lift %.2f D; needed: %s" % (name, lift, ", ".join(
        k for k, v in rows.items() if v["needed"]) or "-"))
json.dump(out, open(os.path.join(results, "budgets.json"), "w"), indent=1)
