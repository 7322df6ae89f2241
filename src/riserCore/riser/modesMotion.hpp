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
// Tabulated shapes (ModeShapes): a riser whose tension varies with depth,
// or that has bending stiffness, vibrates in shapes that are not sines; a
// riser-dynamics code's eigen-analysis gives them as phi_n at heights
// z_0 < ... < z_{M-1}. Mode n then takes the n-th column, joined along z as
// riser::SampleGrid joins samples (slope continuous, curvature piecewise
// linear), as a standing wave a_n phi_n(z) sin(omega_n t + phase_n); the
// riser is known at the table's heights only (std::out_of_range beyond).
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
// or, with tabulated shapes (in place of foot, length and wave):
//       shapes ( (0 0 0) (10 0.031 0.063) ... );   // (z phi_1 phi_2 ...)
//
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef RISERCORE_RISER_MODESMOTION_HPP
#define RISERCORE_RISER_MODESMOTION_HPP

#include "checks.hpp"
#include "interpolation/sampleGrid.hpp"
#include "riser/riserMotion.hpp"

#include <array>
#include <cmath>
#include <memory>
#include <sstream>
#include <stdexcept>
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

//- Mode shapes phi_n(z) tabulated at heights (column n - 1: mode n),
//  joined along z as riser::SampleGrid joins samples
class ModeShapes
{
public:
    //- The tolerance of the sampling check (relative), the motion table's
    static constexpr double samplingTolerance = 1e-2;

    //- heights (M >= 2, increasing) and columns[n - 1][i]: phi_n at height
    //  i, finite; std::invalid_argument otherwise, or where the heights are
    //  too coarse for a shape (naming the spacing needed)
    ModeShapes(std::vector<double> heights, std::vector<std::vector<double>> columns)
    :
        grid_(std::move(heights), "riser::ModeShapes", "height")
    {
        const char* law = "riser::ModeShapes";
        requireInRange(law, "number of shapes", double(columns.size()), 1.0, Bound::closed,
                       HUGE_VAL, Bound::open);
        double error = 0.0;
        for (std::vector<double>& phi : columns)
        {
            if (phi.size() != std::size_t(grid_.size()))
            {
                throw std::invalid_argument(std::string(law) + ": a value per height needed");
            }
            for (double v : phi)
            {
                requireInRange(law, "shape value", v, -HUGE_VAL, Bound::open, HUGE_VAL,
                               Bound::open);
            }
            shapes_.emplace_back(grid_, std::move(phi));
            const SampleGrid::Column& c = shapes_.back();
            double maxValue = 0.0, maxSlope = 0.0;
            for (int i = 0; i < grid_.size(); ++i)
            {
                maxValue = std::max(maxValue, std::abs(c.value[i]));
                maxSlope = std::max(maxSlope, std::abs(c.slope[i]));
            }
            if (maxSlope > 0)
            {
                const auto at = [&](int k) { return c.value[k]; };
                error = std::max(error, grid_.slopeErrorEstimate(at)/maxSlope);
            }
            // the interpolant may overshoot its nodes: the motion table's
            // margin of 5 %
            maxAbs_.push_back({1.05*maxValue, 1.05*maxSlope});
        }
        if (error > samplingTolerance)
        {
            std::ostringstream msg;
            msg << law << ": the heights are too coarse for the shapes (the nodal slopes'"
                << " error estimate is " << error << " of the largest slope); sample at most"
                << " every " << grid_.maxSpacing()*std::sqrt(samplingTolerance/error)
                << " m along z";
            throw std::invalid_argument(msg.str());
        }
    }

    int count() const { return static_cast<int>(shapes_.size()); }
    const SampleGrid& grid() const { return grid_; }

    //- phi_n, its slope and its curvature in a piece of the grid
    void evaluate(int n, const SampleGrid::Piece& p, double (&out)[3]) const
    {
        shapes_[n - 1].evaluate(p, out);
    }

    //- Bounds of |phi_n| (nz = 0) and of its slope (nz = 1) over the riser
    double maxAbs(int n, int nz) const { return maxAbs_[n - 1][nz]; }

private:
    SampleGrid grid_;
    std::vector<SampleGrid::Column> shapes_;
    std::vector<std::array<double, 2>> maxAbs_;
};

using ShapesPtr = std::shared_ptr<const ModeShapes>;

class ModesMotion final : public StateMotion
{
public:
    enum class Wave { standing, travelling };

    //- The riser from foot to foot + length, the modes of x_c and of y_c;
    //  with shapes, the modes' tabulated shapes (standing waves, the riser
    //  from the table's first height to its last: foot and length are
    //  those)
    ModesMotion(double foot, double length, Wave wave, std::vector<Mode> x,
                std::vector<Mode> y, ShapesPtr shapes = nullptr)
    :
        foot_(shapes ? shapes->grid().front() : foot),
        length_(shapes ? shapes->grid().back() - shapes->grid().front() : length),
        wave_(wave), x_(std::move(x)), y_(std::move(y)), shapes_(std::move(shapes))
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
                if (shapes_ && m.number > shapes_->count())
                {
                    throw std::invalid_argument
                    (
                        std::string(law) + ": mode " + std::to_string(m.number)
                      + " has no shape: the shapes' table has "
                      + std::to_string(shapes_->count())
                    );
                }
            }
        }
        if (shapes_ && wave_ != Wave::standing)
        {
            throw std::invalid_argument
            (
                std::string(law) + ": tabulated shapes are standing waves"
            );
        }
    }

    static MotionPtr make(double foot, double length, Wave wave, std::vector<Mode> x,
                          std::vector<Mode> y, ShapesPtr shapes = nullptr)
    {
        return std::make_shared<const ModesMotion>(foot, length, wave, std::move(x),
                                                   std::move(y), std::move(shapes));
    }

    double foot() const { return foot_; }
    double length() const { return length_; }
    Wave wave() const { return wave_; }
    const std::vector<Mode>& x() const { return x_; }
    const std::vector<Mode>& y() const { return y_; }
    //- The tabulated shapes (null: the sines)
    const ShapesPtr& shapes() const { return shapes_; }
    //- k_n = n pi / L_r [1/m]
    double wavenumber(const Mode& m) const { return m.number*M_PI/length_; }

    const char* type() const override { return "modes"; }

    //- Tabulated shapes are known at their heights only
    MotionDomain domain() const override
    {
        MotionDomain d;
        if (shapes_)
        {
            d.zMin = shapes_->grid().front();
            d.zMax = shapes_->grid().back();
        }
        return d;
    }

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
        if (shapes_) return tabulatedSum(list, z, t);
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

    //- The sum of standing modes of tabulated shapes at one point
    Derivatives tabulatedSum(const std::vector<Mode>& list, double z, double t) const
    {
        if (!shapes_->grid().contains(z))
        {
            std::ostringstream msg;
            msg << "riser::ModesMotion: height " << z << " m outside the shapes' heights ["
                << shapes_->grid().front() << ", " << shapes_->grid().back() << "] m";
            throw std::out_of_range(msg.str());
        }
        const SampleGrid::Piece piece = shapes_->grid().piece(z);
        Derivatives d;
        for (const Mode& m : list)
        {
            double phi[3];
            shapes_->evaluate(m.number, piece, phi);
            const double a = m.amplitude, w = m.omega;
            const double st = std::sin(w*t + m.phase), ct = std::cos(w*t + m.phase);
            d.value += a*phi[0]*st;
            d.dt += a*w*phi[0]*ct;
            d.dtt -= a*w*w*phi[0]*st;
            d.dz += a*phi[1]*st;
            d.dzt += a*w*phi[1]*ct;
            d.dzz += a*phi[2]*st;
        }
        return d;
    }

    //- The bound of |phi_n| (nz = 0) or of its slope (nz = 1): k_n^nz of
    //  a sine, the nodes' of a tabulated shape
    double shapeBound(const Mode& m, int nz) const
    {
        return shapes_ ? shapes_->maxAbs(m.number, nz) : std::pow(wavenumber(m), nz);
    }

    //- sum a omega^nt (bound of the shape's nz-th z derivative) over the list
    double bound(const std::vector<Mode>& list, int nt, int nz) const
    {
        double s = 0.0;
        for (const Mode& m : list)
        {
            s += m.amplitude*std::pow(m.omega, nt)*shapeBound(m, nz);
        }
        return s;
    }

    double offsetBound(const std::vector<Mode>& list, double t) const
    {
        double s = 0.0;
        for (const Mode& m : list)
        {
            s += wave_ == Wave::standing
                ? std::abs(m.amplitude*std::sin(m.omega*t + m.phase))*shapeBound(m, 0)
                : m.amplitude;
        }
        return s;
    }

    double foot_, length_;
    Wave wave_;
    std::vector<Mode> x_, y_;
    ShapesPtr shapes_;
};

} // namespace riser

#endif
