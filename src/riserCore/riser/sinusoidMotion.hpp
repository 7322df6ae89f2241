// riserCore: the riser motion 'sinusoid' (doc/theory.md section 2), a rigid
// riser shaken along x:
//   x_c(t) = A sin(omega t + phi0),   y_c = 0,
//   U_r(t) = A omega cos(omega t + phi0),
//   a_r(t) = -A omega^2 sin(omega t + phi0),
// the same at every height z.
//
// Usage (constant/riserProperties, read by Foam::riserModel):
//   motion { type sinusoid; A 0.1; f 3; phi0 0; }   // or omega instead of f
// or, as before the motion models, the same entries A, f (omega), phi0 at the
// top level of the file.
//
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef RISERCORE_RISER_SINUSOIDMOTION_HPP
#define RISERCORE_RISER_SINUSOIDMOTION_HPP

#include "checks.hpp"
#include "riser/riserMotion.hpp"

#include <cmath>
#include <memory>

namespace riser {

class SinusoidMotion final : public RiserMotion
{
public:
    //- A: amplitude [m]; omega: angular frequency [rad/s]; phi0: phase [rad]
    SinusoidMotion(double A, double omega, double phi0)
    :
        A_(A), omega_(omega), phi0_(phi0)
    {
        const char* law = "riser::SinusoidMotion";
        requireNonNegative(law, "A", A);
        requireNonNegative(law, "omega", omega);
        requireInRange(law, "phi0", phi0, -HUGE_VAL, Bound::open, HUGE_VAL, Bound::open);
    }

    //- The shared motion of A, omega, phi0
    static MotionPtr make(double A, double omega, double phi0)
    {
        return std::make_shared<const SinusoidMotion>(A, omega, phi0);
    }

    //- A riser at rest
    static MotionPtr atRest() { return make(0.0, 0.0, 0.0); }

    double amplitude() const { return A_; }
    double omega() const { return omega_; }
    double phase() const { return phi0_; }

    const char* type() const override { return "sinusoid"; }

    Vector axis(double, double t) const override
    {
        return Vector(A_*std::sin(omega_*t + phi0_), 0.0, 0.0);
    }

    Vector velocity(double, double t) const override
    {
        return Vector(A_*omega_*std::cos(omega_*t + phi0_), 0.0, 0.0);
    }

    Vector acceleration(double, double t) const override
    {
        return Vector(-A_*omega_*omega_*std::sin(omega_*t + phi0_), 0.0, 0.0);
    }

    AxisState state(double z, double t) const override
    {
        return AxisState{axis(z, t), velocity(z, t), acceleration(z, t)};
    }

    //- A omega
    double maxSpeed() const override { return A_*omega_; }
    //- A omega^2
    double maxAcceleration() const override { return A_*omega_*omega_; }
    double maxSlope() const override { return 0.0; }
    //- |x_c(t)|
    double axisOffsetBound(double t) const override
    {
        return std::abs(A_*std::sin(omega_*t + phi0_));
    }

    bool steady() const override { return omega_ == 0.0; }
    bool uniformAlongAxis() const override { return true; }
    double angularFrequency() const override { return omega_; }

private:
    double A_, omega_, phi0_;
};

} // namespace riser

#endif
