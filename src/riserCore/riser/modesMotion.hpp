// riserCore: the riser motion 'modes' (doc/theory.md section 2.2), a
// tensioned riser pinned at its foot z_f and its top z_f + L_r whose axis
// moves in x and y, each a sum of its modes of vibration,
//   phi_n(z) = sin(k_n (z - z_f)),   k_n = n pi / L_r,   n = 1, 2, ...
// as standing waves,
//   x_c(z, t) = sum_n a_n sin(k_n (z - z_f)) sin(omega_n t + phase_n),
// or as waves travelling up the riser (towards +z, at omega_n / k_n),
//   x_c(z, t) = sum_n a_n sin(omega_n t + phase_n - k_n (z - z_f)),
// and y_c alike. Riser-dynamics codes report vortex-induced vibration so:
// the n-th mode at the shedding frequency cross-flow, a mode at twice it
// in-line.
//
// Besides the axis, its velocity and acceleration, a motion that varies
// along the riser has derivatives along it (AxisState): the slope
// d(x_c, y_c)/dz, its rate d(U_r, V_r)/dz and the curvature
// d^2(x_c, y_c)/dz^2, which the carrier following the riser needs.
//
// Bounds: the speed is at most hypot(sum a omega over x, the same over y),
// the acceleration hypot(sum a omega^2, ...), the slope hypot(sum a k, ...),
// reached where every mode peaks at once.
//
// Usage (constant/riserProperties, read by Foam::riserModel):
//   motion
//   {
//       type    modes;
//       foot    0;                 // z_f, the riser's foot [m]
//       length  1000;              // L_r, foot to top [m]
//       wave    standing;          // or travelling
//       x ( (5 0.5 0.2 0) );       // (n amplitude [m] frequency [Hz] phase [rad])
//       y ( );                     // either list may be empty or left out
//   }
//
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef RISERCORE_RISER_MODESMOTION_HPP
#define RISERCORE_RISER_MODESMOTION_HPP

#include "checks.hpp"
#include "riser/riserMotion.hpp"

#include <cmath>
#include <memory>
#include <utility>
#include <vector>

namespace riser {

//- One mode: a sin(k (z - z_f)) sin(omega t + phase) (standing), or
//  a sin(omega t + phase - k (z - z_f)) (travelling), k = n pi / L_r
struct Mode
{
    int number;         //!< n >= 1
    double amplitude;   //!< a [m], >= 0
    double omega;       //!< angular frequency [rad/s], >= 0
    double phase;       //!< [rad], finite
};

class ModesMotion final : public StateMotion
{
public:
    enum class Wave { standing, travelling };

    //- The riser from foot to foot + length, the modes of x_c and of y_c
    ModesMotion(double foot, double length, Wave wave, std::vector<Mode> x,
                std::vector<Mode> y)
    :
        foot_(foot), length_(length), wave_(wave), x_(std::move(x)), y_(std::move(y))
    {
        const char* law = "riser::ModesMotion";
        requireInRange(law, "foot", foot, -HUGE_VAL, Bound::open, HUGE_VAL, Bound::open);
        requireInRange(law, "length", length, 0.0, Bound::open, HUGE_VAL, Bound::open);
        for (const std::vector<Mode>* list : {&x_, &y_})
        {
            for (const Mode& m : *list)
            {
                requireInRange(law, "n", m.number, 1.0, Bound::closed, HUGE_VAL, Bound::open);
                requireNonNegative(law, "amplitude", m.amplitude);
                requireNonNegative(law, "omega", m.omega);
                requireInRange(law, "phase", m.phase, -HUGE_VAL, Bound::open,
                               HUGE_VAL, Bound::open);
            }
        }
    }

    static MotionPtr make(double foot, double length, Wave wave, std::vector<Mode> x,
                          std::vector<Mode> y)
    {
        return std::make_shared<const ModesMotion>(foot, length, wave, std::move(x),
                                                   std::move(y));
    }

    double foot() const { return foot_; }
    double length() const { return length_; }
    Wave wave() const { return wave_; }
    const std::vector<Mode>& x() const { return x_; }
    const std::vector<Mode>& y() const { return y_; }
    //- k_n = n pi / L_r [1/m]
    double wavenumber(const Mode& m) const { return m.number*M_PI/length_; }

    const char* type() const override { return "modes"; }

    AxisState computeState(double z, double t) const override
    {
        AxisState s;
        const Derivatives dx = sum(x_, z, t), dy = sum(y_, z, t);
        s.position = Vector(dx.value, dy.value, 0.0);
        s.velocity = Vector(dx.dt, dy.dt, 0.0);
        s.acceleration = Vector(dx.dtt, dy.dtt, 0.0);
        s.slope = Vector(dx.dz, dy.dz, 0.0);
        s.slopeRate = Vector(dx.dzt, dy.dzt, 0.0);
        s.curvature = Vector(dx.dzz, dy.dzz, 0.0);
        return s;
    }

    double maxSpeed() const override { return std::hypot(bound(x_, 1, 0), bound(y_, 1, 0)); }
    double maxAcceleration() const override
    {
        return std::hypot(bound(x_, 2, 0), bound(y_, 2, 0));
    }
    //- The largest slope |d(x_c, y_c)/dz| over every height and time
    double maxSlope() const override { return std::hypot(bound(x_, 0, 1), bound(y_, 0, 1)); }

    //- hypot of the sums of |a sin(omega t + phase)| (standing) or of a
    //  (travelling) over x and over y
    double axisOffsetBound(double t) const override
    {
        return std::hypot(offsetBound(x_, t), offsetBound(y_, t));
    }

    bool steady() const override
    {
        for (const std::vector<Mode>* list : {&x_, &y_})
        {
            for (const Mode& m : *list)
            {
                if (m.omega != 0.0 && m.amplitude != 0.0) return false;
            }
        }
        return true;
    }

    //- Only a riser that does not move at all is the same at every height
    bool uniformAlongAxis() const override
    {
        for (const std::vector<Mode>* list : {&x_, &y_})
        {
            for (const Mode& m : *list)
            {
                if (m.amplitude != 0.0) return false;
            }
        }
        return true;
    }

    double angularFrequency() const override
    {
        std::vector<std::pair<double, double>> terms;
        for (const std::vector<Mode>* list : {&x_, &y_})
        {
            for (const Mode& m : *list) terms.emplace_back(m.amplitude, m.omega);
        }
        return commonAngularFrequency("riser::ModesMotion: the modes", terms);
    }

private:
    //- A sum of modes and its derivatives in t and z at one point
    struct Derivatives
    {
        double value = 0, dt = 0, dtt = 0, dz = 0, dzt = 0, dzz = 0;
    };

    Derivatives sum(const std::vector<Mode>& list, double z, double t) const
    {
        Derivatives d;
        const double zeta = z - foot_;
        for (const Mode& m : list)
        {
            const double a = m.amplitude, w = m.omega, k = wavenumber(m);
            if (wave_ == Wave::standing)
            {
                const double sz = std::sin(k*zeta), cz = std::cos(k*zeta);
                const double st = std::sin(w*t + m.phase), ct = std::cos(w*t + m.phase);
                d.value += a*sz*st;
                d.dt += a*w*sz*ct;
                d.dtt -= a*w*w*sz*st;
                d.dz += a*k*cz*st;
                d.dzt += a*k*w*cz*ct;
                d.dzz -= a*k*k*sz*st;
            }
            else
            {
                const double arg = w*t + m.phase - k*zeta;
                const double s = std::sin(arg), c = std::cos(arg);
                d.value += a*s;
                d.dt += a*w*c;
                d.dtt -= a*w*w*s;
                d.dz -= a*k*c;
                d.dzt += a*k*w*s;
                d.dzz -= a*k*k*s;
            }
        }
        return d;
    }

    //- sum a omega^nt k^nz over the list
    double bound(const std::vector<Mode>& list, int nt, int nz) const
    {
        double s = 0.0;
        for (const Mode& m : list)
        {
            s += m.amplitude*std::pow(m.omega, nt)*std::pow(wavenumber(m), nz);
        }
        return s;
    }

    double offsetBound(const std::vector<Mode>& list, double t) const
    {
        double s = 0.0;
        for (const Mode& m : list)
        {
            s += wave_ == Wave::standing
                ? std::abs(m.amplitude*std::sin(m.omega*t + m.phase)) : m.amplitude;
        }
        return s;
    }

    double foot_, length_;
    Wave wave_;
    std::vector<Mode> x_, y_;
};

} // namespace riser

#endif
