"""Mesh independence of the spread at a fixed physical width.

One ore (d = 10 mm) at the centre of a box, spread over b = 5 d (sigma =
3.5 d; T = b^2/4) in N = 4 pseudo-steps on grids of uniform cubes of h =
0.5 d, d, 2 d and 4 d (an odd number of cells, so that the ore sits at a
cell centre on every grid; sides 0.325 to 0.44 m, the walls at least
4.6 sigma away). The kernel's width in metres must be at least the
largest cell: b = 5 d admits h = 4 d (b = 3 d would not, and is refused).

- The width does not depend on the grid: the second moment along each
  axis is 2 T on every grid (exact on a uniform grid; what is left is the
  walls' reflection of the tails, measured 1.6e-3 at 4.6 sigma; tolerance
  3e-3 as in kernelGaussian).
- The profile: the x-marginal's L1 distance to the N-step closed form
  (kernel.steps1d, cell averages; the same for every grid) is below
  0.25 (h/sigma)^2 on every grid (second order, as in kernelGaussian);
  the distances are printed: they bound the difference between any two
  grids' profiles.
- What the carrier sees at the ore: theta in the cell holding it. The
  grid-independent reference is the cell average of the 3-D N-step
  kernel over that cell (it falls as the cell grows past sigma: a cell
  value is an average). The spread's value converges to it at second
  order: within 5 % at h = 0.5 d (h/sigma = 0.14), and the error falls
  by at least 3.5 from h = d to h = 0.5 d (4 for second order); on the
  coarse grids (h >= sigma/2) the centre value is well above it (printed:
  the kernel spans one or two cells there). Over the four grids it varies
  by less than a factor 1.5 (checked), where the stock one-cell deposit,
  pi d^3/6 / h^3, goes from 4.19 at h = 0.5 d (theta > 1: alpha_c clips)
  to 0.0082 at h = 4 d, a factor of 512 (printed).
- The deposit stays centred: the first moment of the spread field is the
  ore's cell centre to 1e-9 sigma (the operator is symmetric and
  conservative: it moves no mass's centroid; the solves run converged,
  tolerance 1e-14, so that the check sees the operator, not the solver's
  default tolerance of 1e-6, see kernelConservation).
"""
import math
import os

import numpy as np

from riserfoam.checks import Checks
from riserfoam import kernel

d = 0.01
vp = math.pi * d ** 3 / 6
b = 5 * d
N = 4
T = b ** 2 / 4
sigma = math.sqrt(2 * T)
checks = Checks(width=66)
work = os.getcwd()
GRIDS = ((0.5, 65), (1, 33), (2, 21), (4, 11))    # h / d, cells per side


def peak_closed_form(h, points=8):
    """The 3-D N-step kernel averaged over the cube of side h about the
    ore, times its volume (tensor Gauss-Legendre, the kernel smooth for
    N = 4)"""
    nodes, weights = np.polynomial.legendre.leggauss(points)
    x = 0.5 * h * nodes
    X, Y, Z = np.meshgrid(x, x, x, indexing="ij")
    W = np.einsum("i,j,k->ijk", weights, weights, weights) / 8
    return vp * (W * kernel.steps3d(np.sqrt(X ** 2 + Y ** 2 + Z ** 2), T, N)).sum()


peaks = []
for ratio, n in GRIDS:
    h = ratio * d
    side = n * h
    case = os.path.join(work, "h%gd" % ratio)
    kernel.box_mesh(case, (-side / 2,) * 3, (side / 2,) * 3, (n,) * 3)
    s = kernel.spread(case, "type diffusion; width 5; widthUnit diameters; pseudoSteps %d; "
                      "tolerance 1e-14;" % N,
                      d, [((0.0, 0.0, 0.0), vp)])
    c = s.cells
    V, th = c[:, 3], c[:, 4]
    Q = (V * th).sum()
    label = "h = %g d" % ratio
    for i, axis in enumerate("xyz"):
        checks.near("%s: second moment along %s / 2T" % (label, axis),
                    (V * th * c[:, i] ** 2).sum() / Q / (2 * T), 1, 3e-3)
    centroid = np.array([(V * th * c[:, i]).sum() / Q for i in range(3)])
    checks.near("%s: centroid of the spread, |x| / sigma" % label,
                np.abs(centroid).max(), 0, 1e-9, sigma)
    # x-marginal per unit length, on the grid's layers
    layer = np.floor((c[:, 0] + side / 2) / h).astype(int)
    marginal = np.bincount(layer, weights=V * th) / Q / h
    centres = -side / 2 + (np.arange(n) + 0.5) * h
    error = np.abs(marginal - kernel.cell_average(lambda x: kernel.steps1d(x, T, N),
                                                  centres, h)).sum() * h
    checks.near("%s: L1 to the N-step closed form / (h/sigma)^2" % label,
                error / (h / sigma) ** 2, 0, 0.25, 1)
    print("%s: L1 of the x-profile to the N-step closed form %.4f" % (label, error))
    # theta at the ore: the cell holding the centre
    at = np.argmin((c[:, :3] ** 2).sum(axis=1))
    closed = peak_closed_form(h)
    stock = vp / h ** 3
    peaks.append((th[at], stock, th[at] / closed - 1))
    print("%s: %d cells; theta at the ore %.4e (closed form %.4e); one-cell deposit %.4e%s"
          % (label, len(c), th[at], closed, stock, "  (> 1: alpha_c clips)" if stock > 1 else ""))

checks.near("h = 0.5 d: theta at the ore against the closed form", peaks[0][2], 0, 0.05, 1)
convergence = peaks[1][2] / peaks[0][2]
print("theta at the ore, error against the closed form: %s; h = d over h = 0.5 d: %.2f"
      % (", ".join("%+.3f" % p[2] for p in peaks), convergence))
if convergence < 3.5:
    print("FAILED: theta at the ore does not converge at second order")
    checks.failures += 1
spread_range = max(p[0] for p in peaks) / min(p[0] for p in peaks)
stock_range = max(p[1] for p in peaks) / min(p[1] for p in peaks)
print("theta at the ore over the grids: spread varies by a factor %.3f, one-cell deposit by %.0f"
      % (spread_range, stock_range))
checks.near("theta at the ore: largest / smallest over the grids (< 1.5)", spread_range, 1, 0.5, 1)
checks.exit()
