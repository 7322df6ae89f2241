// riserCore: the riser's wall, a circular cylinder of diameter D about the
// moving axis of riser::RiserMotion (doc/theory.md section 3). With h the
// distance of x from the axis in the cross-section at x's height,
//   distance = D/2 - h,   normal = (x - x_c, y - y_c, 0)/h,
//   velocity = (U_r, V_r, 0),
//   overlap of a sphere of radius r: h + r - D/2
// (every point of the rigid riser moves with it). On the axis itself, where
// no direction is nearest, the normal is taken along +x.
//
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef RISERCORE_WALL_CYLINDERWALL_HPP
#define RISERCORE_WALL_CYLINDERWALL_HPP

#include "wall/wall.hpp"

#include "checks.hpp"
#include "riser/riserMotion.hpp"

#include <limits>
#include <utility>

namespace riser {

class CylinderWall final : public Wall
{
public:
    //- D: pipe diameter [m]; motion: the riser's kinematics (shared)
    CylinderWall(double D, MotionPtr motion)
    :
        D_(D), motion_(std::move(motion))
    {
        requirePositive("riser::CylinderWall", "D", D);
    }

    double diameter() const { return D_; }
    double radius() const { return 0.5*D_; }
    const RiserMotion& motion() const { return *motion_; }
    const MotionPtr& motionPtr() const { return motion_; }

    //- Distance h of x from the axis, in the cross-section
    double axisDistance(const Vector& x, double t) const
    {
        return motion_->radialOffset(x, t).norm();
    }

    double distance(const Vector& x, double t) const override
    {
        return radius() - axisDistance(x, t);
    }

    //- h + r - R: the sum of the two lengths first, then the difference
    //  of nearly equal numbers (the overlap is ~1e-3 r)
    double overlap(const Vector& x, double r, double t) const override
    {
        return axisDistance(x, t) + r - radius();
    }

    Vector normal(const Vector& x, double t) const override
    {
        const Vector r = motion_->radialOffset(x, t);
        const double h = r.norm();
        return h > 0.0 ? Vector(r/h) : Vector(1.0, 0.0, 0.0);
    }

    Vector velocity(const Vector& x, double t) const override
    {
        return motion_->velocity(x.z(), t);
    }

    //- overlap, normal and velocity as above, to the last bit, with the
    //  riser's kinematics evaluated once per time and height (the grains
    //  of a sub-step all ask at one time; a riser the same at every
    //  height is asked once for all of them)
    ContactPoint contactPoint(const Vector& x, double r, double t) const override
    {
        const double z = uniform_ ? 0.0 : x.z();
        if (!(t == t_ && z == z_))
        {
            t_ = t;
            z_ = z;
            state_ = motion_->state(z, t);
        }
        const Vector off = RiserMotion::radialOffset(x, state_);
        const double h = off.norm();
        return ContactPoint
        {
            h + r - radius(),
            h > 0.0 ? Vector(off/h) : Vector(1.0, 0.0, 0.0),
            state_.velocity
        };
    }

private:
    double D_;
    MotionPtr motion_;
    //- motion_->uniformAlongAxis()
    bool uniform_ = motion_->uniformAlongAxis();
    //- The time and height of the kinematics kept, and those (a cache: not
    //  for use from several threads at once)
    mutable double t_ = std::numeric_limits<double>::quiet_NaN(), z_ = 0.0;
    mutable AxisState state_{Vector::Zero(), Vector::Zero(), Vector::Zero()};
};

} // namespace riser

#endif
