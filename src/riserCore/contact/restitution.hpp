// riserCore: restitution of the damped Hertz contact, and its inverse.
//
// A normal impact at speed v of a body of mass M on a Hertz spring with Tsuji
// damping, M d2delta/dt2 = -k delta^(3/2) - alpha sqrt(k M) delta^(1/4) ddelta/dt,
// becomes, in the units delta_s = (M v^2 / k)^(2/5), T = delta_s / v,
//     x'' = -x^(3/2) - alpha x^(1/4) x',   x(0) = 0, x'(0) = 1,
// so the coefficient of restitution e = -x'(end of contact) depends on the
// damping ratio alpha alone, not on v, M, k (Tsuji et al., Powder Technol.
// 71, 239, 1992). This file integrates that universal equation and inverts
// it.
//
// Choice made here, and its consequence:
//   NormalForceFloor::tensionAllowed - the dashpot may pull (the force may
//       turn attractive before the overlap closes), as the paper writes it.
//       Then the closed form of the linear spring–dashpot carries over,
//           alpha = sqrt(5) (-ln e) / sqrt(pi^2 + ln^2 e),
//       and dampingRatio() returns it: integrating the equation above with
//       it reproduces e to 1e-6 for e in [0.1, 1] (checked in the tests).
//   NormalForceFloor::noTension - the normal force is clipped at zero, so
//       the particle leaves when the force vanishes, earlier and faster:
//       with the closed-form alpha, e = 0.5 would come out as 0.55 and
//       e = 0.1 as 0.25. dampingRatio() then calibrates alpha numerically
//       by bisection on e(alpha), which is monotone.
// e = 0 has no finite damping ratio (e -> 0 only as alpha -> infinity): it
// is rejected; e = 1 gives alpha = 0.
//
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef RISERCORE_CONTACT_RESTITUTION_HPP
#define RISERCORE_CONTACT_RESTITUTION_HPP

#include "checks.hpp"

#include <algorithm>
#include <cmath>

namespace riser {

enum class NormalForceFloor { tensionAllowed, noTension };

//- The closed form, exact when the dashpot may pull (see above).
inline double closedFormDampingRatio(double e)
{
    requireInRange("riser::closedFormDampingRatio", "e", e, 0.0, Bound::open, 1.0, Bound::closed);
    const double l = std::log(e);
    return std::sqrt(5.0)*(-l)/std::sqrt(M_PI*M_PI + l*l);
}

//- Coefficient of restitution of the dimensionless impact for damping ratio
//  alpha >= 0, by classical RK4 with step dtau and linear location of the
//  end of contact. The default step gives |error| < 1e-6 (tested by halving).
inline double hertzRestitution(double alpha, NormalForceFloor floor,
                               double dtau = 2e-4)
{
    requireNonNegative("riser::hertzRestitution", "alpha", alpha);
    requirePositive("riser::hertzRestitution", "dtau", dtau);
    const bool clip = floor == NormalForceFloor::noTension;
    auto accel = [alpha, clip](double x, double u)
    {
        if (x <= 0.0) return 0.0;
        const double f = x*std::sqrt(x) + alpha*std::sqrt(std::sqrt(x))*u;
        return clip ? -std::max(f, 0.0) : -f;
    };
    double x = 0.0, u = 1.0;
    const double tauMax = 1e4;   // e below ~1e-9 at this stage: report 0
    for (double tau = 0.0; tau < tauMax; tau += dtau)
    {
        const double k1x = u,                k1u = accel(x, u);
        const double k2x = u + 0.5*dtau*k1u, k2u = accel(x + 0.5*dtau*k1x, k2x);
        const double k3x = u + 0.5*dtau*k2u, k3u = accel(x + 0.5*dtau*k2x, k3x);
        const double k4x = u + dtau*k3u,     k4u = accel(x + dtau*k3x, k4x);
        const double xNew = x + dtau/6.0*(k1x + 2.0*k2x + 2.0*k3x + k4x);
        const double uNew = u + dtau/6.0*(k1u + 2.0*k2u + 2.0*k3u + k4u);
        if (xNew <= 0.0 && uNew < 0.0)
        {
            // End of contact inside the step: the acceleration vanishes at
            // x = 0, so the velocity is linear there to second order.
            const double s = x/(x - xNew);
            return -(u + s*(uNew - u));
        }
        x = xNew;
        u = uNew;
    }
    return 0.0;
}

//- Damping ratio alpha that gives restitution e in (0, 1] for the chosen
//  floor: the closed form with tension allowed, otherwise bisection on the
//  monotone map e(alpha) to 1e-10 in alpha.
inline double dampingRatio(double e, NormalForceFloor floor)
{
    requireInRange("riser::dampingRatio", "e", e, 0.0, Bound::open, 1.0, Bound::closed);
    if (e == 1.0) return 0.0;
    if (floor == NormalForceFloor::tensionAllowed) return closedFormDampingRatio(e);
    double lo = 0.0, hi = 1.0;
    while (hertzRestitution(hi, floor) > e)
    {
        lo = hi;
        hi *= 2.0;
    }
    while (hi - lo > 1e-10*std::max(1.0, hi))
    {
        const double mid = 0.5*(lo + hi);
        (hertzRestitution(mid, floor) > e ? lo : hi) = mid;
    }
    return 0.5*(lo + hi);
}

} // namespace riser

#endif
