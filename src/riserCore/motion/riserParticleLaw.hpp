// riserCore: the law of motion of one sphere in the oscillating riser, in
// the lab frame, for the mesh-free engine (riserParticle). It knows the
// forces, not how they are integrated (motion/riserIntegrators.hpp):
//
//   (m_p + C_A m_f) dv/dt = F_D + F_L + C_A m_f Du/Dt + m_f Du/Dt + (m_p - m_f) g + F_C
//   dx/dt = v
//
// (doc/theory.md section 1: the added mass's dv/dt on the left; the fluid
// stress m_f Du/Dt; the buoyant weight), with the carrier of
// riser::RiserFlow evaluated exactly at the particle, each force from its
// own folder of the core (the functions OpenFOAM's particle forces call
// too), the list of forces of motion/forceList.hpp, and the Hertz–Mindlin
// force of contact/ at the riser's wall (riser::Wall). Each force can be
// switched off (a scene needs no more than it uses). The Basset force is not
// part of this law: its history needs a fixed step
// (motion/historyStepper.hpp), and the engine's integrators adapt theirs.
//
// The contact's tangential spring delta_t is part of the state: it grows
// with the tangential velocity of the contact point while in contact and is
// kept in the tangent plane; the Coulomb cap resets it (springAfter). So is,
// for a wet contact (contact/wetRestitution.hpp), the normal approach speed
// at the start of the contact in progress, which sets its restitution: the
// integrators record it at the contact's onset; it is not integrated.
//
// ParticleSystem puts the law in the form the integrators step,
// dy/dt = f(t, y), y = (x, v, delta_t).
//
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef RISERCORE_MOTION_RISERPARTICLELAW_HPP
#define RISERCORE_MOTION_RISERPARTICLELAW_HPP

#include "motion/forceList.hpp"

#include "addedMass/addedMass.hpp"
#include "carrier/riserFlow.hpp"
#include "contact/hertzMindlin.hpp"
#include "drag/dragCoefficient.hpp"
#include "fluidStress/fluidStress.hpp"
#include "gravity/buoyantWeight.hpp"
#include "lift/saffmanMeiLift.hpp"
#include "vector.hpp"
#include "wall/wall.hpp"

#include <limits>
#include <optional>

namespace riser {

//- The particle's state: position, velocity, tangential contact spring,
//  and the normal approach speed at the start of the contact in progress
//  (a wet contact's; NaN outside a contact or unknown)
struct ParticleState
{
    Vector x = Vector::Zero();
    Vector v = Vector::Zero();
    Vector spring = Vector::Zero();
    double approachSpeed = std::numeric_limits<double>::quiet_NaN();
};

class RiserParticleLaw
{
public:
    RiserParticleLaw(const RiserFlow& riser, double d, double rhoP, double rhoF,
                     double mu, const Vector& g, const ForceSelection& forces,
                     std::optional<HertzMindlinParameters> contact)
    :
        riser_(riser), d_(d), rhoP_(rhoP), rhoF_(rhoF), mu_(mu), g_(g),
        forces_(forces),
        factors_(d/(forces.pipeDiameter > 0.0 ? forces.pipeDiameter : riser.diameter())),
        contact_(contact ? std::optional<HertzMindlin>(HertzMindlin(*contact)) : std::nullopt)
    {
        const char* law = "riser::RiserParticleLaw";
        requireInRange(law, "d", d, 0.0, Bound::open, riser.diameter(), Bound::open);
        requirePositive(law, "rho_p", rhoP);
        requirePositive(law, "rho_f", rhoF);
        requirePositive(law, "mu", mu);
        requireNonNegative(law, "C_A", forces.CA);
        forces_[Force::contact] = bool(contact_);
    }

    const RiserFlow& riser() const { return riser_; }
    //- The wall the particle touches
    const Wall& wall() const { return riser_.wall(); }
    const ForceSelection& selection() const { return forces_; }
    double diameter() const { return d_; }
    double radius() const { return 0.5*d_; }
    double volume() const { return M_PI*d_*d_*d_/6.0; }
    double mass() const { return rhoP_*volume(); }
    double fluidMass() const { return rhoF_*volume(); }
    bool hasContact() const { return bool(contact_); }
    const HertzMindlin& contactLaw() const { return *contact_; }
    //- The particle in a contact: its radius, and the inertia the contact
    //  force accelerates (one inertia for every force, doc/theory.md
    //  section 3.7), for which the damping is calibrated
    ContactBody body() const { return ContactBody{radius(), inertia()}; }

    //- Mass with the added mass (the left-hand side)
    double inertia() const
    {
        return mass() + (forces_[Force::addedMass] ? addedMassInertia(forces_.CA, fluidMass()) : 0.0);
    }

    //- The wall contact point of the particle centred at x
    ContactPoint wallContact(const Vector& x, double t) const
    {
        return wall().contactPoint(x, radius(), t);
    }

    //- Overlap with the wall (negative: the gap)
    double overlap(const Vector& x, double t) const { return wall().overlap(x, radius(), t); }

    //- Every force at time t and state s, the contact's at contact point c
    //  (none: no contact force)
    ForceReport forces(double t, const ParticleState& s, const std::optional<ContactPoint>& c) const
    {
        ForceReport f;
        // the riser's kinematics at the particle's height, once (the same
        // bits as the carrier's own evaluations at (x, t))
        const AxisState axis = riser_.motion().state(s.x.z(), t);
        const Vector u = riser_.velocity(s.x, axis);
        const Vector w = u - s.v;
        const Vector DuDt = riser_.materialDerivative(s.x, axis);
        if (forces_[Force::drag])
        {
            f[Force::drag] = dragForce(forces_.dragLaw, factors_, d_, rhoF_, mu_, w);
        }
        if (forces_[Force::lift])
        {
            f[Force::lift] = saffmanMeiLiftForce(d_, rhoF_, mu_, w, riser_.vorticity(s.x, axis));
        }
        if (forces_[Force::addedMass])
        {
            f[Force::addedMass] = addedMassForce(forces_.CA, fluidMass(), DuDt);
        }
        if (forces_[Force::fluidStress]) f[Force::fluidStress] = fluidStressForce(fluidMass(), DuDt);
        if (forces_[Force::gravity]) f[Force::gravity] = buoyantWeight(mass(), fluidMass(), g_);
        if (contact_ && c)
        {
            f.overlap = c->overlap;
            if (f.overlap > 0.0)
            {
                const ContactForce cf = contact_->force
                (
                    body(), f.overlap, c->normal, s.v - c->velocity, s.spring,
                    s.approachSpeed
                );
                f[Force::contact] = cf.normal + cf.tangential;
                f.sliding = cf.sliding;
            }
        }
        return f;
    }

    //- Every force at time t and state s, the contact at the wall included
    ForceReport forces(double t, const ParticleState& s) const
    {
        return forces(t, s, contact_ ? std::optional<ContactPoint>(wallContact(s.x, t)) : std::nullopt);
    }

    //- dv/dt at time t and state s
    Vector acceleration(double t, const ParticleState& s) const
    {
        return forces(t, s).total()/inertia();
    }

    //- d(spring)/dt: the contact point's tangential velocity relative to
    //  the body touched, while in contact (zero outside)
    static Vector springRate(const ParticleState& s, const ContactPoint& c)
    {
        if (c.overlap <= 0.0) return Vector::Zero();
        const Vector U = s.v - c.velocity;
        return U - U.dot(c.normal)*c.normal;
    }

    //- The spring after the Coulomb cap, kept in the tangent plane
    Vector cappedSpring(double t, const ParticleState& s) const
    {
        if (!contact_) return Vector::Zero();
        const ContactPoint c = wallContact(s.x, t);
        if (c.overlap <= 0.0) return Vector::Zero();
        const Vector spring = s.spring - s.spring.dot(c.normal)*c.normal;
        return contact_->force
        (
            body(), c.overlap, c.normal, s.v - c.velocity, spring, s.approachSpeed
        ).springAfter;
    }

private:
    RiserFlow riser_;
    double d_, rhoP_, rhoF_, mu_;
    Vector g_;
    ForceSelection forces_;
    WallFactors factors_;
    std::optional<HertzMindlin> contact_;
};


//- The law as the first-order system the integrators step: y = (x, v,
//  delta_t); with contact off, no contact force and no spring. The approach
//  speed of the contact in progress is the system's, set by the integrator
//  at the contact's onset.
class ParticleSystem
{
public:
    using State = Eigen::Matrix<double, 9, 1>;

    ParticleSystem(const RiserParticleLaw& law, bool contact)
    :
        law_(law), contact_(contact && law.hasContact())
    {}

    static State pack(const ParticleState& s)
    {
        State y;
        y << s.x, s.v, s.spring;
        return y;
    }

    static ParticleState unpack(const State& y)
    {
        ParticleState s;
        s.x = y.segment<3>(0);
        s.v = y.segment<3>(3);
        s.spring = y.segment<3>(6);
        return s;
    }

    //- The approach speed of the contact in progress (NaN: none)
    double approachSpeed() const { return approachSpeed_; }
    void approachSpeed(double v) { approachSpeed_ = v; }

    //- dy/dt at (t, y) (the law may throw: its values are computed before
    //  they are put into dy)
    State rate(double t, const State& y) const
    {
        ParticleState s = unpack(y);
        s.approachSpeed = approachSpeed_;
        State dy;
        if (!contact_)
        {
            s.spring.setZero();
            const Vector a = law_.forces(t, s, std::nullopt).total()/law_.inertia();
            dy << s.v, a, Vector::Zero();
            return dy;
        }
        const ContactPoint c = law_.wallContact(s.x, t);
        const Vector a = law_.forces(t, s, c).total()/law_.inertia();
        dy << s.v, a, RiserParticleLaw::springRate(s, c);
        return dy;
    }

private:
    const RiserParticleLaw& law_;
    bool contact_;
    double approachSpeed_ = std::numeric_limits<double>::quiet_NaN();
};

} // namespace riser

#endif
