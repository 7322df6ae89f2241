"""The coarse-particle kernel (particleKernel) driven by the utility
riserKernel: a box or riser mesh, point deposits spread, the sums and the
cells read back; and the closed forms the spread is checked against.

Closed forms, for the diffusion d(phi)/d(tau) = laplacian(phi) to the
pseudo-time T = b^2/4 (b the bandwidth, sigma^2 = 2 T per axis):
- gaussian1d: the exact solution's profile along one axis (the integral
  over the other two), the Gaussian of variance 2 T;
- steps1d: the same profile after N implicit Euler steps of T/N in
  continuous space: the inverse Fourier transform of (1 + l^2 k^2)^-N,
  l^2 = T/N, a Matern function z^nu K_nu(z), nu = N - 1/2, z = |x|/l;
  its variance is 2 T too, its excess kurtosis 3/N;
- steps3d: that kernel in 3-D, as a function of the distance (nu = N - 3/2).

SPDX-License-Identifier: GPL-3.0-or-later
"""
import math
import os
import re

import numpy as np
from . import foamfields as ff
from .cases import run


def gaussian1d(x, T):
    """The profile along an axis of a unit point deposit diffused to T"""
    return np.exp(-x ** 2 / (4 * T)) / math.sqrt(4 * math.pi * T)


def _zK(z, m):
    """z^nu K_nu(z) / sqrt(pi/2) for nu = m + 1/2 (m = 0, 1, ...): the
    modified Bessel function of half-integer order is elementary,
    K_nu(z) = sqrt(pi/(2z)) e^-z sum_j (m+j)!/(j!(m-j)!) (2z)^-j"""
    return np.exp(-z) * sum(math.factorial(m + j) / (math.factorial(j) * math.factorial(m - j))
                            / 2 ** j * z ** (m - j) for j in range(m + 1))


def steps1d(x, T, N):
    """The profile along an axis after N implicit Euler steps of T/N:
    z^nu K_nu(z) / (l 2^(N-1) (N-1)! sqrt(2 pi)), nu = N - 1/2"""
    l = math.sqrt(T / N)
    return _zK(np.abs(x) / l, N - 1) / (2 * l * 2 ** (N - 1) * math.factorial(N - 1))


def steps3d(r, T, N):
    """The 3-D kernel after N >= 2 implicit Euler steps of T/N, at the
    distance r: z^nu K_nu(z) / (l^3 2^(N-1) (N-1)! (2 pi)^(3/2)),
    nu = N - 3/2"""
    l = math.sqrt(T / N)
    return (_zK(r / l, N - 2) * math.sqrt(math.pi / 2)
            / (l ** 3 * 2 ** (N - 1) * math.factorial(N - 1) * (2 * math.pi) ** 1.5))


def cell_average(profile, centres, h, points=16):
    """The mean of profile(x) over cells of width h about the centres
    (Gauss-Legendre, points per cell)"""
    nodes, weights = np.polynomial.legendre.leggauss(points)
    return sum(w / 2 * profile(centres + 0.5 * h * s) for s, w in zip(nodes, weights))


_SYSTEM = {
    "controlDict": """application riserKernel;
startFrom startTime;
startTime 0;
stopAt endTime;
endTime 0;
deltaT 1;
writeControl timeStep;
writeInterval 1;
""",
    "fvSchemes": """ddtSchemes { default Euler; }
gradSchemes { default Gauss linear; }
divSchemes { default none; }
laplacianSchemes { default Gauss linear corrected; }
interpolationSchemes { default linear; }
snGradSchemes { default corrected; }
""",
    "fvSolution": "",
}


def system(case):
    """The system files the utility needs (no schemes of its own are read:
    particleKernel brings its Laplacian)"""
    os.makedirs(os.path.join(case, "system"), exist_ok=True)
    os.makedirs(os.path.join(case, "constant"), exist_ok=True)
    for name, body in _SYSTEM.items():
        ff.write_dictionary(os.path.join(case, "system", name), body)


def box_mesh(case, lo, hi, cells):
    """A box of uniform hexahedra from lo to hi (3 tuples), cells per axis
    (3 numbers), every face a wall"""
    system(case)
    (x0, y0, z0), (x1, y1, z1) = lo, hi
    vertices = [(x0, y0, z0), (x1, y0, z0), (x1, y1, z0), (x0, y1, z0),
                (x0, y0, z1), (x1, y0, z1), (x1, y1, z1), (x0, y1, z1)]
    ff.write_dictionary(os.path.join(case, "system", "blockMeshDict"), """
vertices (%s);
blocks ( hex (0 1 2 3 4 5 6 7) (%d %d %d) simpleGrading (1 1 1) );
boundary
(
    walls { type wall; faces ((0 4 7 3) (1 2 6 5) (0 1 5 4) (3 7 6 2) (0 3 2 1) (4 5 6 7)); }
);
""" % (" ".join("(%.17g %.17g %.17g)" % v for v in vertices), *cells))
    run(["blockMesh", "-case", case], os.path.join(case, "log.blockMesh"))


def kernel_dict(case, kernel, diameter, deposits=(), sources=()):
    """system/riserKernelDict: kernel the kernel sub-dictionary's body,
    deposits [(point, volume)], sources [(point, vector)]"""
    def vec(v):
        return "(%.17g %.17g %.17g)" % tuple(v)
    ff.write_dictionary(os.path.join(case, "system", "riserKernelDict"), """
kernel { %s }
diameter %.17g;
deposits ( %s );
sources ( %s );
""" % (kernel, diameter, " ".join("(%s %.17g)" % (vec(p), v) for p, v in deposits),
       " ".join("(%s %s)" % (vec(p), vec(v)) for p, v in sources)))


class Spread:
    """riserKernel's result in case: sums (before, after) of the deposits
    and (vectors) of the sources, bandwidth, largest cell size, cross-section;
    cells: columns x y z V theta ax ay az"""

    def __init__(self, case, log):
        def number(name):
            return float(re.search(r"^%s (\S+)" % name, log, re.M).group(1))
        self.bandwidth = number("bandwidth") if "bandwidth" in log else None
        self.largest_cell = number("largestCellSize")
        self.cross_section = number("crossSection")
        m = re.search(r"^deposits before (\S+) after (\S+)", log, re.M)
        self.deposits = (float(m.group(1)), float(m.group(2)))
        vector = r"\((\S+) (\S+) (\S+)\)"
        m = re.search(r"^sources before %s after %s" % (vector, vector), log, re.M)
        self.sources = (np.array([float(g) for g in m.groups()[:3]]),
                        np.array([float(g) for g in m.groups()[3:]]))
        files = [os.path.join(case, "postProcessing", "riserKernel", "cells.dat")]
        if not os.path.exists(files[0]):
            files = sorted(os.path.join(case, p, "postProcessing", "riserKernel", "cells.dat")
                           for p in os.listdir(case) if p.startswith("processor"))
        self.cells = np.vstack([np.loadtxt(f, ndmin=2) for f in files])


def spread(case, kernel, diameter, deposits=(), sources=(), parallel=0, may_fail=False):
    """Run riserKernel in case (on parallel processors if > 1); a Spread,
    or the log's text if it failed and may_fail"""
    kernel_dict(case, kernel, diameter, deposits, sources)
    log = os.path.join(case, "log.riserKernel")
    if parallel > 1:
        text = run(["mpirun", "--allow-run-as-root", "--oversubscribe", "-np", str(parallel), "riserKernel",
                    "-parallel", "-case", case], log, may_fail=may_fail)
    else:
        text = run(["riserKernel", "-case", case], log, may_fail=may_fail)
    if text is None:
        return open(log).read()
    return Spread(case, text)
