// Tests of the wet treatment of a contact (src/riserCore/contact/
// wetRestitution.hpp): a normal impact stepped through the contact kernel
// with the law's per-contact damping rebounds with the restitution of
// Legendre et al. (Chem. Eng. Sci. 61, 3543, 2006), e = e_dry exp(-35/St),
// St = (rho_p + rho_f/2) v d / (9 mu), written out here from the densities
// (the code builds St from the contact body's inertia and radius instead),
// and does not rebound below St_c = 10 (Joseph et al., J. Fluid Mech. 433,
// 329, 2001). Between two spheres, St with the reduced inertia and radius
// (Yang & Hunt, Phys. Fluids 18, 121506, 2006). The granular engine's wall
// and pair contacts give the same.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "contact/contactKernel.hpp"
#include "contact/pairContact.hpp"
#include "granular/granularSystem.hpp"
#include "wall/planeWall.hpp"

#include "normalImpact.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

using namespace riser;

namespace {

// a steel sphere in silicone oil (Gondret et al., Phys. Fluids 14, 643, 2002)
const double rhoP = 7800.0, rhoF = 935.0, eDry = 0.97;
const ElasticMaterial steel(200e9, 0.3), glass(63e9, 0.23);

HertzMindlin wetLaw(double mu, const ElasticMaterial& other = glass)
{
    HertzMindlinParameters p{steel, other, eDry, 1.0, 0.0};
    p.wet = WetRestitution{mu};
    return HertzMindlin(p);
}

double legendre(double St) { return eDry*std::exp(-35.0/St); }

//- Normal impact of a body (R, M) at speed v on the wall, the overlap and
//  its rate stepped by classical RK4 (oracles/normalImpact.hpp) with the
//  force of the kernel (dt = 0: evaluation), 4,000 steps per Hertz contact
//  time. Returns the speed of separation over v, 0 if the body has not
//  left after 100 contact times.
double impact(const HertzMindlin& law, const ContactBody& b, double v)
{
    const Vector n(0.0, 0.0, -1.0);           // from the centre to the wall
    const ImpactResult r = normalImpact
    (
        [&](double delta, double u)
        {
            // U.n = d(delta)/dt = u; the force on the body along -n slows it
            const ContactSide body{u*n, Vector::Zero(), b.radius};
            return stepContact(law, b, delta, n, body, wallSide(Vector::Zero()),
                               Vector::Zero(), v, 0.0).force.dot(n)/b.mass;
        },
        v, law.contactTime(b, v)/4000.0, 400000L
    );
    return r.ended ? r.reboundSpeed/v : 0.0;
}

//- The speed at which a sphere of diameter d meets the wall with Stokes
//  number St (Legendre's definition) in a liquid of viscosity mu
double speedOf(double St, double d, double mu) { return St*9.0*mu/((rhoP + 0.5*rhoF)*d); }

} // namespace

// e(St) over St 12 to 1,000 on the wall: the closed-form damping of each
// contact reproduces e = e_dry exp(-35/St). Tolerance 1e-5 in e: the closed
// form is exact for the Tsuji-damped Hertz contact with tension allowed
// (restitution.hpp, checked there to 1e-6 against its own integration by
// the same scheme at a coarser step); the RK4 at 4,000 steps a contact time
// and the linear location of its end leave far less.
TEST(WetRestitution, WallImpactReboundsWithLegendresRestitution)
{
    const double d = 3e-3, mu = 0.01;
    const double M = (rhoP + 0.5*rhoF)*M_PI*d*d*d/6.0;   // m_p + m_f/2
    const HertzMindlin law = wetLaw(mu);
    for (double St : {12.0, 20.0, 50.0, 152.0, 500.0, 1000.0})
    {
        const double e = impact(law, ContactBody(0.5*d, M), speedOf(St, d, mu));
        EXPECT_NEAR(e, legendre(St), 1e-5) << "St = " << St;
    }
}

// Below St_c no rebound: the overlap closes without the body leaving the
// wall within 100 contact times; just above St_c the fit's 0.035 e_dry
// (the cut-off's jump is 0.03 e_dry).
TEST(WetRestitution, NoReboundBelowTheCriticalStokesNumber)
{
    const double d = 3e-3, mu = 0.01;
    const double M = (rhoP + 0.5*rhoF)*M_PI*d*d*d/6.0;
    const HertzMindlin law = wetLaw(mu);
    for (double St : {0.5, 5.0, 9.9})
    {
        EXPECT_LT(impact(law, ContactBody(0.5*d, M), speedOf(St, d, mu)), 1e-6) << "St = " << St;
    }
    EXPECT_GT(impact(law, ContactBody(0.5*d, M), speedOf(10.5, d, mu)), 0.03);
}

// Two unlike spheres head-on: their relative speed rebounds with e(St*),
// St* = M* v / (6 pi mu R*^2) with the reduced inertia M* and radius R*
// written out here (tolerance as above).
TEST(WetRestitution, PairImpactTakesTheReducedInertiaAndRadius)
{
    const double mu = 0.02, di = 4e-3, dj = 7e-3;
    const double mi = (rhoP + 0.5*rhoF)*M_PI*di*di*di/6.0;
    const double mj = (rhoP + 0.5*rhoF)*M_PI*dj*dj*dj/6.0;
    const double Mr = mi*mj/(mi + mj), Rr = 0.5*di*0.5*dj/(0.5*di + 0.5*dj);
    const HertzMindlin law = wetLaw(mu, steel);
    for (double St : {15.0, 80.0, 400.0})
    {
        const double v = St*6.0*M_PI*mu*Rr*Rr/Mr;
        const double e = impact(law, pairBody(0.5*di, mi, 0.5*dj, mj), v);
        EXPECT_NEAR(e, legendre(St), 1e-5) << "St = " << St;
    }
}

// The granular engine's wall and pair contacts keep each contact's approach
// speed: a grain dropped on a plane at St 40 and two grains meeting at St
// 100 rebound with Legendre's e. Tolerance 2e-3: velocity Verlet (the
// damping evaluated at the half-step velocity) at the engine's step, 1/200
// of the contact time, misses the closed-form restitution of the wall
// impact by 7e-4 at St 40 and 4e-5 at St 100 (measured; 1.6e-3 and 7e-6 at
// 1/100, 2e-4 and 1.5e-4 at 1/400: the phase of the first overlap in the
// step takes part).
TEST(WetRestitution, GranularEngineContactsReboundWithLegendresRestitution)
{
    const double d = 3e-3, mu = 0.01;
    const double M = (rhoP + 0.5*rhoF)*M_PI*d*d*d/6.0;
    const HertzMindlin law = wetLaw(mu, steel);
    {
        const double v = speedOf(40.0, d, mu);
        GranularSystem g(std::nullopt, law, Vector::Zero(), false);
        const PlaneWall floor(Vector::Zero(), Vector(0.0, 0.0, 1.0));
        g.addWall(floor);
        g.addGrain(Grain{Vector(0.0, 0.0, 0.5*d + 1e-7), Vector(0.0, 0.0, -v), Vector::Zero(),
                         0.5*d, M});
        const double h = law.contactTime(ContactBody(0.5*d, M), v)/200.0;
        for (int k = 0; k < 2000; ++k) g.step(h);
        EXPECT_NEAR(g.grains()[0].v.z()/v, legendre(40.0), 2e-3);
    }
    {
        const double v = speedOf(0.5*100.0, d, mu);  // St* = (M/2)v/(6 pi mu R^2/4) = 2 St(v)
        GranularSystem g(law, std::nullopt, Vector::Zero(), false);
        g.addGrain(Grain{Vector(0.0, 0.0, 0.0), Vector(0.0, 0.0, 0.5*v), Vector::Zero(),
                         0.5*d, M});
        g.addGrain(Grain{Vector(0.0, 0.0, d + 1e-7), Vector(0.0, 0.0, -0.5*v), Vector::Zero(),
                         0.5*d, M});
        const double h = law.contactTime(pairBody(0.5*d, M, 0.5*d, M), v)/200.0;
        for (int k = 0; k < 2000; ++k) g.step(h);
        const double e = (g.grains()[1].v.z() - g.grains()[0].v.z())/v;
        EXPECT_NEAR(e, legendre(100.0), 2e-3);
    }
}

// Refused: a wet law with the normal force clipped (no finite damping for
// e = 0), entries out of range, and a wet contact evaluated without its
// approach speed.
TEST(WetRestitution, RefusesWhatItCannotDo)
{
    HertzMindlinParameters p{steel, glass, eDry, 1.0, 0.0, NormalForceFloor::noTension};
    p.wet = WetRestitution{0.01};
    EXPECT_THROW(HertzMindlin{p}, std::invalid_argument);
    p.floor = NormalForceFloor::tensionAllowed;
    p.wet = WetRestitution{0.0};
    EXPECT_THROW(HertzMindlin{p}, std::invalid_argument);
    p.wet = WetRestitution{0.01, -1.0};
    EXPECT_THROW(HertzMindlin{p}, std::invalid_argument);
    p.wet = WetRestitution{0.01, 35.0, -1.0};
    EXPECT_THROW(HertzMindlin{p}, std::invalid_argument);
    const HertzMindlin law = wetLaw(0.01);
    const ContactBody b(1.5e-3, 1e-4);
    const Vector n(0.0, 0.0, -1.0);
    EXPECT_THROW(law.force(b, 1e-7, n, Vector(0.0, 0.0, -0.1), Vector::Zero()),
                 std::invalid_argument);
    // the dry law ignores the approach speed
    const HertzMindlin dry(HertzMindlinParameters{steel, glass, eDry, 1.0, 0.0});
    EXPECT_EQ(dry.force(b, 1e-7, n, Vector(0.0, 0.0, -0.1), Vector::Zero()).normal,
              dry.force(b, 1e-7, n, Vector(0.0, 0.0, -0.1), Vector::Zero(), 0.3).normal);
}
