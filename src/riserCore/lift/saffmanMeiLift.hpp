// riserCore: Saffman–Mei shear-lift coefficient (Mei, Int. J. Multiphase
// Flow 18, 145, 1992), as used by Wei et al., Phys. Fluids 35, 113311 (2023).
//
// With Re_p = rho d |w| / mu (slip), Re_s = rho d^2 |Omega| / mu (vorticity),
// b = Re_s / (2 Re_p):
//
//   C_L = 4.1126 / sqrt(Re_s) f(Re_p, Re_s)
//   f   = (1 - 0.3314 sqrt(b)) exp(-0.1 Re_p) + 0.3314 sqrt(b)   Re_p <= 40
//       = 0.0524 sqrt(b Re_p)                                    Re_p > 40
//
// and the force F_L = (pi d^3 / 8) rho C_L (w x Omega). For Re_p, Re_s -> 0
// it reduces to Saffman's 6.46 mu a^2 |w| sqrt(|Omega| / nu).
//
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef RISERCORE_LIFT_SAFFMANMEILIFT_HPP
#define RISERCORE_LIFT_SAFFMANMEILIFT_HPP

#include "checks.hpp"
#include "vector.hpp"

#include <cmath>

namespace riser {

//- Mei's correction f(Re_p, Re_s) to Saffman's lift (f -> 1 as Re_p -> 0).
inline double saffmanMeiCorrection(double Rep, double Res)
{
    requirePositive("riser::saffmanMeiCorrection", "Re_p", Rep);
    requireNonNegative("riser::saffmanMeiCorrection", "Re_s", Res);
    const double b = 0.5*Res/Rep;
    if (Rep <= 40.0)
    {
        const double sb = 0.3314*std::sqrt(b);
        return (1.0 - sb)*std::exp(-0.1*Rep) + sb;
    }
    return 0.0524*std::sqrt(b*Rep);
}

//- C_L sqrt(Re_s) = 4.1126 f: finite as Re_s -> 0, so that the force
//  F_L = (pi/8) d^2 sqrt(rho mu / |Omega|) [C_L sqrt(Re_s)] (w x Omega)
//  needs no division by a vanishing vorticity or slip.
inline double saffmanMeiCoefficientTimesSqrtRes(double Rep, double Res)
{
    if (Rep == 0.0) return 4.1126;   // f -> 1 as Re_p -> 0 at fixed Re_s
    return 4.1126*saffmanMeiCorrection(Rep, Res);
}

//- Lift coefficient C_L for Re_p > 0, Re_s > 0.
inline double saffmanMeiCoefficient(double Rep, double Res)
{
    requirePositive("riser::saffmanMeiCoefficient", "Re_s", Res);
    return saffmanMeiCoefficientTimesSqrtRes(Rep, Res)/std::sqrt(Res);
}

//- The force's prefactor: F_L = c (w x Omega) with
//  c = (pi/8) d^2 sqrt(rho mu / |Omega|) [C_L sqrt(Re_s)], for slip speed
//  |w| >= 0 and vorticity magnitude |Omega| >= 0 (c = 0 without vorticity).
inline double saffmanMeiLiftPrefactor(double d, double rho, double mu,
                                      double slip, double magOmega)
{
    if (magOmega <= 0.0) return 0.0;
    const double Rep = rho*slip*d/mu;
    const double Res = rho*d*d*magOmega/mu;
    return M_PI/8.0*d*d*std::sqrt(rho*mu/magOmega)
          *saffmanMeiCoefficientTimesSqrtRes(Rep, Res);
}

//- The lift force F_L = c (w x Omega) on a sphere of diameter d with slip
//  w = u - v in a fluid of density rho and viscosity mu and vorticity Omega
inline Vector saffmanMeiLiftForce(double d, double rho, double mu, const Vector& w,
                                  const Vector& Omega)
{
    return saffmanMeiLiftPrefactor(d, rho, mu, w.norm(), Omega.norm())*w.cross(Omega);
}

} // namespace riser

#endif
