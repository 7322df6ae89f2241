"""A restarted (or decomposed, or killed and restarted) riserParcelFoam run
against the uninterrupted one.

    python3 -m riserfoam.restarts <whole> <other> <time> <tolerance>

compares, for the cloud kinematicCloud:
  - the particles' positions and velocities written at <time>: the same
    count, and each vector within <tolerance> relative (|a - b| / |a|);
  - the particle tables (riserParticleTable/particles.dat): the same rows,
    each particle's times strictly increasing and equal to the whole run's
    (no row missing or repeated), every column within <tolerance> of the
    column's largest magnitude (at least 1e-11: the table has 12 digits),
    the lifting distance among them, except origProc (the processor that
    injected the particle, 0 in a serial run);
  - the contact tables (riserContact/contacts.dat), when the whole run
    has one: the same number of contacts, their start and end times within
    <tolerance> relative to the time;
  - the particles' wall-contact counts written at <time> (wallContacts),
    when the whole run wrote them: equal, so that a restart read them back.
Prints the largest differences and exits non-zero on a failure.

SPDX-License-Identifier: GPL-3.0-or-later
"""
import math
import os
import sys

import numpy as np

from riserfoam import foamfields, tables

CLOUD = "kinematicCloud"


def output(case, model, base):
    """The path of a cloud model's table in a case."""
    return os.path.join(case, "postProcessing", "lagrangian", CLOUD, model, base + ".dat")


def state_difference(whole, other, time):
    """Largest relative difference of positions and velocities at time."""
    worst = 0.0
    for field in ("positions", "U"):
        a = foamfields.read_vectors(os.path.join(whole, time, "lagrangian", CLOUD, field))
        b = foamfields.read_vectors(os.path.join(other, time, "lagrangian", CLOUD, field))
        if len(a) != len(b):
            raise AssertionError("%s at %s: %d particles, %d in the whole run"
                                 % (field, time, len(b), len(a)))
        for u, v in zip(a, b):
            worst = max(worst, math.dist(u, v) / max(math.hypot(*u), 1e-300))
    return worst


def table_difference(whole, other, tolerance):
    """Largest difference of the particle tables, per column scale, and that
    of the lift column; raises on missing or repeated rows."""
    a = tables.read(output(whole, "riserParticleTable", "particles"))
    b = tables.read(output(other, "riserParticleTable", "particles"))
    if len(a) != len(b):
        raise AssertionError("particles.dat: %d rows, %d in the whole run" % (len(b), len(a)))
    for key in sorted(set(a["origId"].tolist())):
        ta, tb = a.particle(key)["t"], b.particle(key)["t"]
        if len(tb) != len(ta) or np.any(np.diff(tb) <= 0) \
                or np.max(np.abs(ta - tb)) > 1e-9:
            raise AssertionError("particles.dat: the times of particle %d are not the"
                                 " whole run's (rows missing or repeated)" % key)
    worst, lift = 0.0, 0.0
    for name in a.names:
        if name == "origProc":
            continue
        scale = max(np.max(np.abs(a[name])), 1e-300)
        d = np.max(np.abs(a[name] - b[name])) / scale
        worst = max(worst, d)
        if name == "lift":
            lift = d
    return worst, lift


def contact_difference(whole, other):
    """Largest relative difference of the contacts' start and end times."""
    path = output(whole, "riserContact", "contacts")
    if not os.path.exists(path):
        return 0.0, 0
    a = tables.read(path)
    b = tables.read(output(other, "riserContact", "contacts"))
    if len(a) != len(b):
        raise AssertionError("contacts.dat: %d contacts, %d in the whole run" % (len(b), len(a)))
    worst = 0.0
    for name in ("tStart", "tEnd"):
        worst = max(worst, float(np.max(np.abs(a[name] - b[name]) / np.abs(a[name]), initial=0)))
    return worst, len(a)


def trace_difference(whole, other, time):
    """The wall-contact counts at time (the whole run's total); raises
    unless they are the whole run's."""
    path = os.path.join(time, "lagrangian", CLOUD, "wallContacts")
    if not os.path.exists(os.path.join(whole, path)):
        return 0
    a = foamfields.read_scalars(os.path.join(whole, path))
    b = foamfields.read_scalars(os.path.join(other, path))
    if a != b:
        raise AssertionError("wallContacts at %s: %s, %s in the whole run" % (time, b, a))
    return int(sum(a))


def main(argv):
    whole, other, time, tolerance = argv[1], argv[2], argv[3], float(argv[4])
    try:
        state = state_difference(whole, other, time)
        table, lift = table_difference(whole, other, max(tolerance, 1e-11))
        contact, contacts = contact_difference(whole, other)
        counted = trace_difference(whole, other, time)
    except AssertionError as failure:
        print("FAILED: %s" % failure)
        return 1
    print("%s against %s: state at %s %.2e relative; particle table %.2e (lift %.2e);"
          " %d contacts, times %.2e relative; %d counted by the particles"
          % (other, whole, time, state, table, lift, contacts, contact, counted))
    ok = state <= tolerance and table <= max(tolerance, 1e-11) and contact <= tolerance
    print("ok" if ok else "FAILED: above the tolerance %g" % tolerance)
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv))
