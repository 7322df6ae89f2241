// riserCore: the law of motion of one sphere in the oscillating riser, in
// the lab frame, for the mesh-free engine (riserParticle). It knows the
// forces, not how they are integrated (motion/riserIntegrators.hpp).
//
//   (m_p + C_A m_f) dv/dt = F_D + F_L + (1 + C_A) m_f Du/Dt + (m_p - m_f) g + F_C
//   dx/dt = v
//
// (MODEL.md section 1: the added mass's dv/dt on the left; the fluid stress
// m_f Du/Dt; the buoyant weight), with the carrier of riser::RiserFlow
// evaluated exactly at the particle, the drag and lift of drag/ and lift/,
// and the Hertz–Mindlin wall force of contact/ for the overlap
// delta_n = R_p - (R - h), h the distance of the centre from the riser axis.
// Each force can be switched off (a scene needs no more than it uses). The
// Basset force is not part of this law: its history needs a fixed step
// (motion/historyStepper.hpp), and the engine's integrators adapt theirs.
//
// The contact's tangential spring delta_t is part of the state: it grows
// with the tangential velocity of the contact point while in contact and is
// kept in the tangent plane; the Coulomb cap resets it (springAfter).
//
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef RISERCORE_MOTION_RISERPARTICLELAW_HPP
#define RISERCORE_MOTION_RISERPARTICLELAW_HPP

#include "../carrier/riserFlow.hpp"
#include "../contact/hertzMindlin.hpp"
#include "../drag/dragCoefficient.hpp"
#include "../lift/saffmanMeiLift.hpp"
#include "../vector.hpp"

#include <optional>

namespace riser {

//- Which forces act, and their coefficients
struct ForceSelection
{
    bool drag = true;
    DragLaw dragLaw = DragLaw::paper;
    double pipeDiameter = 0.0;      //!< for the wall factors (0: the riser's)
    bool lift = true;
    bool addedMass = true;
    double CA = 0.5;
    bool fluidStress = true;
    bool gravity = true;
};

//- The particle's state: position, velocity, tangential contact spring
struct ParticleState
{
    Vector x = Vector::Zero();
    Vector v = Vector::Zero();
    Vector spring = Vector::Zero();
};

//- Every force at one state (lab frame), the contact's overlaps included
struct ForceReport
{
    Vector drag = Vector::Zero();
    Vector lift = Vector::Zero();
    Vector addedMass = Vector::Zero();      //!< its explicit part C_A m_f Du/Dt
    Vector fluidStress = Vector::Zero();
    Vector gravity = Vector::Zero();
    Vector contact = Vector::Zero();
    double overlap = 0.0;                   //!< delta_n (> 0 in contact)
    bool sliding = false;
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
    }

    const RiserFlow& riser() const { return riser_; }
    double diameter() const { return d_; }
    double radius() const { return 0.5*d_; }
    double volume() const { return M_PI*d_*d_*d_/6.0; }
    double mass() const { return rhoP_*volume(); }
    double fluidMass() const { return rhoF_*volume(); }
    bool hasContact() const { return bool(contact_); }
    const HertzMindlin& contactLaw() const { return *contact_; }

    //- Mass with the added mass (the left-hand side)
    double inertia() const
    {
        return mass() + (forces_.addedMass ? forces_.CA*fluidMass() : 0.0);
    }

    //- Riser axis at time t (passes through (x_c, 0, z))
    Vector axis(double t) const { return Vector(riser_.axisPosition(t), 0.0, 0.0); }

    //- Wall velocity (the riser's)
    Vector wallVelocity(double t) const { return Vector(riser_.riserVelocity(t), 0.0, 0.0); }

    //- Distance of the centre from the axis
    double axisDistance(const Vector& x, double t) const
    {
        const Vector r = x - axis(t);
        return std::hypot(r.x(), r.y());
    }

    //- Overlap delta_n = R_p - (R - h) (negative: the gap)
    double overlap(const Vector& x, double t) const
    {
        return radius() - (riser_.radius() - axisDistance(x, t));
    }

    //- Unit normal from the centre towards the nearest wall
    Vector wallNormal(const Vector& x, double t) const
    {
        Vector r = x - axis(t);
        r.z() = 0.0;
        const double h = r.norm();
        return h > 0.0 ? Vector(r/h) : Vector(1.0, 0.0, 0.0);
    }

    //- Every force at time t and state s
    ForceReport forces(double t, const ParticleState& s) const
    {
        ForceReport f;
        const Vector u = riser_.velocity(s.x, t);
        const Vector w = u - s.v;
        const double slip = w.norm();
        const Vector DuDt = riser_.materialDerivative(s.x, t);
        if (forces_.drag)
        {
            const double Re = rhoF_*slip*d_/mu_;
            f.drag = dragFactor(forces_.dragLaw, factors_, d_, mu_, Re)*w;
        }
        if (forces_.lift)
        {
            const Vector Omega = riser_.vorticity(s.x, t);
            f.lift = saffmanMeiLiftPrefactor(d_, rhoF_, mu_, slip, Omega.norm())*w.cross(Omega);
        }
        if (forces_.addedMass) f.addedMass = forces_.CA*fluidMass()*DuDt;
        if (forces_.fluidStress) f.fluidStress = fluidMass()*DuDt;
        if (forces_.gravity) f.gravity = (mass() - fluidMass())*g_;
        if (contact_)
        {
            f.overlap = overlap(s.x, t);
            if (f.overlap > 0.0)
            {
                const ContactForce c = contact_->force
                (
                    ContactBody{radius(), mass()}, f.overlap, wallNormal(s.x, t),
                    s.v - wallVelocity(t), s.spring
                );
                f.contact = c.normal + c.tangential;
                f.sliding = c.sliding;
            }
        }
        return f;
    }

    //- dv/dt at time t and state s
    Vector acceleration(double t, const ParticleState& s) const
    {
        const ForceReport f = forces(t, s);
        return (f.drag + f.lift + f.addedMass + f.fluidStress + f.gravity + f.contact)/inertia();
    }

    //- d(spring)/dt: the contact point's tangential velocity relative to
    //  the wall while in contact (zero outside)
    Vector springRate(double t, const ParticleState& s) const
    {
        if (!contact_ || overlap(s.x, t) <= 0.0) return Vector::Zero();
        const Vector n = wallNormal(s.x, t);
        const Vector U = s.v - wallVelocity(t);
        return U - U.dot(n)*n;
    }

    //- The spring after the Coulomb cap, kept in the tangent plane
    Vector cappedSpring(double t, const ParticleState& s) const
    {
        if (!contact_) return Vector::Zero();
        const double dn = overlap(s.x, t);
        if (dn <= 0.0) return Vector::Zero();
        const Vector n = wallNormal(s.x, t);
        Vector spring = s.spring - s.spring.dot(n)*n;
        const ContactForce c = contact_->force
        (
            ContactBody{radius(), mass()}, dn, n, s.v - wallVelocity(t), spring
        );
        return c.springAfter;
    }

private:
    RiserFlow riser_;
    double d_, rhoP_, rhoF_, mu_;
    Vector g_;
    ForceSelection forces_;
    WallFactors factors_;
    std::optional<HertzMindlin> contact_;
};

} // namespace riser

#endif
