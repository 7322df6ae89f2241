"""The kernel keeps sum(theta V) and the sum of the spread amounts.

On the riser O-grid (D = 0.1 m, L = 0.2 m, 12 cells across the core, 24
along, cyclic ends), ores of d = 10 mm (volume pi d^3/6) deposited near
both cyclic ends, near the wall and at the axis, and momentum-like vector
sources, spread over b = 3 d in 4 pseudo-steps:

- conservation, at the default solver tolerance (1e-4): the sum of theta
  V and each component of the summed sources before and after, relative
  1e-12. The fluxes of each implicit step cancel pairwise (cyclic faces
  included) and vanish at the wall, and the kernel puts the solves'
  residual back (particleKernel.H), so what is left is the round-off of
  sums over 11,520 cells (about 1e-16 x sqrt(11520) each): 1e-12 is a
  hundred times above it. Vector sources of both signs are measured
  against the sum of their magnitudes;
- the spread stays non-negative (the matrix is an M-matrix): the smallest
  theta is not below -1e-12 of the largest (round-off);
- the default tolerance against converged solves (tolerance 1e-14): the
  difference in sum |theta - theta_conv| V, and in sum |amount -
  amount_conv| per component, is at most 2 N tol times sum theta V (sum
  |amounts|). The bound: A = V - dtau L has column sums V_i (L's columns
  sum to zero), so V^T A^-1 = 1^T and a residual r leaves an error e with
  sum V |e| <= |r|_1 <= tol sum |phi| V; the later steps do not enlarge
  it (A^-1 V is a contraction in that norm), so N steps leave at most N
  tol, and restoring the sum adds at most as much again;
- the checks below of the discrete operator itself run converged
  (tolerance 1e-14), so that they see the operator and not the solver:
- the cyclic ends pass the field through as an inner face would: an ore
  in the lowest cell layer spreads through the ends as the same ore 12
  layers up spreads inside the riser, the layers' sums at +-k layers
  agreeing to ten times the spread of the layers' volumes (equal but for
  blockMesh's point placement, about 1e-8: printed);
- the moving mesh (riserOscillation, A = 0.1 m, f = 3 Hz, moved a quarter
  period: the riser shifted by A along x): the same deposits shifted with
  the riser give the same sums (1e-12) and the same spread field
  (relative 1e-9: the translated geometry differs from the static one by
  round-off only);
- 2 processors split at mid-height (a processor boundary and the cyclic
  across the processors): the same sums (1e-12) and the serial field
  (1e-9 of its largest value: the parallel preconditioner differs, the
  solutions agree to the solver's tolerance).
"""
import math
import os
import shutil

import numpy as np

from riserfoam import foamfields as ff
from riserfoam.cases import ROOT, riser_mesh, run
from riserfoam.checks import Checks
from riserfoam import kernel

d = 0.01
vp = math.pi * d ** 3 / 6
KERNEL = "type diffusion; width 3; widthUnit diameters; pseudoSteps 4;"
N_STEPS, TOLERANCE = 4, 1e-4       # pseudoSteps above; the default tolerance
CONVERGED = KERNEL + " tolerance 1e-14;"
# generic points (not on a face of the grid, where serial and parallel
# runs may pick different cells), two of them next to the processor
# boundary at mid-height
DEPOSITS = [((0.0003, 0.0002, 0.004), vp), ((0.03, 0.02, 0.197), vp),
            ((0.0007, -0.045, 0.0996), vp), ((0.001, 0.002, 0.1004), 0.5 * vp)]
SOURCES = [((0.04, 0.0011, 0.1004), (1.0, -2.0, 3.0)), ((0.0004, 0.0006, 0.001), (-0.5, 0.25, 2.0)),
           ((-0.02, 0.01, 0.199), (0.3, 0.7, -4.0))]

checks = Checks(width=64)
work = os.getcwd()


def riser(name):
    case = os.path.join(work, name)
    kernel.system(case)
    riser_mesh(case, 0.1, 0.2, 12, ends="cyclic")
    return case


def conservation(label, s):
    before, after = s.deposits
    checks.near("%s: sum theta V, relative change" % label, after, before, 1e-12)
    scale = sum(np.abs(v).sum() for _, v in SOURCES)
    for i, axis in enumerate("xyz"):
        checks.near("%s: sum of sources %s, change / sum |sources|" % (label, axis),
                    s.sources[1][i], s.sources[0][i], 1e-12, scale)


# --- serial, static
static = riser("static")
s = kernel.spread(static, KERNEL, d, DEPOSITS, SOURCES)
print("bandwidth %.6g m, largest cell %.6g m, cross-section %.6g m, %d cells"
      % (s.bandwidth, s.largest_cell, s.cross_section, len(s.cells)))
conservation("static", s)
theta = s.cells[:, 4]
print("smallest theta %.3e, largest %.3e" % (theta.min(), theta.max()))
if theta.min() < -1e-12 * theta.max():
    print("FAILED: the spread went negative")
    checks.failures += 1
default_cells = s.cells

# --- serial, static, converged: the reference of the checks below
static = riser("staticConverged")
s = kernel.spread(static, CONVERGED, d, DEPOSITS, SOURCES)
conservation("static, converged", s)
bound = 2 * N_STEPS * TOLERANCE
volume = s.cells[:, 3]
checks.near("default tolerance: sum |theta - converged| V / sum theta V",
            (np.abs(default_cells[:, 4] - s.cells[:, 4]) * volume).sum(), 0, bound,
            (s.cells[:, 4] * volume).sum())
scale = sum(np.abs(v).sum() for _, v in SOURCES)
for i, axis in enumerate("xyz"):
    checks.near("default tolerance: sum |source %s - converged| / sum |sources|" % axis,
                np.abs(default_cells[:, 5 + i] - s.cells[:, 5 + i]).sum(), 0, bound, scale)
static_cells = s.cells

# --- cyclic ends: an ore in the lowest layer against the same ore 12
# layers up, in the middle of the riser
layers = []
for name, z in (("ends", 0.0042), ("middle", 0.1042)):
    case = riser(name)
    s = kernel.spread(case, CONVERGED, d, [((0.0003, 0.0002, z), vp)])
    layer = np.floor(s.cells[:, 2] / (0.2 / 24)).astype(int)
    layers.append((np.bincount(layer, weights=s.cells[:, 3]),
                   np.bincount(layer, weights=s.cells[:, 4] * s.cells[:, 3])))
(volume, ends), (_, middle) = layers
# the layers' volumes are equal to blockMesh's placement of the points
# only: their spread sets the tolerance (ten times it)
uneven = (volume.max() - volume.min()) / volume.max()
print("layer volumes equal to %.1e (relative)" % uneven)
worst = max(abs(ends[k % 24] - middle[(12 + k) % 24]) for k in range(-11, 12)) / ends.max()
checks.near("cyclic ends: layer sums at +-k layers, through the ends vs inside",
            worst, 0, 10 * uneven + 1e-12, 1)
print("layer sums about the ore's layer, through the ends: %s"
      % " ".join("%.3e" % (ends[k % 24] / ends.max()) for k in range(-3, 4)))

# --- moving mesh: a quarter period of the riser's oscillation
moving = riser("moving")
shutil.copy(os.path.join(ROOT, "tutorials/riser/oscillatingContactMovingMesh/constant/dynamicMeshDict"),
            os.path.join(moving, "constant"))
shutil.copy(os.path.join(ROOT, "tutorials/riser/oscillatingContactMovingMesh/constant/riserProperties"),
            os.path.join(moving, "constant"))
ff.set_entry(os.path.join(moving, "system/controlDict"), "endTime", repr(1 / 12))
ff.set_entry(os.path.join(moving, "system/controlDict"), "deltaT", repr(1 / 120))
shift = np.array([0.1, 0.0, 0.0])
s = kernel.spread(moving, CONVERGED, d, [(tuple(np.array(p) + shift), v) for p, v in DEPOSITS],
                  [(tuple(np.array(p) + shift), v) for p, v in SOURCES])
conservation("moving mesh", s)
checks.near("moving mesh: cell centres shifted by A along x",
            np.abs(s.cells[:, :3] - static_cells[:, :3] - shift).max(), 0, 1e-12, 0.1)
checks.near("moving mesh: spread theta against the static one",
            np.abs(s.cells[:, 4] - static_cells[:, 4]).max(), 0, 1e-9, static_cells[:, 4].max())

# --- 2 processors split at mid-height
parallel = riser("parallel")
ff.write_dictionary(os.path.join(parallel, "system/decomposeParDict"),
                    "numberOfSubdomains 2;\nmethod simple;\ncoeffs { n (1 1 2); }\n")
run(["decomposePar", "-case", parallel], os.path.join(parallel, "log.decomposePar"))
s = kernel.spread(parallel, CONVERGED, d, DEPOSITS, SOURCES, parallel=2)
conservation("2 processors", s)
# each processor's cell is the serial cell at its centre (the nearest)
centres = static_cells[:, :3]
serial, gap = [], []
for chunk in np.array_split(s.cells[:, :3], 32):
    dist = ((chunk[:, None, :] - centres[None, :, :]) ** 2).sum(axis=2)
    serial.extend(dist.argmin(axis=1))
    gap.extend(np.sqrt(dist.min(axis=1)))
serial, gap = np.array(serial), np.array(gap)
if gap.max() > 1e-12 or len(set(serial)) != len(static_cells):
    print("FAILED: the processors' cells are not the serial ones")
    checks.failures += 1
checks.near("2 processors: spread theta against the serial one",
            np.abs(s.cells[:, 4] - static_cells[serial, 4]).max(), 0, 1e-9,
            static_cells[:, 4].max())
checks.exit()
