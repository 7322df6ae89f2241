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
- The library's turbulent carrier (theory guide section 2.7), written
  afresh from the guide for the tests that check the C++ one:
  Colebrook's friction factor, Reichardt's law with the log law above, the
  roughness shift, Coles' wake and the axis cubic, the wake's strength
  from the bulk speed (turbulent_profile).
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


def colebrook_friction(Re, relative_roughness=0.0):
    """Darcy's friction factor of Colebrook-White at Re and k_s/D (bisection
    on 1/sqrt(f))"""
    def residual(x):
        return x + 2 * math.log10(relative_roughness / 3.7 + 2.51 * x / Re)
    lo, hi = 1.0, 30.0
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if residual(mid) < 0 else (lo, mid)
    return 1 / (0.5 * (lo + hi)) ** 2


def turbulent_profile(ub, D, nu, ks=0.0):
    """w(r) of the library's turbulent carrier (theory guide section 2.7) at
    bulk speed ub in a pipe of diameter D, viscosity nu, sand-grain
    roughness ks: a function of r (scalar or array, |r| <= D/2)"""
    R = D / 2
    chi = 11.0
    C = B - math.log(KAPPA) / KAPPA
    ut = ub * math.sqrt(colebrook_friction(ub * D / nu, ks / D) / 8)
    Rp = R * ut / nu
    shift = math.log(1 + 0.3 * ks * ut / nu) / KAPPA

    def inner(yp):
        e = np.exp(-yp / chi)
        return (np.log(1 + KAPPA * yp) / KAPPA + C * (1 - e - yp / chi * np.exp(-yp / 3))
                - shift * (1 - e))

    h = 1e-6 * Rp
    g = Rp * (inner(Rp + h) - inner(Rp - h)) / (2 * h)

    def base(eta):
        return inner(eta * Rp) - g / 3 * eta ** 3

    def wake(eta):
        return 2 / KAPPA * np.sin(0.5 * math.pi * eta) ** 2

    # section means 2 int_0^1 F(eta) (1 - eta) d eta by Simpson's rule,
    # eta = s^4 graded to the wall
    s = np.linspace(0, 1, 400001)
    eta = s ** 4
    deta = 4 * s ** 3

    def mean(F):
        v = F(eta) * (1 - eta) * deta
        return 2 * (s[1] - s[0]) / 3 * (v[0] + v[-1] + 4 * v[1:-1:2].sum() + 2 * v[2:-1:2].sum())

    Pi = (ub / ut - mean(base)) / mean(wake)

    def w(r):
        e = (R - np.abs(np.asarray(r, dtype=float))) / R
        value = ut * (base(e) + Pi * wake(e))
        return float(value) if value.ndim == 0 else value
    return w

