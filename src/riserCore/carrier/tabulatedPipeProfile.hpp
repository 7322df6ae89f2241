// riserCore: a mean pipe flow given by samples at radii 0 = r_0 < r_1 <
// ... < r_{M-1} = R of its axial speed w, its turbulent kinetic energy k
// and its eddy viscosity nu_t (doc/theory.md section 2.7), as the utility
// riserCarrierProfile writes them from a precursor run (riserCoupledFoam
// with a RAS model, without ores) or a user from their own CFD or data.
//
// Each quantity is an even function of r joined as riser::SampleGrid
// joins samples, on the samples mirrored about the axis (-r_{M-1} ..
// r_{M-1}): cubic Hermite pieces, three-point nodal slopes, so that the
// slope is continuous and zero on the axis, and a quadratic profile (the
// laminar one) is reproduced exactly. Between the samples k and nu_t are
// kept non-negative (the cubic may undershoot where they fall steeply to
// the wall).
//
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef RISERCORE_CARRIER_TABULATEDPIPEPROFILE_HPP
#define RISERCORE_CARRIER_TABULATEDPIPEPROFILE_HPP

#include "carrier/pipeProfile.hpp"
#include "checks.hpp"
#include "interpolation/sampleGrid.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace riser {

class TabulatedPipeProfile final : public PipeProfile
{
public:
    //- R: the pipe's radius [m]; the samples at radii r (r_0 = 0, r_{M-1}
    //  within 1e-6 R of R, increasing, M >= 3): the speed w [m/s], k
    //  [m^2/s^2] >= 0 and nu_t [m^2/s] >= 0; std::invalid_argument
    //  otherwise
    TabulatedPipeProfile(double R, const std::vector<double>& r, const std::vector<double>& w,
                         const std::vector<double>& k, const std::vector<double>& nut)
    :
        R_(R),
        grid_(mirrored(R, r), "riser::TabulatedPipeProfile", "radius")
    {
        const char* law = "riser::TabulatedPipeProfile";
        const std::size_t M = r.size();
        if (w.size() != M || k.size() != M || nut.size() != M)
        {
            throw std::invalid_argument(std::string(law) + ": a speed, k and nu_t per radius");
        }
        for (std::size_t i = 0; i < M; ++i)
        {
            requireInRange(law, "speed", w[i], -HUGE_VAL, Bound::open, HUGE_VAL, Bound::open);
            requireInRange(law, "k", k[i], 0.0, Bound::closed, HUGE_VAL, Bound::open);
            requireInRange(law, "nu_t", nut[i], 0.0, Bound::closed, HUGE_VAL, Bound::open);
        }
        w_ = SampleGrid::Column(grid_, mirroredValues(w));
        k_ = SampleGrid::Column(grid_, mirroredValues(k));
        nut_ = SampleGrid::Column(grid_, mirroredValues(nut));
    }

    const char* type() const override { return "tabulated"; }
    double radius() const override { return R_; }
    double centreLineSpeed() const override { return w_.value[mid()]; }
    //- The turbulent kinetic energy k at distance r from the axis
    double turbulentEnergy(double r) const { return std::max(valueAt(k_, r)[0], 0.0); }
    //- The eddy viscosity nu_t at distance r from the axis
    double eddyViscosity(double r) const { return std::max(valueAt(nut_, r)[0], 0.0); }

protected:
    Values compute(double r) const override
    {
        const std::array<double, 3> w = valueAt(w_, r);
        return {w[0], w[1]};
    }

private:
    //- A quantity's value and derivatives at distance r from the axis
    std::array<double, 3> valueAt(const SampleGrid::Column& c, double r) const
    {
        double out[3];
        c.evaluate(grid_.piece(clamp(r)), out);
        return {out[0], out[1], out[2]};
    }

    //- The samples of a quantity mirrored about the axis (even in r)
    static std::vector<double> mirroredValues(const std::vector<double>& half)
    {
        std::vector<double> values;
        for (std::size_t i = half.size() - 1; i > 0; --i) values.push_back(half[i]);
        values.insert(values.end(), half.begin(), half.end());
        return values;
    }

    //- The radii mirrored about the axis, checked
    static std::vector<double> mirrored(double R, const std::vector<double>& r)
    {
        const char* law = "riser::TabulatedPipeProfile";
        requirePositive(law, "R", R);
        requireInRange(law, "number of radii", double(r.size()), 3.0, Bound::closed,
                       HUGE_VAL, Bound::open);
        if (r.front() != 0.0)
        {
            throw std::invalid_argument(std::string(law) + ": the first radius must be 0 (the axis)");
        }
        if (std::abs(r.back() - R) > 1e-6*R)
        {
            std::ostringstream msg;
            msg << law << ": the last radius " << r.back() << " m must be the pipe's radius "
                << R << " m (the wall)";
            throw std::invalid_argument(msg.str());
        }
        for (std::size_t i = 1; i < r.size(); ++i)
        {
            if (!(r[i] > r[i - 1]))
            {
                throw std::invalid_argument
                (
                    std::string(law) + ": the radii must increase (radius "
                  + std::to_string(i + 1) + ")"
                );
            }
        }
        std::vector<double> points = mirroredValues(r);
        for (std::size_t i = 0; i + 1 < r.size(); ++i) points[i] = -points[i];
        return points;
    }

    //- |r| within the samples (beyond the wall, the wall's)
    double clamp(double r) const { return std::min(std::abs(r), grid_.back()); }

    //- The axis' place on the mirrored grid
    int mid() const { return grid_.size()/2; }

    double R_;
    SampleGrid grid_;
    SampleGrid::Column w_, k_, nut_;
};

} // namespace riser

#endif
