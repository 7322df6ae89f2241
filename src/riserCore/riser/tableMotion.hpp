// riserCore: the riser motion 'table' (doc/theory.md section 2.6): the
// axis' displacements x_c(z, t), y_c(z, t) sampled on a grid of heights
// z_0 < ... < z_{M-1} (any spacing) and of times t_0 < ... < t_{N-1} (a
// fixed interval h), as a riser-dynamics code writes them.
//
// In time, each height's samples are joined by quintic Hermite pieces
// whose nodal velocity and acceleration are the fourth-order central
// differences of the samples (one-sided of the same order in the two
// first and last intervals): position, velocity and acceleration are
// continuous, and the interpolation error falls as h^4. Along the riser,
// each time's samples as riser::SampleGrid joins them: cubic Hermite pieces
// whose nodal slopes are the second-order differences of the samples
// (three-point, for any spacing): the slope is continuous, the curvature
// piecewise linear in z.
//
// Sampling: a table too coarse for the motion it holds is refused
// (checkSampling). In time the fourth- and second-order acceleration
// estimates at each node differ by (h^2/12) x'''' to leading order; where
// that difference exceeds 1e-2 of the largest acceleration in the table
// (fewer than ~18 samples a period of a sinusoid), the interval needed
// (the difference scales as h^2) is named. Along z, the nodal slopes' error
// (dz^2/6) x''' (x''' from neighbouring second differences) against the
// largest slope, alike (fewer than ~26 samples a wavelength).
//
// The motion is not defined outside the table's heights and times: asked
// there it throws std::out_of_range (callers check their runs fit).
//
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef RISERCORE_RISER_TABLEMOTION_HPP
#define RISERCORE_RISER_TABLEMOTION_HPP

#include "checks.hpp"
#include "interpolation/sampleGrid.hpp"
#include "riser/riserMotion.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <utility>
#include <vector>

namespace riser {

class TableMotion final : public StateMotion
{
public:
    //- The tolerance of the sampling checks (relative)
    static constexpr double samplingTolerance = 1e-2;

    //- heights (M >= 2, increasing), times t0 + j h (N >= 6 samples), and
    //  the displacements x[j*M + i], y[j*M + i] of height i at time j
    TableMotion(std::vector<double> heights, double t0, double h, int N,
                std::vector<double> x, std::vector<double> y)
    :
        grid_(std::move(heights), "riser::TableMotion", "height"), t0_(t0), h_(h), N_(N)
    {
        const char* law = "riser::TableMotion";
        const int M = grid_.size();
        requireInRange(law, "number of times", N, 6, Bound::closed, HUGE_VAL, Bound::open);
        requireInRange(law, "t0", t0, -HUGE_VAL, Bound::open, HUGE_VAL, Bound::open);
        requireInRange(law, "time interval", h, 0.0, Bound::open, HUGE_VAL, Bound::open);
        if (x.size() != std::size_t(M)*N || y.size() != std::size_t(M)*N)
        {
            throw std::invalid_argument(std::string(law) + ": M N displacements needed");
        }
        for (const std::vector<double>* d : {&x, &y})
        {
            for (double v : *d)
            {
                requireInRange(law, "displacement", v, -HUGE_VAL, Bound::open, HUGE_VAL,
                               Bound::open);
            }
        }
        nodes_[0] = buildNodes(x);
        nodes_[1] = buildNodes(y);
        bounds();
    }

    static MotionPtr make(std::vector<double> heights, double t0, double h, int N,
                          std::vector<double> x, std::vector<double> y)
    {
        return std::make_shared<const TableMotion>(std::move(heights), t0, h, N,
                                                   std::move(x), std::move(y));
    }

    const std::vector<double>& heights() const { return grid_.points(); }
    double startTime() const { return t0_; }
    double endTime() const { return t0_ + h_*(N_ - 1); }
    double interval() const { return h_; }

    //- The largest relative sampling error estimate in time and along z
    //  (checkSampling refuses beyond samplingTolerance)
    double timeSamplingError() const { return timeError_; }
    double heightSamplingError() const { return heightError_; }

    //- std::invalid_argument naming the sampling needed, where the table
    //  is too coarse for the motion it holds
    void checkSampling() const
    {
        std::ostringstream msg;
        if (timeError_ > samplingTolerance)
        {
            msg << "riser::TableMotion: the time interval " << h_ << " s is too coarse"
                << " for the motion (fourth- and second-order accelerations differ by "
                << timeError_ << " of the largest); sample at most every "
                << h_*std::sqrt(samplingTolerance/timeError_) << " s";
            throw std::invalid_argument(msg.str());
        }
        if (heightError_ > samplingTolerance)
        {
            msg << "riser::TableMotion: the heights are too coarse for the motion"
                << " (the nodal slopes' error estimate is " << heightError_
                << " of the largest slope); sample at most every "
                << grid_.maxSpacing()*std::sqrt(samplingTolerance/heightError_)
                << " m along z";
            throw std::invalid_argument(msg.str());
        }
    }

    const char* type() const override { return "table"; }

    AxisState computeState(double z, double t) const override
    {
        const int M = grid_.size();
        if (!(grid_.contains(z) && t >= t0_ && t <= endTime()))
        {
            std::ostringstream msg;
            msg << "riser::TableMotion: (z, t) = (" << z << ", " << t << ") outside the"
                << " table's heights [" << grid_.front() << ", " << grid_.back()
                << "] m and times [" << t0_ << ", " << endTime() << "] s";
            throw std::out_of_range(msg.str());
        }
        const SampleGrid::Piece piece = grid_.piece(z);
        const int i = piece.i;
        const int j = std::min(int((t - t0_)/h_), N_ - 2);
        // the quintic's basis in time (per derivative, scaled by h^n to
        // act on the nodes' value, h velocity and h^2 acceleration), and
        // the cubic's along z
        double T[3][6];
        timeBasis((t - t0_)/h_ - j, T);
        double H[3][4];
        SampleGrid::basis(piece, H);
        AxisState st;
        for (int c = 0; c < 2; ++c)
        {
            // the four nodes of the cell: heights i, i+1 at times j, j+1
            const Node& a0 = nodes_[c][j*M + i];
            const Node& a1 = nodes_[c][j*M + i + 1];
            const Node& b0 = nodes_[c][(j + 1)*M + i];
            const Node& b1 = nodes_[c][(j + 1)*M + i + 1];
            // value and z-slope at heights i, i+1, time derivative n
            auto inTime = [&](const double (&a)[3], const double (&b)[3], int n)
            {
                const double* w = T[n];
                return w[0]*a[0] + w[1]*a[1] + w[2]*a[2] + w[3]*b[0] + w[4]*b[1] + w[5]*b[2];
            };
            double f[2][3], m[2][3];
            for (int n = 0; n < 3; ++n)
            {
                f[0][n] = inTime(a0.f, b0.f, n);
                f[1][n] = inTime(a1.f, b1.f, n);
                m[0][n] = inTime(a0.m, b0.m, n);
                m[1][n] = inTime(a1.m, b1.m, n);
            }
            auto combine = [&](int dzOrder, int n)
            {
                const double* B = H[dzOrder];
                return B[0]*f[0][n] + B[1]*m[0][n] + B[2]*f[1][n] + B[3]*m[1][n];
            };
            st.position[c] = combine(0, 0);
            st.velocity[c] = combine(0, 1);
            st.acceleration[c] = combine(0, 2);
            st.slope[c] = combine(1, 0);
            st.slopeRate[c] = combine(1, 1);
            st.curvature[c] = combine(2, 0);
        }
        return st;
    }

    double maxSpeed() const override { return maxSpeed_; }
    double maxAcceleration() const override { return maxAcceleration_; }
    double maxSlope() const override { return maxSlope_; }
    double axisOffsetBound(double) const override { return maxOffset_; }
    MotionDomain domain() const override
    {
        return MotionDomain{grid_.front(), grid_.back(), t0_, endTime()};
    }

    bool steady() const override { return maxSpeed_ == 0.0; }
    bool uniformAlongAxis() const override { return false; }

    //- A table has no one frequency
    double angularFrequency() const override
    {
        throw std::domain_error
        (
            "riser::TableMotion: a tabulated motion has no one frequency, and the"
            " riser's frequency is asked for"
        );
    }

private:
    //- Per height and time sample: value, velocity and acceleration in
    //  time, for the displacement and for its z-slope
    struct Node
    {
        double f[3], m[3];
    };

    //- The nodes of one component (x or y) of the samples d
    std::vector<Node> buildNodes(const std::vector<double>& d)
    {
        const int M = grid_.size();
        std::vector<double> slope(d.size());
        for (int j = 0; j < N_; ++j)
        {
            const auto at = [&](int k) { return d[j*M + k]; };
            for (int i = 0; i < M; ++i)
            {
                slope[j*M + i] = grid_.slope(at, i);
            }
            heightDiff_ = std::max(heightDiff_, grid_.slopeErrorEstimate(at));
        }
        std::vector<Node> nodes(d.size());
        for (int i = 0; i < M; ++i)
        {
            for (int j = 0; j < N_; ++j)
            {
                Node& n = nodes[j*M + i];
                timeDerivatives(d, i, j, n.f);
                timeDerivatives(slope, i, j, n.m);
            }
        }
        // the sampling error estimates of this component
        for (int i = 0; i < M; ++i)
        {
            for (int j = 2; j < N_ - 2; ++j)
            {
                const double a2 = (d[(j + 1)*M + i] - 2*d[j*M + i] + d[(j - 1)*M + i])/(h_*h_);
                timeDiff_ = std::max(timeDiff_, std::abs(nodes[j*M + i].f[2] - a2));
            }
        }
        return nodes;
    }

    //- Value, first and second time derivative of samples d at (i, j):
    //  fourth-order differences, central where the stencil fits, else
    //  one-sided on the five nearest samples
    void timeDerivatives(const std::vector<double>& d, int i, int j, double (&out)[3]) const
    {
        const int M = grid_.size();
        auto at = [&](int k) { return d[k*M + i]; };
        out[0] = at(j);
        // the five-point stencil k0 .. k0+4 containing j
        const int k0 = std::min(std::max(j - 2, 0), N_ - 5);
        const int p = j - k0;   // j's place in the stencil, 0..4
        // weights of the first and second derivative at place p on unit
        // spacing (Fornberg's five-point weights)
        static const double W1[5][5] =
        {
            {-25.0/12, 4, -3, 4.0/3, -1.0/4},
            {-1.0/4, -5.0/6, 3.0/2, -1.0/2, 1.0/12},
            {1.0/12, -2.0/3, 0, 2.0/3, -1.0/12},
            {-1.0/12, 1.0/2, -3.0/2, 5.0/6, 1.0/4},
            {1.0/4, -4.0/3, 3, -4, 25.0/12}
        };
        static const double W2[5][5] =
        {
            {35.0/12, -26.0/3, 19.0/2, -14.0/3, 11.0/12},
            {11.0/12, -5.0/3, 1.0/2, 1.0/3, -1.0/12},
            {-1.0/12, 4.0/3, -5.0/2, 4.0/3, -1.0/12},
            {-1.0/12, 1.0/3, 1.0/2, -5.0/3, 11.0/12},
            {11.0/12, -14.0/3, 19.0/2, -26.0/3, 35.0/12}
        };
        double d1 = 0, d2 = 0;
        for (int k = 0; k < 5; ++k)
        {
            d1 += W1[p][k]*at(k0 + k);
            d2 += W2[p][k]*at(k0 + k);
        }
        out[1] = d1/h_;
        out[2] = d2/(h_*h_);
    }

    //- The quintic Hermite basis at fraction tau of a time interval, for
    //  the value and its first two time derivatives (rows), acting on a
    //  node pair's (p0, v0, a0, p1, v1, a1): the h powers folded in
    void timeBasis(double tau, double (&T)[3][6]) const
    {
        const double t = tau, t2 = t*t, t3 = t2*t, t4 = t3*t, t5 = t4*t;
        const double B[3][6] =
        {
            {1 - 10*t3 + 15*t4 - 6*t5, t - 6*t3 + 8*t4 - 3*t5, 0.5*t2 - 1.5*t3 + 1.5*t4 - 0.5*t5,
             10*t3 - 15*t4 + 6*t5, -4*t3 + 7*t4 - 3*t5, 0.5*t3 - t4 + 0.5*t5},
            {-30*t2 + 60*t3 - 30*t4, 1 - 18*t2 + 32*t3 - 15*t4, t - 4.5*t2 + 6*t3 - 2.5*t4,
             30*t2 - 60*t3 + 30*t4, -12*t2 + 28*t3 - 15*t4, 1.5*t2 - 4*t3 + 2.5*t4},
            {-60*t + 180*t2 - 120*t3, -36*t + 96*t2 - 60*t3, 1 - 9*t + 18*t2 - 10*t3,
             60*t - 180*t2 + 120*t3, -24*t + 84*t2 - 60*t3, 3*t - 12*t2 + 10*t3}
        };
        // d^n/dt^n = (1/h^n) d^n/dtau^n; the velocity and acceleration
        // weights act on h v and h^2 a
        const double scale[3] = {1, 1/h_, 1/(h_*h_)};
        const double hPower[6] = {1, h_, h_*h_, 1, h_, h_*h_};
        for (int n = 0; n < 3; ++n)
        {
            for (int k = 0; k < 6; ++k)
            {
                T[n][k] = scale[n]*B[n][k]*hPower[k];
            }
        }
    }

    //- The bounds over the nodes of both components (hypot of the
    //  components' largest), and the relative sampling errors
    void bounds()
    {
        double mx[2][4] = {{0, 0, 0, 0}, {0, 0, 0, 0}};
        for (int c = 0; c < 2; ++c)
        {
            for (const Node& n : nodes_[c])
            {
                mx[c][0] = std::max(mx[c][0], std::abs(n.f[0]));
                mx[c][1] = std::max(mx[c][1], std::abs(n.f[1]));
                mx[c][2] = std::max(mx[c][2], std::abs(n.f[2]));
                mx[c][3] = std::max(mx[c][3], std::abs(n.m[0]));
            }
        }
        // the interpolant may overshoot its nodes: a margin of 5 % (where
        // the sampling check passes, the interpolant's acceleration is
        // within ~1e-2 of the samples' differences, and its overshoot of
        // the nodes' values smaller still)
        const double margin = 1.05;
        maxOffset_ = margin*std::hypot(mx[0][0], mx[1][0]);
        maxSpeed_ = margin*std::hypot(mx[0][1], mx[1][1]);
        maxAcceleration_ = margin*std::hypot(mx[0][2], mx[1][2]);
        maxSlope_ = margin*std::hypot(mx[0][3], mx[1][3]);
        const double aMax = std::max(mx[0][2], mx[1][2]);
        const double sMax = std::max(mx[0][3], mx[1][3]);
        timeError_ = aMax > 0 ? timeDiff_/aMax : 0.0;
        heightError_ = sMax > 0 ? heightDiff_/sMax : 0.0;
    }

    SampleGrid grid_;
    double t0_, h_;
    int N_;
    std::vector<Node> nodes_[2];
    double timeDiff_ = 0, heightDiff_ = 0;
    double timeError_ = 0, heightError_ = 0;
    double maxOffset_ = 0, maxSpeed_ = 0, maxAcceleration_ = 0, maxSlope_ = 0;
};

} // namespace riser

#endif
