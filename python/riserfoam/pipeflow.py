"""Fully developed flow in a smooth straight pipe: the closed forms and
correlations that the turbulent riser's initial fields, plots and checks
compare with.

- Prandtl's smooth-pipe law for Darcy's friction factor lambda,
  1/sqrt(lambda) = 2.0 log10(Re sqrt(lambda)) - 0.8 (Prandtl 1935;
  Schlichting & Gersten, Boundary-Layer Theory, 2017, eq. 17.61), and
  the wall shear it gives: u_tau = u_b sqrt(lambda/8),
  -dp/dz = lambda rho u_b^2 / (2 D).
- The log law u/u_tau = ln(y u_tau/nu)/kappa + B, kappa = 0.41, B = 5.2
  (Pope, Turbulent Flows, 2000, sec. 7.1).
- The 1/n power law u = u_max (1 - r/R)^(1/n), whose bulk velocity is
  u_max 2 n^2 / ((n + 1)(2 n + 1)) (n = 7 near Re = 1e5).
- The turbulence estimates of a RAS model's initial fields: k from a
  turbulence intensity I of the bulk velocity, k = 3/2 (I u_b)^2, and omega
  and epsilon from a length scale l, omega = sqrt(k) / (C_mu^(1/4) l),
  epsilon = C_mu^(3/4) k^(3/2) / l.

Every function takes scalars (and gives floats) or numpy arrays.

SPDX-License-Identifier: GPL-3.0-or-later
"""
import math

import numpy as np

KAPPA = 0.41
B = 5.2
C_MU = 0.09


def prandtl_friction(Re):
    """Darcy's friction factor of Prandtl's smooth-pipe law at Re = u_b D / nu
    (fixed-point iteration, converged to round-off)"""
    lam = 0.02
    for _ in range(100):
        lam = (2.0 * math.log10(Re * math.sqrt(lam)) - 0.8) ** -2
    return lam


def friction_velocity(ub, D, nu):
    """u_tau = u_b sqrt(lambda/8) of Prandtl's law"""
    return ub * math.sqrt(prandtl_friction(ub * D / nu) / 8.0)


def pressure_gradient(ub, D, nu, rho):
    """-dp/dz = lambda rho u_b^2 / (2 D) of Prandtl's law [Pa/m]"""
    return prandtl_friction(ub * D / nu) * rho * ub ** 2 / (2.0 * D)


def log_law(y, u_tau, nu):
    """u(y) = u_tau (ln(y u_tau/nu)/kappa + B), y the distance from the wall"""
    y = np.asarray(y, dtype=float)
    return u_tau * (np.log(y * u_tau / nu) / KAPPA + B)


def power_law(r, R, ub, n=7):
    """u(r) = u_max (1 - r/R)^(1/n) with the bulk velocity ub (zero beyond R)"""
    umax = ub * (n + 1) * (2 * n + 1) / (2.0 * n * n)
    r = np.asarray(r, dtype=float)
    value = umax * np.maximum(0.0, 1.0 - r / R) ** (1.0 / n)
    return float(value) if value.ndim == 0 else value


def turbulence_estimates(ub, D, intensity=0.05, length=0.07):
    """(k, omega, epsilon) from the intensity (of ub) and the length scale
    l (of D): omega = sqrt(k)/(C_mu^1/4 l), epsilon = C_mu^3/4 k^3/2 / l"""
    k = 1.5 * (intensity * ub) ** 2
    l = length * D
    return k, math.sqrt(k) / (C_MU ** 0.25 * l), C_MU ** 0.75 * k ** 1.5 / l
