// Tests of particle–particle contact and the many-grain engine
// (src/riserCore/contact/pairContact.hpp, src/riserCore/granular): Hertz
// closed forms for head-on impacts, the rigid-body impulse closed form for
// gross sliding, conservation of momentum and energy, and the cell list
// against a search over all pairs.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "granular/granularSystem.hpp"
#include "wall/planeWall.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <algorithm>
#include <memory>
#include <random>
#include <set>

using namespace riser;

namespace {

double sphereMass(double R, double rho) { return rho*4.0/3.0*M_PI*R*R*R; }

HertzMindlin law(const ElasticMaterial& a, const ElasticMaterial& b, double e, double mu,
                 double et = 1.0)
{
    return HertzMindlin(HertzMindlinParameters{a, b, e, et, mu});
}

struct Impact { double deltaMax, forceMax, duration, vAfter, vtAfter; Vector omegaI, omegaJ; };

// Two spheres approach along x at relative speed v (and slide past each other
// along y at relative speed vt), starting just touching; the engine runs
// until they separate. Step: tc/steps.
Impact collide(const HertzMindlin& pairLaw, double Ri, double mi, double Rj, double mj,
               double v, double vt, bool rotation, double tc, int steps = 4000)
{
    GranularSystem s(pairLaw, pairLaw, Vector::Zero(), rotation);
    // velocities such that the total momentum is zero
    const double M = mi + mj;
    s.addGrain(Grain{Vector(0, 0, 0), Vector(v*mj/M, vt*mj/M, 0), Vector::Zero(), Ri, mi});
    s.addGrain(Grain{Vector(Ri + Rj, 0, 0), Vector(-v*mi/M, -vt*mi/M, 0), Vector::Zero(), Rj, mj});
    const double dt = tc/steps;
    Impact r{0, 0, 0, 0, 0, Vector::Zero(), Vector::Zero()};
    bool touched = false;
    for (int k = 0; k < 100*steps; ++k)
    {
        s.step(dt);
        const bool touching = s.pairContacts() > 0;
        if (touching)
        {
            touched = true;
            r.duration += dt;
            const double d = Ri + Rj - (s.grains()[1].x - s.grains()[0].x).norm();
            r.deltaMax = std::max(r.deltaMax, d);
            r.forceMax = std::max(r.forceMax, std::abs(s.contactForce(0).x()));
        }
        else if (touched)
        {
            const Vector dv = s.grains()[1].v - s.grains()[0].v;
            r.vAfter = dv.x();          // separation speed
            r.vtAfter = -dv.y();
            r.omegaI = s.grains()[0].omega;
            r.omegaJ = s.grains()[1].omega;
            return r;
        }
    }
    ADD_FAILURE() << "contact did not end";
    return r;
}

// Hertz (Johnson 1985, sec. 11.1): undamped impact at relative speed v of
// the pair (R_eq, M_eq)
struct HertzClosedForm { double deltaMax, forceMax, duration; };
HertzClosedForm hertz(double Eeq, double Req, double Meq, double v)
{
    const double dMax = std::pow(15.0*Meq*v*v/(16.0*Eeq*std::sqrt(Req)), 0.4);
    return {dMax, 4.0/3.0*Eeq*std::sqrt(Req)*std::pow(dMax, 1.5),
            2.8683*std::pow(Meq*Meq/(Req*Eeq*Eeq*v), 0.2)};
}

// Soda-lime glass spheres, R = 10 mm, as in Chung & Ooi (Granular Matter 13,
// 643, 2011) test 1; impact at 10 m/s relative speed.
const ElasticMaterial glass(4.8e10, 0.20);
const double rhoGlass = 2800.0;
const ElasticMaterial steel(2.0e11, 0.29);
const double rhoSteel = 7800.0;

// The scene of the hand-over tests: a glass pair that meets obliquely at
// 0.2 m/s (approach) with 0.1 m/s sliding, over a floor at z = -0.1, with
// gravity and rotation; third, a grain on the floor (position, velocity,
// spin given)
std::unique_ptr<GranularSystem> handOverScene(const HertzMindlin& l, const PlaneWall& floor)
{
    auto s = std::make_unique<GranularSystem>(l, l, Vector(0, 0, -9.81), true);
    s->addWall(floor);
    return s;
}

//- Hand the contact forces of one system's last evaluation to another
void handOverForces(const GranularSystem& from, GranularSystem& to)
{
    std::vector<Vector> F, T;
    for (std::size_t i = 0; i < from.grains().size(); ++i)
    {
        F.push_back(from.contactForce(i));
        T.push_back(from.contactTorque(i));
    }
    to.setContactForces(F, T);
}

void addHandOverGrains(GranularSystem& s, double R, double m, const Vector& x3,
                       const Vector& v3, const Vector& omega3)
{
    s.addGrain(Grain{Vector(0, 0, 0), Vector(0.1, 0.05, 0), Vector::Zero(), R, m});
    s.addGrain(Grain{Vector(2*R, 0, 0), Vector(-0.1, -0.05, 0), Vector::Zero(), R, m});
    s.addGrain(Grain{x3, v3, omega3, R, m});
}

} // namespace


// Identical spheres: R_eq = R/2, M_eq = m/2. The engine steps at tc/4000:
// velocity Verlet is second order, so the discrete peak and duration are
// within ~(1/4000) of the continuous ones; delta_max, F_max and t_c must be
// within the 0.5 % a user can ask of a DEM code (checked much tighter: 0.1 %,
// which the step resolves 4 times over).
TEST(PairContact, HeadOnIdenticalSpheresMatchHertz)
{
    const double R = 0.01, m = sphereMass(R, rhoGlass), v = 10.0;
    const HertzMindlin l = law(glass, glass, 1.0, 0.0);
    const HertzClosedForm h = hertz(l.equivalentYoungModulus(), R/2, m/2, v);
    const Impact r = collide(l, R, m, R, m, v, 0.0, false, h.duration);
    EXPECT_NEAR(r.deltaMax/h.deltaMax, 1.0, 1e-3);
    EXPECT_NEAR(r.forceMax/h.forceMax, 1.0, 1e-3);
    EXPECT_NEAR(r.duration/h.duration, 1.0, 1e-3);
    EXPECT_NEAR(r.vAfter/v, 1.0, 1e-3);
    // E_eq of two like spheres: E / (2 (1 - nu^2))
    EXPECT_NEAR(l.equivalentYoungModulus(), 4.8e10/(2*(1 - 0.04)), 1.0);
}

// Unequal sizes and densities: steel R = 6 mm against glass R = 10 mm.
TEST(PairContact, HeadOnUnequalSpheresMatchHertz)
{
    const double Ri = 0.01, mi = sphereMass(Ri, rhoGlass);
    const double Rj = 0.006, mj = sphereMass(Rj, rhoSteel);
    const double v = 2.0;
    const HertzMindlin l = law(glass, steel, 1.0, 0.0);
    const double Req = Ri*Rj/(Ri + Rj), Meq = mi*mj/(mi + mj);
    const HertzClosedForm h = hertz(l.equivalentYoungModulus(), Req, Meq, v);
    const Impact r = collide(l, Ri, mi, Rj, mj, v, 0.0, false, h.duration);
    EXPECT_NEAR(r.deltaMax/h.deltaMax, 1.0, 1e-3);
    EXPECT_NEAR(r.forceMax/h.forceMax, 1.0, 1e-3);
    EXPECT_NEAR(r.duration/h.duration, 1.0, 1e-3);
    const double Eeq = 1.0/((1 - 0.04)/4.8e10 + (1 - 0.29*0.29)/2.0e11);
    EXPECT_NEAR(l.equivalentYoungModulus()/Eeq, 1.0, 1e-14);
}

// The damping is calibrated on M_eq, so the pair rebounds with e_n: within
// 0.5 % (the target), for like and unlike pairs.
TEST(PairContact, RestitutionOfPairsEqualsTarget)
{
    for (double e : {0.3, 0.76, 1.0})
    {
        const double Ri = 0.01, mi = sphereMass(Ri, rhoGlass);
        const double Rj = 0.006, mj = sphereMass(Rj, rhoSteel);
        const HertzMindlin like = law(glass, glass, e, 0.0);
        const HertzMindlin unlike = law(glass, steel, e, 0.0);
        const double v = 1.0;
        const double tcLike = hertz(like.equivalentYoungModulus(), Ri/2, mi/2, v).duration;
        const double tcUnlike = hertz(unlike.equivalentYoungModulus(), Ri*Rj/(Ri + Rj),
                                      mi*mj/(mi + mj), v).duration;
        EXPECT_NEAR(collide(like, Ri, mi, Ri, mi, v, 0, false, tcLike).vAfter/v, e, 5e-3*e) << e;
        EXPECT_NEAR(collide(unlike, Ri, mi, Rj, mj, v, 0, false, tcUnlike).vAfter/v, e, 5e-3*e) << e;
    }
}

// Oblique impact in gross sliding: the tangential impulse is mu times the
// normal one throughout, so (rigid-body impulse theory; Maw, Barber &
// Fawcett, Wear 38, 101, 1976; Chung & Ooi 2011 test 6) the relative
// tangential velocity of the centres drops by mu (1 + e) v_n, and with
// rotation each sphere spins up by R_k mu (1 + e) v_n M_eq / I_k. This holds
// when the normal force never pulls: the Coulomb limit is mu |F_n|, so a
// dashpot that pulls at the end of a damped contact adds tangential but
// removes normal impulse (+1.3 % at e = 0.76); the cases are therefore an
// elastic contact and a damped one with the normal force floored at zero.
// The theory takes the normal as fixed; in the simulation it turns by about
// v_t t_c / (R_i + R_j) while the spheres slide past each other, which moves
// part of the normal impulse into the tangential direction. At v_n = 1 cm/s,
// v_t = 2.5 v_n (gross sliding with rotation needs v_t > 7/2 mu (1 + e) v_n
// <= 2.1 v_n) that turn is ~4e-4 rad, an error of ~turn/mu ~ 0.1 %: 0.5 % is
// allowed.
TEST(PairContact, ObliqueGrossSlidingMatchesImpulseTheory)
{
    const double R = 0.01, m = sphereMass(R, rhoGlass);
    const double Rj = 0.006, mj = sphereMass(Rj, rhoSteel);
    const double mu = 0.3, vn = 0.01, vt = 0.025;
    const double Req = R*Rj/(R + Rj), Meq = m*mj/(m + mj);
    for (const auto floor : {NormalForceFloor::tensionAllowed, NormalForceFloor::noTension})
    for (bool rotation : {false, true})
    {
        const double e = floor == NormalForceFloor::tensionAllowed ? 1.0 : 0.76;
        const HertzMindlin l(HertzMindlinParameters{glass, steel, e, 0.5, mu, floor});
        const double tc = hertz(l.equivalentYoungModulus(), Req, Meq, vn).duration;
        const Impact r = collide(l, R, m, Rj, mj, vn, vt, rotation, tc);
        EXPECT_NEAR(r.vAfter/vn, e, 5e-3*e) << e << rotation;
        const double drop = mu*(1 + e)*vn;
        EXPECT_NEAR((vt - r.vtAfter)/drop, 1.0, 5e-3) << e << rotation;
        if (rotation)
        {
            // the tangential impulse on i is -J_t y (it slides along +y
            // relative to j); spin about z: omega_i = R_i n x J_t / I_i
            const double Jt = mu*(1 + e)*vn*Meq;
            EXPECT_NEAR(r.omegaI.z()/(-R*Jt/(0.4*m*R*R)), 1.0, 5e-3) << e;
            EXPECT_NEAR(r.omegaJ.z()/(-Rj*Jt/(0.4*mj*Rj*Rj)), 1.0, 5e-3) << e;
        }
    }
}

namespace {

// N grains with random velocities in a closed box, no gravity
struct Box
{
    std::vector<std::unique_ptr<PlaneWall>> faces;
    explicit Box(double L)
    {
        for (int k = 0; k < 3; ++k)
        {
            Vector m = Vector::Zero();
            m[k] = 1.0;
            faces.emplace_back(new PlaneWall(Vector::Zero(), m));
            faces.emplace_back(new PlaneWall(L*m, -m));
        }
    }
};

void fillBox(GranularSystem& s, double L, int n, double R, double rho, unsigned seed)
{
    std::mt19937 gen(seed);
    std::uniform_real_distribution<double> u(R*1.05, L - R*1.05), w(-1.0, 1.0), size(0.7, 1.0);
    std::vector<Grain> placed;
    while (int(placed.size()) < n)
    {
        const double r = R*size(gen);
        const Vector x(u(gen), u(gen), u(gen));
        bool free = true;
        for (const Grain& q : placed) free = free && (q.x - x).norm() > q.radius + r;
        if (!free) continue;
        placed.push_back(Grain{x, Vector(w(gen), w(gen), w(gen)), Vector::Zero(), r, sphereMass(r, rho)});
    }
    for (const Grain& q : placed) s.addGrain(q);
}

// 300 grains of radius 0.7 R .. R (glass) at random in a closed box of side
// L, moving at random, no gravity; the walls and the pairs of one law
struct BoxOfGrains
{
    static constexpr double L = 0.1, R = 0.006;
    Box box;
    GranularSystem s;
    BoxOfGrains(const HertzMindlin& l, bool rotation, unsigned seed)
    :
        box(L), s(l, l, Vector::Zero(), rotation)
    {
        for (const auto& f : box.faces) s.addWall(*f);
        fillBox(s, L, 300, R, rhoGlass, seed);
    }
};

} // namespace

// Pair forces are equal and opposite: the grains' momentum changes only by
// what the walls gave, to round-off, over more than 1,000 pair contacts
// (frictional, inelastic, rotating: every term of the law).
TEST(GranularSystem, PairsConserveMomentum)
{
    BoxOfGrains scene(law(glass, glass, 0.5, 0.4, 0.5), true, 7);
    GranularSystem& s = scene.s;
    const Vector p0 = s.momentum();
    double scale = 0.0;
    for (const Grain& q : s.grains()) scale += q.mass*q.v.norm();
    const double dt = 2e-6;
    while (s.pairContactsBegun() < 1000) s.step(dt);
    // each step adds round-off of ~1e-16 of the momenta involved; over
    // ~1e4 steps that stays below 1e-12 of sum m|v|
    EXPECT_LT((s.momentum() - p0 - s.wallImpulse()).norm(), 1e-12*scale);
    EXPECT_GT(s.wallContactsBegun(), 100);
}

// e_n = 1, mu = 0: the grains' kinetic energy plus the contacts' elastic
// energy is constant: within 1e-4 over more than 1,000 contacts. Velocity
// Verlet conserves a shadow energy; the error of each contact is of order
// (dt/t_c)^2, here dt = t_c/100.
TEST(GranularSystem, ElasticFrictionlessContactsConserveEnergy)
{
    const HertzMindlin l = law(glass, glass, 1.0, 0.0);
    BoxOfGrains scene(l, false, 11);
    GranularSystem& s = scene.s;
    const double R = BoxOfGrains::R;
    const double e0 = s.energy();
    // contact time at the largest relative speed (2 sqrt 3 m/s), smallest grain
    const double Rmin = 0.7*R, mmin = sphereMass(Rmin, rhoGlass);
    const double tc = hertz(l.equivalentYoungModulus(), Rmin/2, mmin/2, 2*std::sqrt(3.0)).duration;
    double worst = 0.0;
    while (s.pairContactsBegun() + s.wallContactsBegun() < 1000)
    {
        s.step(tc/100);
        worst = std::max(worst, std::abs(s.energy()/e0 - 1.0));
    }
    EXPECT_LT(worst, 1e-4);
}

// The cell list finds exactly the pairs closer than the cutoff that a
// search over all pairs finds, for a dense cloud and for a sparse one with
// a dense cluster; it visits a number of candidate pairs proportional to N
// (each centre meets those of 14 cells of side cutoff: at the densities here
// at most about 60 per centre), not N^2/2.
TEST(CellList, FindsEveryClosePair)
{
    std::mt19937 gen(3);
    for (double spread : {0.05, 5.0})
    {
        // a cloud of the given spread with a dense cluster in one corner
        std::uniform_real_distribution<double> u(0.0, spread), corner(0.0, 0.05);
        std::vector<Vector> x;
        for (int i = 0; i < 1000; ++i) x.emplace_back(u(gen), u(gen), 0.3*u(gen));
        for (int i = 0; i < 1000; ++i) x.emplace_back(corner(gen), corner(gen), corner(gen));
        x.emplace_back(0.0, 0.0, 0.0);    // a point on the box's corner
        const double cut = 0.004;
        std::set<std::pair<std::size_t, std::size_t>> brute, cells;
        for (std::size_t i = 0; i < x.size(); ++i)
            for (std::size_t j = i + 1; j < x.size(); ++j)
                if ((x[i] - x[j]).norm() < cut) brute.insert({i, j});
        CellList c;
        c.build(x, cut);
        long visits = 0;
        c.forEachPair([&](std::size_t i, std::size_t j)
        {
            ++visits;
            EXPECT_NE(i, j);
            if ((x[i] - x[j]).norm() < cut) cells.insert({std::min(i, j), std::max(i, j)});
        });
        EXPECT_EQ(brute, cells) << spread;
        EXPECT_GT(brute.size(), 0u);
        EXPECT_LT(visits, long(x.size())*60) << spread;
    }
}


// The periodic pair search against all pairs with the minimum-image
// distance along z: the same pairs, each once, with i < j and the shift of
// j's nearest image (independent oracle: a double loop over all pairs).
TEST(NearPairs, FindsEveryClosePairAcrossPeriodicEnds)
{
    std::mt19937 gen(7);
    const double z0 = -0.3, L = 0.2, cut = 0.01;
    std::uniform_real_distribution<double> xy(0.0, 0.05), z(z0, z0 + L);
    std::vector<Vector> x;
    for (int i = 0; i < 2000; ++i) x.emplace_back(xy(gen), xy(gen), z(gen));
    x.emplace_back(0.0, 0.0, z0);           // on the lower end
    x.emplace_back(0.0, 0.0, z0 + L - 1e-4);   // just below the upper end
    std::map<std::pair<std::size_t, std::size_t>, double> brute, found;
    for (std::size_t i = 0; i < x.size(); ++i)
    {
        for (std::size_t j = i + 1; j < x.size(); ++j)
        {
            for (const double dz : {0.0, L, -L})
            {
                if ((x[j] + Vector(0, 0, dz) - x[i]).norm() < cut) brute[{i, j}] = dz;
            }
        }
    }
    NearPairs pairs;
    pairs.setPeriodic(z0, L);
    long visits = 0;
    pairs.forEachPair(x, cut, [&](std::size_t i, std::size_t j, double dz)
    {
        ++visits;
        EXPECT_LT(i, j);
        if ((x[j] + Vector(0, 0, dz) - x[i]).norm() < cut)
        {
            EXPECT_TRUE(found.emplace(std::make_pair(i, j), dz).second) << i << ' ' << j;
        }
    });
    EXPECT_EQ(brute, found);
    EXPECT_GT(std::count_if(brute.begin(), brute.end(),
                            [](const auto& p) { return p.second != 0.0; }), 0);
    // a section not longer than twice the cutoff is refused
    NearPairs shortSection;
    shortSection.setPeriodic(z0, 2*cut);
    EXPECT_THROW(shortSection.forEachPair(x, cut, [](std::size_t, std::size_t, double) {}),
                 std::invalid_argument);
}


// A processor may hold none of a group's grains: an engine without grains
// in a periodic section steps (no pairs, no error; its cutoff is then 0).
TEST(GranularSystem, StepsWithoutGrainsInAPeriodicSection)
{
    const HertzMindlin l = law(glass, glass, 0.76, 0.3);
    GranularSystem empty(l, l, Vector(0, 0, -9.81), false);
    empty.setPeriodic(0.0, 0.1);
    EXPECT_NO_THROW(for (int k = 0; k < 3; ++k) empty.step(1e-5));
    EXPECT_EQ(empty.pairContacts(), 0u);
    NearPairs pairs;
    pairs.setPeriodic(0.0, 0.1);
    long visits = 0;
    pairs.forEachPair(std::vector<Vector>(), 0.0, [&](std::size_t, std::size_t, double) { ++visits; });
    EXPECT_EQ(visits, 0);
}


// A grain's own acceleration is integrated exactly by velocity Verlet when
// it is constant: x = x0 + v0 T + a T^2/2, v = v0 + a T (to round-off,
// relative 1e-12 over 1000 steps).
TEST(GranularSystem, OwnAccelerationIsIntegratedExactly)
{
    const HertzMindlin l = law(glass, glass, 0.76, 0.3);
    GranularSystem s(l, l, Vector(0, 0, -9.81), false);
    Grain g{Vector(0.1, -0.2, 0.3), Vector(0.5, 0.0, -1.0), Vector::Zero(), 0.005,
            sphereMass(0.005, rhoGlass)};
    g.accel = Vector(1.5, -2.0, 4.0);
    s.addGrain(g);
    const double T = 0.01;
    for (int k = 0; k < 1000; ++k) s.step(T/1000);
    const Vector a = g.accel + Vector(0, 0, -9.81);
    const Vector x = g.x + T*g.v + 0.5*T*T*a;
    const Vector v = g.v + T*a;
    EXPECT_LT((s.grains()[0].x - x).norm(), 1e-12*x.norm());
    EXPECT_LT((s.grains()[0].v - v).norm(), 1e-12*v.norm());
}

// A grain's own acceleration linear in its velocity, a0 + beta (u - v) (a
// fluid's drag linearised): velocity Verlet with the half-step velocity is
// second order, v(t) = u + a0/beta + (v0 - u - a0/beta) exp(-beta t): at
// beta dt = 0.01 over t = 2/beta the error is ~(beta dt)^2 = 1e-4 of the
// change at most, and a quarter of it at half the step.
TEST(GranularSystem, LinearDragIsSecondOrder)
{
    const HertzMindlin l = law(glass, glass, 0.76, 0.3);
    const double beta = 20.0, T = 2.0/beta;
    const Vector u(0.1, 0.0, 1.0), a0(0.0, 0.0, -3.0), v0(0.5, -0.2, 0.0);
    auto error = [&](int steps)
    {
        GranularSystem s(l, std::nullopt, Vector::Zero(), false);
        Grain g{Vector::Zero(), v0, Vector::Zero(), 0.005, sphereMass(0.005, rhoGlass)};
        g.accel = a0;
        g.drag = beta;
        g.carrierVelocity = u;
        s.addGrain(g);
        for (int k = 0; k < steps; ++k) s.step(T/steps);
        const Vector vInf = u + a0/beta;
        const Vector exact = vInf + (v0 - vInf)*std::exp(-beta*T);
        return (s.grains()[0].v - exact).norm()/(v0 - vInf).norm();
    };
    const double coarse = error(200), fine = error(400);
    EXPECT_LT(coarse, 1e-4);
    EXPECT_NEAR(coarse/fine, 4.0, 0.2);
    GranularSystem s(l, std::nullopt, Vector::Zero(), false);
    Grain g{Vector::Zero(), v0, Vector::Zero(), 0.005, 1.0};
    g.drag = beta;
    s.addGrain(g);
    EXPECT_THROW(s.step(2.0/beta), std::invalid_argument);   // beta dt > 1
}

// Either kind of contact may be left out. Without a pair law two grains on
// a head-on course pass through each other in free flight (x = x0 + v T to
// round-off: no force ever acts), while one of them still rebounds from a
// wall with e_n (the Hertz-Tsuji damping is calibrated for it; within 0.5 %
// at t_c/200 steps, the first-order error of the velocity Verlet
// restitution). Without a wall law a wall is refused.
TEST(GranularSystem, EitherContactMayBeLeftOut)
{
    const double R = 0.005, m = sphereMass(R, rhoGlass), v = 1.0;
    const HertzMindlin l = law(glass, glass, 0.76, 0.3);
    const double tc = hertz(l.equivalentYoungModulus(), R, m, v).duration;
    const PlaneWall floor(Vector(0, 0, 0), Vector(0, 0, 1));
    GranularSystem s(std::nullopt, l, Vector::Zero(), false);
    s.addWall(floor);
    s.addGrain(Grain{Vector(0, 0, 0.05), Vector(0, 0, -v), Vector::Zero(), R, m});
    s.addGrain(Grain{Vector(0, 0, 0.05 + 3*R), Vector(0, 0, v), Vector::Zero(), R, m});
    s.addGrain(Grain{Vector(0, 0, 0.05 + 6*R), Vector(0, 0, -v), Vector::Zero(), R, m});
    const double dt = tc/200, T = 0.05;
    const int steps = int(T/dt);
    for (int k = 0; k < steps; ++k) s.step(dt);
    // grains 1 and 2 crossed each other (they were 3R apart, closing at 2v)
    EXPECT_EQ(s.pairContacts(), 0u);
    const double t = steps*dt;
    EXPECT_NEAR(s.grains()[1].x.z(), 0.05 + 3*R + v*t, 1e-12);
    EXPECT_NEAR(s.grains()[2].x.z(), 0.05 + 6*R - v*t, 1e-12);
    EXPECT_NEAR(s.grains()[0].v.z(), 0.76*v, 0.005*0.76*v);

    GranularSystem dry(l, std::nullopt, Vector::Zero(), false);
    EXPECT_THROW(dry.addWall(floor), std::invalid_argument);
}

// Two spheres meeting across the ends of a periodic section (one just below
// z0 + L moving up, one just above z0 moving down) collide exactly as the
// same pair in the middle: the same separation velocities to round-off.
TEST(GranularSystem, PairsMeetAcrossPeriodicEnds)
{
    const double R = 0.005, m = sphereMass(R, rhoGlass), v = 1.0;
    const HertzMindlin l = law(glass, glass, 0.76, 0.3);
    const double tc = hertz(l.equivalentYoungModulus(), R/2, m/2, v).duration;
    auto run = [&](double zi, double zj, bool periodic)
    {
        GranularSystem s(l, l, Vector::Zero(), false);
        if (periodic) s.setPeriodic(0.0, 0.2);
        s.addGrain(Grain{Vector(0, 0, zi), Vector(0.1, 0, 0.5*v), Vector::Zero(), R, m});
        s.addGrain(Grain{Vector(0, 0, zj), Vector(0, 0, -0.5*v), Vector::Zero(), R, m});
        for (int k = 0; k < 4000; ++k) s.step(tc/1000);
        return std::make_pair(s.grains()[0].v, s.grains()[1].v);
    };
    // 0.1 mm gap, closed after 1e-4 s
    // to round-off: positions near 0.2 m against overlaps of ~1e-5 m give
    // relative force errors of ~1e-16 * 0.2/1e-5 = 2e-12; 1e-10 m/s allowed
    const auto middle = run(0.1 - R - 5e-5, 0.1 + R + 5e-5, false);
    const auto ends = run(0.2 - R - 5e-5, R + 5e-5, true);
    EXPECT_GT(middle.first.z(), -0.5*0.76*v*1.01);
    EXPECT_LT(middle.first.z(), -0.5*0.76*v*0.99);   // it did rebound
    EXPECT_LT((ends.first - middle.first).norm(), 1e-10);
    EXPECT_LT((ends.second - middle.second).norm(), 1e-10);
}

// Handing a contact over: a sticking oblique pair contact and a grain
// rolling on a wall are run for half of their time, their state (positions,
// velocities, spins, springs) is copied into a new system, which runs the
// rest. The result equals the uninterrupted run's to round-off. (The
// forces are handed over too: a sliding contact's capped spring, -F_t/k_t,
// does not give back F_t, whose damping part it leaves out.)
TEST(GranularSystem, ContactStateHandedOverEqualsUninterruptedRun)
{
    const double R = 0.005, m = sphereMass(R, rhoGlass);
    const HertzMindlin l = law(glass, glass, 0.76, 1.0);
    const double tc = hertz(l.equivalentYoungModulus(), R/2, m/2, 0.1).duration;
    const PlaneWall floor(Vector(0, 0, -0.1), Vector(0, 0, 1));
    auto fresh = [&]() { return handOverScene(l, floor); };
    auto setUp = [&](GranularSystem& s)
    {
        // resting on the floor, sliding
        // (the static overlap under gravity is 3e-8 m)
        addHandOverGrains(s, R, m, Vector(0.05, 0, -0.1 + R - 3e-8), Vector(0.2, 0, 0),
                          Vector::Zero());
    };
    // the pair touches for ~0.9 tc: handed over in its middle
    const int n = 400;
    const double dt = tc/n;
    auto whole = fresh();
    setUp(*whole);
    for (int k = 0; k < n; ++k) whole->step(dt);

    auto first = fresh();
    setUp(*first);
    for (int k = 0; k < n/2; ++k) first->step(dt);
    ASSERT_GT(first->pairContacts(), 0u);
    ASSERT_GT(first->wallContacts(), 0u);
    auto second = fresh();
    for (const Grain& g : first->grains()) second->addGrain(g);
    second->setTime(first->time());
    first->forEachPairContact([&](std::size_t i, std::size_t j, const Vector& s)
    {
        // set in j's frame on purpose: the system turns it into i's
        second->setPairSpring(j, i, -s);
    });
    for (std::size_t i = 0; i < first->grains().size(); ++i)
    {
        if (first->wallContact(i, 0).touching)
        {
            second->setWallSpring(i, 0, first->wallSpring(i, 0));
        }
    }
    handOverForces(*first, *second);
    for (int k = n/2; k < n; ++k) second->step(dt);
    // round-off: the summation order of the forces may differ (the Verlet
    // lists are built at other times); x ~ 0.1 m, v ~ 0.1 m/s, omega ~ 20/s
    for (std::size_t i = 0; i < 3; ++i)
    {
        const Grain& a = whole->grains()[i];
        const Grain& b = second->grains()[i];
        EXPECT_LT((a.x - b.x).norm(), 1e-14) << i;
        EXPECT_LT((a.v - b.v).norm(), 1e-12) << i;
        EXPECT_LT((a.omega - b.omega).norm(), 1e-9) << i;
    }
    // without the springs the tangential history is lost: a visible change
    auto forgetful = fresh();
    for (const Grain& g : first->grains()) forgetful->addGrain(g);
    forgetful->setTime(first->time());
    for (int k = n/2; k < n; ++k) forgetful->step(dt);
    EXPECT_GT((forgetful->grains()[0].v - whole->grains()[0].v).norm(), 1e-6);
}

// --- energy dissipated in contacts ------------------------------------------
//
// The engine tallies, per grain, the work of each contact's force on the
// contact's relative motion (granularSystem.hpp, top): the trapezoid in the
// force over each step, with the step's half-step velocities. Two checks of
// different strength:
//   - against the kinetic energy the grains lost: exact to round-off over an
//     impact that starts and ends without contact force (the tally is the
//     work of velocity Verlet's kicks, and the rest of the kinetic energy
//     change over a step, m h^2/8 (|a_1|^2 - |a_0|^2), telescopes to zero);
//   - against the closed form of the continuous impact, 1/2 M v^2 (1 - e^2)
//     (the damping ratio reproduces e to 1e-6, restitution.hpp): the
//     difference is the discrete trajectory's. The trapezoid is second
//     order for a smooth force, but a contact starts and ends inside a step,
//     where the Hertz spring (~ delta^(3/2)) and above all the damping
//     (~ delta^(1/4)) are not smooth: the error is first order in the step
//     and changes with the phase of the contact's ends against the steps.
//     Measured for N = 50 ... 4000 steps per contact time, e = 0.3, 0.76,
//     0.9, either floor of the normal force: below 0.15/N of 1/2 M v^2
//     (1.5e-3 at N = 100, 8e-5 at N = 1000). Allowed: 0.25/N, at N = 1000
//     and N = 4000.

namespace {

struct Dissipation
{
    double tallied;         // sum of both grains' (or the grain's) tallies
    double kineticLoss;     // kinetic energy before - after (with spin)
    double half0, half1;    // each grain's pair tally
    long completed0, completed1;
    double impact0, impact1;
};

// Two grains approach along x at relative speed v (and slide along y at vt),
// starting just touching, zero total momentum; run until they part, then a
// few steps more
Dissipation pairImpact(const HertzMindlin& l, double Ri, double mi, double Rj, double mj,
                       double v, double vt, bool rotation, double tc, int steps)
{
    GranularSystem s(l, l, Vector::Zero(), rotation);
    const double M = mi + mj;
    s.addGrain(Grain{Vector(0, 0, 0), Vector(v*mj/M, vt*mj/M, 0), Vector::Zero(), Ri, mi});
    s.addGrain(Grain{Vector(Ri + Rj, 0, 0), Vector(-v*mi/M, -vt*mi/M, 0), Vector::Zero(),
                     Rj, mj});
    const double e0 = s.kineticEnergy();
    bool touched = false;
    for (int k = 0; k < 100*steps; ++k)
    {
        s.step(tc/steps);
        touched = touched || s.pairContacts() > 0;
        if (touched && s.pairContacts() == 0) break;
    }
    EXPECT_TRUE(touched && s.pairContacts() == 0) << "the contact did not end";
    for (int k = 0; k < 10; ++k) s.step(tc/steps);
    return Dissipation{s.dissipatedEnergy(), e0 - s.kineticEnergy(), s.pairEnergy(0),
                       s.pairEnergy(1), s.pairContactsCompleted(0),
                       s.pairContactsCompleted(1), s.pairImpactSpeed(0),
                       s.pairImpactSpeed(1)};
}

} // namespace

// Head-on: 1/2 M_eq v^2 (1 - e^2), like and unlike spheres, e = 0.3, 0.76, 1
TEST(ContactEnergy, HeadOnPairImpactDissipatesClosedForm)
{
    const double Ri = 0.01, mi = sphereMass(Ri, rhoGlass);
    const double Rj = 0.006, mj = sphereMass(Rj, rhoSteel);
    const double v = 1.0;
    for (double e : {0.3, 0.76, 1.0})
    for (bool unlike : {false, true})
    for (int N : {1000, 4000})
    {
        const double R2 = unlike ? Rj : Ri, m2 = unlike ? mj : mi;
        const HertzMindlin l = law(glass, unlike ? steel : glass, e, 0.3);
        const double Meq = mi*m2/(mi + m2);
        const double tc = hertz(l.equivalentYoungModulus(), Ri*R2/(Ri + R2), Meq, v).duration;
        const double scale = 0.5*Meq*v*v;
        const double want = scale*(1 - e*e);
        const Dissipation d = pairImpact(l, Ri, mi, R2, m2, v, 0.0, false, tc, N);
        const double error = (d.tallied - want)/scale;
        std::printf("pair e = %.2f %-6s N = %4d: tallied %.9e J, 1/2 M v^2 (1 - e^2)"
                    " = %.9e J, error %.2e of 1/2 M v^2 (allowed %.1e)\n",
                    e, unlike ? "unlike" : "like", N, d.tallied, want, error, 0.25/N);
        EXPECT_LT(std::abs(error), 0.25/N) << e << unlike << N;
        // the kinetic energy lost: to round-off
        EXPECT_NEAR(d.tallied, d.kineticLoss, 1e-12*scale) << e << unlike;
        // half to each grain; one contact each, met at speed v (no force
        // before the contact: the half-step velocity is v)
        EXPECT_NEAR(d.half0, d.half1, 1e-15*scale);
        EXPECT_EQ(d.completed0, 1);
        EXPECT_EQ(d.completed1, 1);
        EXPECT_NEAR(d.impact0, v, 1e-12);
        EXPECT_NEAR(d.impact1, v, 1e-12);
    }
}

// A grain against a plane wall at normal speed v: 1/2 m v^2 (1 - e^2), all
// of it the grain's wallEnergy
TEST(ContactEnergy, WallImpactDissipatesClosedForm)
{
    const double R = 0.005, m = sphereMass(R, rhoGlass), v = 0.8;
    const PlaneWall floor(Vector(0, 0, 0), Vector(0, 0, 1));
    for (double e : {0.3, 0.76, 1.0})
    for (int N : {1000, 4000})
    {
        const HertzMindlin l = law(glass, steel, e, 0.3);
        const double tc = hertz(l.equivalentYoungModulus(), R, m, v).duration;
        GranularSystem s(l, l, Vector::Zero(), false);
        s.addWall(floor);
        s.addGrain(Grain{Vector(0, 0, R), Vector(0, 0, -v), Vector::Zero(), R, m});
        const double e0 = s.kineticEnergy();
        for (int k = 0; k < 3*N; ++k) s.step(tc/N);
        ASSERT_EQ(s.wallContacts(), 0u);
        ASSERT_EQ(s.wallContactsBegun(), 1);
        const double scale = 0.5*m*v*v, want = scale*(1 - e*e);
        const double error = (s.wallEnergy(0) - want)/scale;
        std::printf("wall e = %.2f N = %4d: tallied %.9e J, 1/2 m v^2 (1 - e^2) = %.9e J,"
                    " error %.2e of 1/2 m v^2 (allowed %.1e)\n",
                    e, N, s.wallEnergy(0), want, error, 0.25/N);
        EXPECT_LT(std::abs(error), 0.25/N) << e << N;
        EXPECT_NEAR(s.wallEnergy(0), e0 - s.kineticEnergy(), 1e-12*scale) << e;
        EXPECT_EQ(s.pairEnergy(0), 0.0);
    }
}

// Oblique impacts in gross sliding, with rotation: the kinetic energy lost,
// translation and spin, is the tally (round-off, as above); friction takes
// a visible share beyond the normal damping's 1/2 M v_n^2 (1 - e^2)
TEST(ContactEnergy, ObliqueSlidingImpactLosesTheTalliedEnergy)
{
    const double R = 0.01, m = sphereMass(R, rhoGlass);
    const double Rj = 0.006, mj = sphereMass(Rj, rhoSteel);
    const double mu = 0.3, vn = 0.01, vt = 0.025, e = 0.76;
    const double Meq = m*mj/(m + mj);
    for (const auto floor : {NormalForceFloor::tensionAllowed, NormalForceFloor::noTension})
    {
        const HertzMindlin l(HertzMindlinParameters{glass, steel, e, 0.5, mu, floor});
        const double tc = hertz(l.equivalentYoungModulus(), R*Rj/(R + Rj), Meq, vn).duration;
        const Dissipation d = pairImpact(l, R, m, Rj, mj, vn, vt, true, tc, 400);
        const double normal = 0.5*Meq*vn*vn*(1 - e*e);
        std::printf("oblique pair: kinetic energy lost %.6e J, tallied %.6e J, normal"
                    " damping alone %.6e J\n", d.kineticLoss, d.tallied, normal);
        EXPECT_NEAR(d.tallied, d.kineticLoss, 1e-12*0.5*Meq*(vn*vn + vt*vt));
        EXPECT_GT(d.tallied, 1.5*normal);
    }
    // a spinning grain sliding onto a wall at 30 degrees
    const PlaneWall floor(Vector(0, 0, 0), Vector(0, 0, 1));
    const HertzMindlin l = law(glass, steel, e, mu, 0.5);
    GranularSystem s(l, l, Vector::Zero(), true);
    s.addWall(floor);
    s.addGrain(Grain{Vector(0, 0, R), Vector(0.5, 0.1, -0.3), Vector(5, -20, 3), R, m});
    const double e0 = s.kineticEnergy();
    const double tc = hertz(l.equivalentYoungModulus(), R, m, 0.3).duration;
    for (int k = 0; k < 300; ++k) s.step(tc/100);
    ASSERT_EQ(s.wallContacts(), 0u);
    std::printf("oblique wall: kinetic energy lost %.6e J, tallied %.6e J\n",
                e0 - s.kineticEnergy(), s.wallEnergy(0));
    EXPECT_NEAR(s.wallEnergy(0), e0 - s.kineticEnergy(), 1e-12*e0);
    EXPECT_GT(s.wallEnergy(0), 1.5*0.5*m*0.09*(1 - e*e));
}

// A closed box of 300 grains, no gravity, damped frictional contacts with
// rotation, 1,000 contacts: the kinetic energy lost equals the sum of the
// tallies less h^2/8 sum (|F_i|^2/m_i + |T_i|^2/I_i) of the contact forces
// and torques now (the telescoped rest of velocity Verlet's kinetic
// energy; 0 at the start, where nothing touches): checked at every step to
// round-off (1e-12 of the initial kinetic energy over ~1e5 steps). The
// tallies of the contacts in progress hold the elastic energy they store
// and give back as they end; at a moment with no contact in progress the
// elastic energy is 0 and the loss equals the tallies.
TEST(ContactEnergy, BoxOfGrainsLosesTheTalliedEnergy)
{
    const HertzMindlin l = law(glass, glass, 0.5, 0.4, 0.5);
    BoxOfGrains scene(l, true, 5);
    GranularSystem& s = scene.s;
    const double R = BoxOfGrains::R;
    const double e0 = s.kineticEnergy();
    const double Rmin = 0.7*R, mmin = sphereMass(Rmin, rhoGlass);
    const double tc = hertz(l.equivalentYoungModulus(), Rmin/2, mmin/2, 2*std::sqrt(3.0)).duration;
    const double h = tc/100;
    double worst = 0.0, largestRest = 0.0, largestElastic = 0.0;
    bool balancedAtRest = false;
    while (s.pairContactsBegun() + s.wallContactsBegun() < 1000 || !balancedAtRest)
    {
        s.step(h);
        double rest = 0.0;
        for (std::size_t i = 0; i < s.grains().size(); ++i)
        {
            const Grain& g = s.grains()[i];
            rest += h*h/8*(s.contactForce(i).squaredNorm()/g.mass
                         + s.contactTorque(i).squaredNorm()/(0.4*g.mass*g.radius*g.radius));
        }
        const double lost = e0 - s.kineticEnergy();
        worst = std::max(worst, std::abs(lost - (s.dissipatedEnergy() - rest)));
        largestRest = std::max(largestRest, rest);
        largestElastic = std::max(largestElastic, s.elasticEnergy());
        if (s.pairContacts() + s.wallContacts() == 0
         && s.pairContactsBegun() + s.wallContactsBegun() >= 1000)
        {
            double walls = 0.0;
            for (std::size_t i = 0; i < s.grains().size(); ++i) walls += s.wallEnergy(i);
            std::printf("box, no contact in progress after %ld contacts: kinetic energy lost"
                        " %.9e J of %.9e J, tallied %.9e J (walls %.6e J), elastic %g J\n",
                        s.pairContactsBegun() + s.wallContactsBegun(), lost, e0,
                        s.dissipatedEnergy(), walls, s.elasticEnergy());
            EXPECT_EQ(s.elasticEnergy(), 0.0);
            EXPECT_NEAR(lost - s.elasticEnergy(), s.dissipatedEnergy(), 1e-12*e0);
            balancedAtRest = true;
        }
        ASSERT_LT(s.time(), 1.0) << "no moment without contacts";
    }
    std::printf("box: largest |lost - (tallied - h^2/8 sum(F^2/m + T^2/I))| %.2e J (of %.2e J);"
                " the h^2 term up to %.2e J, the elastic energy up to %.2e J\n",
                worst, e0, largestRest, largestElastic);
    EXPECT_LT(worst, 1e-12*e0);
    EXPECT_GT(largestRest, 1e3*worst);          // the identity sees its terms
    EXPECT_GT(e0 - s.kineticEnergy(), 0.1*e0);  // a test of a real loss
}

// Handing contacts in progress over with their forces and approach speeds
// (setPairContact, setWallContact): the tallies of the two runs add up to
// the uninterrupted run's to round-off; with the springs alone the forces
// are derived from the state handed over, a difference of O(h^2)
TEST(ContactEnergy, HandedOverContactsTallyAsTheUninterruptedRun)
{
    const double R = 0.005, m = sphereMass(R, rhoGlass);
    const HertzMindlin l = law(glass, glass, 0.76, 0.3, 0.5);
    const double tc = hertz(l.equivalentYoungModulus(), R/2, m/2, 0.1).duration;
    const PlaneWall floor(Vector(0, 0, -0.1), Vector(0, 0, 1));
    auto fresh = [&]() { return handOverScene(l, floor); };
    auto setUp = [&](GranularSystem& s)
    {
        // dropped onto the floor at 0.05 m/s: touches before the hand-over
        addHandOverGrains(s, R, m, Vector(0.05, 0, -0.1 + R + 2e-7), Vector(0.2, 0, -0.05),
                          Vector(0, 30, 0));
    };
    const int n = 400;
    const double dt = tc/n;
    auto whole = fresh();
    setUp(*whole);
    for (int k = 0; k < 2*n; ++k) whole->step(dt);

    for (bool withForces : {true, false})
    {
        auto first = fresh();
        setUp(*first);
        for (int k = 0; k < n/2; ++k) first->step(dt);
        ASSERT_GT(first->pairContacts(), 0u);
        ASSERT_GT(first->wallContacts(), 0u);
        auto second = fresh();
        for (const Grain& g : first->grains()) second->addGrain(g);
        second->setTime(first->time());
        first->forEachPairContactState([&](std::size_t i, std::size_t j,
                                           const PairContactState& c)
        {
            PairContactState h = c;
            h.forceKnown = withForces;
            if (!withForces) h.approachSpeed = std::numeric_limits<double>::quiet_NaN();
            second->setPairContact(i, j, h);
        });
        for (std::size_t i = 0; i < 3; ++i)
        {
            if (!first->wallContact(i, 0).touching) continue;
            if (withForces)
            {
                second->setWallContact(i, 0, first->wallSpring(i, 0),
                                       first->wallContact(i, 0).force,
                                       first->wallApproachSpeed(i, 0));
            }
            else
            {
                second->setWallSpring(i, 0, first->wallSpring(i, 0));
            }
        }
        handOverForces(*first, *second);
        for (int k = n/2; k < 2*n; ++k) second->step(dt);
        ASSERT_EQ(whole->pairContacts(), 0u);
        double scale = 0.0;
        for (std::size_t i = 0; i < 3; ++i)
        {
            scale = std::max(scale, std::abs(whole->wallEnergy(i)) + std::abs(whole->pairEnergy(i)));
        }
        for (std::size_t i = 0; i < 3; ++i)
        {
            const double wall = first->wallEnergy(i) + second->wallEnergy(i);
            const double pair = first->pairEnergy(i) + second->pairEnergy(i);
            const double tol = (withForces ? 1e-10 : 1e-5)*scale;
            EXPECT_NEAR(wall, whole->wallEnergy(i), tol) << i << withForces;
            EXPECT_NEAR(pair, whole->pairEnergy(i), tol) << i << withForces;
            EXPECT_EQ(second->pairContactsCompleted(i), whole->pairContactsCompleted(i));
            if (withForces)
            {
                EXPECT_EQ(second->pairImpactSpeed(i), whole->pairImpactSpeed(i)) << i;
            }
            if (i < 2)
            {
                std::printf("hand-over %s: grain %zu pair tally %.9e J, uninterrupted %.9e J\n",
                            withForces ? "with forces" : "springs only", i, pair,
                            whole->pairEnergy(i));
            }
        }
    }
}

TEST(NearPairs, NearestImageReducesTheAxialSeparationToHalfALength)
{
    // closed forms: in a section of length 1 a separation of 0.7 along z is
    // -0.3 to the nearest image, 2.2 is 0.2; x and y are untouched; open
    // space (L = 0) keeps the separation
    const Vector d = nearestImage(Vector(0.1, -0.2, 0.7), 1.0);
    EXPECT_DOUBLE_EQ(d.x(), 0.1);
    EXPECT_DOUBLE_EQ(d.y(), -0.2);
    EXPECT_NEAR(d.z(), -0.3, 1e-15);
    EXPECT_NEAR(nearestImage(Vector(0, 0, 2.2), 1.0).z(), 0.2, 1e-15);
    EXPECT_NEAR(nearestImage(Vector(0, 0, -0.7), 1.0).z(), 0.3, 1e-15);
    EXPECT_DOUBLE_EQ(nearestImage(Vector(0, 0, 0.7), 0.0).z(), 0.7);
    // every reduced separation lies within half a length
    for (double z = -5.0; z <= 5.0; z += 0.013)
        EXPECT_LE(std::abs(nearestImage(Vector(0, 0, z), 1.3).z()), 0.65 + 1e-12);
}
