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
        w_ = Column(grid_, w);
        k_ = Column(grid_, k);
        nut_ = Column(grid_, nut);
    }

    const char* type() const override { return "tabulated"; }
    double radius() const override { return R_; }
    double centreLineSpeed() const override { return w_.value[mid()]; }
    //- The turbulent kinetic energy k at distance r from the axis
    double turbulentEnergy(double r) const { return std::max(k_.at(grid_, clamp(r), 0), 0.0); }
    //- The eddy viscosity nu_t at distance r from the axis
    double eddyViscosity(double r) const { return std::max(nut_.at(grid_, clamp(r), 0), 0.0); }

protected:
    Values compute(double r) const override
    {
        const double x = clamp(r);
        return {w_.at(grid_, x, 0), w_.at(grid_, x, 1)};
    }

private:
    //- One quantity's samples on the mirrored grid and their nodal slopes
    struct Column
    {
        std::vector<double> value, slope;

        Column() = default;
        Column(const SampleGrid& grid, const std::vector<double>& half)
        {
            const int M = static_cast<int>(half.size());
            for (int i = M - 1; i > 0; --i) value.push_back(half[i]);
            value.insert(value.end(), half.begin(), half.end());
            const auto at = [&](int j) { return value[j]; };
            for (int j = 0; j < grid.size(); ++j) slope.push_back(grid.slope(at, j));
        }

        //- The value (derivative 0) or the slope (1) at r >= 0
        double at(const SampleGrid& grid, double r, int derivative) const
        {
            const SampleGrid::Piece p = grid.piece(r);
            double H[3][4];
            SampleGrid::basis(p, H);
            const double* B = H[derivative];
            return B[0]*value[p.i] + B[1]*slope[p.i] + B[2]*value[p.i + 1]
                 + B[3]*slope[p.i + 1];
        }
    };

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
        std::vector<double> points;
        for (std::size_t i = r.size() - 1; i > 0; --i) points.push_back(-r[i]);
        points.insert(points.end(), r.begin(), r.end());
        return points;
    }

    //- |r| within the samples (beyond the wall, the wall's)
    double clamp(double r) const { return std::min(std::abs(r), grid_.back()); }

    //- The axis' place on the mirrored grid
    int mid() const { return grid_.size()/2; }

    double R_;
    SampleGrid grid_;
    Column w_, k_, nut_;
};

} // namespace riser

#endif
