"""When the liquid at the wall matters for one ore: the (A, f) regime map of
the mesh-free engine (riserParticle -sweep, 20 periods a case, the lift
after 10 s) with dry contacts and with wet ones (riserContactCoeffs' wet {
type stokesRestitution; }: e = e_n exp(-35/St), St = (rho_p + rho_f/2) U_in
d / (9 mu)), in water (mu = 1e-3 Pa s) and in a liquid ten times as
viscous (a fine slurry's effective viscosity). Each viscosity's dry and wet
maps share everything but the contact, so their difference is the wet
restitution's alone. Writes results/<map>.dat, results/summary.txt and the
figure.

usage: wetRegimeMap.py <riserFoam root> <scratch folder> <results folder> <figure>
SPDX-License-Identifier: GPL-3.0-or-later
"""
import os
import shutil
import sys
import time

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402  (after the backend)
import numpy as np  # noqa: E402
from riserfoam import foamfields as ff  # noqa: E402
from riserfoam.carrier import D, UCM  # noqa: E402
from riserfoam.cases import RiserCase  # noqa: E402

root, scratch, results, figure = sys.argv[1:5]
N = 40
As = np.linspace(0.25, 2.0, N) * D
fs = np.linspace(0.025, 0.4, N) * UCM / D
VISCOSITIES = (1e-6, 1e-5)      # nu [m^2/s] of the liquid, rho 1000 kg/m^3


def sweep(name, nu, wet):
    """the regime map's rows (dicts by column) at viscosity nu, wet or dry"""
    case = RiserCase(root, scratch, name)
    ff.set_entry(os.path.join(case.path, "constant/transportProperties"), "nu", repr(nu))
    if wet:
        ff.set_nested(os.path.join(case.path, "constant/kinematicCloudProperties"),
                      "subModels/riserContactCoeffs/wet", "{ type stokesRestitution; }")
    table = case.sweep(As, fs, periods=20, liftTime=10)
    shutil.copy(table.path, os.path.join(results, name + ".dat"))
    return list(table)


summary, maps = [], []
for nu in VISCOSITIES:
    start = time.time()
    dry = sweep("dry_nu%g" % nu, nu, False)
    wet = sweep("wet_nu%g" % nu, nu, True)
    wall = time.time() - start
    ok = [k for k in range(N * N) if dry[k]["status"] == "ok" and wet[k]["status"] == "ok"]
    lift = np.full(N * N, np.nan)
    for k in ok:
        lift[k] = wet[k]["lift"] / dry[k]["lift"] - 1
    contact = [k for k in ok if dry[k]["regime"] != "noContact"]
    changed = [k for k in ok if dry[k]["regime"] != wet[k]["regime"]]
    change = np.abs(lift[contact])
    summary.append(
        "nu = %g m^2/s: %d x %d cases dry and wet, %.1f s wall, %d failed; %d with contacts; "
        "regime changed in %d; |lift change| with contacts: median %.2f %%, 90th percentile "
        "%.2f %%, largest %.2f %% (A = %.3g D, f = %.3g u_cm/D)"
        % (nu, N, N, wall, N * N - len(ok), len(contact), len(changed),
           100 * np.median(change), 100 * np.percentile(change, 90), 100 * change.max(),
           As[contact[int(np.argmax(change))] // N] / D,
           fs[contact[int(np.argmax(change))] % N] * D / UCM))
    maps.append((nu, lift.reshape(N, N), changed))

fig, axes = plt.subplots(1, 2, figsize=(12, 5))
for ax, (nu, lift, changed) in zip(axes, maps):
    scale = max(np.nanmax(np.abs(lift)), 1e-3) * 100
    mesh = ax.pcolormesh(As / D, fs * D / UCM, 100 * lift.T, cmap="RdBu_r",
                         vmin=-scale, vmax=scale, shading="nearest")
    fig.colorbar(mesh, ax=ax, label="lift wet / lift dry - 1 [%]")
    if changed:
        ax.plot([As[k // N] / D for k in changed], [fs[k % N] * D / UCM for k in changed],
                "kx", ms=4, label="regime changed")
        ax.legend(fontsize=8, loc="upper right")
    ax.set_xlabel("A / D")
    ax.set_ylabel("f D / u_cm")
    ax.set_title("nu = %g m^2/s (mu = %g Pa s)" % (nu, 1000 * nu))
fig.suptitle("wet against dry wall contacts, one ore (riserParticle, 20 periods a case)")
fig.tight_layout()
fig.savefig(figure, dpi=110)
with open(os.path.join(results, "summary.txt"), "w") as out:
    out.write("\n".join(summary) + "\n")
print("\n".join(summary))
