// Tests of the riser's motion models (src/riserCore/riser): the sinusoid
// against its closed form to the bit, the harmonics against their analytic
// derivatives and central finite differences, the figure-of-eight orbit
// against its closed form, the bounds and the frame changes.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "carrier/riserFlow.hpp"
#include "riser/harmonicsMotion.hpp"
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

// The harmonics' velocity and acceleration are the derivatives of their
// position: against the analytic sums, and against central differences.
// Differences of step h err by h^2/6 |x'''| (sum a w^3 = 0.05 (2 pi 3)^3
// + ... ~ 400 m/s^3: 7e-11 at h = 1e-6) plus round-off eps |x|/h ~ 1e-11:
// 1e-8 on the velocity covers both; on the acceleration, the difference of
// velocities, sum a w^4 h^2/6 ~ 1e-8 and eps |v|/h ~ 1e-9: 1e-6. The
// differences are taken at t <= 3.3 s: at t = 1234 s the round-off of the
// sines' arguments, eps w t ~ 5e-12 rad, alone gives 1e-4 over 2h.
TEST(HarmonicsMotion, DerivativesAnalyticAndByFiniteDifferences)
{
    const double w1 = twoPi*3.0, w2 = twoPi*1.7, w3 = twoPi*0.5;
    const HarmonicsMotion m({{0.05, w1, 0.4}, {0.02, w2, -1.0}}, {{0.03, w3, 2.0}});
    const double h = 1e-6;
    for (double t : times)
    {
        const double ax = 0.05*std::sin(w1*t + 0.4) + 0.02*std::sin(w2*t - 1.0);
        const double ay = 0.03*std::sin(w3*t + 2.0);
        const double vx = 0.05*w1*std::cos(w1*t + 0.4) + 0.02*w2*std::cos(w2*t - 1.0);
        const double vy = 0.03*w3*std::cos(w3*t + 2.0);
        const double accx = -0.05*w1*w1*std::sin(w1*t + 0.4) - 0.02*w2*w2*std::sin(w2*t - 1.0);
        const double accy = -0.03*w3*w3*std::sin(w3*t + 2.0);
        for (double z : heights)
        {
            // closed forms: a few ulps of the largest term (|a w^2| <= 18 m/s^2)
            EXPECT_NEAR((m.axis(z, t) - Vector(ax, ay, 0.0)).norm(), 0.0, 1e-15);
            EXPECT_NEAR((m.velocity(z, t) - Vector(vx, vy, 0.0)).norm(), 0.0, 1e-14);
            EXPECT_NEAR((m.acceleration(z, t) - Vector(accx, accy, 0.0)).norm(), 0.0, 1e-13);
            if (t < 10.0)
            {
                const Vector v = (m.axis(z, t + h) - m.axis(z, t - h))/(2.0*h);
                const Vector a = (m.velocity(z, t + h) - m.velocity(z, t - h))/(2.0*h);
                EXPECT_NEAR((m.velocity(z, t) - v).norm(), 0.0, 1e-8) << t;
                EXPECT_NEAR((m.acceleration(z, t) - a).norm(), 0.0, 1e-6) << t;
            }
            const AxisState s = m.state(z, t);
            EXPECT_EQ(s.position, m.axis(z, t));
            EXPECT_EQ(s.velocity, m.velocity(z, t));
            EXPECT_EQ(s.acceleration, m.acceleration(z, t));
        }
        EXPECT_EQ(m.axisOffsetBound(t), m.axis(0.0, t).norm());
    }
    // the bounds: every harmonic at its peak at once
    EXPECT_NEAR(m.maxSpeed(), std::hypot(0.05*w1 + 0.02*w2, 0.03*w3), 1e-15);
    EXPECT_NEAR(m.maxAcceleration(), std::hypot(0.05*w1*w1 + 0.02*w2*w2, 0.03*w3*w3), 1e-12);
    EXPECT_THROW(m.angularFrequency(), std::domain_error);
    EXPECT_FALSE(m.steady());
}

// The figure-of-eight of vortex-induced vibration: cross-flow y = b sin(w t)
// at the shedding frequency, in-line x = a sin(2 w t) at twice it. Closed
// form: x = 2 a (y/b) cos(w t); the orbit passes the origin twice a period
// and returns after each period T = 2 pi / w (to the round-off of the
// sines' arguments, w t < 30 rad: eps 30 b ~ 3e-16 m; 1e-14 m with margin).
TEST(HarmonicsMotion, FigureOfEightOrbit)
{
    const double a = 0.01, b = 0.05, w = twoPi*0.8;
    const HarmonicsMotion m({{a, 2.0*w, 0.0}}, {{b, w, 0.0}});
    const double T = twoPi/w;
    for (int i = 0; i <= 40; ++i)
    {
        const double t = 0.3 + i*T/40.0;
        const Vector p = m.axis(0.5, t);
        EXPECT_NEAR(p.x(), a*std::sin(2.0*w*t), 1e-16) << t;
        EXPECT_NEAR(p.y(), b*std::sin(w*t), 1e-16) << t;
        EXPECT_NEAR(p.x(), 2.0*a*(p.y()/b)*std::cos(w*t), 1e-16) << t;
        EXPECT_NEAR((m.axis(0.5, t + 3.0*T) - p).norm(), 0.0, 1e-14) << t;
        EXPECT_EQ(p.z(), 0.0);
    }
    for (double t : {0.0, 0.5*T, T})
    {
        EXPECT_NEAR(m.axis(0.0, t).norm(), 0.0, 1e-16);
    }
    EXPECT_THROW(m.frequency(), std::domain_error);
}

// One harmonic in x is the sinusoid, to the bit (the sums start from 0,
// which adds exactly); one in y is the sinusoid turned by 90 degrees.
TEST(HarmonicsMotion, OneHarmonicIsTheSinusoid)
{
    const double A = 0.1, omega = twoPi*3.0, phi0 = 0.4;
    const SinusoidMotion s(A, omega, phi0);
    const HarmonicsMotion hx({{A, omega, phi0}}, {}), hy({}, {{A, omega, phi0}});
    for (double t : times)
    {
        EXPECT_EQ(hx.axis(0.0, t), s.axis(0.0, t));
        EXPECT_EQ(hx.velocity(0.0, t), s.velocity(0.0, t));
        EXPECT_EQ(hx.acceleration(0.0, t), s.acceleration(0.0, t));
        const Vector x = s.axis(0.0, t), y = hy.axis(0.0, t);
        EXPECT_EQ(y, Vector(0.0, x.x(), 0.0));
        EXPECT_EQ(hy.velocity(0.0, t).y(), s.velocity(0.0, t).x());
        EXPECT_EQ(hy.acceleration(0.0, t).y(), s.acceleration(0.0, t).x());
    }
    EXPECT_EQ(hx.maxSpeed(), s.maxSpeed());
    EXPECT_EQ(hy.maxAcceleration(), s.maxAcceleration());
    EXPECT_EQ(hx.angularFrequency(), omega);
}

TEST(HarmonicsMotion, RejectsBadArguments)
{
    EXPECT_THROW(HarmonicsMotion({{-0.1, 1.0, 0.0}}, {}), std::invalid_argument);
    EXPECT_THROW(HarmonicsMotion({}, {{0.1, -1.0, 0.0}}), std::invalid_argument);
    EXPECT_THROW(HarmonicsMotion({{0.1, 1.0, NAN}}, {}), std::invalid_argument);
    EXPECT_THROW(HarmonicsMotion({{0.1, INFINITY, 0.0}}, {}), std::invalid_argument);
    EXPECT_THROW(SinusoidMotion(0.1, 1.0, NAN), std::invalid_argument);
    EXPECT_TRUE(HarmonicsMotion({}, {}).steady());
}

// The carrier and the wall move with an axis that moves in x and y: the
// Poiseuille flow about (x_c, y_c) carried at (U_r, V_r), its curl about the
// moving axis, Du/Dt the riser's acceleration (central differences, as in
// riserFlowTest: tolerance 1e-5 over truncation ~1e-9 and round-off ~1e-10),
// the wall's distance, normal and velocity. Closed forms to round-off of
// the sums (1e-15 on values of order 1).
TEST(HarmonicsMotion, CarrierAndWallAboutTheMovingAxis)
{
    const double w = twoPi*0.8;
    const RiserFlow flow(0.1, 1.0, HarmonicsMotion::make({{0.02, 2.0*w, 0.3}}, {{0.05, w, -0.2}}));
    const double R = 0.05, h = 1e-6;
    for (double t : {0.0, 0.07, 0.21, 1.3})
    {
        const double z = 0.4;
        const Vector a = flow.motion().axis(z, t), U = flow.motion().velocity(z, t);
        EXPECT_NEAR((flow.velocity(Vector(a.x(), a.y(), z), t) - Vector(U.x(), U.y(), 1.0)).norm(), 0.0, 1e-15);
        for (double theta : {0.0, 1.0, 2.5, 4.0})
        {
            const Vector onWall(a.x() + R*std::cos(theta), a.y() + R*std::sin(theta), z);
            EXPECT_NEAR(flow.velocity(onWall, t).z(), 0.0, 1e-14);
            EXPECT_NEAR(flow.wall().distance(onWall, t), 0.0, 1e-15);
            const Vector x(a.x() + 0.6*R*std::cos(theta), a.y() + 0.6*R*std::sin(theta), z);
            const double c = 2.0*1.0/(R*R);
            EXPECT_NEAR((flow.vorticity(x, t) - Vector(-c*(x.y() - a.y()), c*(x.x() - a.x()), 0.0)).norm(),
                        0.0, 1e-12);
            EXPECT_NEAR((flow.wall().normal(x, t) - Vector(std::cos(theta), std::sin(theta), 0.0)).norm(),
                        0.0, 1e-14);
            EXPECT_TRUE(flow.wall().velocity(x, t) == U);
            // Du/Dt = du/dt + (u.grad) u, by central differences
            const Vector u = flow.velocity(x, t);
            Vector DuDt = (flow.velocity(x, t + h) - flow.velocity(x, t - h))/(2.0*h);
            for (int k = 0; k < 3; ++k)
            {
                Vector e = Vector::Zero(); e[k] = h;
                DuDt += u[k]*(flow.velocity(x + e, t) - flow.velocity(x - e, t))/(2.0*h);
            }
            EXPECT_NEAR((flow.materialDerivative(x, t) - DuDt).norm(), 0.0, 1e-5);
            EXPECT_TRUE(flow.materialDerivative(x, t) == flow.motion().acceleration(z, t));
        }
    }
}
