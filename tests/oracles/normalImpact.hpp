// A head-on impact on a wall integrated by the test itself: the overlap
// delta and its rate u (the approach speed, U . n) by classical RK4 at a
// fixed step, from first touch (delta = 0, u = v) to the end of contact
// (delta back to 0, located linearly in the step); the caller supplies
// the acceleration along n, a(delta, u) (the contact law's or the
// kernel's force over the inertia). Shared by the core tests of the
// contact law and of the wet restitution.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef RISER_TESTS_NORMALIMPACT_HPP
#define RISER_TESTS_NORMALIMPACT_HPP

#include <algorithm>
#include <cmath>

struct ImpactResult
{
    double deltaMax = 0.0, accelMax = 0.0, duration = 0.0, reboundSpeed = 0.0;
    bool ended = false;     //!< false: still in contact after maxSteps
};

template<class Acceleration>
ImpactResult normalImpact(const Acceleration& a, double v, double dt, long maxSteps)
{
    ImpactResult r;
    double delta = 0.0, u = v, t = 0.0;
    for (long i = 0; i < maxSteps; ++i)
    {
        const double k1d = u,              k1u = a(delta, u);
        const double k2d = u + 0.5*dt*k1u, k2u = a(delta + 0.5*dt*k1d, k2d);
        const double k3d = u + 0.5*dt*k2u, k3u = a(delta + 0.5*dt*k2d, k3d);
        const double k4d = u + dt*k3u,     k4u = a(delta + dt*k3d, k4d);
        const double dNew = delta + dt/6.0*(k1d + 2*k2d + 2*k3d + k4d);
        const double uNew = u + dt/6.0*(k1u + 2*k2u + 2*k3u + k4u);
        if (dNew <= 0.0 && uNew < 0.0)
        {
            const double s = delta/(delta - dNew);
            r.duration = t + s*dt;
            r.reboundSpeed = -(u + s*(uNew - u));
            r.ended = true;
            return r;
        }
        delta = dNew;
        u = uNew;
        t += dt;
        r.deltaMax = std::max(r.deltaMax, delta);
        r.accelMax = std::max(r.accelMax, std::abs(a(delta, u)));
    }
    return r;
}

#endif
