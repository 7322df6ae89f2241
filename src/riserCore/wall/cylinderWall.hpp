// riserCore: the riser's wall, a circular cylinder of diameter D about the
// moving axis of riser::RiserMotion (doc/theory.md section 3). With h the
// distance of x from the axis in the cross-section,
//   distance = D/2 - h,   normal = (x - x_c, y, 0)/h,   velocity = (U_r, 0, 0),
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

namespace riser {

class CylinderWall final : public Wall
{
public:
    //- D: pipe diameter [m]; motion: the riser's kinematics
    CylinderWall(double D, const RiserMotion& motion)
    :
        D_(D), motion_(motion)
    {
        requirePositive("riser::CylinderWall", "D", D);
    }

    double diameter() const { return D_; }
    double radius() const { return 0.5*D_; }
    const RiserMotion& motion() const { return motion_; }

    //- Distance h of x from the axis, in the cross-section
    double axisDistance(const Vector& x, double t) const
    {
        return motion_.radialOffset(x, t).norm();
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
        const Vector r = motion_.radialOffset(x, t);
        const double h = r.norm();
        return h > 0.0 ? Vector(r/h) : Vector(1.0, 0.0, 0.0);
    }

    Vector velocity(const Vector&, double t) const override
    {
        return motion_.velocity(t);
    }

    //- overlap, normal and velocity as above, to the last bit, with the
    //  riser's kinematics evaluated once per time (the grains of a
    //  sub-step all ask at one time)
    ContactPoint contactPoint(const Vector& x, double r, double t) const override
    {
        if (!(t == t_))
        {
            t_ = t;
            state_ = motion_.state(t);
        }
        const Vector off = motion_.radialOffset(x, state_);
        const double h = off.norm();
        return ContactPoint
        {
            h + r - radius(),
            h > 0.0 ? Vector(off/h) : Vector(1.0, 0.0, 0.0),
            Vector(state_.velocity, 0.0, 0.0)
        };
    }

private:
    double D_;
    RiserMotion motion_;
    //- The time of the kinematics kept, and those (a cache: not for use
    //  from several threads at once)
    mutable double t_ = std::numeric_limits<double>::quiet_NaN();
    mutable RiserMotion::State state_{0.0, 0.0, 0.0};
};

} // namespace riser

#endif
