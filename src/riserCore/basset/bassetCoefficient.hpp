// riserCore: coefficient C_H of the Basset history force
//   F_H = C_H (d^2 / 4) sqrt(pi rho mu) int_0^t (dw/dtau) / sqrt(t - tau) dtau.
//
// classical (BassetModel::classical): C_H = 6, Basset's creeping-flow value.
//
// michaelidesRoig (BassetModel::michaelidesRoig): Michaelides & Roig, AIChE J.
// 57, 2997 (2011), reinterpreting the data of Odar & Hamilton, as printed by
// Wei et al. (2023):
//   C_H = 6.00 - 3.16 [1 - exp(-0.14 Re_p St^0.82)]^2.5,
//   St  = 9 mu / (16 pi f R_p^2 rho)      (f: carrier oscillation frequency)
// Implemented form: the exponent 2.5 applies to the whole bracket
// [1 - exp(-0.14 Re_p St^0.82)]. C_H falls from 6 (Re_p -> 0) towards 2.84.
// For a steady carrier (f = 0, St -> infinity) the correlation has no
// frequency to work with; this implementation then returns the classical
// value 6 (stated in the interface, not silently chosen by the caller).
//
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef RISERCORE_BASSET_BASSETCOEFFICIENT_HPP
#define RISERCORE_BASSET_BASSETCOEFFICIENT_HPP

#include "checks.hpp"

#include <cmath>

namespace riser {

enum class BassetModel { classical, michaelidesRoig };

//- Classical creeping-flow Basset coefficient.
constexpr double classicalBassetCoefficient = 6.0;

//- Stokes-like number of the Michaelides–Roig correlation.
inline double bassetStrouhal(double mu, double rho, double radius, double frequency)
{
    const char* law = "riser::bassetStrouhal";
    requirePositive(law, "mu", mu);
    requirePositive(law, "rho_f", rho);
    requirePositive(law, "R_p", radius);
    requirePositive(law, "f", frequency);
    return 9.0*mu/(16.0*M_PI*frequency*radius*radius*rho);
}

//- St^0.82, the Strouhal factor of the Michaelides–Roig correlation: the
//  same for every particle of one size in one fluid, so that a caller
//  evaluating many such particles may keep it (a pow each).
inline double bassetStrouhalFactor(double mu, double rho, double radius, double frequency)
{
    return std::pow(bassetStrouhal(mu, rho, radius, frequency), 0.82);
}

//- C_H for particle Reynolds number Re_p >= 0 and carrier frequency f >= 0,
//  with the Strouhal factor St^0.82 of bassetStrouhalFactor given (not
//  used by the classical model nor at f = 0).
inline double bassetCoefficient(BassetModel model, double Rep, double frequency,
                                double strouhalFactor)
{
    requireNonNegative("riser::bassetCoefficient", "Re_p", Rep);
    requireNonNegative("riser::bassetCoefficient", "f", frequency);
    if (model == BassetModel::classical || frequency == 0.0)
    {
        return classicalBassetCoefficient;
    }
    const double bracket = 1.0 - std::exp(-0.14*Rep*strouhalFactor);
    return 6.00 - 3.16*std::pow(bracket, 2.5);
}

//- C_H for particle Reynolds number Re_p >= 0 and carrier frequency f >= 0.
inline double bassetCoefficient(BassetModel model, double Rep, double mu,
                                double rho, double radius, double frequency)
{
    const bool correlated = model == BassetModel::michaelidesRoig && frequency != 0.0;
    return bassetCoefficient
    (
        model, Rep, frequency,
        correlated ? bassetStrouhalFactor(mu, rho, radius, frequency) : 0.0
    );
}

} // namespace riser

#endif
