// riserCore: many spheres in contact with each other and with walls, with
// no fluid: discrete element method (Cundall & Strack, Geotechnique 29, 47,
// 1979) with the Hertz–Mindlin law of contact/hertzMindlin.hpp for both
// kinds of contact (pairs through contact/pairContact.hpp, walls through
// riser::Wall). Candidate pairs come from a Verlet list (Verlet, Phys. Rev.
// 159, 98, 1967): the pairs closer than 2 R_max + skin, found by a cell list
// (granular/cellList.hpp) and rebuilt when some grain has moved more than
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
// Beside gravity each grain may carry an acceleration of its own, constant
// over the steps (e.g. the fluid's, frozen over a flow step while the
// contacts are sub-stepped). A section may be periodic along z (length L
// from z0): grains touch across its ends through their images, and the
// positions are not wrapped (a caller wraps them, or tracks the particles
// through its periodic mesh). The contact state can be set before the first
// step and read after any (the springs of pairs and of walls), so that a
// caller holding contacts of its own (particles of a CFD cloud) can hand
// them over and take them back.
//
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef RISERCORE_GRANULAR_GRANULARSYSTEM_HPP
#define RISERCORE_GRANULAR_GRANULARSYSTEM_HPP

#include "contact/pairContact.hpp"
#include "granular/cellList.hpp"
#include "wall/wall.hpp"

#include <algorithm>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace riser {

//- One sphere: position, velocity, angular velocity, radius, mass; an
//  acceleration of its own beside gravity (default none) and its moment of
//  inertia (default 0: a solid sphere of its mass, 2/5 m R^2)
struct Grain
{
    Vector x;
    Vector v;
    Vector omega;
    double radius;
    double mass;
    Vector accel = Vector::Zero();
    double inertia = 0.0;
};

//- A grain's contact with a wall at the last force evaluation
struct WallContactState
{
    bool touching;
    double overlap;
    double normalForce;     //!< |normal force|
};

class GranularSystem
{
public:
    //- pairLaw: the law between two grains (both materials the grains');
    //  wallLaw: between a grain and any wall; g: gravity; skin: the Verlet
    //  list's margin as a fraction of the largest radius (cost only: any
    //  skin > 0 finds every contact)
    GranularSystem(const HertzMindlin& pairLaw, const HertzMindlin& wallLaw,
                   const Vector& g, bool rotation, double skin = 0.4)
    :
        pairLaw_(pairLaw), wallLaw_(wallLaw), g_(g), rotation_(rotation), skin_(skin)
    {
        requirePositive("riser::GranularSystem", "skin", skin);
    }

    //- A wall the grains touch; the caller keeps it alive
    void addWall(const Wall& w)
    {
        walls_.push_back(&w);
        const std::size_t nw = grains_.size()*walls_.size();
        wallSpring_.assign(nw, Vector::Zero());
        wallTouching_.assign(nw, false);
        wallState_.assign(nw, WallContactState{false, 0.0, 0.0});
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
        const std::size_t nw = grains_.size()*walls_.size();
        wallSpring_.resize(nw, Vector::Zero());
        wallTouching_.resize(nw, false);
        wallState_.resize(nw, WallContactState{false, 0.0, 0.0});
        listValid_ = false;
        forcesValid_ = false;
    }

    //- The section is periodic along z: length L from z0 (L larger than
    //  twice the reach of a contact, 2 (2 R_max + skin))
    void setPeriodic(double z0, double length)
    {
        requirePositive("riser::GranularSystem::setPeriodic", "L", length);
        z0_ = z0;
        length_ = length;
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
    //  first step
    void setPairSpring(std::size_t i, std::size_t j, const Vector& s)
    {
        checkIndex(i);
        checkIndex(j);
        const bool swapped = j < i;
        preset_[key(swapped ? j : i, swapped ? i : j)] = swapped ? Vector(-s) : s;
        listValid_ = false;
        forcesValid_ = false;
    }

    //- A wall contact in progress: grain i touches wall w with spring s
    void setWallSpring(std::size_t i, std::size_t w, const Vector& s)
    {
        checkIndex(i);
        const std::size_t k = i*walls_.size() + w;
        wallSpring_.at(k) = s;
        wallTouching_.at(k) = true;
        forcesValid_ = false;
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

    //- The spring of grain i on wall w (zero when not touching)
    const Vector& wallSpring(std::size_t i, std::size_t w) const
    {
        return wallSpring_.at(i*walls_.size() + w);
    }

    //- Grain i's contact with wall w at the last force evaluation
    const WallContactState& wallContact(std::size_t i, std::size_t w) const
    {
        return wallState_.at(i*walls_.size() + w);
    }

    //- Contact torque on grain i at the last evaluation
    const Vector& contactTorque(std::size_t i) const { return torque_.at(i); }

    const std::vector<Grain>& grains() const { return grains_; }
    double time() const { return t_; }

    //- Advance every grain by dt
    void step(double dt)
    {
        requirePositive("riser::GranularSystem::step", "dt", dt);
        if (!forcesValid_) computeForces(0.0);
        kick(0.5*dt);
        for (Grain& p : grains_) p.x += dt*p.v;
        t_ += dt;
        computeForces(dt);
        kick(0.5*dt);
    }

    //- Pairs and grain-wall contacts in contact now
    std::size_t pairContacts() const { return pairsTouching_; }
    std::size_t wallContacts() const { return wallsTouching_; }

    //- Contacts begun since the start (each counted at its first step)
    long pairContactsBegun() const { return pairBegun_; }
    long wallContactsBegun() const { return wallBegun_; }

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

    //- Kinetic (with rotation), gravitational and elastic energy of the
    //  contacts (2/5 k_n delta^(5/2) normal, 1/2 k_t |delta_t|^2 tangential);
    //  the grains' own accelerations have no potential here
    double energy() const
    {
        double e = elastic_;
        for (const Grain& q : grains_)
        {
            e += 0.5*q.mass*q.v.squaredNorm() - q.mass*g_.dot(q.x);
            if (rotation_) e += 0.5*inertia(q)*q.omega.squaredNorm();
        }
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

    //- The kept spring turned into the plane normal to n, length kept
    static Vector turned(const Vector& s, const Vector& n)
    {
        const Vector st = s - s.dot(n)*n;
        const double l = st.norm();
        return l > 0.0 ? Vector(st*(s.norm()/l)) : Vector(Vector::Zero());
    }

    void kick(double h)
    {
        for (std::size_t i = 0; i < grains_.size(); ++i)
        {
            Grain& p = grains_[i];
            p.v += h*(force_[i]/p.mass + g_ + p.accel);
            if (rotation_) p.omega += h*torque_[i]/inertia(p);
        }
        wallImpulse_ += h*wallForce_;
    }

    //- A candidate pair of the Verlet list (i < j) and its spring, kept in
    //  i's frame (normal from i towards j); j is met through its image
    //  shifted by dz along z (0, or +-L across the ends of a periodic
    //  section)
    struct Candidate
    {
        std::uint32_t i, j;
        double dz;
        Vector spring;
        bool touching;
    };

    //- Rebuild the candidate list, carrying over the springs of the pairs
    //  in contact (and those set by setPairSpring)
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
        const double cutoff = 2.0*rMax + skinLength_;
        std::unordered_map<std::uint64_t, Vector> kept(preset_.begin(), preset_.end());
        preset_.clear();
        for (const Candidate& c : list_)
        {
            if (c.touching) kept.emplace(key(c.i, c.j), c.spring);
        }
        list_.clear();

        // the centres, then the images (+-L) of those within the cutoff of
        // an end of a periodic section
        all_.assign(positions_.begin(), positions_.end());
        original_.resize(n);
        shift_.assign(n, 0.0);
        for (std::size_t i = 0; i < n; ++i) original_[i] = i;
        if (length_ > 0.0)
        {
            requireInRange("riser::GranularSystem", "periodic length L / (2 cutoff)",
                           length_/(2.0*cutoff), 1.0, Bound::open, 1e300, Bound::closed);
            for (std::size_t i = 0; i < n; ++i)
            {
                const double z = positions_[i].z();
                for (const double dz : {length_, -length_})
                {
                    const bool nearEnd =
                        dz > 0.0 ? z - z0_ < cutoff : z0_ + length_ - z < cutoff;
                    if (!nearEnd) continue;
                    all_.push_back(positions_[i] + Vector(0.0, 0.0, dz));
                    original_.push_back(i);
                    shift_.push_back(dz);
                }
            }
        }
        cells_.build(all_, cutoff);
        cells_.forEachPair([&](std::size_t a, std::size_t b)
        {
            if (a >= n && b >= n) return;  // two images: met through an original
            if (a >= n) std::swap(a, b);
            std::size_t i = original_[a], j = original_[b];
            double dz = shift_[b];
            // a pair across the ends is met twice (i with j's image, j with
            // i's): kept once, through the image of the larger index
            if (i == j || (b >= n && j < i)) return;
            if (j < i)
            {
                std::swap(i, j);
                dz = -dz;
            }
            const double reach = grains_[i].radius + grains_[j].radius + skinLength_;
            if ((all_[b] - all_[a]).squaredNorm() > reach*reach) return;
            const auto k = kept.find(key(i, j));
            list_.push_back(Candidate{std::uint32_t(i), std::uint32_t(j), dz,
                k == kept.end() ? Vector(Vector::Zero()) : k->second, k != kept.end()});
        });
        listValid_ = true;
        ++builds_;
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
    //  springs grow by U_t dt)
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
            if (geo.overlap <= 0.0)
            {
                cand.touching = false;
                cand.spring.setZero();
                continue;
            }
            if (!cand.touching) ++pairBegun_;
            const Vector U = rotation_
              ? pairContactVelocity(geo, a.v, a.omega, a.radius, b.v, b.omega, b.radius)
              : Vector(a.v - b.v);
            const Vector Ut = U - U.dot(geo.normal)*geo.normal;
            const Vector spring = turned(cand.spring, geo.normal) + dt*Ut;
            const ContactBody body = pairBody(a.radius, a.mass, b.radius, b.mass);
            const ContactForce c = pairLaw_.force(body, geo.overlap, geo.normal, U, spring);
            const Vector F = c.normal + c.tangential;
            force_[cand.i] += F;
            force_[cand.j] -= F;
            if (rotation_)
            {
                torque_[cand.i] += (a.radius*geo.normal).cross(c.tangential);
                torque_[cand.j] += (b.radius*geo.normal).cross(c.tangential);
            }
            cand.spring = c.springAfter;
            cand.touching = true;
            ++pairsTouching_;
            elastic_ += energyOf(body, geo.overlap, c.springAfter, pairLaw_);
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
                const std::size_t k = i*walls_.size() + w;
                const ContactPoint cp = walls_[w]->contactPoint(p.x, p.radius, t_);
                if (cp.overlap <= 0.0)
                {
                    wallTouching_[k] = false;
                    wallSpring_[k].setZero();
                    wallState_[k] = WallContactState{false, cp.overlap, 0.0};
                    continue;
                }
                if (!wallTouching_[k]) ++wallBegun_;
                Vector U = p.v - cp.velocity;
                if (rotation_) U += p.omega.cross(p.radius*cp.normal);
                const Vector Ut = U - U.dot(cp.normal)*cp.normal;
                const Vector spring = turned(wallSpring_[k], cp.normal) + dt*Ut;
                const ContactBody body(p.radius, p.mass);
                const ContactForce c = wallLaw_.force(body, cp.overlap, cp.normal, U, spring);
                const Vector F = c.normal + c.tangential;
                force_[i] += F;
                wallForce_ += F;
                if (rotation_) torque_[i] += (p.radius*cp.normal).cross(c.tangential);
                wallSpring_[k] = c.springAfter;
                wallTouching_[k] = true;
                wallState_[k] = WallContactState{true, cp.overlap, c.normal.norm()};
                ++wallsTouching_;
                elastic_ += energyOf(body, cp.overlap, c.springAfter, wallLaw_);
            }
        }
        forcesValid_ = true;
    }

    static void require32bit(std::size_t n)
    {
        requireInRange("riser::GranularSystem", "number of grains", double(n),
                       0.0, Bound::closed, 4294967295.0, Bound::closed);
    }

    static double energyOf(const ContactBody& b, double delta, const Vector& spring,
                           const HertzMindlin& law)
    {
        const double kt = 8.0*law.equivalentShearModulus()*std::sqrt(b.radius*delta);
        return 0.4*law.normalStiffness(b)*delta*delta*std::sqrt(delta)
             + 0.5*kt*spring.squaredNorm();
    }

    HertzMindlin pairLaw_, wallLaw_;
    Vector g_;
    bool rotation_;
    std::vector<const Wall*> walls_;
    std::vector<Grain> grains_;
    double skin_;
    double skinLength_ = 0.0;
    std::vector<Vector> force_, torque_;
    std::vector<Vector> positions_;     //!< centres at the last list build
    std::vector<Vector> all_;           //!< the centres and their images
    std::vector<std::size_t> original_; //!< the grain of each of all_
    std::vector<double> shift_;         //!< the image's z shift
    std::vector<Candidate> list_;
    std::unordered_map<std::uint64_t, Vector> preset_;  //!< setPairSpring's
    double z0_ = 0.0, length_ = 0.0;    //!< periodic section (length 0: none)
    std::vector<Vector> wallSpring_;    //!< per grain and wall
    std::vector<bool> wallTouching_;
    std::vector<WallContactState> wallState_;
    std::size_t pairsTouching_ = 0, wallsTouching_ = 0;
    CellList cells_;
    Vector wallForce_ = Vector::Zero();
    Vector wallImpulse_ = Vector::Zero();
    double elastic_ = 0.0;
    double largestPairOverlap_ = 0.0;
    double t_ = 0.0;
    long pairBegun_ = 0, wallBegun_ = 0, builds_ = 0;
    bool listValid_ = false;
    bool forcesValid_ = false;
};

} // namespace riser

#endif
