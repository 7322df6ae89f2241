// riserCore: integrators of the riser particle law (motion/riserParticleLaw.hpp)
// for the mesh-free engine. The law gives forces (as riser::ParticleSystem);
// the steppers and the step controller of motion/odeSteppers.hpp advance it;
// a scheme here decides how to step, locates the contact events and reports
// to an observer (rows at output times, and contacts).
//
// paperScheme - the scheme of Wei et al. (2023) as described in
//     doc/theory.md section 3: a fifth-order Runge–Kutta step (Dormand–Prince) of fixed
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

#include "motion/odeSteppers.hpp"
#include "motion/riserParticleLaw.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
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

//- Throw IntegrationFailure saying what at time t
[[noreturn]] inline void fail(const char* what, double t)
{
    std::ostringstream msg;
    msg << what << " at t = " << t << " s";
    throw IntegrationFailure(msg.str());
}

//- A system as the schemes step it: its evaluations counted, and a state
//  the integration reached that the law refuses (not finite, or out of a
//  law's range: std::invalid_argument, the parameters having been checked
//  when the law was built) turned into IntegrationFailure
template<class System>
class Checked
{
public:
    using State = typename System::State;

    Checked(const System& sys, long& evaluations)
    :
        sys_(sys), evaluations_(evaluations)
    {}

    State rate(double t, const State& y) const
    {
        ++evaluations_;
        const char* what = "state not finite";
        if (y.allFinite())
        {
            try
            {
                return sys_.rate(t, y);
            }
            catch (const std::invalid_argument& e)
            {
                what = e.what();
            }
        }
        fail(what, t);
    }

private:
    const System& sys_;
    long& evaluations_;
};

//- Throw IntegrationFailure if the state is not finite or the particle is
//  deeper in the wall than its radius
inline void requireSane(const RiserParticleLaw& law, double t, const ParticleSystem::State& y)
{
    if (!y.allFinite()) fail("state not finite", t);
    if (law.hasContact() && law.overlap(y.segment<3>(0), t) > law.radius())
    {
        fail("overlap beyond the particle radius", t);
    }
}

//- The first stage of a Dormand–Prince step from (t, y): the last step's
//  end rate while the state, the time and the system are the same
template<class System>
class FirstStage
{
public:
    using State = typename System::State;

    const State& at(const System& sys, double t, const State& y, bool sameSystem)
    {
        if (!(valid_ && sameSystem && t == t_ && y == y_))
        {
            k1_ = sys.rate(t, y);
            t_ = t;
            y_ = y;
            valid_ = true;
        }
        return k1_;
    }

    //- A step from (t, y) ended at (tEnd, yEnd) with rate kEnd there
    void stepped(double tEnd, const State& yEnd, const State& kEnd)
    {
        t_ = tEnd;
        y_ = yEnd;
        k1_ = kEnd;
        valid_ = true;
    }

private:
    bool valid_ = false;
    double t_ = 0.0;
    State y_ = State::Zero(), k1_ = State::Zero();
};

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
        using Y = ParticleSystem::State;
        IntegratorStats stats;
        const ParticleSystem flowLaw(law, false);
        const detail::Checked<ParticleSystem> flow(flowLaw, stats.forceEvaluations);
        detail::FirstStage<detail::Checked<ParticleSystem>> first;
        auto flowStep = [&](double t, const ParticleState& from, double h)
        {
            const Y y = ParticleSystem::pack(from);
            const DenseStep<Y> st = dormandPrince5(flow, t, y, h, first.at(flow, t, y, true));
            first.stepped(t + h, st.y, st.rateEnd);
            return st.y;
        };

        const long perRow = std::max(1L, long(std::ceil(outputInterval/h_ - 1e-9)));
        const double h = outputInterval/perRow;
        double t = t0;
        long k = 0, nextRow = perRow;
        // the approach speed of the last contact: the rows report a state
        // left overlapping by a contact at frozen position with its force
        double lastApproach = s.approachSpeed;
        if (obs.row) obs.row(t, s);
        while (t < tEnd - 0.5*h)
        {
            const Y y = flowStep(t, s, h);
            t = t0 + (++k)*h;
            detail::requireSane(law, t, y);
            s = ParticleSystem::unpack(y);
            s.spring.setZero();
            s.approachSpeed = lastApproach;
            ++stats.steps;
            if (law.hasContact())
            {
                const ContactPoint c = law.wallContact(s.x, t);
                const double approach = (s.v - c.velocity).dot(c.normal);
                if (c.overlap > -eps_*law.diameter() && approach > 0.0)
                {
                    t = contact(law, t, tEnd, s, obs, stats);
                    lastApproach = s.approachSpeed;
                    // back on the flow grid
                    k = std::lround(std::ceil((t - t0)/h - 1e-9));
                    const double tGrid = t0 + k*h;
                    if (tGrid > t)
                    {
                        s = ParticleSystem::unpack(flowStep(t, s, tGrid - t));
                        s.spring.setZero();
                        s.approachSpeed = lastApproach;
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
    //- The contact at frozen position x and normal n: the state (v,
    //  delta_n, delta_t), the overlap a variable of its own
    class ContactPhase
    {
    public:
        using State = Eigen::Matrix<double, 7, 1>;

        //- at x, normal n, the contact's approach speed vIn
        ContactPhase(const RiserParticleLaw& law, const Vector& x, const Vector& n,
                     double vIn)
        :
            law_(law), x_(x), n_(n), vIn_(vIn)
        {}

        ContactPoint contactPoint(double t, double dn) const
        {
            return ContactPoint{dn, n_, law_.wall().velocity(x_, t)};
        }

        ParticleState particle(const State& z) const
        {
            return ParticleState{x_, z.segment<3>(0), z.segment<3>(4), vIn_};
        }

        State rate(double t, const State& z) const
        {
            const ParticleState s = particle(z);
            const ContactPoint c = contactPoint(t, z(3));
            const Vector a = law_.forces(t, s, c).total()/law_.inertia();
            State dz;
            dz << a, (s.v - c.velocity).dot(n_), RiserParticleLaw::springRate(s, c);
            return dz;
        }

    private:
        const RiserParticleLaw& law_;
        Vector x_, n_;
        double vIn_;
    };

    //- The contact phase at frozen position: returns the time at its end
    //  (or tEnd, with the contact in progress: not reported as completed)
    double contact(const RiserParticleLaw& law, double t, double tEnd, ParticleState& s,
                   const Observer& obs, IntegratorStats& stats) const
    {
        const Vector x = s.x;
        const ContactPoint c0 = law.wallContact(x, t);
        const Vector n = c0.normal;
        ContactRecord rec;
        rec.start = t;
        rec.side = n.x() >= 0.0 ? 1 : -1;
        rec.impactSpeed = (s.v - c0.velocity).dot(n);
        const ContactPhase phase(law, x, n, rec.impactSpeed);
        const detail::Checked<ContactPhase> system(phase, stats.forceEvaluations);
        double dn = c0.overlap;
        if (start_ == ContactStart::detection) dn = std::min(dn, 0.0);
        bool touched = dn > 0.0;

        ContactPhase::State z;
        z << s.v, dn, Vector::Zero();
        // a contact never longer than the time to leave the eps band at the
        // approach speed, or than 1e6 contact steps, or past the run's end
        // (an ore left at the wall by a restitution of 0)
        bool ended = false;
        for (long i = 0; i < 1000000 && t < tEnd - 0.5*hc_; ++i)
        {
            z = rungeKutta4(system, t, z, hc_);
            t += hc_;
            ++stats.contactSteps;
            if (!z.allFinite() || z(3) > law.radius())
            {
                std::ostringstream msg;
                msg << "contact at frozen position: overlap " << z(3)/law.diameter()
                    << " d, speed " << z.segment<3>(0).norm() << " m/s at t = " << t << " s";
                throw IntegrationFailure(msg.str());
            }
            const ContactPoint c = phase.contactPoint(t, z(3));
            const Vector U = z.segment<3>(0) - c.velocity;
            if (c.overlap > 0.0)
            {
                touched = true;
                z.segment<3>(4) = law.contactLaw().force
                (
                    law.body(), c.overlap, n, U, z.segment<3>(4), rec.impactSpeed
                ).springAfter;
                rec.maxOverlap = std::max(rec.maxOverlap, c.overlap);
            }
            const bool leaving = U.dot(n) < 0.0;
            if ((touched && c.overlap <= 0.0) || (!touched && leaving))
            {
                ended = true;
                break;
            }
        }
        s.v = z.segment<3>(0);
        s.spring.setZero();
        s.approachSpeed = rec.impactSpeed;
        rec.end = t;
        rec.reboundSpeed = -(s.v - law.wall().velocity(x, t)).dot(n);
        // a contact still in progress at the run's end is not complete
        const bool inProgress = !ended && t >= tEnd - 0.5*hc_;
        if (touched && !inProgress && obs.contact) obs.contact(rec);
        return t;
    }

    double h_, hc_, eps_;
    ContactStart start_;
};


//- Adaptive Dormand–Prince 5(4) with contact events (see top)
class AdaptiveScheme
{
public:
    //- The default relative tolerance (riserParticle's adaptiveCoeffs;
    //  validation/riserParticle: its cost and error against the others)
    static constexpr double defaultTolerance = 1e-10;

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
        using Y = ParticleSystem::State;
        using Checked = detail::Checked<ParticleSystem>;
        IntegratorStats stats;
        // the touching system holds the approach speed of the contact in
        // progress (a wet contact's restitution depends on it)
        ParticleSystem freeLaw(law, false), touchingLaw(law, true);
        const Checked free(freeLaw, stats.forceEvaluations);
        const Checked touching(touchingLaw, stats.forceEvaluations);
        detail::FirstStage<Checked> first;

        // absolute scales: D for positions, a speed for velocities, d/1e3
        // for the spring (the contact's overlaps are ~1e-3 d)
        const double L = law.riser().diameter();
        const double V = std::max({law.riser().centreLineSpeed(),
                                   law.riser().motion().maxSpeed(), 1e-3});
        const double S = 1e-3*law.diameter();
        Y scale;
        scale << L, L, L, V, V, V, S, S, S;
        const ErrorControl<Y> control(tol_, scale);

        double t = t0;
        Y y = ParticleSystem::pack(s);
        long row = 0;
        double nextRow = t0;
        bool inContact = law.hasContact() && law.overlap(s.x, t) > 0.0;
        bool wasInContact = inContact;
        if (inContact)
        {
            // released in contact: the approach speed given, else the
            // normal speed at the release (none when leaving)
            const ContactPoint c = law.wallContact(s.x, t);
            touchingLaw.approachSpeed
            (
                std::isfinite(s.approachSpeed)
              ? s.approachSpeed
              : std::max((s.v - c.velocity).dot(c.normal), 0.0)
            );
        }
        auto emitRows = [&]()
        {
            while (obs.row && t >= nextRow - 1e-12*std::max(1.0, std::abs(nextRow)))
            {
                ParticleState p = ParticleSystem::unpack(y);
                p.approachSpeed = touchingLaw.approachSpeed();
                obs.row(nextRow, p);
                nextRow = t0 + (++row)*outputInterval;
            }
        };
        emitRows();

        ContactRecord rec;
        // the first step from the scene's scales, not the output interval
        // (the trajectory must not depend on how often rows are written)
        double h = std::min(hMax_, 1e-3*L/V);
        const double contactScale = 1e-7*law.diameter();   // overlap resolution of events
        bool justRejected = false;

        while (t < tEnd - 1e-12*tEnd)
        {
            const Checked& sys = inContact ? touching : free;
            const Y k1 = first.at(sys, t, y, inContact == wasInContact);
            wasInContact = inContact;
            double hTry = std::min({h, hMax_, tEnd - t});
            DenseStep<Y> step;
            try
            {
                step = dormandPrince5(sys, t, y, hTry, k1);
            }
            catch (const IntegrationFailure&)
            {
                // a stage left the finite numbers: a step far too long
                if (hTry < 1e-12*std::max(1.0, std::abs(t))) throw;
                step.y.setConstant(NAN);
                step.err.setConstant(INFINITY);
            }
            const double e = control.norm(step.err, y, step.y);
            if (!(e <= 1.0))
            {
                ++stats.rejected;
                h = ErrorControl<Y>::afterRejection(hTry, e);
                justRejected = true;
                continue;
            }
            if (law.hasContact())
            {
                locateContactEvent(law, sys, t, y, k1, inContact, contactScale, hTry, step);
            }
            detail::requireSane(law, t + hTry, step.y);
            // rows inside the step from its continuous extension; a row at
            // its end gets the state after the contact bookkeeping below
            while (obs.row && nextRow < t + hTry - 1e-12*std::max(1.0, std::abs(nextRow)))
            {
                ParticleState p = ParticleSystem::unpack(step.at((nextRow - t)/hTry));
                // the spring as the law holds it (capped), zero outside
                p.approachSpeed = touchingLaw.approachSpeed();
                p.spring = inContact ? law.cappedSpring(nextRow, p) : Vector::Zero();
                obs.row(nextRow, p);
                nextRow = t0 + (++row)*outputInterval;
            }
            t += hTry;
            y = step.y;
            first.stepped(t, y, step.rateEnd);
            ++stats.steps;
            if (inContact) ++stats.contactSteps;

            if (law.hasContact())
            {
                ParticleState p = ParticleSystem::unpack(y);
                const ContactPoint c = law.wallContact(p.x, t);
                const double Un = (p.v - c.velocity).dot(c.normal);
                if (!inContact && c.overlap > 0.0)
                {
                    inContact = true;
                    rec = ContactRecord{};
                    rec.start = t;
                    rec.side = c.normal.x() >= 0.0 ? 1 : -1;
                    rec.impactSpeed = Un;
                    touchingLaw.approachSpeed(Un);
                    p.spring.setZero();
                }
                else if (inContact && c.overlap <= 0.0)
                {
                    inContact = false;
                    rec.end = t;
                    rec.reboundSpeed = -Un;
                    touchingLaw.approachSpeed(std::numeric_limits<double>::quiet_NaN());
                    p.spring.setZero();
                    if (obs.contact) obs.contact(rec);
                }
                else if (inContact)
                {
                    rec.maxOverlap = std::max(rec.maxOverlap, c.overlap);
                    p.approachSpeed = touchingLaw.approachSpeed();
                    p.spring = law.cappedSpring(t, p);
                }
                y = ParticleSystem::pack(p);
            }
            emitRows();
            h = ErrorControl<Y>::afterAcceptance(hTry, e, justRejected);
            justRejected = false;
        }
        return stats;
    }

private:
    //- A contact event inside the accepted step from (t, y) of length h:
    //  a change of sign of the overlap. The step is replaced by the step to
    //  the crossing, found by regula falsi (Illinois variant) on the step
    //  length, the overlap being smooth in it; the crossing's side is kept
    //  (hi crosses, lo does not)
    template<class System>
    static void locateContactEvent
    (
        const RiserParticleLaw& law, const System& sys, double t,
        const ParticleSystem::State& y, const ParticleSystem::State& k1,
        bool inContact, double contactScale, double& h,
        DenseStep<ParticleSystem::State>& step
    )
    {
        const double after = law.overlap(step.y.segment<3>(0), t + h);
        const bool onset = !inContact && after > 0.0;
        const bool release = inContact && after <= 0.0;
        if (!((onset && after > contactScale) || (release && -after > contactScale))) return;

        double lo = 0.0, hi = h;
        double oLo = law.overlap(y.segment<3>(0), t), oHi = after;
        int sameSide = 0;
        DenseStep<ParticleSystem::State> stepHi = step;
        for (int i = 0; i < 60; ++i)
        {
            double mid = lo - oLo*(hi - lo)/(oHi - oLo);
            if (!(mid > lo && mid < hi)) mid = 0.5*(lo + hi);
            const DenseStep<ParticleSystem::State> stepMid = dormandPrince5(sys, t, y, mid, k1);
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
        h = hi;
        step = stepHi;
    }

    double tol_, hMax_;
};

} // namespace riser

#endif
