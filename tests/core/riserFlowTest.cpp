// Tests of the analytic oscillating-riser carrier (src/riserCore/carrier).
// SPDX-License-Identifier: GPL-3.0-or-later
#include "carrier/riserFlow.hpp"
#include "wall/cylinderWall.hpp"

#include <gtest/gtest.h>
#include <cmath>

using namespace riser;

namespace {
// The paper's base case: D = 0.1 m, u_cm = 1 m/s, A = 0.1 m, f = 3 Hz, phi0 = 0.4.
const RiserFlow flow(0.1, 1.0, 0.1, 2.0*M_PI*3.0, 0.4);
const double h = 1e-6;    // finite-difference step [m] and [s]

// Central differences have truncation error h^2/6 u''' (u is quadratic in x,
// so exact up to round-off there; sinusoidal in t: A w^3 h^2 / 6 ~ 1e-9) and
// round-off eps |u| / h ~ 1e-10: tolerance 1e-7 covers both with margin.
const double tol = 1e-7;

// The axis x_c and the riser's velocity U_r at height z = 2 m
double xc(double t) { return flow.motion().axis(2.0, t).x(); }
double Ur(double t) { return flow.motion().velocity(2.0, t).x(); }

Vector dudx(const Vector& x, double t, int k)
{
    Vector e = Vector::Zero(); e[k] = h;
    return (flow.velocity(x + e, t) - flow.velocity(x - e, t))/(2.0*h);
}
}

TEST(RiserFlow, VorticityEqualsCurlByFiniteDifferences)
{
    for (double t : {0.0, 0.07, 0.21})
    {
        for (const Vector& x : {Vector(0.01, -0.02, 0.3), Vector(-0.03, 0.04, 1.0), Vector(0.1, 0.0, 0.0)})
        {
            const Vector gx = dudx(x, t, 0), gy = dudx(x, t, 1), gz = dudx(x, t, 2);
            const Vector curl(gy.z() - gz.y(), gz.x() - gx.z(), gx.y() - gy.x());
            EXPECT_NEAR((flow.vorticity(x, t) - curl).norm(), 0.0, tol*100.0);
        }
    }
}

TEST(RiserFlow, MaterialDerivativeByFiniteDifferences)
{
    for (double t : {0.0, 0.07, 0.21})
    {
        const Vector x(0.02, 0.01, 0.5);
        const Vector u = flow.velocity(x, t);
        const Vector dudt = (flow.velocity(x, t + h) - flow.velocity(x, t - h))/(2.0*h);
        const Vector convective = dudx(x, t, 0)*u.x() + dudx(x, t, 1)*u.y() + dudx(x, t, 2)*u.z();
        EXPECT_NEAR((flow.materialDerivative(x, t) - (dudt + convective)).norm(), 0.0, tol*100.0);
    }
}

TEST(RiserFlow, RiserKinematics)
{
    for (double t : {0.0, 0.05, 0.13})
    {
        const double v = (xc(t + h) - xc(t - h))/(2.0*h);
        const double a = (Ur(t + h) - Ur(t - h))/(2.0*h);
        EXPECT_NEAR(Ur(t), v, tol);
        EXPECT_NEAR(flow.motion().acceleration(2.0, t).x(), a, tol*100.0);
    }
    EXPECT_NEAR(xc(0.0), 0.1*std::sin(0.4), 1e-15);
    // Poiseuille profile: u_cm on the axis, zero on the wall, riser speed sideways
    const double t = 0.1;
    EXPECT_NEAR(flow.velocity(Vector(xc(t), 0, 2), t).z(), 1.0, 1e-15);
    EXPECT_NEAR(flow.velocity(Vector(xc(t) + 0.05, 0, 2), t).z(), 0.0, 1e-15);
    EXPECT_NEAR(flow.velocity(Vector(0, 0.05, 2), t).x(), Ur(t), 1e-15);
}

// The kinematics taken once for a height and time (RiserMotion::state, as
// the cloud's forces share them) give the values of the evaluations at
// (z, t), to the bit; a riser that does not oscillate has the same
// kinematics at every t >= 0.
TEST(RiserFlow, StateEvaluationIsTheTimeEvaluation)
{
    const RiserFlow still(0.1, 1.0, SinusoidMotion::atRest());
    for (double t : {0.0, 0.0123456789, 0.07, 0.21, 3.3})
    {
        for (const Vector& x : {Vector(0.01, -0.02, 0.3), Vector(-0.03, 0.04, 1.0)})
        {
            const AxisState s = flow.motion().state(x.z(), t);
            EXPECT_EQ(s.position, flow.motion().axis(x.z(), t));
            EXPECT_EQ(s.velocity, flow.motion().velocity(x.z(), t));
            EXPECT_EQ(s.acceleration, flow.motion().acceleration(x.z(), t));
            EXPECT_TRUE(flow.velocity(x, s) == flow.velocity(x, t));
            EXPECT_TRUE(flow.vorticity(x, s) == flow.vorticity(x, t));
            EXPECT_TRUE(flow.materialDerivative(s) == flow.materialDerivative(x, t));
            EXPECT_TRUE(RiserMotion::radialOffset(x, s) == flow.motion().radialOffset(x, t));
            const AxisState s0 = still.motion().state(x.z(), 0.0);
            EXPECT_TRUE(still.velocity(x, s0) == still.velocity(x, t));
            EXPECT_TRUE(still.vorticity(x, s0) == still.vorticity(x, t));
            EXPECT_TRUE(still.materialDerivative(s0) == still.materialDerivative(x, t));
        }
    }
}

// The wall's contact point (its kinematics evaluated once per time) equals
// the wall's distance, normal and velocity to the last bit, whatever the
// order of the times asked (repeated, back and forth); on the axis the
// normal is +x.
TEST(CylinderWall, ContactPointIsTheWallsOverlapNormalAndVelocity)
{
    const CylinderWall wall(0.1, flow.motionPtr());
    const double r = 0.005;
    for (double t : {0.0, 0.0123456789, 0.0123456789, 0.21, 0.07, 0.21, 3.3, 0.0})
    {
        for (const Vector& x :
             {Vector(0.01, -0.02, 0.3), Vector(-0.03, 0.04, 1.0), Vector(0.049, 0.0, -2.0)})
        {
            const ContactPoint c = wall.contactPoint(x, r, t);
            EXPECT_TRUE(c.overlap == wall.overlap(x, r, t)) << t;
            EXPECT_TRUE(c.normal == wall.normal(x, t)) << t;
            EXPECT_TRUE(c.velocity == wall.velocity(x, t)) << t;
        }
        const Vector onAxis(flow.motion().axis(0.5, t).x(), 0.0, 0.5);
        EXPECT_TRUE(wall.contactPoint(onAxis, r, t).normal == Vector(1.0, 0.0, 0.0));
    }
}

TEST(RiserFlow, RejectsBadArguments)
{
    EXPECT_THROW(RiserFlow(0.0, 1.0, 0.1, 1.0, 0.0), std::invalid_argument);
    EXPECT_THROW(RiserFlow(0.1, -1.0, 0.1, 1.0, 0.0), std::invalid_argument);
    EXPECT_THROW(RiserFlow(0.1, 1.0, -0.1, 1.0, 0.0), std::invalid_argument);
    EXPECT_THROW(RiserFlow(0.1, 1.0, 0.1, -1.0, 0.0), std::invalid_argument);
}
