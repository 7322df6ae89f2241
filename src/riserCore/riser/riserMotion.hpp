// riserCore: the riser's motion (doc/theory.md section 2), the one thing
// every caller asks for the riser's axis, its velocity or acceleration, or a
// change of frame. The riser's axis is parallel to z; at height z and time t
// it passes through (x_c, y_c) and moves with (U_r, V_r):
//   axis(z, t)         = (x_c, y_c, 0)
//   velocity(z, t)     = (U_r, V_r, 0)        the wall's at that height
//   acceleration(z, t) = (dU_r/dt, dV_r/dt, 0)
// The riser frame translates with the axis: a position relative to the
// riser is x - axis(x_z, t), a velocity relative to it v - velocity(x_z, t),
// both asked at the point's own height x_z. A motion that varies along the
// riser (riser::ModesMotion) also has derivatives along z: the slope
// d(x_c, y_c)/dz, its rate of change d(U_r, V_r)/dz, and the curvature
// d^2(x_c, y_c)/dz^2 (zero where the motion is the same at every height).
//
// A motion is a run-time selected model (riser::SinusoidMotion,
// riser::HarmonicsMotion, riser::ModesMotion); it is immutable, and the flow, its wall and the
// OpenFOAM layer share one instance (MotionPtr). A virtual call per
// evaluation is the price of the choice: next to the sines it evaluates it
// is small, and no evaluation allocates.
//
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef RISERCORE_RISER_RISERMOTION_HPP
#define RISERCORE_RISER_RISERMOTION_HPP

#include "vector.hpp"

#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace riser {

//- Where a motion is known: every height and time, but for a tabulated
//  one (riser::TableMotion), which throws std::out_of_range beyond
struct MotionDomain
{
    double zMin = -HUGE_VAL, zMax = HUGE_VAL;   //!< heights [m]
    double tMin = -HUGE_VAL, tMax = HUGE_VAL;   //!< times [s]
};

//- The axis' kinematics at one height and time (z components zero)
struct AxisState
{
    Vector position = Vector::Zero();       //!< (x_c, y_c, 0) [m]
    Vector velocity = Vector::Zero();       //!< (U_r, V_r, 0) [m/s]
    Vector acceleration = Vector::Zero();   //!< (dU_r/dt, dV_r/dt, 0) [m/s^2]
    Vector slope = Vector::Zero();          //!< d(x_c, y_c)/dz [-]
    Vector slopeRate = Vector::Zero();      //!< d(U_r, V_r)/dz [1/s]
    Vector curvature = Vector::Zero();      //!< d^2(x_c, y_c)/dz^2 [1/m]
};

class RiserMotion
{
public:
    virtual ~RiserMotion() = default;

    //- The model's name in constant/riserProperties (sinusoid, harmonics)
    virtual const char* type() const = 0;

    //- The axis point (x_c, y_c, 0) at height z
    virtual Vector axis(double z, double t) const = 0;
    //- The riser's velocity at height z: every point of its cross-section
    //  moves so
    virtual Vector velocity(double z, double t) const = 0;
    //- The riser's acceleration at height z
    virtual Vector acceleration(double z, double t) const = 0;
    //- axis, velocity and acceleration at (z, t), to the last bit, for
    //  callers that ask for several of them at once
    virtual AxisState state(double z, double t) const = 0;

    //- Bounds over every height and time: the largest speed and
    //  acceleration of the riser (what the contact planner allows for)
    virtual double maxSpeed() const = 0;
    virtual double maxAcceleration() const = 0;
    //- The largest slope |d(x_c, y_c)/dz| over every height and time
    virtual double maxSlope() const = 0;
    //- The largest distance |(x_c, y_c)| of the axis from the z axis over
    //  every height at time t
    virtual double axisOffsetBound(double t) const = 0;

    //- The heights and times where the motion is known (callers check
    //  that their runs fit before they start)
    virtual MotionDomain domain() const { return MotionDomain(); }

    //- The kinematics are the same at every time (a riser at rest, or one
    //  standing aside)
    virtual bool steady() const = 0;
    //- The kinematics are the same at every height (a rigid riser)
    virtual bool uniformAlongAxis() const = 0;

    //- The motion's one angular frequency [rad/s] (0 at rest), for the
    //  callers that need "the" frequency (the Michaelides-Roig Basset
    //  coefficient, the sweeps); std::domain_error for a motion of several
    //  frequencies, whose callers must say what they mean instead
    virtual double angularFrequency() const = 0;
    //- The same in Hz
    double frequency() const { return angularFrequency()/(2.0*M_PI); }

    //- Lab position to the riser frame (relative to the axis at its height)
    Vector toRiserFrame(const Vector& x, double t) const { return x - axis(x.z(), t); }
    //- Riser-frame position to the lab
    Vector toLabFrame(const Vector& x, double t) const { return x + axis(x.z(), t); }
    //- Lab velocity v at x to the velocity relative to the riser: the rate
    //  of change of x - axis(x_z, t) along the path, v - U_r - v_z s (the
    //  slope s of a riser that varies along z: a body rising along the
    //  sloping axis keeps its offset from it)
    Vector relativeVelocity(const Vector& x, const Vector& v, double t) const
    {
        if (!uniformAlongAxis())
        {
            const AxisState s = state(x.z(), t);
            return v - s.velocity - v.z()*s.slope;
        }
        return v - velocity(x.z(), t);
    }
    //- Velocity relative to the riser at x to the lab's
    Vector labVelocity(const Vector& x, const Vector& v, double t) const
    {
        if (!uniformAlongAxis())
        {
            const AxisState s = state(x.z(), t);
            return v + s.velocity + v.z()*s.slope;
        }
        return v + velocity(x.z(), t);
    }

    //- Offset of x from the axis in the cross-section (z component zero)
    Vector radialOffset(const Vector& x, double t) const
    {
        return offsetFromAxis(x, axis(x.z(), t));
    }

    //- The same, with the axis' kinematics s = state(x_z, t)
    static Vector radialOffset(const Vector& x, const AxisState& s)
    {
        return offsetFromAxis(x, s.position);
    }

private:
    //- Offset of x from the axis point a (y_c = 0 subtracts exactly)
    static Vector offsetFromAxis(const Vector& x, const Vector& a)
    {
        return Vector(x.x() - a.x(), x.y() - a.y(), 0.0);
    }
};

//- A motion whose kinematics at a height and time are computed together
//  (riser::ModesMotion, riser::TableMotion): the axis, its velocity and
//  acceleration are parts of its state, and the last state asked is kept
//  (the carrier and the wall of a particle ask at one height and time in
//  turn; a cache: not for use from several threads at once)
class StateMotion : public RiserMotion
{
public:
    Vector axis(double z, double t) const final { return state(z, t).position; }
    Vector velocity(double z, double t) const final { return state(z, t).velocity; }
    Vector acceleration(double z, double t) const final { return state(z, t).acceleration; }

    AxisState state(double z, double t) const final
    {
        if (!(z == lastZ_ && t == lastT_))
        {
            last_ = computeState(z, t);
            lastZ_ = z;
            lastT_ = t;
        }
        return last_;
    }

protected:
    //- The state at (z, t), every part of it
    virtual AxisState computeState(double z, double t) const = 0;

private:
    mutable double lastZ_ = NAN, lastT_ = NAN;
    mutable AxisState last_;
};

//- The shared, immutable motion of a flow, its wall and their copies
using MotionPtr = std::shared_ptr<const RiserMotion>;

//- The one angular frequency of the terms (amplitude, omega) that move (0
//  if none does); std::domain_error, naming what, if they have several
inline double commonAngularFrequency
(
    const std::string& what,
    const std::vector<std::pair<double, double>>& terms
)
{
    double omega = 0.0;
    for (const std::pair<double, double>& term : terms)
    {
        if (term.first == 0.0 || term.second == 0.0) continue;
        if (omega != 0.0 && term.second != omega)
        {
            throw std::domain_error
            (
                what + " have several frequencies, and the riser's frequency"
                " is asked for"
            );
        }
        omega = term.second;
    }
    return omega;
}

} // namespace riser

#endif
