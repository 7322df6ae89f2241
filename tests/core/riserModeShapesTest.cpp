// Tests of the tabulated mode shapes of the riser motion 'modes'
// (riser::ModeShapes in src/riserCore/riser/modesMotion.hpp):
// - a quadratic shape on uneven heights is reproduced to round-off (the
//   three-point nodal slopes and the cubic pieces are exact for it), with
//   its time factor a sin(omega t + phase);
// - the sines sampled at M heights converge to the closed-form modes at
//   the interpolation's orders: 3 in the position (the nodal slopes' error
//   dz^2 f'''/6 times a piece's length), 2 in the slope, 1 in the
//   curvature (piecewise linear);
// - the bounds hold over a dense sampling; the domain is the table's;
// - bad shapes are refused (heights, values, columns, a travelling wave,
//   a table too coarse, naming the spacing needed), and a height beyond
//   the table throws std::out_of_range.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "riser/modesMotion.hpp"

#include <gtest/gtest.h>
#include <cmath>
#include <stdexcept>
#include <string>

using namespace riser;

namespace {

const double twoPi = 2.0*M_PI;
using W = ModesMotion::Wave;

// shapes sin(n pi (z - z0)/L), n = 1 .. columns, at M heights from z0 to
// z0 + L, evenly spaced
ShapesPtr sampledSines(double z0, double L, int M, int columns)
{
    std::vector<double> z;
    std::vector<std::vector<double>> phi(columns);
    for (int i = 0; i < M; ++i)
    {
        z.push_back(z0 + L*i/(M - 1));
        for (int n = 1; n <= columns; ++n)
        {
            phi[n - 1].push_back(std::sin(n*M_PI*(z.back() - z0)/L));
        }
    }
    return std::make_shared<const ModeShapes>(z, phi);
}

} // namespace


TEST(ModeShapes, QuadraticShapeReproduced)
{
    // heights of uneven spacing; phi_1 = 1 + 0.3 u - 0.02 u^2, u = z - 5
    std::vector<double> z{5.0, 5.7, 7.1, 9.0, 9.4, 12.2, 15.0};
    std::vector<double> phi;
    auto f = [](double zz) { const double u = zz - 5; return 1 + 0.3*u - 0.02*u*u; };
    for (double zz : z) phi.push_back(f(zz));
    const ModesMotion m(0, 1, W::standing, {Mode{1, 0.4, twoPi*0.3, 0.2}}, {},
                        std::make_shared<const ModeShapes>(z, std::vector<std::vector<double>>{phi}));
    for (double zz : {5.0, 5.3, 6.6, 8.0, 9.2, 11.0, 14.99, 15.0})
    {
        for (double t : {0.0, 0.4, 2.7})
        {
            const double u = zz - 5, st = std::sin(twoPi*0.3*t + 0.2);
            const AxisState s = m.state(zz, t);
            // round-off of O(1) sums over a few nodes: 1e-13
            EXPECT_NEAR(s.position.x(), 0.4*f(zz)*st, 1e-13);
            EXPECT_NEAR(s.slope.x(), 0.4*(0.3 - 0.04*u)*st, 1e-13);
            EXPECT_NEAR(s.curvature.x(), 0.4*(-0.04)*st, 1e-12);
            EXPECT_NEAR(s.acceleration.x(), -0.4*f(zz)*st*std::pow(twoPi*0.3, 2), 1e-12);
            EXPECT_EQ(s.position.y(), 0.0);
        }
    }
    EXPECT_EQ(m.domain().zMin, 5.0);
    EXPECT_EQ(m.domain().zMax, 15.0);
    EXPECT_EQ(m.foot(), 5.0);
    EXPECT_EQ(m.length(), 10.0);
}


TEST(ModeShapes, ConvergeToTheSineModesAtTheirOrders)
{
    // modes 2 (x) and 3 (y) of a 100 m riser from z = -20 m
    const std::vector<Mode> x{Mode{2, 0.3, twoPi*0.4, 0.1}}, y{Mode{3, 0.2, twoPi*0.6, -0.5}};
    const ModesMotion exact(-20.0, 100.0, W::standing, x, y);
    double error[3][3];     // [refinement][position, slope, curvature]
    const int Ms[3] = {101, 201, 401};
    for (int r = 0; r < 3; ++r)
    {
        const ModesMotion tab(0, 1, W::standing, x, y, sampledSines(-20.0, 100.0, Ms[r], 3));
        error[r][0] = error[r][1] = error[r][2] = 0;
        for (int i = 0; i <= 997; ++i)
        {
            const double z = -20.0 + 100.0*i/997;
            const double t = 0.37 + 0.011*i;
            const AxisState a = tab.state(z, t), b = exact.state(z, t);
            error[r][0] = std::max(error[r][0], (a.position - b.position).norm());
            error[r][1] = std::max(error[r][1], (a.slope - b.slope).norm());
            error[r][2] = std::max(error[r][2], (a.curvature - b.curvature).norm());
        }
    }
    // observed orders between successive halvings, within 0.3 of the
    // theoretical 3, 2, 1 (the leading term dominates at 66 to 266
    // heights a wavelength)
    const double order[3] = {3, 2, 1};
    for (int r = 0; r + 1 < 3; ++r)
    {
        for (int d = 0; d < 3; ++d)
        {
            const double observed = std::log2(error[r][d]/error[r + 1][d]);
            EXPECT_GT(observed, order[d] - 0.3) << "derivative " << d << " refinement " << r;
        }
    }
    // and small: at 1 m the position within the nodal slopes' error,
    // a k^3 dz^2/6, times a piece's length dz, of the two modes together
    const double k2 = 2*M_PI/100, k3 = 3*M_PI/100, dz = 1.0;
    EXPECT_LT(error[0][0], std::hypot(0.3*std::pow(k2, 3), 0.2*std::pow(k3, 3))*std::pow(dz, 3)/6);
}


TEST(ModeShapes, BoundsHold)
{
    const ModesMotion m(0, 1, W::standing, {Mode{2, 0.3, twoPi*0.4, 0.1}},
                        {Mode{1, 0.5, twoPi*0.2, 0}, Mode{3, 0.1, twoPi*0.5, 1}},
                        sampledSines(0.0, 50.0, 200, 3));
    double speed = 0, acceleration = 0, slope = 0;
    for (int i = 0; i <= 500; ++i)
    {
        for (int j = 0; j <= 200; ++j)
        {
            const double z = 50.0*i/500, t = 12.0*j/200;
            const AxisState s = m.state(z, t);
            speed = std::max(speed, s.velocity.norm());
            acceleration = std::max(acceleration, s.acceleration.norm());
            slope = std::max(slope, s.slope.norm());
            EXPECT_LE(s.position.norm(), m.axisOffsetBound(t));
        }
    }
    EXPECT_LE(speed, m.maxSpeed());
    EXPECT_LE(acceleration, m.maxAcceleration());
    EXPECT_LE(slope, m.maxSlope());
    // the bounds are the sines' within the 5 % margin and the end nodes'
    // one-sided slopes' error, dz^2 k^2/3 = 7e-4 of mode 3 (dz = 0.25 m,
    // k = 3 pi/50 1/m)
    const ModesMotion sines(0.0, 50.0, W::standing, {Mode{2, 0.3, twoPi*0.4, 0.1}},
                            {Mode{1, 0.5, twoPi*0.2, 0}, Mode{3, 0.1, twoPi*0.5, 1}});
    EXPECT_LE(m.maxSlope(), 1.05*sines.maxSlope()*(1 + 1e-3));
    EXPECT_GE(m.maxSlope(), sines.maxSlope()*(1 - 1e-3));
}


TEST(ModeShapes, Refused)
{
    const std::vector<std::vector<double>> one{{0, 0.5, 0.8, 1, 0.8, 0.5, 0}};
    auto heights = [](std::vector<double> z) { return z; };
    // heights not increasing, too few, a value not finite, a column short
    EXPECT_THROW(ModeShapes(heights({0, 1, 2, 2, 4, 5, 6}), one), std::invalid_argument);
    EXPECT_THROW(ModeShapes(heights({0}), {{1}}), std::invalid_argument);
    EXPECT_THROW(ModeShapes(heights({0, 1, 2, 3, 4, 5, 6}), {{0, 0.5, NAN, 1, 0.8, 0.5, 0}}),
                 std::invalid_argument);
    EXPECT_THROW(ModeShapes(heights({0, 1, 2, 3, 4, 5, 6}), {{0, 0.5, 0.8}}), std::invalid_argument);
    EXPECT_THROW(ModeShapes(heights({0, 1, 2, 3, 4, 5, 6}), {}), std::invalid_argument);
    // a mode without its column, a travelling wave
    const ShapesPtr s = sampledSines(0, 100, 101, 2);
    EXPECT_THROW(ModesMotion(0, 1, W::standing, {Mode{3, 0.1, 1, 0}}, {}, s), std::invalid_argument);
    EXPECT_THROW(ModesMotion(0, 1, W::travelling, {Mode{1, 0.1, 1, 0}}, {}, s), std::invalid_argument);
    // beyond the table's heights
    const ModesMotion m(0, 1, W::standing, {Mode{2, 0.1, 1, 0}}, {}, s);
    EXPECT_THROW(m.state(100.5, 0.0), std::out_of_range);
    EXPECT_THROW(m.state(-0.5, 0.0), std::out_of_range);
    EXPECT_NO_THROW(m.state(100.0, 0.0));
    // too coarse: mode 6 of 100 m at 21 heights, 6.7 a wavelength
    try
    {
        sampledSines(0, 100, 21, 6);
        ADD_FAILURE() << "a coarse table accepted";
    }
    catch (const std::invalid_argument& e)
    {
        EXPECT_NE(std::string(e.what()).find("sample at most every"), std::string::npos);
    }
}
