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
// I = 2/5 m R^2 when rotation is on. The tangential spring of a contact,
// kept from its first to its last step, is turned into the current tangent
// plane (its length kept) and then grows by U_t dt; the law caps it.
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

//- One sphere: position, velocity, angular velocity, radius, mass
struct Grain
{
    Vector x;
    Vector v;
    Vector omega;
    double radius;
    double mass;
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
        wallSpring_.assign(grains_.size()*walls_.size(), Vector::Zero());
        wallTouching_.assign(grains_.size()*walls_.size(), false);
        forcesValid_ = false;
    }

    void addGrain(const Grain& p)
    {
        requirePositive("riser::GranularSystem", "R", p.radius);
        requirePositive("riser::GranularSystem", "m", p.mass);
        // a new grain joins with no contact history; the list is rebuilt
        std::vector<Vector> springs(wallSpring_);
        std::vector<bool> touching(wallTouching_);
        grains_.push_back(p);
        springs.resize(grains_.size()*walls_.size(), Vector::Zero());
        touching.resize(grains_.size()*walls_.size(), false);
        wallSpring_.swap(springs);
        wallTouching_.swap(touching);
        listValid_ = false;
        forcesValid_ = false;
    }

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
    //  contacts (2/5 k_n delta^(5/2) normal, 1/2 k_t |delta_t|^2 tangential)
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
    static double inertia(const Grain& q) { return 0.4*q.mass*q.radius*q.radius; }

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
            p.v += h*(force_[i]/p.mass + g_);
            if (rotation_) p.omega += h*torque_[i]/inertia(p);
        }
        wallImpulse_ += h*wallForce_;
    }

    //- A candidate pair of the Verlet list (i < j) and its spring, kept in
    //  i's frame (normal from i towards j)
    struct Candidate
    {
        std::uint32_t i, j;
        Vector spring;
        bool touching;
    };

    //- Rebuild the candidate list, carrying over the springs of the pairs
    //  in contact
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
        std::unordered_map<std::uint64_t, Vector> kept;
        kept.reserve(pairsTouching_ + 1);
        for (const Candidate& c : list_)
        {
            if (c.touching) kept.emplace((std::uint64_t(c.i) << 32) | c.j, c.spring);
        }
        list_.clear();
        cells_.build(positions_, 2.0*rMax + skinLength_);
        cells_.forEachPair([&](std::size_t a, std::size_t b)
        {
            const std::size_t i = std::min(a, b), j = std::max(a, b);
            const double reach = grains_[i].radius + grains_[j].radius + skinLength_;
            if ((positions_[j] - positions_[i]).squaredNorm() > reach*reach) return;
            const auto k = kept.find((std::uint64_t(i) << 32) | j);
            list_.push_back(Candidate{std::uint32_t(i), std::uint32_t(j),
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
            const PairGeometry geo = pairGeometry(a.x, a.radius, b.x, b.radius);
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
    std::vector<Candidate> list_;
    std::vector<Vector> wallSpring_;    //!< per grain and wall
    std::vector<bool> wallTouching_;
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
