// riserCore: the analytic carrier of an oscillating riser (doc/theory.md
// section 2; Wei et al., Phys. Fluids 35, 113311, 2023, sec. II, sign of
// curl corrected).
//
// The riser (riser::RiserMotion) moves its axis sideways, to (x_c, y_c) at
// velocity (U_r, V_r). The fluid translates rigidly with the riser and
// carries upward Poiseuille flow about the moving axis (pipe radius R = D/2,
// centre-line speed u_cm), with r = (x - x_c, y - y_c, 0) the offset from
// the axis, all of the riser's kinematics at the point's height z:
//   u       = ( U_r, V_r, w ),   w = u_cm [1 - |r|^2 / R^2]
//   Du/Dt   = ( dU_r/dt, dV_r/dt, 0 )   (exact for a riser whose motion is
//                                  the same at every z: the local change of
//                                  u_z as the axis moves cancels its
//                                  convection by (U_r, V_r))
//   curl u  = ( -2 u_cm (y - y_c) / R^2, 2 u_cm (x - x_c) / R^2, 0 )
// A riser whose motion varies along z (slope s = d(x_c, y_c)/dz, its rate
// s_t = d(U_r, V_r)/dz, curvature c = d^2(x_c, y_c)/dz^2) is sheared: each
// horizontal cross-section is the pipe's about the local axis (the slope
// neglected in the cross-section, doc/theory.md section 2.2), and the fluid
// follows it, each fluid particle keeping its offset r from the local axis
// and its axial speed w(|r|):
//   u       = ( U_r + w s_x, V_r + w s_y, w )
//   Du/Dt   = ( a_r + 2 w s_t + w^2 c, 0 )   (the axis' acceleration
//                                  along the fluid's path z = z_0 + w t)
//   curl u  = ( g_y - s_t,y + (g . s) s_y - w c_y,
//              -g_x + s_t,x - (g . s) s_x + w c_x,
//               g_x s_y - g_y s_x ),   g = grad w = -2 u_cm r / R^2,
// each exact for that field (|r| is constant along its paths).
// Outside the pipe the formulas are continued analytically; callers decide
// what a position outside the pipe means. The pipe's wall is the
// riser::CylinderWall of the same diameter and motion (wall()).
//
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef RISERCORE_CARRIER_RISERFLOW_HPP
#define RISERCORE_CARRIER_RISERFLOW_HPP

#include "carrier/pipeProfile.hpp"
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

    //- D: pipe diameter [m]; a profile of that diameter (turbulent or
    //  tabulated, its centre-line speed u_cm) in place of Poiseuille's;
    //  motion: the riser's
    RiserFlow(double D, std::shared_ptr<const PipeProfile> profile, MotionPtr motion)
    :
        RiserFlow(D, profile->centreLineSpeed(), std::move(motion))
    {
        if (std::abs(profile->radius() - radius()) > 1e-12*radius())
        {
            throw std::invalid_argument
            (
                "riser::RiserFlow: the profile's diameter is not the riser's"
            );
        }
        profile_ = std::move(profile);
    }

    //- D, uCentre, and a sinusoid's A [m], omega [rad/s], phi0 [rad]
    RiserFlow(double D, double uCentre, double A, double omega, double phi0)
    :
        RiserFlow(D, uCentre, SinusoidMotion::make(A, omega, phi0))
    {}

    //- The same carrier (diameter, profile) on another motion
    RiserFlow withMotion(MotionPtr motion) const
    {
        RiserFlow other(diameter(), uCentre_, std::move(motion));
        other.profile_ = profile_;
        return other;
    }

    double diameter() const { return wall_.diameter(); }
    double radius() const { return wall_.radius(); }
    double centreLineSpeed() const { return uCentre_; }
    //- The profile (null: Poiseuille's)
    const PipeProfile* profile() const { return profile_.get(); }
    const RiserMotion& motion() const { return wall_.motion(); }
    const MotionPtr& motionPtr() const { return wall_.motionPtr(); }
    const CylinderWall& wall() const { return wall_; }

    //- Carrier velocity u(x, t).
    Vector velocity(const Vector& x, double t) const
    {
        if (!motion().uniformAlongAxis()) return velocity(x, motion().state(x.z(), t));
        return velocityAt(motion().radialOffset(x, t), motion().velocity(x.z(), t));
    }

    //- u at x, with the riser's kinematics s = motion().state(x_z, t)
    Vector velocity(const Vector& x, const AxisState& s) const
    {
        Vector u = velocityAt(motion().radialOffset(x, s), s.velocity);
        if (!motion().uniformAlongAxis())
        {
            u.x() += u.z()*s.slope.x();
            u.y() += u.z()*s.slope.y();
        }
        return u;
    }

    //- Material derivative Du/Dt(x, t).
    Vector materialDerivative(const Vector& x, double t) const
    {
        if (!motion().uniformAlongAxis())
        {
            return materialDerivative(x, motion().state(x.z(), t));
        }
        return motion().acceleration(x.z(), t);
    }

    //- Du/Dt at x with the riser's kinematics s at the point
    Vector materialDerivative(const Vector& x, const AxisState& s) const
    {
        if (!motion().uniformAlongAxis())
        {
            const double w = axialSpeed(motion().radialOffset(x, s));
            return s.acceleration + 2.0*w*s.slopeRate + w*w*s.curvature;
        }
        return s.acceleration;
    }

    //- Du/Dt with the riser's kinematics s of a riser the same at every
    //  height (uniform in its cross-section)
    Vector materialDerivative(const AxisState& s) const
    {
        return s.acceleration;
    }

    //- Vorticity curl u (x, t).
    Vector vorticity(const Vector& x, double t) const
    {
        if (!motion().uniformAlongAxis()) return vorticity(x, motion().state(x.z(), t));
        return vorticityAt(motion().radialOffset(x, t));
    }

    //- curl u at x, with the riser's kinematics s at the point
    Vector vorticity(const Vector& x, const AxisState& s) const
    {
        const Vector r = motion().radialOffset(x, s);
        Vector omega = vorticityAt(r);
        if (!motion().uniformAlongAxis())
        {
            omega += shearVorticity(r, s);
        }
        return omega;
    }

    //- The part of curl u that a riser varying along z adds (its slope,
    //  slope rate and curvature in s) at offset r from the local axis
    Vector shearVorticity(const Vector& r, const AxisState& s) const
    {
        const double w = axialSpeed(r);
        const Vector g = axialSpeedGradient(r);
        const double gs = g.dot(s.slope);
        return Vector
        (
            -s.slopeRate.y() + gs*s.slope.y() - w*s.curvature.y(),
            s.slopeRate.x() - gs*s.slope.x() + w*s.curvature.x(),
            g.x()*s.slope.y() - g.y()*s.slope.x()
        );
    }

private:
    //- u at offset r from the axis of a riser moving at Ur
    Vector velocityAt(const Vector& r, const Vector& Ur) const
    {
        return Vector(Ur.x(), Ur.y(), axialSpeed(r));
    }

    //- w at offset r from the axis
    double axialSpeed(const Vector& r) const
    {
        if (profile_) return profile_->speed(r.norm());
        const double R = radius();
        return uCentre_*(1.0 - r.squaredNorm()/(R*R));
    }

    //- The cross-section's gradient of w at offset r, grad w = w'(|r|) r/|r|
    Vector axialSpeedGradient(const Vector& r) const
    {
        if (profile_)
        {
            const double rm = r.norm();
            return rm > 0.0 ? (profile_->gradient(rm)/rm)*r : Vector(Vector::Zero());
        }
        const double R = radius();
        return (-2.0*uCentre_/(R*R))*r;
    }

    //- curl u at offset r from the axis: (dw/dy, -dw/dx, 0)
    Vector vorticityAt(const Vector& r) const
    {
        if (profile_)
        {
            const Vector g = axialSpeedGradient(r);
            return Vector(g.y(), -g.x(), 0.0);
        }
        const double c = 2.0*uCentre_/(radius()*radius());
        return Vector(-c*r.y(), c*r.x(), 0.0);
    }

    CylinderWall wall_;
    double uCentre_;
    std::shared_ptr<const PipeProfile> profile_;
};

} // namespace riser

#endif
