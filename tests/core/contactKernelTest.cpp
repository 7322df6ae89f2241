// Tests of the contact kernel (src/riserCore/contact/contactKernel.hpp):
// the contact point's velocity against rigid-body kinematics of the two
// touching points, the spring's turning and growth against their closed
// forms, and the torques and the power against their definitions.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "contact/contactKernel.hpp"
#include "contact/pairContact.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace riser;

namespace {

const ElasticMaterial glass(63e9, 0.23);

HertzMindlin law(double mu, double e = 0.9)
{
    return HertzMindlin(HertzMindlinParameters{glass, glass, e, 1.0, mu});
}

// relative to the size of the vectors compared (double round-off)
constexpr double tol = 1e-13;

} // namespace

// U from the velocities of the two material points at the contact: i's
// surface point x_i + R_i n and j's x_j - R_j n, each v + omega x (point -
// centre); the wall side is a point moving with the wall's velocity.
TEST(ContactKernel, ContactVelocityIsThatOfTheTouchingPoints)
{
    const Vector xi(0.1, -0.2, 0.3), xj(0.1 + 0.006, -0.2 + 0.002, 0.3 - 0.003);
    const double Ri = 0.004, Rj = 0.003;
    const ContactSide i{Vector(0.3, -1.2, 0.5), Vector(40.0, -15.0, 7.0), Ri};
    const ContactSide j{Vector(-0.7, 0.2, 0.9), Vector(-3.0, 22.0, -31.0), Rj};
    const Vector n = (xj - xi).normalized();
    const Vector pointI = xi + Ri*n, pointJ = xj - Rj*n;
    const Vector expected =
        (i.v + i.omega.cross(pointI - xi)) - (j.v + j.omega.cross(pointJ - xj));
    EXPECT_LT((contactVelocity(i, j, n) - expected).norm(), tol*expected.norm());

    const Vector w(0.05, 0.0, -0.02);
    const Vector atWall = i.v + i.omega.cross(Ri*n) - w;
    EXPECT_LT((contactVelocity(i, wallSide(w), n) - atWall).norm(), tol*atWall.norm());
}

// A kept spring is turned into the new tangent plane with its length kept
// (a rigid rotation of a sticking contact leaves the spring's length, and so
// its force at the same overlap, unchanged); one along n has no tangential
// direction and is dropped.
TEST(ContactKernel, SpringTurnsWithTheNormalKeepingItsLength)
{
    const Vector s0(0.0, 2e-6, 0.0);
    Vector n(0.0, 0.0, 1.0);
    Vector s = s0;
    for (int k = 1; k <= 6; ++k)
    {
        const double a = 0.25*k;    // the normal turns about x
        n = Vector(0.0, -std::sin(a), std::cos(a));
        s = turnedSpring(s, n);
        EXPECT_NEAR(s.dot(n), 0.0, tol*s0.norm());
        EXPECT_NEAR(s.norm(), s0.norm(), tol*s0.norm());
    }
    // about x by 1.5 rad: (0, 2e-6, 0) turns into (0, 2e-6 cos, 2e-6 sin)
    EXPECT_LT((s - Vector(0.0, 2e-6*std::cos(1.5), 2e-6*std::sin(1.5))).norm(), 1e-12*s0.norm());
    EXPECT_EQ(turnedSpring(Vector(0.0, 0.0, 3e-6), Vector(0.0, 0.0, 1.0)), Vector::Zero());
}

// A constant tangential slip U_t at a fixed overlap: the spring grows by U_t
// dt a step while the contact sticks (k steps: k U_t dt, the trial force
// k_t k U_t dt + eta_t U_t below mu F_n), and the Coulomb cap then holds
// |F_t| = mu |F_n| with the spring s = -F_t/k_t.
TEST(ContactKernel, SpringGrowsBySlipUntilTheCoulombCap)
{
    const double mu = 0.3, R = 0.005, m = 2500.0*4.0/3.0*M_PI*R*R*R;
    const HertzMindlin hm = law(mu);
    const ContactBody body(R, m);
    const double delta = 1e-6, dt = 1e-7;
    const Vector n(0.0, 0.0, -1.0);
    const ContactSide p{Vector(0.01, 0.0, 0.0), Vector::Zero(), R};
    const ContactSide wall = wallSide(Vector::Zero());
    const double kt = 8.0*hm.equivalentShearModulus()*std::sqrt(R*delta);
    const double etaT = 2.0*linearDampingRatio(1.0)*std::sqrt(kt*m);
    const double Fn = hm.normalStiffness(body)*std::pow(delta, 1.5);   // U_n = 0
    Vector s = Vector::Zero();
    int k = 0;
    for (; k < 100000; ++k)
    {
        const ContactStep c = stepContact(hm, body, delta, n, p, wall, s, NAN, dt);
        EXPECT_NEAR(c.law.normal.norm(), Fn, 1e-12*Fn);
        if (c.law.sliding)
        {
            EXPECT_NEAR(c.law.tangential.norm(), mu*Fn, 1e-12*Fn);
            EXPECT_LT((c.law.springAfter + c.law.tangential/kt).norm(), 1e-12*c.law.springAfter.norm());
            break;
        }
        const Vector expected = (k + 1)*dt*p.v;
        EXPECT_LT((c.law.springAfter - expected).norm(), 1e-12*expected.norm());
        EXPECT_LE(kt*c.law.springAfter.norm() + etaT*p.v.norm(), mu*Fn*(1 + 1e-12));
        s = c.law.springAfter;
    }
    // the step it starts to slide: the first k with k_t k U_t dt > mu F_n
    const int firstSliding = int(std::floor((mu*Fn - etaT*p.v.norm())/(kt*dt*p.v.norm())));
    EXPECT_NEAR(k, firstSliding, 1);
}

// On a pair: F on i and -F on j, torques R_i n x F_t and R_j n x F_t, the
// power F.U; the angular momentum about a point then changes at delta n x
// F_t (the forces act at the two surface points, delta apart along n).
TEST(ContactKernel, PairTorquesAndPowerFollowTheirDefinitions)
{
    const double Ri = 0.004, Rj = 0.003, rho = 2500.0;
    const double mi = rho*4.0/3.0*M_PI*Ri*Ri*Ri, mj = rho*4.0/3.0*M_PI*Rj*Rj*Rj;
    const Vector xi(0.0, 0.0, 0.0), xj(0.0069995, 0.0, 0.0);
    const PairGeometry g = pairGeometry(xi, Ri, xj, Rj);
    ASSERT_GT(g.overlap, 0.0);
    const ContactSide i{Vector(0.2, 0.1, -0.05), Vector(3.0, -20.0, 9.0), Ri};
    const ContactSide j{Vector(-0.1, 0.0, 0.02), Vector(-5.0, 4.0, 11.0), Rj};
    const HertzMindlin hm = law(0.5);
    const Vector s0(0.0, 1e-7, -2e-7);
    const ContactStep c =
        stepContact(hm, pairBody(Ri, mi, Rj, mj), g.overlap, g.normal, i, j, s0, NAN, 1e-6);
    EXPECT_GT(c.law.tangential.norm(), 0.0);
    EXPECT_LT((c.force - c.law.normal - c.law.tangential).norm(), tol*c.force.norm());
    EXPECT_LT((c.torqueI - (Ri*g.normal).cross(c.law.tangential)).norm(), tol*c.torqueI.norm());
    EXPECT_LT((c.torqueJ - (Rj*g.normal).cross(c.law.tangential)).norm(), tol*c.torqueJ.norm());
    EXPECT_NEAR(c.power, c.force.dot(contactVelocity(i, j, g.normal)), tol*std::abs(c.power));
    const Vector Ldot =
        xi.cross(c.force) + c.torqueI + xj.cross(-c.force) + c.torqueJ;
    const Vector expected = g.overlap*g.normal.cross(c.law.tangential);
    EXPECT_LT((Ldot - expected).norm(), 1e-9*c.torqueI.norm());
    // apart: nothing
    const ContactStep apart = stepContact(hm, pairBody(Ri, mi, Rj, mj), -1e-6, g.normal, i, j, s0, NAN, 1e-6);
    EXPECT_EQ(apart.force, Vector::Zero());
    EXPECT_EQ(apart.law.springAfter, Vector::Zero());
    EXPECT_EQ(apart.power, 0.0);
}
