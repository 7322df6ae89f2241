// riserCore: one contact over one step of a time-stepped DEM, the kernel
// that every stepped contact path calls (the tracked cloud's wall and pair
// contacts, the grain engine's pairs and walls, the hand-over between them).
//
// Two sides touch: body i, and body j or a wall (a wall is a side with the
// wall's velocity at the contact point, no spin and no radius). With n the
// unit normal from i's centre towards j (or the wall) and delta_n > 0 the
// overlap:
//
//   U     = v_i - v_j + omega_i x (R_i n) + omega_j x (R_j n)
//           (velocity of i's contact point relative to j's; Johnson,
//           Contact Mechanics, 1985, ch. 4)
//   s     = |s_0| (s_0 - (s_0.n) n)/|s_0 - (s_0.n) n| + U_t dt
//           (the kept tangential spring s_0 turned into the tangent plane,
//           its length kept, then grown by the tangential slip of the step;
//           a spring that lies along n has no tangential direction and is
//           dropped)
//   F     = F_n + F_t from the Hertz–Mindlin law (contact/hertzMindlin.hpp)
//           on body i, -F on j (Newton's third law)
//   T_i   = R_i n x F_t,   T_j = R_j n x F_t   (torques about the centres)
//   P     = F.U, the power of the contact force on the relative motion
//           (the dissipation of a step is -dt/2 (P_before + P_after), the
//           trapezoid rule, summed by the caller)
//   E_el  = 2/5 k_n delta_n^(5/2) + 1/2 k_t |s|^2 (energy in the springs,
//           elasticEnergy, for a caller that tallies it)
//
// vIn is the contact's normal approach speed at its start (U.n at its first
// evaluation), which a wet law's damping depends on (contact/
// wetRestitution.hpp); a dry law ignores it.
//
// The spring kept after the step is the law's (after the Coulomb cap). dt = 0
// evaluates the force of a contact handed over with its spring, without
// stepping it.
//
// The mesh-free single-particle engine (motion/) integrates the spring as a
// state of its ODE system instead, so it calls the law itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef RISERCORE_CONTACT_CONTACTKERNEL_HPP
#define RISERCORE_CONTACT_CONTACTKERNEL_HPP

#include "contact/hertzMindlin.hpp"

#include <cmath>

namespace riser {

//- One side of a contact: its centre's velocity, its spin and its radius
//  (a wall: the wall's velocity at the contact point, no spin, radius 0)
struct ContactSide
{
    Vector v;
    Vector omega;
    double radius;
};

//- The wall as the second side of a contact
inline ContactSide wallSide(const Vector& wallVelocity)
{
    return ContactSide{wallVelocity, Vector::Zero(), 0.0};
}

//- U: velocity of i's contact point relative to j's, n from i towards j
inline Vector contactVelocity(const ContactSide& i, const ContactSide& j, const Vector& n)
{
    return i.v - j.v + i.omega.cross(i.radius*n) + j.omega.cross(j.radius*n);
}

//- The kept spring turned into the plane normal to n, its length kept
inline Vector turnedSpring(const Vector& s, const Vector& n)
{
    const Vector st = s - s.dot(n)*n;
    const double l = st.norm();
    return l > 0.0 ? Vector(st*(s.norm()/l)) : Vector(Vector::Zero());
}

//- Energy held in the springs of a contact at overlap delta > 0 with
//  spring s
inline double elasticEnergy(const HertzMindlin& law, const ContactBody& b,
                            double delta, const Vector& s)
{
    const double kt = 8.0*law.equivalentShearModulus()*std::sqrt(b.radius*delta);
    return 0.4*law.normalStiffness(b)*delta*delta*std::sqrt(delta) + 0.5*kt*s.squaredNorm();
}

//- What one step of a contact gives
struct ContactStep
{
    ContactForce law;   //!< F_n, F_t, the spring kept, sliding
    Vector force;       //!< F = F_n + F_t on i (-F on j)
    Vector torqueI;     //!< about i's centre
    Vector torqueJ;     //!< about j's centre
    Vector U;           //!< i's contact point relative to j's
    double power;       //!< F.U
};

//- One contact over a step dt: sides i and j with overlap along n (from i
//  towards j; apart, overlap <= 0: all zero), body the equivalent R and M
//  the law sees, kept the spring the contact kept from its previous step,
//  vIn its normal approach speed at its start
inline ContactStep stepContact(const HertzMindlin& law, const ContactBody& body,
                               double overlap, const Vector& n,
                               const ContactSide& i, const ContactSide& j,
                               const Vector& kept, double vIn, double dt)
{
    requireNonNegative("riser::stepContact", "dt", dt);
    ContactStep c;
    c.U = contactVelocity(i, j, n);
    if (overlap <= 0.0)
    {
        // apart: no force, no spring kept
        c.law = ContactForce{Vector::Zero(), Vector::Zero(), Vector::Zero(), false};
        c.force = c.torqueI = c.torqueJ = Vector::Zero();
        c.power = 0.0;
        return c;
    }
    const Vector Ut = c.U - c.U.dot(n)*n;
    c.law = law.force(body, overlap, n, c.U, turnedSpring(kept, n) + dt*Ut, vIn);
    c.force = c.law.normal + c.law.tangential;
    c.torqueI = (i.radius*n).cross(c.law.tangential);
    c.torqueJ = (j.radius*n).cross(c.law.tangential);
    c.power = c.force.dot(c.U);
    return c;
}

} // namespace riser

#endif
