// Tests of the riser's motion models (src/riserCore/riser): the sinusoid
// against its closed form to the bit, its bounds and frame changes.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "riser/sinusoidMotion.hpp"

#include <gtest/gtest.h>
#include <cmath>
#include <stdexcept>

using namespace riser;

namespace {
const double twoPi = 2.0*M_PI;
const double times[] = {0.0, 0.0123456789, 0.07, 0.21, 3.3, 1234.5678};
const double heights[] = {-2.0, 0.0, 0.3, 1000.0};
}

// The sinusoid is the riser of before the motion models: the same
// floating-point operations in the same order, so the same bits at every
// height and time (EXPECT_EQ, no tolerance).
TEST(SinusoidMotion, IsTheFormerClosedFormToTheBit)
{
    const double A = 0.1, omega = twoPi*3.0, phi0 = 0.4;
    const SinusoidMotion m(A, omega, phi0);
    for (double t : times)
    {
        const double xc = A*std::sin(omega*t + phi0);
        const double Ur = A*omega*std::cos(omega*t + phi0);
        const double ar = -A*omega*omega*std::sin(omega*t + phi0);
        for (double z : heights)
        {
            EXPECT_EQ(m.axis(z, t), Vector(xc, 0.0, 0.0));
            EXPECT_EQ(m.velocity(z, t), Vector(Ur, 0.0, 0.0));
            EXPECT_EQ(m.acceleration(z, t), Vector(ar, 0.0, 0.0));
            const AxisState s = m.state(z, t);
            EXPECT_EQ(s.position, m.axis(z, t));
            EXPECT_EQ(s.velocity, m.velocity(z, t));
            EXPECT_EQ(s.acceleration, m.acceleration(z, t));
            const Vector x(0.01, -0.02, z), v(0.3, -0.1, 1.2);
            EXPECT_EQ(m.toRiserFrame(x, t), Vector(x.x() - xc, x.y(), z));
            EXPECT_EQ(m.toLabFrame(x, t), Vector(x.x() + xc, x.y(), z));
            EXPECT_EQ(m.relativeVelocity(x, v, t), Vector(v.x() - Ur, v.y(), v.z()));
            EXPECT_EQ(m.labVelocity(x, v, t), Vector(v.x() + Ur, v.y(), v.z()));
            EXPECT_EQ(m.radialOffset(x, t), Vector(x.x() - xc, x.y(), 0.0));
        }
        EXPECT_EQ(m.axisOffsetBound(t), std::abs(xc));
    }
    EXPECT_EQ(m.maxSpeed(), A*omega);
    EXPECT_EQ(m.maxAcceleration(), A*omega*omega);
    EXPECT_EQ(m.frequency(), omega/(2.0*M_PI));
    EXPECT_FALSE(m.steady());
    EXPECT_TRUE(SinusoidMotion::atRest()->steady());
}
