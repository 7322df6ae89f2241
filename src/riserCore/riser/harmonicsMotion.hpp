// riserCore: the riser motion 'harmonics' (doc/theory.md section 2), a rigid
// riser whose axis moves in x and y, each a sum of harmonics:
//   x_c(t) = sum_i a_i sin(omega_i t + phi_i)      (the x harmonics)
//   y_c(t) = sum_j b_j sin(omega_j t + psi_j)      (the y harmonics)
//   velocity     = sum a omega cos(omega t + phi),
//   acceleration = -sum a omega^2 sin(omega t + phi),
// the same at every height z. Vortex-induced vibration moves a riser so:
// cross-flow (y) at the shedding frequency f_s and in-line (x) at 2 f_s,
// the figure-of-eight orbit x = a sin(2 omega_s t + phi), y = b sin(omega_s t).
//
// Bounds: the speed is at most hypot(sum |a| omega over x, the same over y),
// the acceleration hypot(sum |a| omega^2 over x, the same over y), reached
// when every harmonic peaks at once.
//
// Usage (constant/riserProperties, read by Foam::riserModel):
//   motion
//   {
//       type harmonics;
//       x ( (0.01 4 0) );      // (amplitude [m] frequency [Hz] phase [rad])
//       y ( (0.05 2 0) );      // either list may be empty or left out
//   }
//
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef RISERCORE_RISER_HARMONICSMOTION_HPP
#define RISERCORE_RISER_HARMONICSMOTION_HPP

#include "checks.hpp"
#include "riser/riserMotion.hpp"

#include <cmath>
#include <memory>
#include <stdexcept>
#include <utility>
#include <vector>

namespace riser {

//- One harmonic a sin(omega t + phi)
struct Harmonic
{
    double amplitude;   //!< a [m], >= 0
    double omega;       //!< angular frequency [rad/s], >= 0
    double phase;       //!< phi [rad], finite
};

class HarmonicsMotion final : public RiserMotion
{
public:
    //- The harmonics of x_c and of y_c
    HarmonicsMotion(std::vector<Harmonic> x, std::vector<Harmonic> y)
    :
        x_(std::move(x)), y_(std::move(y))
    {
        for (const std::vector<Harmonic>* list : {&x_, &y_})
        {
            for (const Harmonic& h : *list)
            {
                const char* law = "riser::HarmonicsMotion";
                requireNonNegative(law, "amplitude", h.amplitude);
                requireNonNegative(law, "omega", h.omega);
                requireInRange(law, "phase", h.phase, -HUGE_VAL, Bound::open,
                               HUGE_VAL, Bound::open);
            }
        }
    }

    static MotionPtr make(std::vector<Harmonic> x, std::vector<Harmonic> y)
    {
        return std::make_shared<const HarmonicsMotion>(std::move(x), std::move(y));
    }

    const std::vector<Harmonic>& x() const { return x_; }
    const std::vector<Harmonic>& y() const { return y_; }

    const char* type() const override { return "harmonics"; }

    Vector axis(double, double t) const override
    {
        return Vector(sum(x_, t, 0), sum(y_, t, 0), 0.0);
    }

    Vector velocity(double, double t) const override
    {
        return Vector(sum(x_, t, 1), sum(y_, t, 1), 0.0);
    }

    Vector acceleration(double, double t) const override
    {
        return Vector(sum(x_, t, 2), sum(y_, t, 2), 0.0);
    }

    AxisState state(double z, double t) const override
    {
        return AxisState{axis(z, t), velocity(z, t), acceleration(z, t)};
    }

    double maxSpeed() const override
    {
        return std::hypot(bound(x_, 1), bound(y_, 1));
    }

    double maxAcceleration() const override
    {
        return std::hypot(bound(x_, 2), bound(y_, 2));
    }

    double maxSlope() const override { return 0.0; }

    double axisOffsetBound(double t) const override { return axis(0.0, t).norm(); }

    bool steady() const override
    {
        for (const std::vector<Harmonic>* list : {&x_, &y_})
        {
            for (const Harmonic& h : *list)
            {
                if (h.omega != 0.0 && h.amplitude != 0.0) return false;
            }
        }
        return true;
    }

    bool uniformAlongAxis() const override { return true; }

    //- The one angular frequency of the harmonics that move (0 if none
    //  does); std::domain_error if they have several
    double angularFrequency() const override
    {
        std::vector<std::pair<double, double>> terms;
        for (const std::vector<Harmonic>* list : {&x_, &y_})
        {
            for (const Harmonic& h : *list) terms.emplace_back(h.amplitude, h.omega);
        }
        return commonAngularFrequency("riser::HarmonicsMotion: the harmonics", terms);
    }

private:
    //- The n-th time derivative (n = 0, 1, 2) of sum a sin(omega t + phi)
    static double sum(const std::vector<Harmonic>& list, double t, int n)
    {
        double s = 0.0;
        for (const Harmonic& h : list)
        {
            const double arg = h.omega*t + h.phase;
            switch (n)
            {
                case 0: s += h.amplitude*std::sin(arg); break;
                case 1: s += h.amplitude*h.omega*std::cos(arg); break;
                default: s -= h.amplitude*h.omega*h.omega*std::sin(arg); break;
            }
        }
        return s;
    }

    //- The largest n-th derivative of the sum: sum a omega^n, each term
    //  multiplied in the sinusoid's order ((a omega) omega)
    static double bound(const std::vector<Harmonic>& list, int n)
    {
        double s = 0.0;
        for (const Harmonic& h : list)
        {
            double term = h.amplitude;
            for (int k = 0; k < n; ++k)
            {
                term *= h.omega;
            }
            s += term;
        }
        return s;
    }

    std::vector<Harmonic> x_, y_;
};

} // namespace riser

#endif
