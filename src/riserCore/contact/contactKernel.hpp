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
// Lubricated (the law's film(), contact/lubrication.hpp): the film acts
// along n at a gap h = -overlap below its cut-off. Its impulse between two
// gaps does not depend on the speed along the way (lubrication.hpp), so
// the kernel gives each evaluation the film's impulse over the gaps the
// evaluation's force acts across. Every stepped caller is of the velocity
// Verlet kind (the colliding cloud's half kicks around its move, the
// grain engine, the trapezoid of a history stepper): the force evaluated
// at gap h with the velocity u = U.n of the half step behind acts half
// behind and half ahead, from the middle of the last move, h + u dt/2, to
// the middle of the next, h - u' dt/2, with u' = u + J/M the half step's
// speed ahead that the impulse J itself sets:
//
//   J = 6 pi mu R*^2 [G(h - (u + J/M) dt/2) - G(h + u dt/2)],
//
// so that consecutive evaluations' intervals join exactly and their
// impulses add up to the film's whole, whatever the step (at a constant
// step; a caller that changes its step there loses part of one
// evaluation's impulse). M is the body's inertia; in a step that starts in
// contact (and may leave it) u' = U.n + dt F.n/M + J/M with the contact's
// force F. J is solved for (Newton's method, kept in its bracket) between
// 0 and the impulse -M (u' - J/M) that stops the relative normal motion,
// so the film slows it and never reverses it. The force is J/dt n; dt = 0
// evaluates the film's force at h instead, -6 pi mu R*^2 g(h) (U.n) n.
// The film has no spring and no torque; its power F.U is dissipated.
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
#include "contact/lubrication.hpp"

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

//- The film's impulse along n of an evaluation at gap h (< 0: an
//  overlap) over a step dt > 0 (see above): u the normal approach speed of
//  the half step behind, uAhead that of the half step ahead without the
//  film, body the equivalent R and M
inline double filmImpulse(const LubricationFilm& film, const ContactBody& body,
                          double gap, double u, double uAhead, double dt)
{
    const double R = body.radius, M = body.mass;
    const double upper = gap + 0.5*u*dt;
    // beyond the cut-off at both ends, whatever J: no film (the lower end
    // lies between gap - uAhead dt/2, J = 0, and gap, J stopping)
    const double cut = film.cutoffGap(R);
    if (upper >= cut && std::min(gap, gap - 0.5*uAhead*dt) >= cut) return 0.0;
    const double c = film.coefficient(R), Gupper = film.potential(R, upper);
    auto lower = [&](double J) { return gap - 0.5*(uAhead + J/M)*dt; };
    // f(J) = J - 6 pi mu R^2 [G(lower(J)) - G(upper)], increasing in J
    auto f = [&](double J) { return J - c*(film.potential(R, lower(J)) - Gupper); };
    const double stop = -M*uAhead;
    if (stop == 0.0) return 0.0;
    const double f0 = f(0.0);
    if (f0 == 0.0) return 0.0;
    // the root lies between 0 and stop, or beyond stop: then stop
    const double fStop = f(stop);
    if ((fStop > 0.0) == (f0 > 0.0)) return stop;
    double lo = std::min(0.0, stop), hi = std::max(0.0, stop);
    const double tol = 1e-13*(hi - lo);
    // Newton's method from the explicit impulse (that of the gap the step
    // reaches without the film), kept in the bracket
    double J = std::min(std::max(-f0, lo), hi);
    for (int k = 0; k < 100; ++k)
    {
        const double fJ = f(J);
        (fJ > 0.0 ? hi : lo) = J;
        const double slope = 1.0 + 0.5*c*film.weight(R, lower(J))*dt/M;
        double next = J - fJ/slope;
        if (!(next > lo && next < hi)) next = 0.5*(lo + hi);
        const bool done = std::abs(next - J) <= tol || hi - lo <= tol;
        J = next;
        if (done) break;
    }
    return J;
}

//- The film's force on i at gap h along n over a step dt (dt = 0: at h),
//  body the equivalent R and M, U i's contact point relative to the other
//  side's
inline Vector filmForce(const LubricationFilm& film, const ContactBody& body,
                        double gap, const Vector& n, const Vector& U, double dt)
{
    if (dt == 0.0)
    {
        return -film.coefficient(body.radius)*film.weight(body.radius, gap)*U.dot(n)*n;
    }
    return (filmImpulse(film, body, gap, U.dot(n), U.dot(n), dt)/dt)*n;
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
//  towards j; apart, overlap <= 0: the film's force if lubricated, else
//  all zero), body the equivalent R and M
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
        // apart: no spring kept; the film's force only, if lubricated
        c.law = ContactForce{Vector::Zero(), Vector::Zero(), Vector::Zero(), false};
        c.force = law.film()
                ? filmForce(*law.film(), body, -overlap, n, c.U, dt)
                : Vector(Vector::Zero());
        c.torqueI = c.torqueJ = Vector::Zero();
        c.power = c.force.dot(c.U);
        return c;
    }
    const Vector Ut = c.U - c.U.dot(n)*n;
    c.law = law.force(body, overlap, n, c.U, turnedSpring(kept, n) + dt*Ut, vIn);
    c.force = c.law.normal + c.law.tangential;
    if (law.film() && dt > 0.0)
    {
        // the film of a step that leaves the contact
        const double Un = c.U.dot(n);
        c.force +=
            (
                filmImpulse
                (
                    *law.film(), body, -overlap, Un, Un + dt*c.force.dot(n)/body.mass, dt
                )/dt
            )*n;
    }
    c.torqueI = (i.radius*n).cross(c.law.tangential);
    c.torqueJ = (j.radius*n).cross(c.law.tangential);
    c.power = c.force.dot(c.U);
    return c;
}

} // namespace riser

#endif
