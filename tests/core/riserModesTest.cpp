// Tests of the riser motion 'modes' (src/riserCore/riser/modesMotion.hpp)
// and of the sheared carrier it gives riser::RiserFlow:
// - a standing and a travelling mode against their closed forms at chosen
//   points (nodes, antinodes, the pinned ends);
// - every derivative of AxisState against central finite differences of
//   the position (an oracle independent of the analytic sums);
// - the bounds against a dense sampling of heights and times;
// - the carrier: its Du/Dt against central differences of u along the
//   fluid's own path and in space (du/dt + (u . grad) u), its curl against
//   finite differences of u, its divergence zero, and the fluid keeping
//   its offset from the local axis (the carrier follows the riser);
// - the frame changes: relativeVelocity(labVelocity(v)) = v, and a body
//   moving with the carrier has no velocity relative to the riser
//   laterally.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "carrier/riserFlow.hpp"
#include "riser/modesMotion.hpp"
#include "riser/sinusoidMotion.hpp"

#include <gtest/gtest.h>
#include <cmath>
#include <stdexcept>

using namespace riser;

namespace {

const double twoPi = 2.0*M_PI;

// A riser of 1000 m from z = -50 m, mode 5 in x and modes 3 and 7 in y
MotionPtr riser1000(ModesMotion::Wave wave)
{
    return ModesMotion::make
    (
        -50.0, 1000.0, wave,
        {Mode{5, 0.5, twoPi*0.2, 0.3}},
        {Mode{3, 0.4, twoPi*0.1, -1.0}, Mode{7, 0.2, twoPi*0.35, 2.0}}
    );
}

// Central differences of the axis position in t and z (steps chosen for
// ~1e-9 truncation and round-off on O(1) m, O(0.1) s^-1, O(1e-2) m^-1
// scales: h_t = 1e-4 s, h_z = 1e-2 m)
struct Differences
{
    Vector dt, dtt, dz, dzt, dzz;
};

Differences differences(const RiserMotion& m, double z, double t)
{
    const double ht = 1e-4, hz = 1e-2;
    auto X = [&](double dz, double dt) { return m.axis(z + dz, t + dt); };
    Differences d;
    d.dt = (X(0, ht) - X(0, -ht))/(2*ht);
    d.dtt = (X(0, ht) - 2*X(0, 0) + X(0, -ht))/(ht*ht);
    d.dz = (X(hz, 0) - X(-hz, 0))/(2*hz);
    d.dzt = (X(hz, ht) - X(hz, -ht) - X(-hz, ht) + X(-hz, -ht))/(4*hz*ht);
    d.dzz = (X(hz, 0) - 2*X(0, 0) + X(-hz, 0))/(hz*hz);
    return d;
}

const double heights[] = {-50.0, -12.3, 100.0, 333.3, 617.0, 950.0};
const double times[] = {0.0, 0.77, 3.1, 12.5, 101.0};

} // namespace


// x_c of a standing mode at its closed form; the pinned ends do not move
TEST(ModesMotion, StandingModeIsItsClosedForm)
{
    const double a = 0.5, w = twoPi*0.2, phase = 0.3, k = 5*M_PI/1000.0;
    const MotionPtr m = riser1000(ModesMotion::Wave::standing);
    for (double t : times)
    {
        for (double z : heights)
        {
            const double expected = a*std::sin(k*(z + 50.0))*std::sin(w*t + phase);
            EXPECT_NEAR(m->axis(z, t).x(), expected, 1e-14);
        }
        // the foot and the top: nodes of every mode (|x| at round-off of
        // sin(n pi))
        EXPECT_NEAR(m->axis(-50.0, t).norm(), 0.0, 1e-15);
        EXPECT_NEAR(m->axis(950.0, t).norm(), 0.0, 1e-12);
    }
    EXPECT_EQ(std::string(m->type()), "modes");
    EXPECT_FALSE(m->uniformAlongAxis());
    EXPECT_FALSE(m->steady());
}

// A travelling wave keeps its shape and moves up at omega / k
TEST(ModesMotion, TravellingWaveMovesUpAtItsPhaseSpeed)
{
    const MotionPtr m = ModesMotion::make
    (
        0.0, 1000.0, ModesMotion::Wave::travelling, {Mode{4, 0.3, twoPi*0.25, 0.1}}, {}
    );
    const double k = 4*M_PI/1000.0, c = twoPi*0.25/k;
    for (double t : times)
    {
        for (double z : heights)
        {
            EXPECT_NEAR(m->axis(z + c*1.7, t + 1.7).x(), m->axis(z, t).x(), 1e-12);
            EXPECT_NEAR(m->axis(z, t).x(), 0.3*std::sin(twoPi*0.25*t + 0.1 - k*z), 1e-14);
        }
    }
}

// Every derivative of the state against central differences of the
// position: tolerance 1e-7 of the derivative's scale (truncation ~h^2
// times the next derivative, round-off ~1e-16/h^2 for the second ones)
TEST(ModesMotion, DerivativesAreThoseOfThePosition)
{
    for (ModesMotion::Wave wave : {ModesMotion::Wave::standing, ModesMotion::Wave::travelling})
    {
        const MotionPtr m = riser1000(wave);
        for (double t : times)
        {
            for (double z : heights)
            {
                const AxisState s = m->state(z, t);
                const Differences d = differences(*m, z, t);
                EXPECT_LT((s.velocity - d.dt).norm(), 1e-7);
                EXPECT_LT((s.acceleration - d.dtt).norm(), 1e-6);
                EXPECT_LT((s.slope - d.dz).norm(), 1e-8);
                EXPECT_LT((s.slopeRate - d.dzt).norm(), 1e-8);
                EXPECT_LT((s.curvature - d.dzz).norm(), 1e-8);
                EXPECT_EQ(s.position, m->axis(z, t));
                EXPECT_EQ(s.velocity, m->velocity(z, t));
                EXPECT_EQ(s.acceleration, m->acceleration(z, t));
            }
        }
    }
}

// The bounds hold at every sampled point and are approached (within 5 %)
// where the modes peak together
TEST(ModesMotion, BoundsHoldOverTheRiser)
{
    const MotionPtr m = riser1000(ModesMotion::Wave::standing);
    double speed = 0, acceleration = 0, slope = 0;
    for (int i = 0; i <= 400; ++i)
    {
        const double z = -50.0 + 1000.0*i/400;
        for (int j = 0; j <= 400; ++j)
        {
            const double t = 30.0*j/400;
            const AxisState s = m->state(z, t);
            speed = std::max(speed, s.velocity.norm());
            acceleration = std::max(acceleration, s.acceleration.norm());
            slope = std::max(slope, s.slope.norm());
            EXPECT_LE(s.position.norm(), m->axisOffsetBound(t)*(1 + 1e-14));
        }
    }
    EXPECT_LE(speed, m->maxSpeed());
    EXPECT_LE(acceleration, m->maxAcceleration());
    EXPECT_LE(slope, m->maxSlope());
    // one mode alone reaches its bounds exactly
    const ModesMotion one(0.0, 1000.0, ModesMotion::Wave::standing, {Mode{5, 0.5, twoPi*0.2, 0}}, {});
    EXPECT_NEAR(one.maxSpeed(), 0.5*twoPi*0.2, 1e-15);
    EXPECT_NEAR(one.maxSlope(), 0.5*5*M_PI/1000.0, 1e-17);
    EXPECT_NEAR(one.state(0.0, 1.25).slope.x(), one.maxSlope(), 1e-17);  // omega t = pi/2 at the foot
    EXPECT_NEAR(one.angularFrequency(), twoPi*0.2, 1e-15);
    EXPECT_THROW(m->angularFrequency(), std::domain_error);
}

TEST(ModesMotion, RefusesBadModes)
{
    using W = ModesMotion::Wave;
    EXPECT_THROW(ModesMotion(0, 0.0, W::standing, {}, {}), std::invalid_argument);
    EXPECT_THROW(ModesMotion(0, 10.0, W::standing, {Mode{0, 0.1, 1, 0}}, {}), std::invalid_argument);
    EXPECT_THROW(ModesMotion(0, 10.0, W::standing, {}, {Mode{-2, 0.1, 1, 0}}), std::invalid_argument);
    EXPECT_THROW(ModesMotion(0, 10.0, W::standing, {Mode{1, -0.1, 1, 0}}, {}), std::invalid_argument);
    EXPECT_THROW(ModesMotion(0, 10.0, W::standing, {Mode{1, 0.1, -1, 0}}, {}), std::invalid_argument);
    EXPECT_THROW(ModesMotion(0, 10.0, W::standing, {Mode{1, 0.1, 1, NAN}}, {}), std::invalid_argument);
    EXPECT_THROW(ModesMotion(NAN, 10.0, W::standing, {}, {}), std::invalid_argument);
}


namespace {

// The carrier of a 0.2 m riser with u_cm = 4 m/s on a riser moving in
// modes 5 (x) and 3, 7 (y)
RiserFlow shearedFlow(ModesMotion::Wave wave)
{
    return RiserFlow(0.2, 4.0, riser1000(wave));
}

const Vector offsets[] = {Vector(0, 0, 0), Vector(0.05, -0.02, 0), Vector(-0.07, 0.06, 0)};

} // namespace


// Du/Dt of the sheared carrier is du/dt + (u . grad) u of its own velocity
// field (central differences, h = 1e-5 m and 1e-5 s: truncation ~1e-10
// times the field's third derivatives, round-off ~1e-16 * 4 m/s / 1e-5 =
// 4e-11); and the fluid keeps its offset from the local axis:
// d/dt (x - x_c(z, t)) = 0 along u
TEST(RiserFlowSheared, MaterialDerivativeIsThatOfTheVelocityField)
{
    for (ModesMotion::Wave wave : {ModesMotion::Wave::standing, ModesMotion::Wave::travelling})
    {
        const RiserFlow flow = shearedFlow(wave);
        const double h = 1e-5;
        for (double t : times)
        {
            for (double z : heights)
            {
                for (const Vector& r : offsets)
                {
                    const Vector x = flow.motion().toLabFrame(Vector(r.x(), r.y(), z), t);
                    const Vector u = flow.velocity(x, t);
                    Vector dudt = (flow.velocity(x, t + h) - flow.velocity(x, t - h))/(2*h);
                    for (int i = 0; i < 3; ++i)
                    {
                        Vector e = Vector::Zero();
                        e[i] = h;
                        dudt += u[i]*(flow.velocity(x + e, t) - flow.velocity(x - e, t))/(2*h);
                    }
                    EXPECT_LT((flow.materialDerivative(x, t) - dudt).norm(), 1e-6)
                        << "z " << z << " t " << t;
                    // the offset from the local axis, carried by u for h
                    const Vector ahead = x + h*u, behind = x - h*u;
                    const Vector drift =
                        flow.motion().radialOffset(ahead, t + h)
                      - flow.motion().radialOffset(behind, t - h);
                    EXPECT_LT(drift.norm()/(2*h), 1e-9);
                    // the fluid has no velocity relative to the riser but
                    // its axial speed
                    const Vector rel = flow.motion().relativeVelocity(x, u, t);
                    EXPECT_LT(std::hypot(rel.x(), rel.y()), 1e-14);
                    EXPECT_NEAR(flow.motion().labVelocity(x, rel, t).x(), u.x(), 1e-14);
                }
            }
        }
    }
}

// curl u against central differences of u (h = 1e-5 m), div u = 0
TEST(RiserFlowSheared, VorticityIsTheCurlOfTheVelocity)
{
    const RiserFlow flow = shearedFlow(ModesMotion::Wave::standing);
    const double h = 1e-5;
    for (double t : times)
    {
        for (double z : heights)
        {
            for (const Vector& r : offsets)
            {
                const Vector x = flow.motion().toLabFrame(Vector(r.x(), r.y(), z), t);
                Vector grad[3];
                for (int i = 0; i < 3; ++i)
                {
                    Vector e = Vector::Zero();
                    e[i] = h;
                    grad[i] = (flow.velocity(x + e, t) - flow.velocity(x - e, t))/(2*h);
                }
                const Vector curl
                (
                    grad[1].z() - grad[2].y(),
                    grad[2].x() - grad[0].z(),
                    grad[0].y() - grad[1].x()
                );
                EXPECT_LT((flow.vorticity(x, t) - curl).norm(), 1e-6);
                EXPECT_LT(std::abs(grad[0].x() + grad[1].y() + grad[2].z()), 1e-6);
            }
        }
    }
}

// A riser the same at every height has no shear terms: the sinusoid's
// carrier through the state is its carrier through (x, t), to the bit
TEST(RiserFlowSheared, UniformRiserUnchanged)
{
    const RiserFlow flow(0.2, 4.0, SinusoidMotion::make(0.1, twoPi*3, 0.2));
    for (double t : times)
    {
        const Vector x(0.03, -0.01, 7.0);
        const AxisState s = flow.motion().state(x.z(), t);
        EXPECT_EQ(flow.velocity(x, s), flow.velocity(x, t));
        EXPECT_EQ(flow.vorticity(x, s), flow.vorticity(x, t));
        EXPECT_EQ(flow.materialDerivative(x, s), flow.materialDerivative(x, t));
        EXPECT_EQ(s.slope, Vector::Zero());
    }
}
