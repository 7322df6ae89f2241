"""The riser motion 'table' against the 'modes' motion it samples (see
Allrun): riserParticle's track of one ore relative to the local axis, and
its lift, as the table's time interval h and height spacing dz are refined.

The table interpolates in time with quintic Hermite pieces whose nodal
velocity and acceleration are fourth-order differences (the acceleration's
error O(h^4)), and along z with cubic Hermite pieces whose nodal slopes are
second-order differences (the position's error O(dz^3), the slope's
O(dz^2); src/riserCore/riser/tableMotion.hpp). The ore feels the riser
through its acceleration and, through the sheared carrier (u = U_r + w s),
through its slope s (the wall is not reached), so its track's error is
expected to fall as h^4 and dz^2. Each series is refined with the other
step held one level finer than its finest, so that it does not floor the
series; the measured orders are written with the differences."""
import math
import os
import sys

from riserfoam import cases, foamfields as ff, tables

HERE = os.path.dirname(os.path.abspath(__file__))
L, A, F, END, Z0 = 100.0, 0.1, 0.5, 20.0, 25.0
ZMIN, ZMAX = 20.0, 40.0
D = 0.1
MODES = "{ type modes; foot 0; length %r; x ((3 %r %r 0)); }" % (L, A, F)
TABLE = '{ type table; file "constant/riserMotion.csv"; }'
# h from 0.1 s (20 samples a period, near the check's 18) and dz from 2 m
# (33 a wavelength, near its 26), each halved three times; the other held
# at half its finest
H = [0.1 / 2 ** k for k in range(4)]
DZ = [2.0 / 2 ** k for k in range(4)]
H_FIXED, DZ_FIXED = H[-1] / 2, DZ[-1] / 2


def displacement(z, t):
    return A * math.sin(3 * math.pi * z / L) * math.sin(2 * math.pi * F * t)


def write_table(case, h, dz):
    heights = [ZMIN + dz * i for i in range(int(round((ZMAX - ZMIN) / dz)) + 1)]
    with open(os.path.join(case, "constant/riserMotion.csv"), "w") as out:
        out.write("t z x y\n")
        for j in range(int(round(END / h)) + 1):
            t = h * j
            for z in heights:
                out.write("%.12g %.12g %.17g 0\n" % (t, z, displacement(z, t)))


def run(work, name, motion, h=None, dz=None):
    case = os.path.join(work, name)
    cases.copy_tutorial("riser/oscillatingNoContact", case)
    riser = cases.set_motion(case, motion)
    ff.set_nested(riser, "frame", "lab")
    ff.write_dictionary(os.path.join(case, "constant/kinematicCloudPositions"),
                        "((0.02 0.02 %r))\n" % Z0, "vectorField")
    control = os.path.join(case, "system/controlDict")
    ff.set_entry(control, "endTime", repr(END))
    ff.set_entry(control, "deltaT", "0.01")
    # the integrator's own error far below the table's
    ff.write_dictionary(os.path.join(case, "system/riserParticleDict"),
                        "adaptiveCoeffs { tolerance 1e-12; }\n")
    if h is not None:
        write_table(case, h, dz)
    cases.run(["riserParticle", "-case", case], os.path.join(case, "log.riserParticle"))
    rows = tables.read(os.path.join(case, "postProcessing/riserParticle/particles.dat"))
    return {round(t, 9): (x, y, l) for t, x, y, l in
            zip(rows["t"], rows["xr"], rows["yr"], rows["lift"])}


def difference(rows, reference):
    common = [t for t in rows if t in reference]
    return max(max(abs(a - b) for a, b in zip(rows[t], reference[t])) for t in common) / D


def orders(values, steps):
    return [math.log(values[k] / values[k + 1]) / math.log(steps[k] / steps[k + 1])
            for k in range(len(values) - 1)]


def chart(series):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import matplotlib.ticker
    fig, axes = plt.subplots(1, 2, figsize=(9, 3.6))
    for ax, (label, steps, errors, slope, unit) in zip(axes, series):
        ax.loglog(steps, errors, "o-", label="table against modes")
        ref = [errors[0] * (s / steps[0]) ** slope for s in steps]
        ax.loglog(steps, ref, "k--", lw=0.8, label="slope %d" % slope)
        ax.xaxis.set_minor_formatter(matplotlib.ticker.NullFormatter())
        ax.set_xlabel("%s [%s]" % (label, unit))
        ax.set_ylabel("largest track difference / D")
        ax.legend()
    fig.suptitle("riser motion table sampled from mode 3 (riserParticle, one ore, 20 s)")
    fig.tight_layout()
    os.makedirs(os.path.join(HERE, "..", "figures"), exist_ok=True)
    fig.savefig(os.path.join(HERE, "..", "figures", "riserMotionTable.png"), dpi=120)


def main():
    work = os.path.abspath(sys.argv[1])
    os.makedirs(work, exist_ok=True)
    reference = run(work, "modes", MODES)
    inTime = [difference(run(work, "h%d" % k, TABLE, h, DZ_FIXED), reference)
              for k, h in enumerate(H)]
    inHeight = [difference(run(work, "dz%d" % k, TABLE, H_FIXED, dz), reference)
                for k, dz in enumerate(DZ)]
    os.makedirs(os.path.join(HERE, "results"), exist_ok=True)
    with open(os.path.join(HERE, "results", "convergence.dat"), "w") as out:
        out.write("# riserParticle, the table of mode 3 (L = %g m, %g m at %g Hz) against"
                  " the modes motion: the largest difference of (xr, yr, lift) over %g s, / D\n"
                  "# refined h [s] at dz = %g m; then refined dz [m] at h = %g s\n"
                  "# kind step difference/D order\n" % (L, A, F, END, DZ_FIXED, H_FIXED))
        for kind, steps, errors in (("h", H, inTime), ("dz", DZ, inHeight)):
            found = [float("nan")] + orders(errors, steps)
            for s, e, o in zip(steps, errors, found):
                out.write("%s %g %.4e %.2f\n" % (kind, s, e, o))
                print("%-2s = %-7g difference %.3e D, order %.2f" % (kind, s, e, o))
    chart([("time interval h", H, inTime, 4, "s"), ("height spacing dz", DZ, inHeight, 2, "m")])


if __name__ == "__main__":
    main()
