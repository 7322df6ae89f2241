// riserCore: the analytic carrier of an oscillating riser (Wei et al., Phys.
// Fluids 35, 113311, 2023, sec. II; sign of curl corrected).
//
// The riser axis is parallel to z and moves sideways along x:
//   x_c(t) = A sin(omega t + phi0),   U_r(t) = A omega cos(omega t + phi0),
//   a_r(t) = -A omega^2 sin(omega t + phi0).
// The fluid translates rigidly with the riser and carries upward Poiseuille
// flow about the moving axis (pipe radius R = D/2, centre-line speed u_cm):
//   u       = ( U_r, 0, u_cm [1 - ((x - x_c)^2 + y^2) / R^2] )
//   Du/Dt   = ( dU_r/dt, 0, 0 )   (exact: u . grad u = 0 for this field)
//   curl u  = ( -2 u_cm y / R^2, 2 u_cm (x - x_c) / R^2, 0 )
// Outside the pipe the formulas are continued analytically; callers decide
// what a position outside the pipe means.
//
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef RISERCORE_CARRIER_RISERFLOW_HPP
#define RISERCORE_CARRIER_RISERFLOW_HPP

#include "../checks.hpp"

#include "../vector.hpp"

#include <cmath>

namespace riser {

class RiserFlow
{
public:
    //- D: pipe diameter [m]; uCentre: centre-line speed [m/s];
    //  A: amplitude [m]; omega: angular frequency [rad/s]; phi0: phase [rad].
    RiserFlow(double D, double uCentre, double A, double omega, double phi0)
    :
        D_(D), uCentre_(uCentre), A_(A), omega_(omega), phi0_(phi0)
    {
        const char* law = "riser::RiserFlow";
        requirePositive(law, "D", D);
        requireNonNegative(law, "u_cm", uCentre);
        requireNonNegative(law, "A", A);
        requireNonNegative(law, "omega", omega);
        requireInRange(law, "phi0", phi0, -HUGE_VAL, Bound::open, HUGE_VAL, Bound::open);
    }

    double diameter() const { return D_; }
    double radius() const { return 0.5*D_; }
    double centreLineSpeed() const { return uCentre_; }
    double amplitude() const { return A_; }
    double omega() const { return omega_; }
    double frequency() const { return omega_/(2.0*M_PI); }
    double phase() const { return phi0_; }

    //- Axis position x_c(t) (the axis passes through (x_c, 0, z)).
    double axisPosition(double t) const { return A_*std::sin(omega_*t + phi0_); }
    //- Riser (and wall) velocity U_r(t) along x.
    double riserVelocity(double t) const { return A_*omega_*std::cos(omega_*t + phi0_); }
    //- Riser acceleration dU_r/dt along x.
    double riserAcceleration(double t) const
    {
        return -A_*omega_*omega_*std::sin(omega_*t + phi0_);
    }

    //- Offset of x from the axis, in the cross-section (z component zero).
    Vector radialOffset(const Vector& x, double t) const
    {
        return Vector(x.x() - axisPosition(t), x.y(), 0.0);
    }

    //- Carrier velocity u(x, t).
    Vector velocity(const Vector& x, double t) const
    {
        const Vector r = radialOffset(x, t);
        const double R = radius();
        return Vector(riserVelocity(t), 0.0, uCentre_*(1.0 - r.squaredNorm()/(R*R)));
    }

    //- Material derivative Du/Dt(x, t).
    Vector materialDerivative(const Vector&, double t) const
    {
        return Vector(riserAcceleration(t), 0.0, 0.0);
    }

    //- Vorticity curl u (x, t).
    Vector vorticity(const Vector& x, double t) const
    {
        const Vector r = radialOffset(x, t);
        const double c = 2.0*uCentre_/(radius()*radius());
        return Vector(-c*r.y(), c*r.x(), 0.0);
    }

private:
    double D_, uCentre_, A_, omega_, phi0_;
};

} // namespace riser

#endif
