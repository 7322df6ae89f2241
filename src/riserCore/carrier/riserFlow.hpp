// riserCore: the analytic carrier of an oscillating riser (doc/theory.md
// section 2; Wei et al., Phys. Fluids 35, 113311, 2023, sec. II, sign of
// curl corrected).
//
// The riser (riser::RiserMotion) moves its axis sideways, to (x_c, y_c) at
// velocity (U_r, V_r). The fluid translates rigidly with the riser and
// carries upward Poiseuille flow about the moving axis (pipe radius R = D/2,
// centre-line speed u_cm), with r = (x - x_c, y - y_c, 0) the offset from
// the axis, all of the riser's kinematics at the point's height z:
//   u       = ( U_r, V_r, u_cm [1 - |r|^2 / R^2] )
//   Du/Dt   = ( dU_r/dt, dV_r/dt, 0 )   (exact for a riser whose motion is
//                                  the same at every z: the local change of
//                                  u_z as the axis moves cancels its
//                                  convection by (U_r, V_r))
//   curl u  = ( -2 u_cm (y - y_c) / R^2, 2 u_cm (x - x_c) / R^2, 0 )
// Outside the pipe the formulas are continued analytically; callers decide
// what a position outside the pipe means. The pipe's wall is the
// riser::CylinderWall of the same diameter and motion (wall()).
//
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef RISERCORE_CARRIER_RISERFLOW_HPP
#define RISERCORE_CARRIER_RISERFLOW_HPP

#include "checks.hpp"
#include "riser/riserMotion.hpp"
#include "riser/sinusoidMotion.hpp"
#include "vector.hpp"
#include "wall/cylinderWall.hpp"

#include <cmath>
#include <utility>

namespace riser {

class RiserFlow
{
public:
    //- D: pipe diameter [m]; uCentre: centre-line speed [m/s]; motion: the
    //  riser's (shared with the wall and the flow's copies)
    RiserFlow(double D, double uCentre, MotionPtr motion)
    :
        wall_(D, std::move(motion)), uCentre_(uCentre)
    {
        requireNonNegative("riser::RiserFlow", "u_cm", uCentre);
    }

    //- D, uCentre, and a sinusoid's A [m], omega [rad/s], phi0 [rad]
    RiserFlow(double D, double uCentre, double A, double omega, double phi0)
    :
        RiserFlow(D, uCentre, SinusoidMotion::make(A, omega, phi0))
    {}

    double diameter() const { return wall_.diameter(); }
    double radius() const { return wall_.radius(); }
    double centreLineSpeed() const { return uCentre_; }
    const RiserMotion& motion() const { return wall_.motion(); }
    const MotionPtr& motionPtr() const { return wall_.motionPtr(); }
    const CylinderWall& wall() const { return wall_; }

    //- Carrier velocity u(x, t).
    Vector velocity(const Vector& x, double t) const
    {
        return velocityAt(motion().radialOffset(x, t), motion().velocity(x.z(), t));
    }

    //- u at x, with the riser's kinematics s = motion().state(x_z, t)
    Vector velocity(const Vector& x, const AxisState& s) const
    {
        return velocityAt(motion().radialOffset(x, s), s.velocity);
    }

    //- Material derivative Du/Dt(x, t).
    Vector materialDerivative(const Vector& x, double t) const
    {
        return motion().acceleration(x.z(), t);
    }

    //- Du/Dt with the riser's kinematics s at the point (uniform in its
    //  cross-section)
    Vector materialDerivative(const AxisState& s) const
    {
        return s.acceleration;
    }

    //- Vorticity curl u (x, t).
    Vector vorticity(const Vector& x, double t) const
    {
        return vorticityAt(motion().radialOffset(x, t));
    }

    //- curl u at x, with the riser's kinematics s at the point
    Vector vorticity(const Vector& x, const AxisState& s) const
    {
        return vorticityAt(motion().radialOffset(x, s));
    }

private:
    //- u at offset r from the axis of a riser moving at Ur
    Vector velocityAt(const Vector& r, const Vector& Ur) const
    {
        const double R = radius();
        return Vector(Ur.x(), Ur.y(), uCentre_*(1.0 - r.squaredNorm()/(R*R)));
    }

    //- curl u at offset r from the axis
    Vector vorticityAt(const Vector& r) const
    {
        const double c = 2.0*uCentre_/(radius()*radius());
        return Vector(-c*r.y(), c*r.x(), 0.0);
    }

    CylinderWall wall_;
    double uCentre_;
};

} // namespace riser

#endif
