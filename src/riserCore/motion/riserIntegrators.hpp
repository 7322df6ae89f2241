// riserCore: integrators of the riser particle law (motion/riserParticleLaw.hpp)
// for the mesh-free engine. The law gives forces; an integrator decides how
// to step, and reports to an observer (rows at output times, and contacts).
//
// paperScheme - the scheme of Wei et al. (2023) as described in MODEL.md
//     section 3: a fifth-order Runge–Kutta step (Dormand–Prince) of fixed
//     flow step h for the flow, the wall ignored; after each step, contact
//     is declared when the gap to the wall is below eps d and the particle
//     approaches the wall; the contact is then integrated by classical RK4
//     with the fixed contact step h_c with the particle's position frozen:
//     the overlap is a variable of its own, d(delta_n)/dt = (v - U_w).n,
//     and the contact ends when delta_n falls below zero after it has been
//     positive. The flow forces act at the frozen position. With the
//     paper's h = 1e-3 D/u_cm the particle moves up to ~1e-4 m per flow
//     step, far more than eps d and than the contact's largest overlap
//     (~1e-5 m), so a flow step usually ends inside the wall. Where
//     delta_n starts is not said by the paper; two readings:
//       ContactStart::detection (default) - at detection: the gap if the
//         step ended in the eps band, zero if it ended inside the wall
//         (the step's penetration is dropped; the contact happens where
//         the particle is);
//       ContactStart::geometric - at the geometric overlap the flow step
//         left: its elastic energy is released on rebound (a gain of
//         several times the impact energy per contact, which runs away in
//         the riser scenes; validation/riserParticle charts it).
//
// adaptive - an embedded Dormand–Prince 5(4) pair with error control on the
//     whole law, contact included, with the particle and the wall moving.
//     Contact onset and end are events: a step across a change of sign of
//     the overlap is replaced by the step to the crossing, found by regula
//     falsi on the step length to an overlap of 1e-7 d (the contact's
//     overlaps are ~1e-3 d), so that no step straddles the force's kink.
//     Steps are not cut short by output times: rows come from the pair's
//     fourth-order continuous extension. No step grows right after a
//     rejected one.
//
// Both throw riser::IntegrationFailure when the state stops making sense (a
// value not finite, or an overlap beyond the particle's radius): a step too
// large for the scene, reported rather than carried on. Callers that trap
// floating-point exceptions should turn the trap off around run().
//
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef RISERCORE_MOTION_RISERINTEGRATORS_HPP
#define RISERCORE_MOTION_RISERINTEGRATORS_HPP

#include "riserParticleLaw.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <sstream>
#include <stdexcept>

namespace riser {

//- An integration that went wrong (see top); what() says when and why
struct IntegrationFailure : std::runtime_error
{
    using std::runtime_error::runtime_error;
};

//- One wall contact, as reported to the observer
struct ContactRecord
{
    double start = 0.0, end = 0.0;
    int side = 0;                   //!< +1: wall at x > x_c, -1: at x < x_c
    double maxOverlap = 0.0;
    double impactSpeed = 0.0;       //!< normal speed towards the wall at the start
    double reboundSpeed = 0.0;      //!< normal speed away from the wall at the end
};

//- What an integrator reports
struct Observer
{
    //- The state at an output time
    std::function<void(double t, const ParticleState&)> row;
    //- A completed contact
    std::function<void(const ContactRecord&)> contact;
};

//- Counters of the work done
struct IntegratorStats
{
    long steps = 0, rejected = 0, contactSteps = 0, forceEvaluations = 0;
};

namespace detail {

// Dormand–Prince 5(4) tableau
struct DP
{
    static constexpr double c2 = 1.0/5, c3 = 3.0/10, c4 = 4.0/5, c5 = 8.0/9;
    static constexpr double a21 = 1.0/5;
    static constexpr double a31 = 3.0/40, a32 = 9.0/40;
    static constexpr double a41 = 44.0/45, a42 = -56.0/15, a43 = 32.0/9;
    static constexpr double a51 = 19372.0/6561, a52 = -25360.0/2187, a53 = 64448.0/6561,
                            a54 = -212.0/729;
    static constexpr double a61 = 9017.0/3168, a62 = -355.0/33, a63 = 46732.0/5247,
                            a64 = 49.0/176, a65 = -5103.0/18656;
    static constexpr double b1 = 35.0/384, b3 = 500.0/1113, b4 = 125.0/192,
                            b5 = -2187.0/6784, b6 = 11.0/84;
    // b - b* (fifth minus fourth order weights)
    static constexpr double e1 = 71.0/57600, e3 = -71.0/16695, e4 = 71.0/1920,
                            e5 = -17253.0/339200, e6 = 22.0/525, e7 = -1.0/40;
    // the fourth-order continuous extension (Hairer, Norsett & Wanner,
    // Solving ODEs I, 2nd ed., sec. II.6, the dense output of DOPRI5)
    static constexpr double d1 = -12715105075.0/11282082432.0,
                            d3 = 87487479700.0/32700410799.0,
                            d4 = -10690763975.0/1880347072.0,
                            d5 = 701980252875.0/199316789632.0,
                            d6 = -1453857185.0/822651844.0,
                            d7 = 69997945.0/29380423.0;
};

//- The state as a vector of 9: x, v, spring
using Y = Eigen::Matrix<double, 9, 1>;

inline Y pack(const ParticleState& s)
{
    Y y;
    y << s.x, s.v, s.spring;
    return y;
}

inline ParticleState unpack(const Y& y)
{
    ParticleState s;
    s.x = y.segment<3>(0);
    s.v = y.segment<3>(3);
    s.spring = y.segment<3>(6);
    return s;
}

//- Throw IntegrationFailure if the state is not finite or the particle is
//  deeper in the wall than its radius
inline void requireSane(const RiserParticleLaw& law, double t, const Y& y)
{
    const char* what = nullptr;
    if (!y.allFinite()) what = "state not finite";
    else if (law.hasContact() && law.overlap(y.segment<3>(0), t) > law.radius())
    {
        what = "overlap beyond the particle radius";
    }
    if (what)
    {
        std::ostringstream msg;
        msg << what << " at t = " << t << " s";
        throw IntegrationFailure(msg.str());
    }
}

//- The law's forces at a state the integration reached: the law's own
//  argument checks (std::invalid_argument) become IntegrationFailure here,
//  the parameters having been checked when the law was built
inline ForceReport forcesAt(const RiserParticleLaw& law, double t, const ParticleState& s)
{
    const char* what = "state not finite";
    if (s.x.allFinite() && s.v.allFinite() && s.spring.allFinite())
    {
        try
        {
            return law.forces(t, s);
        }
        catch (const std::invalid_argument& e)
        {
            what = e.what();
        }
    }
    std::ostringstream msg;
    msg << what << " at t = " << t << " s";
    throw IntegrationFailure(msg.str());
}

//- dy/dt of the whole law (contact included or not)
inline Y rate(const RiserParticleLaw& law, double t, const Y& y, bool contact, long& evaluations)
{
    ++evaluations;
    ParticleState s = unpack(y);
    if (!contact) s.spring.setZero();
    Y dy;
    const ForceReport f = forcesAt(law, t, s);
    Vector F = f.drag + f.lift + f.addedMass + f.fluidStress + f.gravity;
    Vector springRate = Vector::Zero();
    if (contact)
    {
        F += f.contact;
        springRate = law.springRate(t, s);
    }
    dy << s.v, F/law.inertia(), springRate;
    return dy;
}

//- One Dormand–Prince step: the fifth-order solution, the error estimate
//  and the coefficients of the continuous extension over the step
struct Step
{
    Y y;        //!< the fifth-order solution at t + h
    Y err;      //!< fifth minus fourth order
    std::array<Y, 5> dense;

    //- The state at t + theta h, theta in [0, 1] (fourth order)
    Y at(double theta) const
    {
        const double u = 1.0 - theta;
        return dense[0] + theta*(dense[1] + u*(dense[2] + theta*(dense[3] + u*dense[4])));
    }
};

inline Step dormandPrince(const RiserParticleLaw& law, double t, const Y& y,
                          double h, bool contact, long& ev)
{
    using C = DP;
    const Y k1 = rate(law, t, y, contact, ev);
    const Y k2 = rate(law, t + C::c2*h, y + h*(C::a21*k1), contact, ev);
    const Y k3 = rate(law, t + C::c3*h, y + h*(C::a31*k1 + C::a32*k2), contact, ev);
    const Y k4 = rate(law, t + C::c4*h, y + h*(C::a41*k1 + C::a42*k2 + C::a43*k3), contact, ev);
    const Y k5 = rate(law, t + C::c5*h,
                      y + h*(C::a51*k1 + C::a52*k2 + C::a53*k3 + C::a54*k4), contact, ev);
    const Y k6 = rate(law, t + h,
                      y + h*(C::a61*k1 + C::a62*k2 + C::a63*k3 + C::a64*k4 + C::a65*k5), contact, ev);
    Step st;
    st.y = y + h*(C::b1*k1 + C::b3*k3 + C::b4*k4 + C::b5*k5 + C::b6*k6);
    const Y k7 = rate(law, t + h, st.y, contact, ev);
    st.err = h*(C::e1*k1 + C::e3*k3 + C::e4*k4 + C::e5*k5 + C::e6*k6 + C::e7*k7);
    st.dense[0] = y;
    st.dense[1] = st.y - y;
    st.dense[2] = h*k1 - st.dense[1];
    st.dense[3] = st.dense[1] - h*k7 - st.dense[2];
    st.dense[4] = h*(C::d1*k1 + C::d3*k3 + C::d4*k4 + C::d5*k5 + C::d6*k6 + C::d7*k7);
    return st;
}

} // namespace detail


//- Where the paper scheme's contact overlap starts (see top)
enum class ContactStart { detection, geometric };

//- The paper's scheme (see top)
class PaperScheme
{
public:
    //- flow step h, contact step hc, detection threshold eps (of d)
    PaperScheme(double h, double hc, double eps,
                ContactStart start = ContactStart::detection)
    :
        h_(h), hc_(hc), eps_(eps), start_(start)
    {
        requirePositive("riser::PaperScheme", "flow step", h);
        requirePositive("riser::PaperScheme", "contact step", hc);
        requireNonNegative("riser::PaperScheme", "eps", eps);
    }

    //- Integrate from (t0, s) to tEnd, rows every outputInterval (the flow
    //  step is shortened, if need be, to divide the row interval)
    IntegratorStats run(const RiserParticleLaw& law, double t0, ParticleState s,
                        double tEnd, double outputInterval, const Observer& obs) const
    {
        IntegratorStats stats;
        const long perRow = std::max(1L, long(std::ceil(outputInterval/h_ - 1e-9)));
        const double h = outputInterval/perRow;
        double t = t0;
        long k = 0, nextRow = perRow;
        if (obs.row) obs.row(t, s);
        while (t < tEnd - 0.5*h)
        {
            const detail::Y y = detail::dormandPrince(law, t, detail::pack(s), h, false,
                                                      stats.forceEvaluations).y;
            t = t0 + (++k)*h;
            detail::requireSane(law, t, y);
            s = detail::unpack(y);
            s.spring.setZero();
            ++stats.steps;
            if (law.hasContact())
            {
                const Vector n = law.wallNormal(s.x, t);
                const double approach = (s.v - law.wallVelocity(t)).dot(n);
                if (law.overlap(s.x, t) > -eps_*law.diameter() && approach > 0.0)
                {
                    t = contact(law, t, s, obs, stats);
                    // back on the flow grid
                    k = std::lround(std::ceil((t - t0)/h - 1e-9));
                    const double tGrid = t0 + k*h;
                    if (tGrid > t)
                    {
                        const detail::Y yg = detail::dormandPrince
                        (
                            law, t, detail::pack(s), tGrid - t, false, stats.forceEvaluations
                        ).y;
                        s = detail::unpack(yg);
                        s.spring.setZero();
                        t = tGrid;
                    }
                }
            }
            // rows on the grid; a row time passed inside a contact (which
            // lasts a fraction of a flow step) gets the state after it
            for (; nextRow <= k; nextRow += perRow)
            {
                if (obs.row) obs.row(t0 + nextRow*h, s);
            }
        }
        return stats;
    }

private:
    //- The contact phase at frozen position: returns the time at its end
    double contact(const RiserParticleLaw& law, double t, ParticleState& s,
                   const Observer& obs, IntegratorStats& stats) const
    {
        const Vector x = s.x;
        const Vector n = law.wallNormal(x, t);
        const ContactBody body{law.radius(), law.mass()};
        double dn = law.overlap(x, t);
        if (start_ == ContactStart::detection) dn = std::min(dn, 0.0);
        Vector spring = Vector::Zero();
        ContactRecord rec;
        rec.start = t;
        rec.side = n.x() >= 0.0 ? 1 : -1;
        rec.impactSpeed = (s.v - law.wallVelocity(t)).dot(n);
        bool touched = dn > 0.0;

        // rates of (v, delta_n, spring) at time tau
        struct Z { Vector v; double dn; Vector spring; };
        auto rate = [&](double tau, const Z& z)
        {
            ++stats.forceEvaluations;
            const ForceReport f = detail::forcesAt(law, tau, ParticleState{x, z.v, Vector::Zero()});
            Vector F = f.drag + f.lift + f.addedMass + f.fluidStress + f.gravity;
            const Vector U = z.v - law.wallVelocity(tau);
            if (z.dn > 0.0)
            {
                const ContactForce c = law.contactLaw().force(body, z.dn, n, U, z.spring);
                F += c.normal + c.tangential;
            }
            const Vector Ut = U - U.dot(n)*n;
            return Z{F/law.inertia(), U.dot(n), z.dn > 0.0 ? Ut : Vector::Zero()};
        };
        auto axpy = [](const Z& a, double c, const Z& b)
        {
            return Z{a.v + c*b.v, a.dn + c*b.dn, a.spring + c*b.spring};
        };

        Z z{s.v, dn, spring};
        // a contact never longer than the time to leave the eps band at the
        // approach speed, or than 1e6 contact steps
        for (long i = 0; i < 1000000; ++i)
        {
            const Z k1 = rate(t, z);
            const Z k2 = rate(t + 0.5*hc_, axpy(z, 0.5*hc_, k1));
            const Z k3 = rate(t + 0.5*hc_, axpy(z, 0.5*hc_, k2));
            const Z k4 = rate(t + hc_, axpy(z, hc_, k3));
            z.v += hc_/6.0*(k1.v + 2.0*k2.v + 2.0*k3.v + k4.v);
            z.dn += hc_/6.0*(k1.dn + 2.0*k2.dn + 2.0*k3.dn + k4.dn);
            z.spring += hc_/6.0*(k1.spring + 2.0*k2.spring + 2.0*k3.spring + k4.spring);
            t += hc_;
            ++stats.contactSteps;
            if (!z.v.allFinite() || !std::isfinite(z.dn) || z.dn > law.radius())
            {
                std::ostringstream msg;
                msg << "contact at frozen position: overlap " << z.dn/law.diameter()
                    << " d, speed " << z.v.norm() << " m/s at t = " << t << " s";
                throw IntegrationFailure(msg.str());
            }
            if (z.dn > 0.0)
            {
                touched = true;
                const ContactForce c = law.contactLaw().force(body, z.dn, n,
                                                              z.v - law.wallVelocity(t), z.spring);
                z.spring = c.springAfter;
                rec.maxOverlap = std::max(rec.maxOverlap, z.dn);
            }
            const bool leaving = (z.v - law.wallVelocity(t)).dot(n) < 0.0;
            if ((touched && z.dn <= 0.0) || (!touched && leaving)) break;
        }
        s.v = z.v;
        s.spring.setZero();
        rec.end = t;
        rec.reboundSpeed = -(s.v - law.wallVelocity(t)).dot(n);
        if (touched && obs.contact) obs.contact(rec);
        return t;
    }

    double h_, hc_, eps_;
    ContactStart start_;
};


//- Adaptive Dormand–Prince 5(4) with contact events (see top)
class AdaptiveScheme
{
public:
    //- relative tolerance, and the largest step
    AdaptiveScheme(double tolerance, double maxStep)
    :
        tol_(tolerance), hMax_(maxStep)
    {
        requireInRange("riser::AdaptiveScheme", "tolerance", tolerance,
                       0.0, Bound::open, 1.0, Bound::open);
        requirePositive("riser::AdaptiveScheme", "maxStep", maxStep);
    }

    IntegratorStats run(const RiserParticleLaw& law, double t0, ParticleState s,
                        double tEnd, double outputInterval, const Observer& obs) const
    {
        IntegratorStats stats;
        // absolute scales: D for positions, a speed for velocities, d/1e3
        // for the spring (the contact's overlaps are ~1e-3 d)
        const double L = law.riser().diameter();
        const double V = std::max({law.riser().centreLineSpeed(),
                                   law.riser().amplitude()*law.riser().omega(), 1e-3});
        const double S = 1e-3*law.diameter();
        auto norm = [&](const detail::Y& err, const detail::Y& a, const detail::Y& b)
        {
            double sum = 0.0;
            for (int i = 0; i < 9; ++i)
            {
                const double scale = (i < 3 ? L : i < 6 ? V : S)*tol_
                                   + tol_*std::max(std::abs(a(i)), std::abs(b(i)));
                sum += (err(i)/scale)*(err(i)/scale);
            }
            return std::sqrt(sum/9.0);
        };

        double t = t0;
        detail::Y y = detail::pack(s);
        long row = 0;
        double nextRow = t0;
        auto emitRows = [&]()
        {
            while (obs.row && t >= nextRow - 1e-12*std::max(1.0, std::abs(nextRow)))
            {
                obs.row(nextRow, detail::unpack(y));
                nextRow = t0 + (++row)*outputInterval;
            }
        };
        emitRows();

        bool inContact = law.hasContact() && law.overlap(s.x, t) > 0.0;
        ContactRecord rec;
        // the first step from the scene's scales, not the output interval
        // (the trajectory must not depend on how often rows are written)
        double h = std::min(hMax_, 1e-3*L/V);
        const double contactScale = 1e-7*law.diameter();   // overlap resolution of events
        bool justRejected = false;

        while (t < tEnd - 1e-12*tEnd)
        {
            double hTry = std::min({h, hMax_, tEnd - t});
            detail::Step step;
            try
            {
                step = detail::dormandPrince(law, t, y, hTry, inContact, stats.forceEvaluations);
            }
            catch (const IntegrationFailure&)
            {
                // a stage left the finite numbers: a step far too long
                if (hTry < 1e-12*std::max(1.0, std::abs(t))) throw;
                step.y.setConstant(NAN);
                step.err.setConstant(INFINITY);
            }
            const double e = norm(step.err, y, step.y);
            if (!(e <= 1.0))
            {
                ++stats.rejected;
                h = hTry*std::max(0.1, 0.9*std::pow(std::isfinite(e) ? e : 1e10, -0.2));
                justRejected = true;
                continue;
            }
            // contact events: a change of sign of the overlap inside the step
            if (law.hasContact())
            {
                const double after = law.overlap(step.y.segment<3>(0), t + hTry);
                const bool onset = !inContact && after > 0.0;
                const bool release = inContact && after <= 0.0;
                if ((onset && after > contactScale) || (release && -after > contactScale))
                {
                    // locate the crossing in the step length: the overlap
                    // is smooth in it, so regula falsi (Illinois variant)
                    // converges in a few Dormand-Prince steps; the
                    // crossing's side is kept (hi crosses, lo does not)
                    double lo = 0.0, hi = hTry;
                    double oLo = law.overlap(y.segment<3>(0), t), oHi = after;
                    int sameSide = 0;
                    detail::Step stepHi = step;
                    for (int i = 0; i < 60; ++i)
                    {
                        double mid = lo - oLo*(hi - lo)/(oHi - oLo);
                        if (!(mid > lo && mid < hi)) mid = 0.5*(lo + hi);
                        const detail::Step stepMid =
                            detail::dormandPrince(law, t, y, mid, inContact, stats.forceEvaluations);
                        const double o = law.overlap(stepMid.y.segment<3>(0), t + mid);
                        const bool crossed = onset ? o > 0.0 : o <= 0.0;
                        if (crossed)
                        {
                            hi = mid; oHi = o; stepHi = stepMid;
                            if (++sameSide > 1) oLo *= 0.5;
                        }
                        else
                        {
                            lo = mid; oLo = o;
                            sameSide = 0;
                            oHi *= 0.5;
                        }
                        if (std::abs(o) <= contactScale && crossed) break;
                    }
                    hTry = hi;
                    step = stepHi;
                }
            }
            detail::requireSane(law, t + hTry, step.y);
            // rows inside the step from its continuous extension; a row at
            // its end gets the state after the contact bookkeeping below
            while (obs.row && nextRow < t + hTry - 1e-12*std::max(1.0, std::abs(nextRow)))
            {
                ParticleState p = detail::unpack(step.at((nextRow - t)/hTry));
                // the spring as the law holds it (capped), zero outside
                p.spring = inContact ? law.cappedSpring(nextRow, p) : Vector::Zero();
                obs.row(nextRow, p);
                nextRow = t0 + (++row)*outputInterval;
            }
            t += hTry;
            y = step.y;
            ++stats.steps;
            if (inContact) ++stats.contactSteps;

            if (law.hasContact())
            {
                ParticleState p = detail::unpack(y);
                const double o = law.overlap(p.x, t);
                const Vector n = law.wallNormal(p.x, t);
                const double Un = (p.v - law.wallVelocity(t)).dot(n);
                if (!inContact && o > 0.0)
                {
                    inContact = true;
                    rec = ContactRecord{};
                    rec.start = t;
                    rec.side = n.x() >= 0.0 ? 1 : -1;
                    rec.impactSpeed = Un;
                    p.spring.setZero();
                }
                else if (inContact && o <= 0.0)
                {
                    inContact = false;
                    rec.end = t;
                    rec.reboundSpeed = -Un;
                    p.spring.setZero();
                    if (obs.contact) obs.contact(rec);
                }
                else if (inContact)
                {
                    rec.maxOverlap = std::max(rec.maxOverlap, o);
                    p.spring = law.cappedSpring(t, p);
                }
                y = detail::pack(p);
            }
            emitRows();
            // no growth right after a rejection (Hairer, Norsett & Wanner,
            // Solving ODEs I, sec. II.4)
            h = hTry*std::min(justRejected ? 1.0 : 5.0, 0.9*std::pow(std::max(e, 1e-10), -0.2));
            justRejected = false;
        }
        return stats;
    }

private:
    double tol_, hMax_;
};

} // namespace riser

#endif
