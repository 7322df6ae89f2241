// riserCore: samples at points z_0 < ... < z_{M-1} of a coordinate (any
// spacing), joined by cubic Hermite pieces whose nodal slopes are the
// second-order (three-point) differences of the samples: the slope is
// continuous, the second derivative piecewise linear (doc/theory.md
// section 2.6). The tabulated riser motion (riser::TableMotion) and mode
// shapes (riser::ModeShapes) join their samples along the riser so, the
// tabulated pipe profile (riser::TabulatedPipeProfile) across the pipe.
//
// The samples are any indexable sequence at(k), k = 0 .. M-1 (a column of
// a table, one time of a motion table); a Column keeps one quantity's
// samples with their nodal slopes and evaluates its cubic. Sampling: the nodal slopes' error
// is (dz^2/6) f''' to leading order, estimated from the change of
// neighbouring second differences (slopeErrorEstimate); callers refuse a
// table whose estimate exceeds their tolerance of the largest slope.
//
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef RISERCORE_INTERPOLATION_SAMPLEGRID_HPP
#define RISERCORE_INTERPOLATION_SAMPLEGRID_HPP

#include "checks.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace riser {

class SampleGrid
{
public:
    //- The piece holding a point: points i, i+1, its length dz and the
    //  fraction s of it
    struct Piece
    {
        int i;
        double dz, s;
    };

    //- points (M >= 2, increasing, finite); law names the caller and
    //  point the coordinate (height, radius) in its std::invalid_argument
    SampleGrid(std::vector<double> points, const char* law, const std::string& point)
    :
        z_(std::move(points))
    {
        const int M = size();
        requireInRange(law, "number of samples", M, 2, Bound::closed, HUGE_VAL, Bound::open);
        for (int i = 0; i < M; ++i)
        {
            requireInRange(law, point.c_str(), z_[i], -HUGE_VAL, Bound::open, HUGE_VAL,
                           Bound::open);
            if (i > 0 && !(z_[i] > z_[i - 1]))
            {
                throw std::invalid_argument
                (
                    std::string(law) + ": the samples' " + point + " must increase ("
                  + point + " " + std::to_string(i) + ")"
                );
            }
        }
        for (int i = 0; i + 1 < M; ++i)
        {
            maxSpacing_ = std::max(maxSpacing_, z_[i + 1] - z_[i]);
        }
    }

    int size() const { return static_cast<int>(z_.size()); }
    const std::vector<double>& points() const { return z_; }
    double front() const { return z_.front(); }
    double back() const { return z_.back(); }
    double maxSpacing() const { return maxSpacing_; }
    bool contains(double z) const { return z >= z_.front() && z <= z_.back(); }

    //- The piece of a point within the grid (the last one at its end)
    Piece piece(double z) const
    {
        const int M = size();
        const int i = std::min
        (
            int(std::upper_bound(z_.begin(), z_.end(), z) - z_.begin()) - 1, M - 2
        );
        const double dz = z_[i + 1] - z_[i];
        return Piece{i, dz, (z - z_[i])/dz};
    }

    //- The cubic Hermite basis of a piece for the value, the slope and the
    //  curvature (rows), acting on (f_i, m_i, f_i+1, m_i+1): the samples
    //  and nodal slopes at its two ends
    static void basis(const Piece& p, double (&H)[3][4])
    {
        const double s = p.s, dz = p.dz, s2 = s*s, s3 = s2*s;
        const double B[3][4] =
        {
            {2*s3 - 3*s2 + 1, (s3 - 2*s2 + s)*dz, -2*s3 + 3*s2, (s3 - s2)*dz},
            {(6*s2 - 6*s)/dz, 3*s2 - 4*s + 1, (-6*s2 + 6*s)/dz, 3*s2 - 2*s},
            {(12*s - 6)/(dz*dz), (6*s - 4)/dz, (-12*s + 6)/(dz*dz), (6*s - 2)/dz}
        };
        std::copy(&B[0][0], &B[0][0] + 12, &H[0][0]);
    }

    //- One quantity's samples at the grid's points and their nodal slopes
    struct Column
    {
        std::vector<double> value, slope;

        Column() = default;

        //- samples: one a point of grid
        Column(const SampleGrid& grid, std::vector<double> samples)
        :
            value(std::move(samples))
        {
            const auto at = [this](int k) { return value[k]; };
            for (int i = 0; i < grid.size(); ++i) slope.push_back(grid.slope(at, i));
        }

        //- The value, the slope and the second derivative in a piece
        void evaluate(const Piece& p, double (&out)[3]) const
        {
            double H[3][4];
            basis(p, H);
            for (int d = 0; d < 3; ++d)
            {
                out[d] = H[d][0]*value[p.i] + H[d][1]*slope[p.i] + H[d][2]*value[p.i + 1]
                       + H[d][3]*slope[p.i + 1];
            }
        }
    };

    //- The nodal slope at point i of the samples at(k): the derivative
    //  of the parabola through three neighbouring samples (one-sided at
    //  the ends; the chord of two points)
    template<class Samples>
    double slope(const Samples& at, int i) const
    {
        const int M = size();
        if (M == 2) return (at(1) - at(0))/(z_[1] - z_[0]);
        const int k0 = std::min(std::max(i - 1, 0), M - 3);
        const double za = z_[k0], zb = z_[k0 + 1], zc = z_[k0 + 2], x = z_[i];
        const double La = ((x - zb) + (x - zc))/((za - zb)*(za - zc));
        const double Lb = ((x - za) + (x - zc))/((zb - za)*(zb - zc));
        const double Lc = ((x - za) + (x - zb))/((zc - za)*(zc - zb));
        return La*at(k0) + Lb*at(k0 + 1) + Lc*at(k0 + 2);
    }

    //- The largest estimate of the nodal slopes' error, (dz^2/6) f''',
    //  from the change of neighbouring second differences of at(k)
    template<class Samples>
    double slopeErrorEstimate(const Samples& at) const
    {
        double e = 0.0;
        for (int i = 1; i + 2 < size(); ++i)
        {
            const double dz = std::max(z_[i + 1] - z_[i], z_[i] - z_[i - 1]);
            const double change = curvature(at, i) - curvature(at, i - 1);
            e = std::max(e, dz*std::abs(change)/6);
        }
        return e;
    }

private:
    //- The second difference of at over the points i, i+1, i+2: the
    //  second derivative about z_(i+1)
    template<class Samples>
    double curvature(const Samples& at, int i) const
    {
        const double h0 = z_[i + 1] - z_[i], h1 = z_[i + 2] - z_[i + 1];
        const double s0 = (at(i + 1) - at(i))/h0;
        const double s1 = (at(i + 2) - at(i + 1))/h1;
        return 2*(s1 - s0)/(h0 + h1);
    }

    std::vector<double> z_;
    double maxSpacing_ = 0;
};

} // namespace riser

#endif
