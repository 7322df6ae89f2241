"""A point deposit spread in a box against the closed forms.

A cube of side 0.24 m of uniform cells (all faces walls), an ore of
d = 10 mm, the kernel b = 3 d (T = b^2/4, sigma^2 = 2 T = (21.2 mm)^2), its
volume deposited in the cell holding a cell centre. The profiles compared
are the marginals along x (the sums over y and z): the marginal of the
discrete solution is exactly that of the 1-D problem (the y and z fluxes
cancel in the sums), so the 1-D closed forms apply.

- Width: the second moment sum theta V (x - x0)^2 / sum theta V along
  each axis equals 2 T exactly on a uniform grid, whatever h and N (the
  discrete Laplacian of x^2 is 2; the matrix is symmetric). What is left
  is the walls' reflection of the far tails (5.2 sigma away or more; the
  N-step kernel's tails decay as exp(-|x|/l), l = sqrt(T/N), and the grid
  adds an excess kurtosis h^2/sigma^2): measured 3e-5 at h = d, N = 16,
  3e-4 at h = d, N = 4 and 1.2e-3 at h = 2 d, N = 4; tolerance 3e-3.
- Shape: N implicit Euler steps give, in continuous space, the kernel
  whose Fourier symbol is (1 + T k^2/N)^-N (kernel.steps1d); the grid
  adds an error of second order in h/sigma (the Laplacian's truncation
  error h^2/12 d4/dx4 over the pseudo-time, L1 about 0.1 (h/sigma)^2; the
  cell values against cell averages add as much). Checked: the L1
  distance of the marginal (per cell width, cell averages of the closed
  form) is below 0.25 (h/sigma)^2 at h = d and h = 2 d, and falls by at
  least 3.5 when h halves (4 for second order; 3.5 allows the next
  order's share at h = 2 d, where h/sigma = 0.94).
- Gaussian: the N-step kernel has the Gaussian's variance and an excess
  kurtosis 3/N; its L1 distance to the Gaussian is a closed-form number
  (0.083 at N = 4, 0.022 at N = 16), printed with the spread's distance to
  the Gaussian: the latter is the former plus at most the grid's error
  above.
- The solves run converged (tolerance 1e-14), so that the checks see the
  discrete operator and not the solver's default tolerance (whose own
  bound, 2 N tolerance in the same L1 norm, kernelConservation checks).
- Wall: the deposit 2.5 cells (a = 25 mm) from the wall x = -0.12: the
  zero-flux wall reflects, the profile is the kernel plus its image in
  the wall (the grid is mirror-symmetric about a wall face, so the image
  holds for the discrete solution too). Checked: the second moment about
  the wall, a^2 + 2 T exactly (tolerance 3e-3 as above), and the L1
  distance to the reflected N-step closed form below 0.25 (h/sigma)^2;
  printed: the distance to the reflected Gaussian.
"""
import math
import os

import numpy as np

from riserfoam.checks import Checks
from riserfoam import kernel

d = 0.01
vp = math.pi * d ** 3 / 6
b = 3 * d
T = b ** 2 / 4
sigma = math.sqrt(2 * T)
side = 0.24
checks = Checks(width=70)
work = os.getcwd()
meshes = {}


def mesh(n):
    if n not in meshes:
        case = os.path.join(work, "box%d" % n)
        kernel.box_mesh(case, (-side / 2,) * 3, (side / 2,) * 3, (n,) * 3)
        meshes[n] = case
    return meshes[n]


def marginal(cells, h):
    """theta V summed over the x-layers, over the total, per unit length;
    the layers' centres"""
    x0 = -side / 2
    layer = np.floor((cells[:, 0] - x0) / h).astype(int)
    mass = np.bincount(layer, weights=cells[:, 3] * cells[:, 4])
    return x0 + (np.arange(len(mass)) + 0.5) * h, mass / mass.sum() / h


def l1(h, values, profile, centres):
    return np.abs(values - kernel.cell_average(profile, centres, h)).sum() * h


def gaussian_distance(N):
    """L1 distance between the N-step kernel and the Gaussian (closed forms)"""
    x = np.linspace(-12 * sigma, 12 * sigma, 200001)
    return np.abs(kernel.steps1d(x, T, N) - kernel.gaussian1d(x, T)).sum() * (x[1] - x[0])


def spread(n, N, x0):
    h = side / n
    s = kernel.spread(mesh(n), "type diffusion; width 3; widthUnit diameters; pseudoSteps %d; "
                      "tolerance 1e-14;" % N,
                      d, [((x0, h / 2, h / 2), vp)])
    return h, s.cells


errors = {}
for n, N in ((12, 4), (24, 4), (24, 16)):
    h = side / n
    x0 = h / 2
    h, cells = spread(n, N, x0)
    Q = (cells[:, 3] * cells[:, 4]).sum()
    label = "h = %g d, N = %d" % (h / d, N)
    for i, axis in enumerate("xyz"):
        m2 = (cells[:, 3] * cells[:, 4] * (cells[:, i] - x0) ** 2).sum() / Q
        checks.near("%s: second moment along %s / 2T" % (label, axis), m2 / (2 * T), 1, 3e-3)
    centres, values = marginal(cells, h)
    errors[(n, N)] = l1(h, values, lambda x: kernel.steps1d(x - x0, T, N), centres)
    checks.near("%s: L1 to the N-step closed form / (h/sigma)^2" % label,
                errors[(n, N)] / (h / sigma) ** 2, 0, 0.25, 1)
    to_gauss = l1(h, values, lambda x: kernel.gaussian1d(x - x0, T), centres)
    print("%s: L1 to the Gaussian %.4f; the N-step closed form's %.4f"
          % (label, to_gauss, gaussian_distance(N)))

order = errors[(12, 4)] / errors[(24, 4)]
print("L1 to the N-step closed form: h = 2 d %.4f, h = d %.4f, ratio %.2f"
      % (errors[(12, 4)], errors[(24, 4)], order))
if order < 3.5:
    print("FAILED: the grid's error does not fall at second order")
    checks.failures += 1

# --- the wall x = -0.12, the deposit 2.5 cells from it
n, N = 24, 4
h = side / n
wall = -side / 2
a = 2.5 * h
h, cells = spread(n, N, wall + a)
Q = (cells[:, 3] * cells[:, 4]).sum()
m2 = (cells[:, 3] * cells[:, 4] * (cells[:, 0] - wall) ** 2).sum() / Q
checks.near("wall: second moment about the wall / (a^2 + 2T)", m2 / (a ** 2 + 2 * T), 1, 3e-3)
centres, values = marginal(cells, h)
error = l1(h, values, lambda x: kernel.steps1d(x - wall - a, T, N)
           + kernel.steps1d(x - wall + a, T, N), centres)
checks.near("wall: L1 to the reflected N-step closed form / (h/sigma)^2",
            error / (h / sigma) ** 2, 0, 0.25, 1)
to_gauss = l1(h, values, lambda x: kernel.gaussian1d(x - wall - a, T)
              + kernel.gaussian1d(x - wall + a, T), centres)
print("wall: L1 to the reflected Gaussian %.4f; first cell: spread %.3f, reflected N-step %.3f,"
      " reflected Gaussian %.3f [1/m]"
      % (to_gauss, values[0],
         kernel.cell_average(lambda x: kernel.steps1d(x - wall - a, T, N)
                             + kernel.steps1d(x - wall + a, T, N), centres[:1], h)[0],
         kernel.cell_average(lambda x: kernel.gaussian1d(x - wall - a, T)
                             + kernel.gaussian1d(x - wall + a, T), centres[:1], h)[0]))
checks.exit()
