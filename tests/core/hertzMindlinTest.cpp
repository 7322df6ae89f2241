// Tests of the Hertz–Mindlin wall-contact law and its restitution
// calibration (src/riserCore/contact).
// SPDX-License-Identifier: GPL-3.0-or-later
#include "contact/hertzMindlin.hpp"

#include "normalImpact.hpp"

#include <gtest/gtest.h>
#include <cmath>

using namespace riser;

namespace {

// A wall so stiff that it is rigid to double precision: (1 - nu^2)/E_w is
// 1e-19 of the particle's compliance in the tests below.
const ElasticMaterial rigidWall(1e30, 0.3);

// Head-on impact at speed v on a wall below the particle, integrated by the
// test itself (oracles/normalImpact.hpp) with classical RK4 at a step of
// duration/steps; the contact law supplies the force only. The particle
// starts touching (delta = 0).
struct Impact { double deltaMax, forceMax, duration, reboundSpeed; };

Impact normalImpact(const HertzMindlin& law, const ContactBody& body, double v,
                    double tcGuess, int steps = 20000)
{
    const Vector n(0, 0, -1);                   // from the centre towards the wall
    const ImpactResult r = ::normalImpact
    (
        [&](double d, double uu)                // du/dt = F.n/m
        {
            return law.force(body, d, n, uu*n, Vector::Zero()).normal.dot(n)/body.mass;
        },
        v, tcGuess/steps, 100L*steps
    );
    if (!r.ended) ADD_FAILURE() << "contact did not end";
    return Impact{r.deltaMax, body.mass*r.accelMax, r.duration, r.reboundSpeed};
}

// Chung & Ooi, Granular Matter 13, 643 (2011), test 2: aluminium-alloy
// sphere, R = 0.1 m, E = 70 GPa, nu = 0.3, rho = 2699 kg/m^3, rigid plane.
const ContactBody chungOoiSphere(0.1, 2699.0*4.0/3.0*M_PI*0.001);

HertzMindlinParameters chungOoiTest2(double e, NormalForceFloor floor)
{
    return HertzMindlinParameters{ElasticMaterial(70e9, 0.3), rigidWall, e, 1.0, 0.0, floor};
}

// Hertz's closed-form impact (Johnson, Contact Mechanics, 1985, sec. 11.4).
struct HertzImpact
{
    double deltaMax, forceMax, duration;
    HertzImpact(double m, double E, double R, double v)
    {
        deltaMax = std::pow(15.0*m*v*v/(16.0*E*std::sqrt(R)), 0.4);
        forceMax = 4.0/3.0*E*std::sqrt(R)*std::pow(deltaMax, 1.5);
        duration = 2.8683*std::pow(m*m/(R*E*E*v), 0.2);
    }
};

} // namespace

// Elastic impact of Chung & Ooi test 2 against Hertz theory within 0.5%;
// the published values (49.7 um, 11.37 kN, 732 us) within their 3 digits.
TEST(HertzMindlin, ChungOoiTest2ElasticImpact)
{
    const HertzMindlin law(chungOoiTest2(1.0, NormalForceFloor::tensionAllowed));
    const ContactBody& b = chungOoiSphere;
    const double v = 0.2;
    const HertzImpact ref(b.mass, 70e9/(1.0 - 0.09), b.radius, v);
    EXPECT_NEAR(law.contactTime(b, v)/ref.duration, 1.0, 1e-12);
    const Impact r = normalImpact(law, b, v, ref.duration);
    EXPECT_NEAR(r.deltaMax/ref.deltaMax, 1.0, 0.005);
    EXPECT_NEAR(r.forceMax/ref.forceMax, 1.0, 0.005);
    EXPECT_NEAR(r.duration/ref.duration, 1.0, 0.005);
    EXPECT_NEAR(r.deltaMax, 49.7e-6, 0.05e-6);
    EXPECT_NEAR(r.forceMax, 11.37e3, 0.01e3);
    EXPECT_NEAR(r.duration, 732e-6, 1e-6);
    EXPECT_NEAR(r.reboundSpeed/v, 1.0, 1e-6);   // no damping: energy kept
}

// The measured restitution equals the target for both end-of-contact
// treatments, and does not depend on the impact speed (0.01 .. 10 m/s).
TEST(HertzMindlin, RestitutionMatchesTargetAtAllSpeeds)
{
    for (auto floor : {NormalForceFloor::tensionAllowed, NormalForceFloor::noTension})
    {
        for (double e : {0.1, 0.3, 0.5, 0.76, 0.9, 1.0})
        {
            const HertzMindlin law(chungOoiTest2(e, floor));
            const ContactBody& b = chungOoiSphere;
            for (double v : {0.01, 0.1, 1.0, 10.0})
            {
                // heavy damping lengthens the contact: allow up to 3 t_c
                const Impact r = normalImpact(law, b, v, 3.0*law.contactTime(b, v), 60000);
                EXPECT_NEAR(r.reboundSpeed/v, e, 0.005*e)
                    << "e = " << e << ", v = " << v
                    << ", floor " << (floor == NormalForceFloor::noTension ? "noTension" : "tension");
            }
        }
    }
}

// With tension allowed the closed form alpha(e) is exact for the Hertz law
// (the universal impact integrated at two steps agrees with e to 1e-6); with
// the force clipped it is not, and the calibrated alpha is larger.
TEST(HertzMindlin, ClosedFormDampingHoldsOnlyWithTension)
{
    for (double e : {0.1, 0.3, 0.5, 0.76, 0.9})
    {
        const double a = closedFormDampingRatio(e);
        EXPECT_NEAR(hertzRestitution(a, NormalForceFloor::tensionAllowed), e, 1e-6);
        EXPECT_NEAR(hertzRestitution(a, NormalForceFloor::tensionAllowed, 1e-4), e, 1e-6);
        EXPECT_GT(hertzRestitution(a, NormalForceFloor::noTension), e + 1e-3);
        EXPECT_GT(dampingRatio(e, NormalForceFloor::noTension), a);
    }
}

// Equivalent moduli: on a rigid wall they reduce to E/(1 - nu^2) and to
// Mindlin's G/(2 - nu) with G = E / (2 (1 + nu)); for two equal bodies to half
// of those.
TEST(HertzMindlin, EquivalentModuli)
{
    const ElasticMaterial ore(60e9, 0.26);
    const double G = 60e9/(2.0*1.26);
    EXPECT_NEAR(equivalentYoungModulus(ore, rigidWall), 60e9/(1.0 - 0.26*0.26), 1e-3);
    EXPECT_NEAR(equivalentShearModulus(ore, rigidWall), G/(2.0 - 0.26), 1e-3);
    EXPECT_NEAR(equivalentYoungModulus(ore, ore), 0.5*60e9/(1.0 - 0.26*0.26), 1e-3);
    EXPECT_NEAR(equivalentShearModulus(ore, ore), 0.5*G/(2.0 - 0.26), 1e-3);
}

// Tangential law: the spring sticks below the Coulomb limit and slides at it.
TEST(HertzMindlin, TangentialStickAndSlide)
{
    const double R = 5e-3, mu = 0.2;
    const ContactBody b(R, 2000.0*4.0/3.0*M_PI*R*R*R);
    const HertzMindlinParameters p{ElasticMaterial(60e9, 0.26), ElasticMaterial(200e9, 0.3),
        0.76, 0.7, mu, NormalForceFloor::tensionAllowed};
    const HertzMindlin law(p);
    const Vector n(1, 0, 0);
    const double delta = 1e-6;
    const double fn = law.normalStiffness(b)*std::pow(delta, 1.5);   // no normal velocity
    const double kt = 8.0*law.equivalentShearModulus()*std::sqrt(R*delta);

    const Vector small(0, 0, 0.5*mu*fn/kt);
    const ContactForce stick = law.force(b, delta, n, Vector::Zero(), small);
    EXPECT_FALSE(stick.sliding);
    EXPECT_NEAR((stick.tangential + kt*small).norm(), 0.0, 1e-9*fn);
    EXPECT_NEAR(stick.normal.dot(n), -fn, 1e-9*fn);

    const Vector large(0, 3.0*mu*fn/kt, 0);
    const ContactForce slide = law.force(b, delta, n, Vector::Zero(), large);
    EXPECT_TRUE(slide.sliding);
    EXPECT_NEAR(slide.tangential.norm(), mu*fn, 1e-9*fn);
    EXPECT_LT(slide.tangential.y(), 0.0);
    EXPECT_NEAR(slide.springAfter.norm(), mu*fn/kt, 1e-12);

    // no overlap, no force
    EXPECT_EQ(law.force(b, 0.0, n, Vector(1, 1, 1), large).normal.norm(), 0.0);
}

// The Coulomb limit bounds the whole tangential force, spring and dashpot
// together: at every sub-step of oblique impacts over the range of Chung &
// Ooi (2011) test 4 (aluminium-oxide sphere, R = 2.5 mm, on an aluminium-
// alloy plane, 3.9 m/s at 5..85 degrees from the normal, mu_c = 0.092,
// e_n = 0.98), with e_t in {0.05, 0.7, 1} and the particle rotating,
// |F_t| <= mu_c |F_n| to 1e-12 relative (the round-off of the rescaling).
// The impacts are integrated by the test (symplectic Euler, 2000 steps per
// contact time, the tangential spring accumulated as riserContact
// does); the law supplies the forces. The test also checks that the cap is
// reached (some sub-steps slide) and that the dashpot alone, which the
// earlier spring-only cap left unbounded, would exceed it at e_t = 0.05.
TEST(HertzMindlin, CoulombLimitBoundsTheTotalTangentialForce)
{
    const double R = 2.5e-3, rho = 4000.0, mu = 0.092, v = 3.9;
    const double m = rho*4.0/3.0*M_PI*R*R*R, I = 0.4*m*R*R;
    const ContactBody body(R, m);
    const Vector n(0, 0, -1);                   // from the centre towards the wall
    for (double et : {0.05, 0.7, 1.0})
    {
        const HertzMindlinParameters p{ElasticMaterial(380e9, 0.23), ElasticMaterial(70e9, 0.33),
            0.98, et, mu, NormalForceFloor::tensionAllowed};
        const HertzMindlin law(p);
        const double dt = law.contactTime(body, v)/2000.0;
        long slid = 0, steps = 0;
        double worst = 0.0, dashpotOverLimit = 0.0;
        for (double angle = 5.0; angle <= 85.0; angle += 5.0)
        {
            const double a = angle*M_PI/180.0;
            Vector x(0, 0, R), vel(v*std::sin(a), 0, -v*std::cos(a)), omega = Vector::Zero();
            Vector spring = Vector::Zero();
            x.z() = R - 1e-12;                  // touching
            for (int i = 0; i < 10000; ++i)
            {
                const double delta = R - x.z();
                if (delta <= 0.0 && i > 0) break;
                const Vector U = vel + omega.cross(R*n);
                const Vector Ut = U - U.dot(n)*n;
                spring += Ut*dt;
                const ContactForce c = law.force(body, std::max(delta, 0.0), n, U, spring);
                spring = c.springAfter;
                const double Fn = c.normal.norm(), Ft = c.tangential.norm();
                if (Fn > 0.0)
                {
                    worst = std::max(worst, Ft/(mu*Fn));
                    const double kt = 8.0*law.equivalentShearModulus()*std::sqrt(R*delta);
                    const double zeta = linearDampingRatio(et);
                    dashpotOverLimit = std::max
                    (
                        dashpotOverLimit, 2.0*zeta*std::sqrt(kt*m)*Ut.norm()/(mu*Fn)
                    );
                }
                slid += c.sliding;
                ++steps;
                const Vector F = c.normal + c.tangential;
                vel += dt*F/m;
                omega += dt*(R*n).cross(c.tangential)/I;
                x += dt*vel;
            }
        }
        EXPECT_LE(worst, 1.0 + 1e-12) << "e_t = " << et;
        EXPECT_GT(slid, 0) << "e_t = " << et;
        EXPECT_GT(steps, 17*1000) << "e_t = " << et;
        if (et == 0.05)
        {
            EXPECT_GT(dashpotOverLimit, 1.0);
        }
    }
}

TEST(HertzMindlin, RejectsBadArguments)
{
    EXPECT_THROW(ElasticMaterial(0.0, 0.3), std::invalid_argument);
    EXPECT_THROW(ElasticMaterial(1e9, 0.5), std::invalid_argument);
    EXPECT_THROW(ElasticMaterial(1e9, -1.0), std::invalid_argument);
    EXPECT_THROW(dampingRatio(0.0, NormalForceFloor::tensionAllowed), std::invalid_argument);
    EXPECT_THROW(dampingRatio(1.01, NormalForceFloor::noTension), std::invalid_argument);
    auto p = chungOoiTest2(0.5, NormalForceFloor::tensionAllowed);
    p.friction = -0.1;
    EXPECT_THROW((HertzMindlin(p)), std::invalid_argument);
    EXPECT_THROW(ContactBody(0.0, 1.0), std::invalid_argument);
    EXPECT_THROW(ContactBody(1.0, -1.0), std::invalid_argument);
    try
    {
        ElasticMaterial bad(1e9, 0.7);
        FAIL();
    }
    catch (const std::invalid_argument& e)
    {
        EXPECT_NE(std::string(e.what()).find("'nu'"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("(-1, 0.5)"), std::string::npos) << e.what();
    }
}
