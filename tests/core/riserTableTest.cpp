// Tests of the riser motion 'table' (src/riserCore/riser/tableMotion.hpp):
// - a polynomial motion the scheme must reproduce exactly (cubic in t,
//   quadratic in z: the quintic Hermite with fourth-order nodal
//   derivatives in time and the cubic Hermite with three-point slopes in z
//   are exact there), every derivative to round-off;
// - a table sampled from a 'modes' motion reproduces it, the error of the
//   position falling at the time interpolation's fourth order and the
//   slope's at the height interpolation's second order as the sampling is
//   refined;
// - velocity and acceleration continuous across the samples;
// - asked outside its heights or times it throws; bad tables refused; a
//   table too coarse refused with the interval it needs.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "riser/modesMotion.hpp"
#include "riser/tableMotion.hpp"

#include <gtest/gtest.h>
#include <cmath>
#include <stdexcept>

using namespace riser;

namespace {

const double twoPi = 2.0*M_PI;

//- The table of motion m sampled at heights z and times t0 + j h
std::shared_ptr<const TableMotion> sample(const RiserMotion& m, const std::vector<double>& z,
                                          double t0, double h, int N)
{
    std::vector<double> x, y;
    for (int j = 0; j < N; ++j)
    {
        for (double zi : z)
        {
            const Vector a = m.axis(zi, t0 + j*h);
            x.push_back(a.x());
            y.push_back(a.y());
        }
    }
    return std::make_shared<const TableMotion>(z, t0, h, N, x, y);
}

std::vector<double> evenly(double from, double to, int n)
{
    std::vector<double> z;
    for (int i = 0; i < n; ++i) z.push_back(from + (to - from)*i/(n - 1));
    return z;
}

} // namespace


// x = P(z) T(t), P quadratic, T cubic; y = -2 x: reproduced with every
// derivative (round-off: values O(1), derivatives by differences of
// samples spaced 0.1 s and ~1 m: 1e-12)
TEST(TableMotion, ReproducesPolynomialsOfItsOrder)
{
    auto P = [](double z) { return 1 + 0.1*z + 0.01*z*z; };
    auto Pz = [](double z) { return 0.1 + 0.02*z; };
    auto T = [](double t) { return 0.2 + 0.3*t - 0.05*t*t + 0.01*t*t*t; };
    auto Tt = [](double t) { return 0.3 - 0.1*t + 0.03*t*t; };
    auto Ttt = [](double t) { return -0.1 + 0.06*t; };
    const std::vector<double> z = {-3.0, -2.0, -0.5, 1.0, 1.2, 4.0};  // uneven
    const double t0 = 1.0, h = 0.1;
    const int N = 30;
    std::vector<double> x, y;
    for (int j = 0; j < N; ++j)
    {
        for (double zi : z)
        {
            x.push_back(P(zi)*T(t0 + j*h));
            y.push_back(-2*P(zi)*T(t0 + j*h));
        }
    }
    const TableMotion m(z, t0, h, N, x, y);
    for (double zq : {-3.0, -2.7, -0.5, 0.3, 1.1, 3.99, 4.0})
    {
        for (double tq : {1.0, 1.04, 1.5, 2.333, 3.8, 3.9})
        {
            const AxisState s = m.state(zq, tq);
            EXPECT_NEAR(s.position.x(), P(zq)*T(tq), 1e-12);
            EXPECT_NEAR(s.position.y(), -2*P(zq)*T(tq), 1e-12);
            EXPECT_NEAR(s.velocity.x(), P(zq)*Tt(tq), 1e-11);
            EXPECT_NEAR(s.acceleration.x(), P(zq)*Ttt(tq), 1e-9);
            EXPECT_NEAR(s.slope.x(), Pz(zq)*T(tq), 1e-12);
            EXPECT_NEAR(s.slopeRate.x(), Pz(zq)*Tt(tq), 1e-11);
            EXPECT_NEAR(s.curvature.x(), 0.02*T(tq), 1e-11);
            EXPECT_EQ(s.position.z(), 0.0);
        }
    }
    EXPECT_THROW(m.state(4.01, 2.0), std::out_of_range);
    EXPECT_THROW(m.state(0.0, 0.99), std::out_of_range);
    EXPECT_THROW(m.state(0.0, 3.91), std::out_of_range);
    EXPECT_THROW(m.angularFrequency(), std::domain_error);
    EXPECT_FALSE(m.uniformAlongAxis());
}

// A table of a standing mode 3 on 100 m (0.5 m at 0.5 Hz, slope 0.047):
// the position's error falls as h^4 in time (a fine height sampling, 201
// heights), the slope's as dz^2 along z (a fine time sampling)
TEST(TableMotion, ConvergesToTheMotionItSamples)
{
    const ModesMotion mode(0.0, 100.0, ModesMotion::Wave::standing,
                           {Mode{3, 0.5, twoPi*0.5, 0.3}}, {Mode{2, 0.2, twoPi*0.25, 0}});
    const std::vector<double> zq = {10.3, 37.7, 51.1, 88.8};
    const std::vector<double> tq = {2.13, 3.77, 5.51, 7.05};
    auto error = [&](const TableMotion& t, bool slope)
    {
        double e = 0;
        for (double z : zq)
        {
            for (double tt : tq)
            {
                const AxisState a = t.state(z, tt), b = mode.state(z, tt);
                e = std::max(e, slope ? (a.slope - b.slope).norm()
                                      : (a.position - b.position).norm());
            }
        }
        return e;
    };
    // in time: 20, 40, 80 samples a period of 2 s
    double previous = 0;
    for (int k = 0; k < 3; ++k)
    {
        const double h = 0.1/(1 << k);
        const auto t = sample(mode, evenly(0.0, 100.0, 2001), 0.0, h, int(10.0/h) + 1);
        const double e = error(*t, false);
        if (k > 0)
        {
            // fourth order: 16 for a halved step, at least 11
            EXPECT_GT(previous/e, 11.0) << "h = " << h;
        }
        previous = e;
        t->checkSampling();
    }
    EXPECT_LT(previous, 1e-6);
    // along z: 50, 100, 200 m of... 26, 51, 101 heights
    for (int k = 0; k < 3; ++k)
    {
        const auto t = sample(mode, evenly(0.0, 100.0, 26*(1 << k) - (1 << k) + 1), 0.0, 0.005, 2001);
        const double e = error(*t, true);
        if (k > 0)
        {
            // second order: 4 for a halved spacing, at least 3
            EXPECT_GT(previous/e, 3.0) << "heights " << t->heights().size();
        }
        previous = e;
    }
}

// Velocity and acceleration continuous across a sample (the pieces join
// in value and first two derivatives), the slope across a height
TEST(TableMotion, ContinuousAcrossSamples)
{
    const ModesMotion mode(0.0, 100.0, ModesMotion::Wave::travelling,
                           {Mode{3, 0.5, twoPi*0.5, 0.3}}, {});
    const auto t = sample(mode, evenly(0.0, 100.0, 101), 0.0, 0.05, 201);
    const double eps = 1e-9;
    for (double tj : {1.0, 2.5, 7.35})
    {
        const AxisState a = t->state(40.5, tj - eps), b = t->state(40.5, tj + eps);
        EXPECT_NEAR(a.velocity.x(), b.velocity.x(), 1e-7);
        EXPECT_NEAR(a.acceleration.x(), b.acceleration.x(), 1e-6);
    }
    for (double zi : {20.0, 55.0})
    {
        const AxisState a = t->state(zi - eps, 3.3), b = t->state(zi + eps, 3.3);
        EXPECT_NEAR(a.slope.x(), b.slope.x(), 1e-9);
        EXPECT_NEAR(a.slopeRate.x(), b.slopeRate.x(), 1e-8);
    }
}

TEST(TableMotion, RefusesBadTables)
{
    const std::vector<double> z = {0, 1, 2};
    const std::vector<double> d(3*6, 0.0);
    EXPECT_NO_THROW(TableMotion(z, 0, 0.1, 6, d, d));
    EXPECT_THROW(TableMotion({0, 2, 1}, 0, 0.1, 6, d, d), std::invalid_argument);
    EXPECT_THROW(TableMotion({0, 1, 1}, 0, 0.1, 6, d, d), std::invalid_argument);
    EXPECT_THROW(TableMotion({0}, 0, 0.1, 6, std::vector<double>(6), std::vector<double>(6)),
                 std::invalid_argument);
    EXPECT_THROW(TableMotion(z, 0, 0.1, 5, std::vector<double>(15), std::vector<double>(15)),
                 std::invalid_argument);
    EXPECT_THROW(TableMotion(z, 0, 0.0, 6, d, d), std::invalid_argument);
    EXPECT_THROW(TableMotion(z, 0, 0.1, 6, std::vector<double>(17), d), std::invalid_argument);
    std::vector<double> bad = d;
    bad[7] = NAN;
    EXPECT_THROW(TableMotion(z, 0, 0.1, 6, bad, d), std::invalid_argument);
}

// 8 samples a period: refused, naming an interval that, taken, passes
TEST(TableMotion, TooCoarseRefusedWithTheIntervalNeeded)
{
    const ModesMotion mode(0.0, 100.0, ModesMotion::Wave::standing,
                           {Mode{1, 0.5, twoPi*0.5, 0.3}}, {});
    const auto coarse = sample(mode, evenly(0.0, 100.0, 101), 0.0, 0.25, 41);
    EXPECT_GT(coarse->timeSamplingError(), TableMotion::samplingTolerance);
    try
    {
        coarse->checkSampling();
        FAIL() << "a table of 8 samples a period passed";
    }
    catch (const std::invalid_argument& e)
    {
        const std::string what = e.what();
        EXPECT_NE(what.find("sample at most every"), std::string::npos) << what;
        const double needed = std::stod(what.substr(what.find("every") + 6));
        const auto fine = sample(mode, evenly(0.0, 100.0, 101), 0.0, 0.9*needed,
                                 int(10.0/(0.9*needed)));
        EXPECT_NO_THROW(fine->checkSampling());
    }
    // along z: mode 10 on 100 m with 11 heights (1 a half wavelength... 2 a
    // wavelength) refused
    const ModesMotion wavy(0.0, 100.0, ModesMotion::Wave::standing,
                           {Mode{10, 0.05, twoPi*0.5, 0.3}}, {});
    const auto sparse = sample(wavy, evenly(0.0, 100.0, 21), 0.0, 0.05, 201);
    EXPECT_THROW(sparse->checkSampling(), std::invalid_argument);
}
