// riserCore: many spheres in contact with each other and with walls, with
// no fluid: discrete element method (Cundall & Strack, Geotechnique 29, 47,
// 1979) with the Hertz–Mindlin law of contact/hertzMindlin.hpp for both
// kinds of contact (pairs through contact/pairContact.hpp, walls through
// riser::Wall). Pairs are found by a cell list (granular/cellList.hpp), so a
// step costs O(N).
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
    //  wallLaw: between a grain and any wall; g: gravity
    GranularSystem(const HertzMindlin& pairLaw, const HertzMindlin& wallLaw,
                   const Vector& g, bool rotation)
    :
        pairLaw_(pairLaw), wallLaw_(wallLaw), g_(g), rotation_(rotation)
    {}

    //- A wall the grains touch; the caller keeps it alive
    void addWall(const Wall& w)
    {
        walls_.push_back(&w);
        forcesValid_ = false;
    }

    void addGrain(const Grain& p)
    {
        requirePositive("riser::GranularSystem", "R", p.radius);
        requirePositive("riser::GranularSystem", "m", p.mass);
        grains_.push_back(p);
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
    std::size_t pairContacts() const { return pairSpring_.size(); }
    std::size_t wallContacts() const { return wallSpring_.size(); }

    //- Contacts begun since the start (each counted at its first step)
    long pairContactsBegun() const { return pairBegun_; }
    long wallContactsBegun() const { return wallBegun_; }

    //- Mean number of grain neighbours in contact, 2 N_pairs / N
    double coordinationNumber() const
    {
        return grains_.empty() ? 0.0 : 2.0*double(pairSpring_.size())/double(grains_.size());
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

    //- Key of the pair (i, j), the same for (j, i)
    static std::uint64_t key(std::size_t i, std::size_t j)
    {
        return (std::uint64_t(std::min(i, j)) << 32) | std::uint64_t(std::max(i, j));
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
            p.v += h*(force_[i]/p.mass + g_);
            if (rotation_) p.omega += h*torque_[i]/inertia(p);
        }
        wallImpulse_ += h*wallForce_;
    }

    //- Forces at the current positions; dt: the step that led here (the
    //  springs grow by U_t dt)
    void computeForces(double dt)
    {
        const std::size_t n = grains_.size();
        force_.assign(n, Vector::Zero());
        torque_.assign(n, Vector::Zero());
        wallForce_.setZero();
        elastic_ = 0.0;
        largestPairOverlap_ = 0.0;

        std::unordered_map<std::uint64_t, Vector> pairs;
        std::unordered_map<std::uint64_t, Vector> walls;
        pairs.reserve(pairSpring_.size() + 16);
        walls.reserve(wallSpring_.size() + 16);

        if (n > 1)
        {
            positions_.resize(n);
            double rMax = 0.0;
            for (std::size_t i = 0; i < n; ++i)
            {
                positions_[i] = grains_[i].x;
                rMax = std::max(rMax, grains_[i].radius);
            }
            cells_.build(positions_, 2.0*rMax);
            cells_.forEachPair([&](std::size_t i, std::size_t j)
            {
                const Grain& a = grains_[i];
                const Grain& b = grains_[j];
                const PairGeometry geo = pairGeometry(a.x, a.radius, b.x, b.radius);
                if (geo.overlap <= 0.0) return;
                const Vector U = rotation_
                  ? pairContactVelocity(geo, a.v, a.omega, a.radius, b.v, b.omega, b.radius)
                  : Vector(a.v - b.v);
                // the spring belongs to the ordered pair (lower index first)
                const double sign = i < j ? 1.0 : -1.0;
                const std::uint64_t k = key(i, j);
                const auto old = pairSpring_.find(k);
                if (old == pairSpring_.end()) ++pairBegun_;
                const Vector kept = old == pairSpring_.end() ? Vector(Vector::Zero()) : Vector(sign*old->second);
                const Vector Ut = U - U.dot(geo.normal)*geo.normal;
                const Vector spring = turned(kept, geo.normal) + dt*Ut;
                const ContactBody body = pairBody(a.radius, a.mass, b.radius, b.mass);
                const ContactForce c = pairLaw_.force(body, geo.overlap, geo.normal, U, spring);
                const Vector F = c.normal + c.tangential;
                force_[i] += F;
                force_[j] -= F;
                if (rotation_)
                {
                    torque_[i] += (a.radius*geo.normal).cross(c.tangential);
                    torque_[j] += (b.radius*geo.normal).cross(c.tangential);
                }
                pairs[k] = sign*c.springAfter;
                elastic_ += energyOf(body, geo.overlap, c.springAfter, pairLaw_);
                largestPairOverlap_ = std::max
                (
                    largestPairOverlap_, geo.overlap/(2.0*std::min(a.radius, b.radius))
                );
            });
        }

        for (std::size_t i = 0; i < n; ++i)
        {
            const Grain& p = grains_[i];
            for (std::size_t w = 0; w < walls_.size(); ++w)
            {
                const ContactPoint cp = walls_[w]->contactPoint(p.x, p.radius, t_);
                if (cp.overlap <= 0.0) continue;
                Vector U = p.v - cp.velocity;
                if (rotation_) U += p.omega.cross(p.radius*cp.normal);
                const std::uint64_t k = std::uint64_t(i)*walls_.size() + w;
                const auto old = wallSpring_.find(k);
                if (old == wallSpring_.end()) ++wallBegun_;
                const Vector kept = old == wallSpring_.end() ? Vector(Vector::Zero()) : old->second;
                const Vector Ut = U - U.dot(cp.normal)*cp.normal;
                const Vector spring = turned(kept, cp.normal) + dt*Ut;
                const ContactBody body(p.radius, p.mass);
                const ContactForce c = wallLaw_.force(body, cp.overlap, cp.normal, U, spring);
                const Vector F = c.normal + c.tangential;
                force_[i] += F;
                wallForce_ += F;
                if (rotation_) torque_[i] += (p.radius*cp.normal).cross(c.tangential);
                walls[k] = c.springAfter;
                elastic_ += energyOf(body, cp.overlap, c.springAfter, wallLaw_);
            }
        }
        pairSpring_.swap(pairs);
        wallSpring_.swap(walls);
        forcesValid_ = true;
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
    std::vector<Vector> force_, torque_, positions_;
    std::unordered_map<std::uint64_t, Vector> pairSpring_, wallSpring_;
    CellList cells_;
    Vector wallForce_ = Vector::Zero();
    Vector wallImpulse_ = Vector::Zero();
    double elastic_ = 0.0;
    double largestPairOverlap_ = 0.0;
    double t_ = 0.0;
    long pairBegun_ = 0, wallBegun_ = 0;
    bool forcesValid_ = false;
};

} // namespace riser

#endif
