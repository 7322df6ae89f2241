// riserCore: many spheres in contact with each other and with walls, with
// no fluid: discrete element method (Cundall & Strack, Geotechnique 29, 47,
// 1979) with the Hertz–Mindlin law of contact/hertzMindlin.hpp for both
// kinds of contact (pairs through contact/pairContact.hpp, walls through
// riser::Wall). Candidate pairs come from a Verlet list (Verlet, Phys. Rev.
// 159, 98, 1967): the pairs closer than 2 R_max + skin, found by a cell list
// (granular/nearPairs.hpp, which meets pairs across the ends of a periodic
// section too) and rebuilt when some grain has moved more than
// skin/2 since the last build, so that no pair can come into contact
// unlisted; a step costs O(N). Each listed pair carries its tangential
// spring, so a contact's history costs nothing to look up.
//
// Time stepping: velocity Verlet,
//   v(t + dt/2) = v(t) + dt/2 a(t),   x(t + dt) = x(t) + dt v(t + dt/2),
//   a(t + dt) from the contacts at x(t + dt) with the velocities v(t + dt/2),
//   v(t + dt)   = v(t + dt/2) + dt/2 a(t + dt),
// and the same for the angular velocity with the moment of inertia
// I = 2/5 m R^2 (or the grain's own) when rotation is on. The tangential
// spring of a contact, kept from its first to its last step, is turned into
// the current tangent plane (its length kept) and then grows by U_t dt; the
// law caps it.
//
// Beside gravity each grain may carry an acceleration of its own, linear in
// its velocity with constant coefficients (e.g. the fluid's, linearised and
// frozen over a flow step while the contacts are sub-stepped: the drag then
// turns with the velocity in a rebound). Its velocity term is taken at the
// velocity before the first half kick and after the second (the trapezoid
// rule: second order, and the first half kick keeps drag dt <= 1). A section may be periodic along z (length L
// from z0): grains touch across its ends through their images, and the
// positions are not wrapped (a caller wraps them, or tracks the particles
// through its periodic mesh). The contact state can be set before the first
// step and read after any (the springs of pairs and of walls), so that a
// caller holding contacts of its own (particles of a CFD cloud) can hand
// them over and take them back. Either kind of contact may be left out (no
// law for it): without a pair law the grains pass through each other and
// no pair is searched for; without a wall law no wall may be added.
//
// Energy dissipated in contacts, measured as the work of each contact's
// force on the contact's relative motion. Over a step h, with F_0 and F_1
// the contact's force on grain i at the evaluations that begin and end the
// step, and U the velocity of i's contact point relative to j's (or to the
// wall) with the step's velocities v(t + h/2) and omega(t + h/2),
//   dE = -h/2 (F_0 . U(n_0, w_0) + F_1 . U(n_1, w_1)),
// the trapezoid in the force, each force taken with the normal n (and wall
// velocity w) of its own evaluation. Then the dE of a grain's contacts add
// up to exactly the work that the two half kicks of its force and torque
// do on v(t + h/2) and omega(t + h/2). Velocity Verlet changes the kinetic
// energy of a grain over a step by that work plus m h^2/8 (|a_1|^2 -
// |a_0|^2) (and the like for the spin), a difference that telescopes: with
// static walls and no other acceleration, the kinetic energy lost since a
// state without contact forces is the sum of dE less h^2/8 sum (|F|^2/m +
// |T|^2/I) of the forces now, so over an impact (no contact force at
// either end) it equals the sum of dE to round-off. The difference from
// the continuous contact is then that of the discrete trajectory, first
// order in h here: a contact starts and ends inside a step, where the
// damping force (~ delta^(1/4)) is not smooth. Over a contact's life the
// elastic energy comes back, so a completed contact's sum is what its
// damping and friction took (and the tangential spring's energy left when
// it ends). The sums are kept per
// grain as they grow, step by step (a contact in progress holds its
// elastic energy in them): wallEnergy (all of a wall contact's dE), and
// pairEnergy (half of a pair contact's dE to each grain); with the pair
// contacts each grain completed and the normal speed of approach at the
// start of its last one, U . n with n from i towards j at the first
// evaluation that finds the overlap.
//
// Lubricated (a law with a film, contact/lubrication.hpp): a pair within
// each other's film and a grain within a wall's get the film's force from
// the contact kernel, its impulse over the step ahead (from the gap and the
// velocities v(t + h/2)), which the two half kicks apply; the pair list
// then reaches R_i + R_j + skin + h_cut of the pair. The film is not a
// contact (no spring, no record, not counted in the contacts begun), and
// its dissipation is tallied by the rectangle rule, -h F.U, so the energy
// balance above holds for the contacts' part only.
//
// Handing over contacts in progress: the springs, and also each contact's
// force at the last evaluation of the run handed over (the F_0 of the
// first step's dE) and a pair's approach speed, when the caller kept them
// (setPairContact, setWallContact). A force not handed over is derived at
// the first step from the state handed over (positions, velocities,
// springs: the velocities are those at the end of the last step, not the
// half-step ones the last evaluation saw, so the first step's dE then
// differs by O(h^2) of the contact's force times its speed); an approach
// speed not handed over is the one found at the first evaluation here.
//
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef RISERCORE_GRANULAR_GRANULARSYSTEM_HPP
#define RISERCORE_GRANULAR_GRANULARSYSTEM_HPP

#include "contact/contactKernel.hpp"
#include "contact/pairContact.hpp"
#include "granular/nearPairs.hpp"
#include "wall/wall.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <stdexcept>
#include <unordered_map>
#include <vector>

namespace riser {

//- One sphere: position, velocity, angular velocity, radius, mass; an
//  acceleration of its own beside gravity, accel + drag (carrierVelocity -
//  v), linear in its velocity v (default none: a fluid's acceleration
//  linearised about the grain's state, its drag rate [1/s] towards the
//  carrier's velocity frozen with the rest), and its moment of inertia
//  (default 0: a solid sphere of its mass, 2/5 m R^2)
struct Grain
{
    Vector x;
    Vector v;
    Vector omega;
    double radius;
    double mass;
    Vector accel = Vector::Zero();
    double inertia = 0.0;
    double drag = 0.0;
    Vector carrierVelocity = Vector::Zero();
};

//- A grain's contact with a wall at the last force evaluation
struct WallContactState
{
    bool touching;
    double overlap;
    double normalForce;                     //!< |normal force|
    Vector force = Vector::Zero();          //!< the wall's force on the grain
    Vector normal = Vector::Zero();         //!< from the centre towards the wall
    Vector wallVelocity = Vector::Zero();   //!< the wall's at the contact
    //! the grain's velocity at the evaluation (the half-step one) relative
    //! to the wall's there, of its centre
    Vector velocity = Vector::Zero();
};

//- A pair contact in progress, in grain i's frame (normal from i towards
//  j): as handed over before the first step, or as read back
struct PairContactState
{
    //- Tangential spring
    Vector spring = Vector::Zero();

    //- Force on i at the last evaluation
    Vector force = Vector::Zero();

    //- Handing over: false if the force is not known (it is then derived
    //  from the state handed over at the first step)
    bool forceKnown = false;

    //- Normal speed of approach at the contact's start; NaN: not known (the
    //  one at the first evaluation here is taken)
    double approachSpeed = std::numeric_limits<double>::quiet_NaN();
};

class GranularSystem
{
public:
    //- pairLaw: the law between two grains (both materials the grains'),
    //  std::nullopt for none; wallLaw: between a grain and any wall,
    //  std::nullopt for none; g: gravity; skin: the Verlet list's margin as
    //  a fraction of the largest radius (cost only: any skin > 0 finds every
    //  contact)
    GranularSystem(std::optional<HertzMindlin> pairLaw,
                   std::optional<HertzMindlin> wallLaw,
                   const Vector& g, bool rotation, double skin = 0.4)
    :
        pairLaw_(std::move(pairLaw)), wallLaw_(std::move(wallLaw)), g_(g),
        rotation_(rotation), skin_(skin)
    {
        requirePositive("riser::GranularSystem", "skin", skin);
    }

    //- A wall the grains touch; the caller keeps it alive
    void addWall(const Wall& w)
    {
        if (!wallLaw_)
        {
            throw std::invalid_argument
            (
                "riser::GranularSystem: a wall added to a system without a wall law"
            );
        }
        walls_.push_back(&w);
        wallSlots_.assign(grains_.size()*walls_.size(), WallSlot());
        forcesValid_ = false;
    }

    void addGrain(const Grain& p)
    {
        requirePositive("riser::GranularSystem", "R", p.radius);
        requirePositive("riser::GranularSystem", "m", p.mass);
        requireInRange("riser::GranularSystem", "moment of inertia", p.inertia,
                       0.0, Bound::closed, 1e300, Bound::closed);
        // a new grain joins with no contact history; the list is rebuilt
        grains_.push_back(p);
        wallSlots_.resize(grains_.size()*walls_.size(), WallSlot());
        wallEnergy_.push_back(0.0);
        pairEnergy_.push_back(0.0);
        pairsCompleted_.push_back(0);
        pairImpactSpeed_.push_back(0.0);
        listValid_ = false;
        forcesValid_ = false;
    }

    //- The section is periodic along z: length L from z0 (L larger than
    //  twice the reach of a contact, 2 (2 R_max + skin))
    void setPeriodic(double z0, double length)
    {
        requirePositive("riser::GranularSystem::setPeriodic", "L", length);
        pairs_.setPeriodic(z0, length);
        listValid_ = false;
        forcesValid_ = false;
    }

    //- Set the clock (the walls are evaluated at the system's time)
    void setTime(double t)
    {
        t_ = t;
        forcesValid_ = false;
    }

    //- A pair contact in progress: grains i and j touch, with the
    //  tangential spring s in i's frame (normal from i to j); before the
    //  first step (its force and approach speed not known)
    void setPairSpring(std::size_t i, std::size_t j, const Vector& s)
    {
        PairContactState c;
        c.spring = s;
        setPairContact(i, j, c);
    }

    //- A pair contact in progress with what the caller kept of it, in i's
    //  frame; before the first step
    void setPairContact(std::size_t i, std::size_t j, const PairContactState& c)
    {
        checkIndex(i);
        checkIndex(j);
        if (!pairLaw_)
        {
            throw std::invalid_argument
            (
                "riser::GranularSystem: a pair contact handed to a system without a pair law"
            );
        }
        PairContactState k = c;
        if (j < i)
        {
            std::swap(i, j);
            k.spring = -k.spring;
            k.force = -k.force;
        }
        preset_[key(i, j)] = k;
        listValid_ = false;
        forcesValid_ = false;
        handedOver_ = true;
    }

    //- A wall contact in progress: grain i touches wall w with spring s
    //  (its force not known)
    void setWallSpring(std::size_t i, std::size_t w, const Vector& s)
    {
        checkIndex(i);
        WallSlot& slot = wallSlots_.at(i*walls_.size() + w);
        slot.spring = s;
        slot.touching = true;
        slot.state = WallContactState{true, 0.0, 0.0};
        slot.approachSpeed = std::numeric_limits<double>::quiet_NaN();
        slot.handedOver = true;
        slot.forceKnown = false;
        forcesValid_ = false;
        handedOver_ = true;
    }

    //- The same, with the wall's force F on the grain at the last
    //  evaluation of the run handed over and the contact's normal approach
    //  speed vIn at its start
    void setWallContact(std::size_t i, std::size_t w, const Vector& s, const Vector& F,
                        double vIn)
    {
        setWallSpring(i, w, s);
        WallSlot& slot = wallSlots_[i*walls_.size() + w];
        slot.state.force = F;
        slot.approachSpeed = vIn;
        slot.forceKnown = true;
    }

    //- The contact forces and torques on the grains at the current state,
    //  as the last evaluation of a run being handed over found them (the
    //  state of velocity Verlet is x, v and the forces: a sliding contact's
    //  kept spring does not give back its force). Call after the grains,
    //  springs and time are set, before the first step.
    void setContactForces(const std::vector<Vector>& F, const std::vector<Vector>& T)
    {
        requireInRange("riser::GranularSystem::setContactForces", "number of forces",
                       double(F.size()), double(grains_.size()), Bound::closed,
                       double(grains_.size()), Bound::closed);
        requireInRange("riser::GranularSystem::setContactForces", "number of torques",
                       double(T.size()), double(grains_.size()), Bound::closed,
                       double(grains_.size()), Bound::closed);
        force_ = F;
        torque_ = T;
        wallForce_.setZero();
        forcesValid_ = true;
    }

    //- Call f(i, j, s) for each pair in contact, s its spring in i's frame
    template<class PairFunction>
    void forEachPairContact(const PairFunction& f) const
    {
        for (const Candidate& c : list_)
        {
            if (c.touching) f(std::size_t(c.i), std::size_t(c.j), c.spring);
        }
    }

    //- Call f(i, j, c) for each pair in contact, c its state in i's frame
    //  (the force of the last evaluation, known)
    template<class PairFunction>
    void forEachPairContactState(const PairFunction& f) const
    {
        for (const Candidate& c : list_)
        {
            if (c.touching)
            {
                PairContactState s;
                s.spring = c.spring;
                s.force = c.force;
                s.forceKnown = true;
                s.approachSpeed = c.approachSpeed;
                f(std::size_t(c.i), std::size_t(c.j), s);
            }
        }
    }

    //- The spring of grain i on wall w (zero when not touching)
    const Vector& wallSpring(std::size_t i, std::size_t w) const
    {
        return wallSlots_.at(i*walls_.size() + w).spring;
    }

    //- The normal approach speed at the start of grain i's contact with
    //  wall w (NaN: none in progress)
    double wallApproachSpeed(std::size_t i, std::size_t w) const
    {
        return wallSlots_.at(i*walls_.size() + w).approachSpeed;
    }

    //- Grain i's contact with wall w at the last force evaluation
    const WallContactState& wallContact(std::size_t i, std::size_t w) const
    {
        return wallSlots_.at(i*walls_.size() + w).state;
    }

    //- Contact torque on grain i at the last evaluation
    const Vector& contactTorque(std::size_t i) const { return torque_.at(i); }

    const std::vector<Grain>& grains() const { return grains_; }
    double time() const { return t_; }

    //- Advance every grain by dt
    void step(double dt)
    {
        step(dt, [](std::vector<Grain>&) {});
    }

    //- Advance every grain by dt; afterMove(grains) is called when the
    //  grains have moved (positions at the step's end, velocities and
    //  spins at its middle), before their forces are evaluated: a caller
    //  that holds copies of grains stepped elsewhere (a processor's halo)
    //  sets their state there
    template<class AfterMove>
    void step(double dt, const AfterMove& afterMove)
    {
        requirePositive("riser::GranularSystem::step", "dt", dt);
        for (const Grain& p : grains_)
        {
            requireInRange("riser::GranularSystem::step", "drag dt", p.drag*dt,
                           0.0, Bound::closed, 1.0, Bound::closed);
        }
        if (!forcesValid_)
        {
            computeForces(0.0);
        }
        else if (handedOver_)
        {
            completeHandedOver();
        }
        handedOver_ = false;
        kick(0.5*dt, false);
        for (Grain& p : grains_) p.x += dt*p.v;
        t_ += dt;
        afterMove(grains_);
        computeForces(dt);
        kick(0.5*dt, true);
    }

    //- Pairs and grain-wall contacts in contact now
    std::size_t pairContacts() const { return pairsTouching_; }
    std::size_t wallContacts() const { return wallsTouching_; }

    //- Contacts begun since the start (each counted at its first step)
    long pairContactsBegun() const { return pairBegun_; }
    long wallContactsBegun() const { return wallBegun_; }

    //- Energy grain i's wall contacts have dissipated since the start (the
    //  sum of their dE, see the top of the file) [J]
    double wallEnergy(std::size_t i) const { return wallEnergy_.at(i); }

    //- Grain i's half of the energy its pair contacts have dissipated
    //  since the start [J]
    double pairEnergy(std::size_t i) const { return pairEnergy_.at(i); }

    //- Pair contacts of grain i completed since the start
    long pairContactsCompleted(std::size_t i) const { return pairsCompleted_.at(i); }

    //- Normal speed of approach at the start of grain i's last completed
    //  pair contact (0 before the first) [m/s]
    double pairImpactSpeed(std::size_t i) const { return pairImpactSpeed_.at(i); }

    //- Energy dissipated in all contacts since the start [J]
    double dissipatedEnergy() const
    {
        double e = 0.0;
        for (std::size_t i = 0; i < grains_.size(); ++i) e += wallEnergy_[i] + pairEnergy_[i];
        return e;
    }

    //- Verlet list builds since the start
    long listBuilds() const { return builds_; }

    //- Mean number of grain neighbours in contact, 2 N_pairs / N
    double coordinationNumber() const
    {
        return grains_.empty() ? 0.0 : 2.0*double(pairsTouching_)/double(grains_.size());
    }

    //- Largest pair overlap now, relative to the smaller diameter
    double largestPairOverlap() const { return largestPairOverlap_; }

    Vector momentum() const
    {
        Vector p = Vector::Zero();
        for (const Grain& q : grains_) p += q.mass*q.v;
        return p;
    }

    //- Kinetic energy of the grains (with rotation when on)
    double kineticEnergy() const
    {
        double e = 0.0;
        for (const Grain& q : grains_)
        {
            e += 0.5*q.mass*q.v.squaredNorm();
            if (rotation_) e += 0.5*inertia(q)*q.omega.squaredNorm();
        }
        return e;
    }

    //- Elastic energy of the contacts now (2/5 k_n delta^(5/2) normal,
    //  1/2 k_t |delta_t|^2 tangential)
    double elasticEnergy() const { return elastic_; }

    //- Kinetic (with rotation), gravitational and elastic energy of the
    //  contacts; the grains' own accelerations have no potential here
    double energy() const
    {
        double e = elastic_ + kineticEnergy();
        for (const Grain& q : grains_) e -= q.mass*g_.dot(q.x);
        return e;
    }

    //- Contact force (pairs and walls) on grain i at the last evaluation
    const Vector& contactForce(std::size_t i) const { return force_.at(i); }

    //- Momentum the walls have given the grains since the start
    const Vector& wallImpulse() const { return wallImpulse_; }

private:
    static double inertia(const Grain& q)
    {
        return q.inertia > 0.0 ? q.inertia : 0.4*q.mass*q.radius*q.radius;
    }

    static std::uint64_t key(std::size_t i, std::size_t j)
    {
        return (std::uint64_t(i) << 32) | std::uint64_t(j);
    }

    void checkIndex(std::size_t i) const
    {
        requireInRange("riser::GranularSystem", "grain index", double(i),
                       0.0, Bound::closed, double(grains_.size()), Bound::open);
    }

    //- The half kicks of velocity Verlet; the own acceleration's drag is
    //  taken at the velocity before the first (explicit) and after the
    //  second (implicit): the trapezoid rule over the step, second order
    void kick(double h, bool second)
    {
        for (std::size_t i = 0; i < grains_.size(); ++i)
        {
            Grain& p = grains_[i];
            const Vector a = force_[i]/p.mass + g_ + p.accel;
            if (p.drag == 0.0)
            {
                p.v += h*a;
            }
            else if (second)
            {
                p.v = (p.v + h*(a + p.drag*p.carrierVelocity))/(1.0 + h*p.drag);
            }
            else
            {
                p.v += h*(a + p.drag*(p.carrierVelocity - p.v));
            }
            if (rotation_) p.omega += h*torque_[i]/inertia(p);
        }
        wallImpulse_ += h*wallForce_;
    }

    //- A candidate pair of the Verlet list (i < j) and its contact state,
    //  kept in i's frame (normal from i towards j); j is met through its
    //  image shifted by dz along z (0, or +-L across the ends of a periodic
    //  section)
    struct Candidate
    {
        std::uint32_t i, j;
        double dz;
        Vector spring;
        bool touching;
        Vector force;           //!< on i at the last evaluation (0: none)
        Vector normal;          //!< of the last evaluation
        double approachSpeed;   //!< at the contact's start (NaN: not known)
        bool handedOver;        //!< set before the first step, not evaluated
        bool forceKnown;        //!< (when handedOver)
    };

    //- Grain i's contact with wall w: its spring, and its state at the last
    //  evaluation
    struct WallSlot
    {
        Vector spring = Vector::Zero();
        bool touching = false;
        WallContactState state{false, 0.0, 0.0};
        //! normal approach speed at the contact's start (NaN: not known)
        double approachSpeed = std::numeric_limits<double>::quiet_NaN();
        bool handedOver = false;    //!< set before the first step
        bool forceKnown = false;    //!< (when handedOver)
    };

    //- The grain as a side of a contact (its spin only with rotation on)
    ContactSide side(const Grain& p) const
    {
        return ContactSide{p.v, rotation_ ? p.omega : Vector(Vector::Zero()), p.radius};
    }

    //- Velocity of i's contact point relative to j's, for normal n
    Vector pairVelocity(const Grain& a, const Grain& b, const Vector& n) const
    {
        return contactVelocity(side(a), side(b), n);
    }

    //- Velocity of the grain's contact point relative to the wall's w
    Vector wallContactVelocity(const Grain& p, const Vector& n, const Vector& w) const
    {
        return contactVelocity(side(p), wallSide(w), n);
    }

    //- Complete the contacts handed over with the state of the grains now:
    //  their normals (and walls' velocities), the forces not handed over
    //  (from the springs as they are) and the approach speeds not known
    void completeHandedOver()
    {
        if (!listValid_) buildList();
        for (Candidate& c : list_)
        {
            if (!c.touching || !c.handedOver) continue;
            const Grain& a = grains_[c.i];
            const Grain& b = grains_[c.j];
            const PairGeometry geo =
                pairGeometry(a.x, a.radius, b.x + Vector(0.0, 0.0, c.dz), b.radius);
            const Vector U = pairVelocity(a, b, geo.normal);
            c.normal = geo.normal;
            if (std::isnan(c.approachSpeed)) c.approachSpeed = U.dot(geo.normal);
            if (!c.forceKnown)
            {
                c.force = stepContact
                (
                    *pairLaw_, pairBody(a.radius, a.mass, b.radius, b.mass),
                    geo.overlap, geo.normal, side(a), side(b), c.spring, c.approachSpeed, 0.0
                ).force;
            }
            c.handedOver = false;
        }
        for (std::size_t i = 0; i < grains_.size(); ++i)
        {
            const Grain& p = grains_[i];
            for (std::size_t w = 0; w < walls_.size(); ++w)
            {
                WallSlot& slot = wallSlots_[i*walls_.size() + w];
                if (!slot.touching || !slot.handedOver) continue;
                const ContactPoint cp = walls_[w]->contactPoint(p.x, p.radius, t_);
                slot.state.overlap = cp.overlap;
                slot.state.normal = cp.normal;
                slot.state.wallVelocity = cp.velocity;
                if (std::isnan(slot.approachSpeed))
                {
                    slot.approachSpeed =
                        wallContactVelocity(p, cp.normal, cp.velocity).dot(cp.normal);
                }
                if (!slot.forceKnown)
                {
                    const ContactStep f = stepContact
                    (
                        *wallLaw_, ContactBody(p.radius, p.mass), cp.overlap, cp.normal,
                        side(p), wallSide(cp.velocity), slot.spring, slot.approachSpeed, 0.0
                    );
                    slot.state.force = f.force;
                    slot.state.normalForce = f.law.normal.norm();
                }
                slot.handedOver = false;
            }
        }
    }

    //- Rebuild the candidate list, carrying over the state of the pairs
    //  in contact (and of those set by setPairContact)
    void buildList()
    {
        const std::size_t n = grains_.size();
        double rMax = 0.0;
        positions_.resize(n);
        for (std::size_t i = 0; i < n; ++i)
        {
            positions_[i] = grains_[i].x;
            rMax = std::max(rMax, grains_[i].radius);
        }
        skinLength_ = skin_*rMax;
        listValid_ = true;
        ++builds_;
        if (!pairLaw_) return;  // no pair contact: no pairs to list
        if (n < 2 && preset_.empty() && list_.empty()) return;  // no pair
        // lubricated: a pair is listed while in each other's film too
        // (R* of two radii up to R_max is at most R_max/2)
        const double cutoff = 2.0*rMax + skinLength_ + pairLaw_->filmGap(0.5*rMax);
        // the contacts in progress (those handed over not yet evaluated)
        std::unordered_map<std::uint64_t, Candidate> kept;
        for (const auto& p : preset_)
        {
            const PairContactState& s = p.second;
            kept.emplace(p.first, Candidate{0, 0, 0.0, s.spring, true, s.force,
                Vector::Zero(), s.approachSpeed, true, s.forceKnown});
        }
        preset_.clear();
        for (const Candidate& c : list_)
        {
            if (c.touching) kept.emplace(key(c.i, c.j), c);
        }
        list_.clear();
        // (a dense packing lists about 3 pairs a grain: no reallocation in
        // the first build of a system made anew in every flow step)
        list_.reserve(4*n);

        pairs_.forEachPair(positions_, cutoff, [&](std::size_t i, std::size_t j, double dz)
        {
            const double Ri = grains_[i].radius, Rj = grains_[j].radius;
            const double reach = Ri + Rj + skinLength_ + pairLaw_->filmGap(Ri*Rj/(Ri + Rj));
            if ((positions_[j] + Vector(0.0, 0.0, dz) - positions_[i]).squaredNorm() > reach*reach)
            {
                return;
            }
            const auto k = kept.find(key(i, j));
            if (k == kept.end())
            {
                list_.push_back(Candidate{std::uint32_t(i), std::uint32_t(j), dz,
                    Vector::Zero(), false, Vector::Zero(), Vector::Zero(),
                    std::numeric_limits<double>::quiet_NaN(), false, false});
            }
            else
            {
                Candidate c = k->second;
                c.i = std::uint32_t(i);
                c.j = std::uint32_t(j);
                c.dz = dz;
                list_.push_back(c);
            }
        });
    }

    //- Has some grain moved more than skin/2 since the list was built?
    bool listStale() const
    {
        const double limit = 0.25*skinLength_*skinLength_;
        for (std::size_t i = 0; i < grains_.size(); ++i)
        {
            if ((grains_[i].x - positions_[i]).squaredNorm() > limit) return true;
        }
        return false;
    }

    //- Forces at the current positions; dt: the step that led here (the
    //  springs grow by U_t dt; the contacts' dissipation over it is added)
    void computeForces(double dt)
    {
        const std::size_t n = grains_.size();
        require32bit(n);
        if (!listValid_ || listStale()) buildList();
        force_.assign(n, Vector::Zero());
        torque_.assign(n, Vector::Zero());
        wallForce_.setZero();
        elastic_ = 0.0;
        largestPairOverlap_ = 0.0;
        pairsTouching_ = 0;
        wallsTouching_ = 0;

        for (Candidate& cand : list_)
        {
            const Grain& a = grains_[cand.i];
            const Grain& b = grains_[cand.j];
            const PairGeometry geo =
                pairGeometry(a.x, a.radius, b.x + Vector(0.0, 0.0, cand.dz), b.radius);
            // the first half of the step's trapezoid (0 for a new contact)
            const double workBefore =
                cand.touching ? cand.force.dot(pairVelocity(a, b, cand.normal)) : 0.0;
            if (geo.overlap <= 0.0)
            {
                if (cand.touching)
                {
                    // the contact ended within the step (one handed over
                    // that was found apart at once: its speed now)
                    tallyPair(cand, -0.5*dt*workBefore);
                    const double speed =
                        std::isnan(cand.approachSpeed)
                      ? pairVelocity(a, b, geo.normal).dot(geo.normal)
                      : cand.approachSpeed;
                    ++pairsCompleted_[cand.i];
                    ++pairsCompleted_[cand.j];
                    pairImpactSpeed_[cand.i] = speed;
                    pairImpactSpeed_[cand.j] = speed;
                }
                cand.touching = false;
                cand.spring.setZero();
                cand.force.setZero();
                cand.approachSpeed = std::numeric_limits<double>::quiet_NaN();
                if (pairLaw_->film())
                {
                    // in each other's film (lubricated): its force, not a
                    // contact (its dissipation by the rectangle rule)
                    const ContactStep c = stepContact
                    (
                        *pairLaw_, pairBody(a.radius, a.mass, b.radius, b.mass), geo.overlap,
                        geo.normal, side(a), side(b), Vector::Zero(), 0.0, dt
                    );
                    force_[cand.i] += c.force;
                    force_[cand.j] -= c.force;
                    tallyPair(cand, -dt*c.power);
                }
                continue;
            }
            const ContactBody body = pairBody(a.radius, a.mass, b.radius, b.mass);
            if (!cand.touching || std::isnan(cand.approachSpeed))
            {
                cand.approachSpeed = pairVelocity(a, b, geo.normal).dot(geo.normal);
            }
            const ContactStep c = stepContact
            (
                *pairLaw_, body, geo.overlap, geo.normal, side(a), side(b), cand.spring,
                cand.approachSpeed, dt
            );
            if (!cand.touching) ++pairBegun_;
            force_[cand.i] += c.force;
            force_[cand.j] -= c.force;
            if (rotation_)
            {
                torque_[cand.i] += c.torqueI;
                torque_[cand.j] += c.torqueJ;
            }
            tallyPair(cand, -0.5*dt*(workBefore + c.power));
            cand.spring = c.law.springAfter;
            cand.touching = true;
            cand.force = c.force;
            cand.normal = geo.normal;
            cand.handedOver = false;
            ++pairsTouching_;
            elastic_ += riser::elasticEnergy(*pairLaw_, body, geo.overlap, c.law.springAfter);
            largestPairOverlap_ = std::max
            (
                largestPairOverlap_, geo.overlap/(2.0*std::min(a.radius, b.radius))
            );
        }

        for (std::size_t i = 0; i < n; ++i)
        {
            const Grain& p = grains_[i];
            for (std::size_t w = 0; w < walls_.size(); ++w)
            {
                WallSlot& slot = wallSlots_[i*walls_.size() + w];
                const ContactPoint cp = walls_[w]->contactPoint(p.x, p.radius, t_);
                const double workBefore =
                    slot.touching
                  ? slot.state.force.dot
                    (
                        wallContactVelocity(p, slot.state.normal, slot.state.wallVelocity)
                    )
                  : 0.0;
                if (cp.overlap <= 0.0)
                {
                    // (a contact that ended within the step: its last part)
                    wallEnergy_[i] -= 0.5*dt*workBefore;
                    slot.touching = false;
                    slot.spring.setZero();
                    slot.approachSpeed = std::numeric_limits<double>::quiet_NaN();
                    slot.state = WallContactState{false, cp.overlap, 0.0};
                    slot.state.velocity = p.v - cp.velocity;
                    slot.handedOver = false;
                    if (wallLaw_->film())
                    {
                        // in the wall's film (lubricated): as a pair's
                        const ContactStep c = stepContact
                        (
                            *wallLaw_, ContactBody(p.radius, p.mass), cp.overlap, cp.normal,
                            side(p), wallSide(cp.velocity), Vector::Zero(), 0.0, dt
                        );
                        force_[i] += c.force;
                        wallForce_ += c.force;
                        wallEnergy_[i] -= dt*c.power;
                    }
                    continue;
                }
                if (!slot.touching) ++wallBegun_;
                if (!slot.touching || std::isnan(slot.approachSpeed))
                {
                    slot.approachSpeed =
                        wallContactVelocity(p, cp.normal, cp.velocity).dot(cp.normal);
                }
                const ContactBody body(p.radius, p.mass);
                const ContactStep c = stepContact
                (
                    *wallLaw_, body, cp.overlap, cp.normal,
                    side(p), wallSide(cp.velocity), slot.spring, slot.approachSpeed, dt
                );
                force_[i] += c.force;
                wallForce_ += c.force;
                if (rotation_) torque_[i] += c.torqueI;
                wallEnergy_[i] -= 0.5*dt*(workBefore + c.power);
                slot.spring = c.law.springAfter;
                slot.touching = true;
                slot.state = WallContactState
                {
                    true, cp.overlap, c.law.normal.norm(), c.force, cp.normal, cp.velocity,
                    p.v - cp.velocity
                };
                slot.handedOver = false;
                ++wallsTouching_;
                elastic_ += riser::elasticEnergy(*wallLaw_, body, cp.overlap, c.law.springAfter);
            }
        }
        forcesValid_ = true;
    }

    //- Half of a pair contact's dissipation to each of its grains
    void tallyPair(const Candidate& c, double dE)
    {
        pairEnergy_[c.i] += 0.5*dE;
        pairEnergy_[c.j] += 0.5*dE;
    }

    static void require32bit(std::size_t n)
    {
        requireInRange("riser::GranularSystem", "number of grains", double(n),
                       0.0, Bound::closed, 4294967295.0, Bound::closed);
    }

    std::optional<HertzMindlin> pairLaw_, wallLaw_;
    Vector g_;
    bool rotation_;
    std::vector<const Wall*> walls_;
    std::vector<Grain> grains_;
    double skin_;
    double skinLength_ = 0.0;
    std::vector<Vector> force_, torque_;
    std::vector<Vector> positions_;     //!< centres at the last list build
    std::vector<Candidate> list_;
    //- setPairContact's, in the frame of the lower index
    std::unordered_map<std::uint64_t, PairContactState> preset_;
    std::vector<WallSlot> wallSlots_;   //!< per grain and wall
    std::size_t pairsTouching_ = 0, wallsTouching_ = 0;
    NearPairs pairs_;                   //!< the pair search (periodic or not)
    Vector wallForce_ = Vector::Zero();
    Vector wallImpulse_ = Vector::Zero();
    //- Per grain: energy dissipated in wall and pair contacts, pair
    //  contacts completed, approach speed of the last
    std::vector<double> wallEnergy_, pairEnergy_;
    std::vector<long> pairsCompleted_;
    std::vector<double> pairImpactSpeed_;
    double elastic_ = 0.0;
    double largestPairOverlap_ = 0.0;
    double t_ = 0.0;
    long pairBegun_ = 0, wallBegun_ = 0, builds_ = 0;
    bool listValid_ = false;
    bool forcesValid_ = false;
    bool handedOver_ = false;           //!< contacts set, not yet completed
};

} // namespace riser

#endif
