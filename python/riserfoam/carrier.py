"""The analytic riser carrier (constant/riserProperties): a pipe of diameter
D whose axis moves sideways as x_c(t) = A sin(omega t + phi0), carrying the
Poiseuille flow u_z = u_cm (1 - (2 r / D)^2) about the moving axis (r: the
distance from it; zero outside the pipe) and, in the lab frame, the riser's
velocity A omega cos(omega t + phi0) along x.

Every function takes scalars (and gives floats) or numpy arrays.

SPDX-License-Identifier: GPL-3.0-or-later
"""
import math
import os
import re

import numpy as np

from . import foamfields as ff

# the tutorials' riser and the paper's scenes (Wei et al. 2023): the
# length D = 0.1 m and the velocity u_cm = 1 m/s, the units of A [D] and
# f [u_cm / D] in the scripts
D = 0.1
UCM = 1.0


def _plain(value):
    return float(value) if np.ndim(value) == 0 else value


class Riser:
    """The riser of constant/riserProperties (SI units): diameter D, centre
    speed u_cm, amplitude A, frequency f [Hz] (or omega [rad/s]), phase phi0."""

    def __init__(self, D=D, u_cm=UCM, A=0.0, f=0.0, phi0=0.0, omega=None):
        self.D, self.u_cm, self.A, self.phi0 = D, u_cm, A, phi0
        self.omega = 2.0 * math.pi * f if omega is None else omega
        self.f = f if omega is None else omega / (2.0 * math.pi)

    @classmethod
    def of_case(cls, case):
        """The riser of the case folder's constant/riserProperties: its
        sinusoid of top-level entries A, f (omega), phi0. A riser given by a
        'motion' dictionary (the harmonics, or a sinusoid written there) is
        refused (ValueError) rather than read as one at rest."""
        path = os.path.join(case, "constant", "riserProperties")
        with open(path) as f:
            if re.search(r"^\s*motion\b", f.read(), re.M):
                raise ValueError("%s: Riser reads the top-level sinusoid A, f, phi0, not "
                                 "a 'motion' dictionary" % path)
        entry = lambda name, default=None: (  # noqa: E731
            ff.read_entry(path, name) if ff.read_entry(path, name) is not None else default)
        omega = entry("omega")
        return cls(entry("D"), entry("uCentre"), entry("A"), entry("f", 0.0),
                   entry("phi0", 0.0), omega)

    def axis(self, t):
        """x_c(t) = A sin(omega t + phi0)"""
        return _plain(self.A * np.sin(self.omega * np.asarray(t) + self.phi0))

    def velocity(self, t):
        """the riser's velocity along x: A omega cos(omega t + phi0)"""
        return _plain(self.A * self.omega * np.cos(self.omega * np.asarray(t) + self.phi0))

    def axis_distance(self, x, y, t=0.0, frame="riser"):
        """the distance of (x, y) from the riser's axis: coordinates relative
        to the axis ('riser') or the lab's ('lab', the axis at x_c(t))"""
        if frame == "lab":
            x = np.asarray(x) - self.axis(t)
        return _plain(np.hypot(x, y))

    def speed(self, r):
        """the Poiseuille speed at distance r from the axis (zero outside)"""
        return _plain(self.u_cm * np.maximum(0.0, 1.0 - (2.0 * np.asarray(r) / self.D) ** 2))

    def carrier(self, x, y, z=0.0, t=0.0, frame="riser"):
        """the carrier's velocity (u_x, u_y, u_z) at (x, y, z) and t: in the
        riser frame ('riser', coordinates relative to the axis) or the lab
        frame ('lab', the axis at x_c(t), the riser's velocity added)"""
        uz = self.speed(self.axis_distance(x, y, t, frame))
        return (self.velocity(t) if frame == "lab" else 0.0, 0.0, uz)
