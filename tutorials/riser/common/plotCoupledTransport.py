#!/usr/bin/python3
"""Plots a turbulent riser section with ores under riserCoupledFoam: the
carrier against the smooth-pipe laws, the driving pressure gradient, the
ores' slip and their radial distribution.

usage: plotCoupledTransport.py <out.png> [title]     (in the case folder)

Reads the case: constant/riserProperties (D), transportProperties (nu,
rhoInf), kinematicCloudProperties (rho0, the ores' SOI), the cell centres
and volumes of 0/C and 0/V (postProcess -func writeCellCentres and
writeCellVolumes -time 0), U and the cloud (labPosition, U) at the write
times, postProcessing/riserDrive/0/drive.dat and the tables of
riserTransportStatistics. Six panels:
  - the carrier's mean axial velocity against r/R (cells binned in rings,
    volume-weighted) at the last write time before the ores (the clear
    carrier after its spin-up) and at the end, with the 1/7 power law at
    the bulk velocity (riserfoam.pipeflow);
  - the same in wall units, u+ against y+ (y = R - r), with u_tau from the
    clear carrier's computed wall shear, u_tau^2 = -dp/dz R/(2 rho), and
    the log law;
  - the drive's dp/dz over time against Prandtl's smooth-pipe law for the
    clear fluid, lambda rho u_b^2/(2 D), and that plus the buoyant weight
    of the suspended ores, C_v (rho_p - rho_f) g;
  - the ores' mean axial slip over time: against the carrier at each ore
    (slipz of transport.dat) and the ores' mean axial velocity less the
    carrier's bulk velocity;
  - the solids fraction against r/R (riserTransportStatistics' annuli of
    equal area at their area-mean radii), averaged from 0.5 s after the
    fill, and the first sample after the fill;
  - the slip against r/R in the same annuli, averaged over the write times
    from 0.5 s after the fill: the ores' mean v_z less the carrier's mean
    U_z there.
Prints the measured numbers behind them.
"""
from riserfoam.cli import help_requested  # noqa: E402

help_requested(__doc__)

import math
import os
import sys
import warnings

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402  (after the backend)
import numpy as np  # noqa: E402
from plotTransportStatistics import bins  # noqa: E402  (this folder)
from riserfoam import foamfields as ff  # noqa: E402
from riserfoam import pipeflow, tables  # noqa: E402

SETTLE = 0.5    # [s] after the fill before the averages start
G = 9.81


def times():
    """the write times after 0, sorted"""
    out = []
    for name in os.listdir("."):
        try:
            value = float(name)
        except ValueError:
            continue
        if value > 0 and os.path.isdir(name):
            out.append((value, name))
    return sorted(out)


def ring_means(r, values, weights, edges):
    """weighted means of values in the rings edges[k] <= r < edges[k+1]
    (nan where empty)"""
    k = np.digitize(r, edges) - 1
    sums = np.bincount(k, weights * values, len(edges))[:len(edges) - 1]
    counts = np.bincount(k, weights, len(edges))[:len(edges) - 1]
    with np.errstate(invalid="ignore"):
        return sums / counts


def main():
    warnings.simplefilter("ignore", RuntimeWarning)     # the means of empty annuli: nan
    out = sys.argv[1]
    title = sys.argv[2] if len(sys.argv) > 2 else os.getcwd()
    D = ff.read_entry("constant/riserProperties", "D")
    R = 0.5 * D
    nu = ff.read_entry("constant/transportProperties", "nu")
    rho = ff.read_entry("constant/transportProperties", "rhoInf")
    rho_p = ff.read_entry("constant/kinematicCloudProperties", "rho0")
    soi = ff.read_entry("constant/kinematicCloudProperties", "SOI")
    C = np.array(ff.read_vectors("0/C", "internalField"))
    V = np.array(ff.read_scalars("0/V", "internalField"))
    r_cell = np.hypot(C[:, 0], C[:, 1])
    written = times()
    clear = [name for t, name in written if t < soi][-1]
    last = written[-1][1]
    late = [name for t, name in written if t >= soi + SETTLE - 1e-9]

    drive = tables.read("postProcessing/riserDrive/0/drive.dat")
    stats = "postProcessing/lagrangian/kinematicCloud/riserTransportStatistics"
    transport = tables.read(os.path.join(stats, "transport.dat"))
    radial = bins(tables.read(os.path.join(stats, "radialProfile.dat")), "Cv_r")
    ub = drive["Ub"][-1]
    Re = ub * D / nu
    prandtl = pipeflow.pressure_gradient(ub, D, nu, rho)
    t_clear = float(clear)
    clear_rows = (drive["t"] > t_clear - 0.1) & (drive["t"] <= t_clear)
    dpdz_clear = -drive["dpdz"][clear_rows].mean()
    u_tau = math.sqrt(dpdz_clear * R / (2 * rho))
    filled = transport["parcels"] > 0
    cv = transport["Cv"][filled][-1]
    weight = cv * (rho_p - rho) * G
    late_rows = drive["t"] >= soi + SETTLE
    dpdz_late = -drive["dpdz"][late_rows].mean()

    fig, ax = plt.subplots(3, 2, figsize=(11, 13))
    edges = np.linspace(0, R, 13)
    rs = np.linspace(0, R, 400)
    for name, style in ((clear, "o-"), (last, "s--")):
        Uz = np.array(ff.read_vectors(os.path.join(name, "U"), "internalField"))[:, 2]
        u = ring_means(r_cell, Uz, V, edges)
        rm = ring_means(r_cell, r_cell, V, edges)
        label = "t = %s s%s" % (name, " (clear, before the ores)" if name == clear else
                                " (with the ores)")
        ax[0, 0].plot(rm / R, u / ub, style, ms=4, label=label)
        y = R - rm
        ax[0, 1].semilogx(y * u_tau / nu, u / u_tau, style, ms=4, label=label)
        if name == clear:
            wall_yplus = (R - r_cell[np.argmax(r_cell)]) * u_tau / nu
            centre = Uz[np.argmin(r_cell)]
    ax[0, 0].plot(rs / R, pipeflow.power_law(rs, R, ub) / ub, "k:", label="1/7 power law")
    ax[0, 0].set(xlabel="r/R", ylabel="U_z / u_b", xlim=(0, 1), ylim=(0, None),
                 title="carrier's mean axial velocity (Re = %.3g)" % Re)
    ax[0, 0].legend(fontsize=8)
    yp = np.logspace(np.log10(10), np.log10(R * u_tau / nu), 50)
    ax[0, 1].semilogx(yp, pipeflow.log_law(yp * nu / u_tau, u_tau, nu) / u_tau, "k:",
                      label="log law (kappa %.2f, B %.1f)" % (pipeflow.KAPPA, pipeflow.B))
    ax[0, 1].set(xlabel="y+ = (R - r) u_tau / nu", ylabel="u+ = U_z / u_tau",
                 title="wall units, u_tau = %.4f m/s (clear carrier's dp/dz)" % u_tau)
    ax[0, 1].legend(fontsize=8)

    ax[1, 0].plot(drive["t"], -drive["dpdz"], lw=0.6, label="riserCoupledFoam")
    ax[1, 0].axhline(prandtl, color="k", ls=":", label="Prandtl, clear fluid: %.1f" % prandtl)
    ax[1, 0].axhline(prandtl + weight, color="r", ls="--",
                     label="+ C_v (rho_p - rho_f) g: %.1f" % (prandtl + weight))
    ax[1, 0].axvline(soi, color="grey", lw=0.6)
    ax[1, 0].set(xlabel="t [s]", ylabel="-dp/dz [Pa/m]", title="driving pressure gradient",
                 ylim=(0, 2 * (prandtl + weight)))
    ax[1, 0].legend(fontsize=8)

    ts = transport["t"][filled]
    ax[1, 1].plot(ts, -transport["slipz"][filled], label="against the carrier at each ore")
    ub_at = np.interp(ts, drive["t"], drive["Ub"])
    ax[1, 1].plot(ts, ub_at - transport["Urz"][filled],
                  label="u_b less the ores' mean v_z")
    ax[1, 1].set(xlabel="t [s]", ylabel="U_z - v_pz [m/s]", title="ores' mean axial slip")
    ax[1, 1].legend(fontsize=8)

    n = radial.shape[1]
    r_annuli = np.sqrt((np.arange(n) + 0.5) / n)
    settled = transport["t"] >= soi + SETTLE
    first = np.argmax(filled)
    ax[2, 0].plot(r_annuli, radial[settled].mean(axis=0), "o-",
                  label="mean of t >= %.3g s" % (soi + SETTLE))
    ax[2, 0].plot(r_annuli, radial[first], "s--",
                  label="first sample after the fill (t = %.3g s)" % transport["t"][first])
    ax[2, 0].axhline(cv, color="k", ls=":", label="C_v = %.3f" % cv)
    ax[2, 0].set(xlabel="r/R (annuli of equal area)", ylabel="C_v", xlim=(0, 1),
                 title="solids fraction")
    ax[2, 0].legend(fontsize=8)

    annulus_edges = R * np.sqrt(np.arange(n + 1) / n)
    annulus_edges[-1] *= 1.0 + 1e-9
    slips, carriers, ores = [], [], []
    for name in late:
        Uz = np.array(ff.read_vectors(os.path.join(name, "U"), "internalField"))[:, 2]
        cloud = os.path.join(name, "lagrangian", "kinematicCloud")
        x = np.array(ff.read_vectors(os.path.join(cloud, "labPosition")))
        w = np.array(ff.read_vectors(os.path.join(cloud, "U")))[:, 2]
        rp = np.hypot(x[:, 0], x[:, 1])
        carrier = ring_means(r_cell, Uz, V, annulus_edges)
        ore = ring_means(rp, w, np.ones_like(w), annulus_edges)
        carriers.append(carrier)
        ores.append(ore)
        slips.append(carrier - ore)
    ax[2, 1].plot(r_annuli, np.nanmean(slips, axis=0), "o-", label="slip U_z - v_pz")
    ax[2, 1].plot(r_annuli, np.nanmean(carriers, axis=0), "s--", label="carrier U_z")
    ax[2, 1].plot(r_annuli, np.nanmean(ores, axis=0), "^--", label="ores v_pz")
    ax[2, 1].set(xlabel="r/R (annuli of equal area)", ylabel="[m/s]", xlim=(0, 1),
                 title="slip against r, %d write times" % len(late))
    ax[2, 1].legend(fontsize=8)

    fig.suptitle(title)
    fig.tight_layout()
    fig.savefig(out, dpi=100)
    late_t = transport["t"] >= soi + SETTLE
    print("plotCoupledTransport: Re = %.4g, clear carrier at t = %s: -dp/dz %.2f Pa/m, Prandtl"
          " %.2f (%+.1f %%), u_tau %.4f m/s, wall cells at y+ %.0f, centre U_z/u_b %.3f"
          % (Re, clear, dpdz_clear, prandtl, 100 * (dpdz_clear / prandtl - 1), u_tau,
             wall_yplus, centre / ub))
    print("plotCoupledTransport: with %d ores, C_v %.4f, t >= %.3g s: -dp/dz %.1f Pa/m, Prandtl"
          " + C_v (rho_p - rho_f) g = %.1f + %.1f = %.1f (%+.1f %%)"
          % (transport["parcels"][filled][-1], cv, soi + SETTLE, dpdz_late, prandtl, weight,
             prandtl + weight, 100 * (dpdz_late / (prandtl + weight) - 1)))
    print("plotCoupledTransport: slip, t >= %.3g s: %.3f m/s against the carrier at the ores,"
          " u_b less the ores' mean v_z %.3f m/s"
          % (soi + SETTLE, -transport["slipz"][late_t].mean(),
             (np.interp(transport["t"][late_t], drive["t"], drive["Ub"])
              - transport["Urz"][late_t]).mean()))
    profile = radial[settled].mean(axis=0)
    print("plotCoupledTransport: C_v by annulus (axis to wall), t >= %.3g s: %s"
          % (soi + SETTLE, " ".join("%.4f" % c for c in profile)))
    print("plotCoupledTransport: slip by annulus [m/s]: %s"
          % " ".join("%.3f" % s for s in np.nanmean(slips, axis=0)))
    print("plotCoupledTransport: wrote %s" % out)


if __name__ == "__main__":
    main()
