// riserCore: the riser's kinematics (doc/theory.md section 2). The riser is
// a rigid pipe whose axis is parallel to z and moves sideways along x:
//   x_c(t) = A sin(omega t + phi0),   U_r(t) = A omega cos(omega t + phi0),
//   a_r(t) = -A omega^2 sin(omega t + phi0).
// The riser frame translates with the axis: a position relative to the
// riser is x - (x_c, 0, 0), a velocity relative to it v - (U_r, 0, 0).
// Every caller that needs the axis, the riser's velocity or acceleration,
// or a change of frame asks this type.
//
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef RISERCORE_RISER_RISERMOTION_HPP
#define RISERCORE_RISER_RISERMOTION_HPP

#include "checks.hpp"
#include "vector.hpp"

#include <cmath>

namespace riser {

class RiserMotion
{
public:
    //- A: amplitude [m]; omega: angular frequency [rad/s]; phi0: phase [rad]
    RiserMotion(double A, double omega, double phi0)
    :
        A_(A), omega_(omega), phi0_(phi0)
    {
        const char* law = "riser::RiserMotion";
        requireNonNegative(law, "A", A);
        requireNonNegative(law, "omega", omega);
        requireInRange(law, "phi0", phi0, -HUGE_VAL, Bound::open, HUGE_VAL, Bound::open);
    }

    //- A riser at rest
    static RiserMotion atRest() { return RiserMotion(0.0, 0.0, 0.0); }

    double amplitude() const { return A_; }
    double omega() const { return omega_; }
    double frequency() const { return omega_/(2.0*M_PI); }
    double phase() const { return phi0_; }
    //- The largest speed of the riser, A omega
    double maxSpeed() const { return A_*omega_; }
    //- The largest acceleration of the riser, A omega^2
    double maxAcceleration() const { return A_*omega_*omega_; }

    //- Axis position x_c(t) (the axis passes through (x_c, 0, z))
    double axisPosition(double t) const { return A_*std::sin(omega_*t + phi0_); }
    //- Riser velocity U_r(t) along x
    double riserVelocity(double t) const { return A_*omega_*std::cos(omega_*t + phi0_); }
    //- Riser acceleration dU_r/dt along x
    double riserAcceleration(double t) const
    {
        return -A_*omega_*omega_*std::sin(omega_*t + phi0_);
    }

    //- The point (x_c, 0, 0) of the axis
    Vector axis(double t) const { return Vector(axisPosition(t), 0.0, 0.0); }
    //- The riser's velocity (U_r, 0, 0): every point of it moves so
    Vector velocity(double t) const { return Vector(riserVelocity(t), 0.0, 0.0); }
    //- The riser's acceleration (a_r, 0, 0)
    Vector acceleration(double t) const { return Vector(riserAcceleration(t), 0.0, 0.0); }

    //- Lab position to the riser frame (relative to the axis point (x_c, 0, 0))
    Vector toRiserFrame(const Vector& x, double t) const { return x - axis(t); }
    //- Riser-frame position to the lab
    Vector toLabFrame(const Vector& x, double t) const { return x + axis(t); }
    //- Lab velocity to the velocity relative to the riser
    Vector relativeVelocity(const Vector& v, double t) const { return v - velocity(t); }
    //- Velocity relative to the riser to the lab's
    Vector labVelocity(const Vector& v, double t) const { return v + velocity(t); }

    //- The riser's kinematics at one time t, for callers that ask for
    //  several of them at that time: axisPosition(t), riserVelocity(t)
    //  and riserAcceleration(t), to the last bit
    struct State
    {
        double axisPosition;    //!< x_c(t) [m]
        double velocity;        //!< U_r(t) [m/s]
        double acceleration;    //!< a_r(t) [m/s^2]
    };

    State state(double t) const
    {
        return State{axisPosition(t), riserVelocity(t), riserAcceleration(t)};
    }

    //- Offset of x from the axis in the cross-section (z component zero)
    Vector radialOffset(const Vector& x, double t) const
    {
        return offsetFromAxis(x, axisPosition(t));
    }

    //- The same, with the riser's kinematics s = state(t) at the time
    Vector radialOffset(const Vector& x, const State& s) const
    {
        return offsetFromAxis(x, s.axisPosition);
    }

private:
    //- Offset of x from the axis at x_c
    static Vector offsetFromAxis(const Vector& x, double xc)
    {
        return Vector(x.x() - xc, x.y(), 0.0);
    }

    double A_, omega_, phi0_;
};

} // namespace riser

#endif
