// riserCore: a second-order stepper for a particle with added mass and a
// Basset history force, the history's newest weight treated implicitly.
//
// The law of motion (the System) is
//     m dv/dt = F(v, t) + m_A (Du/Dt - dv/dt) + K_H H(t),
//     H(t)    = w(0)/sqrt(t) + int_0^t (dw/dtau) / sqrt(t - tau) dtau,
//     w = u - v,
// with F every other force (drag, lift, fluid stress, weight, ...), m_A the
// added mass and K_H = C_H (d^2/4) sqrt(pi rho mu) the history coefficient.
// The System supplies m, m_A, K_H, F(v, t), u(t) and Du/Dt(t) along the
// particle's path; it knows nothing of the scheme.
//
// Scheme: trapezoidal in v, with the acceleration a_{n+1} at the new time
// from the law of motion there,
//     v_{n+1} = v_n + h/2 (a_n + a_{n+1}),
//     (m + m_A + K_H c) a_{n+1} = F(v_{n+1}, t_{n+1}) + (m_A + K_H c) Du/Dt
//                                 + K_H H_known,   c = (4/3) sqrt(h),
// where H_known is the history integral at t_{n+1} without its newest value
// (riser::HistoryIntegral): the newest weight sits beside the added mass,
// so the scheme stays stable for light particles, where an explicit newest
// weight does not. F's dependence on v_{n+1} is resolved by fixed-point
// iteration (to a relative change of 1e-14, at most 50 iterations). A stiff
// F (a contact's film, a spring within one step) makes that iteration
// diverge. For a scalar v the step then solves its equation by bisection:
// with F non-increasing in v_{n+1} (drag, dashpots, and springs and films
// through the position z_n + h/2 (v_n + v_{n+1})) the residual
// (m + m_A + K_H c) a - F - ... grows with a, so the root is unique. For a
// vector v a step left unconverged (relative change above 1e-8) is an error.
//
// For comparison the newest weight can be lagged instead (explicit: it uses
// the previous acceleration). The previous value then enters twice (its own
// weight and the lagged newest one), and the scheme is unstable above about
// 0.43 h_c, where h_c = pi a^2 (beta + 1/2)^2 / (36 nu) is the step at which
// K_H (4/3) sqrt(h) = m + m_A (beta = rho_p/rho_f; measured in
// validation/basset: bounded at 0.42 h_c, growing at 0.45 h_c). Light
// particles have a small h_c: for them only the implicit weight is usable.

// The history kernel is the classical one or Mei & Adrian's finite-Re one
// (HistoryKernelLaw); the latter needs the System's
//     double historyAgeScale(const Value& v, double t)
// the kernel's age scale s* at the particle's Reynolds number
// (riser::meiAdrianAgeScale), taken at the start of each step for that
// step's history.
//
// The step h is constant (the history's grid). The history's first value
// needs dw/dt at t = 0: the System must start without slip (w(0) = 0) or
// accept the initial-slip term, which makes the Basset force infinite at
// t = 0+ (it is integrable); the stepper then starts from the acceleration
// without that term, a first-step error of order sqrt(h).
//
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef RISERCORE_MOTION_HISTORYSTEPPER_HPP
#define RISERCORE_MOTION_HISTORYSTEPPER_HPP

#include "basset/historyIntegral.hpp"

#include <cmath>
#include <stdexcept>
#include <type_traits>
#include <utility>

namespace riser {

enum class NewestHistoryWeight { implicit, lagged };

//- Whether a System gives the finite-Re kernel's age scale
template<class System, class = void>
struct givesHistoryAgeScale : std::false_type {};

template<class System>
struct givesHistoryAgeScale
<
    System,
    std::void_t<decltype(std::declval<const System&>().historyAgeScale
    (
        std::declval<typename System::Value>(), 0.0
    ))>
> : std::true_type {};

template<class System>
class HistoryStepper
{
public:
    using Value = typename System::Value;

    HistoryStepper(const System& system, HistoryMethod method, double h,
                   long window, const Value& v0, double t0 = 0.0,
                   NewestHistoryWeight newest = NewestHistoryWeight::implicit,
                   HistoryTail tail = HistoryTail::vanHinsberg2011,
                   HistoryKernelLaw law = HistoryKernelLaw::classical)
    :
        sys_(system),
        implicit_(newest == NewestHistoryWeight::implicit),
        h_(h),
        t_(t0),
        v_(v0),
        a_(initialAcceleration(system, v0, t0)),
        history_(method, h, window, system.carrierVelocity(t0) - v0,
                 system.carrierAcceleration(t0) - a_, tail, law)
    {
        if (law == HistoryKernelLaw::meiAdrian && !givesHistoryAgeScale<System>::value)
        {
            throw std::invalid_argument
            (
                "riser::HistoryStepper: the finite-Re history kernel needs the"
                " system's historyAgeScale(v, t)"
            );
        }
    }

    //- Start the history anew at the current time: with the current slip
    //  as its initial slip (initialSlip), or with none, and the current
    //  rate of change of the slip as its first value
    void restartHistory(bool initialSlip)
    {
        const Value w = sys_.carrierVelocity(t_) - v_;
        history_ = HistoryIntegral<Value>
        (
            history_.method(), h_, history_.window(), initialSlip ? w : Value(w*0.0),
            sys_.carrierAcceleration(t_) - a_, history_.tail(), history_.law()
        );
    }

    double time() const { return t_; }
    const Value& velocity() const { return v_; }
    const Value& acceleration() const { return a_; }

    void step()
    {
        const double tNew = t_ + h_;
        const double c = history_.newestWeight();
        const double mA = sys_.addedMass(), KH = sys_.historyCoefficient();
        const Value DuDt = sys_.carrierAcceleration(tNew);
        const double inertia = sys_.mass() + mA + (implicit_ ? KH*c : 0.0);
        const Value H = history_.knownPart(ageScale());
        const Value known = implicit_
          ? Value(KH*H + (mA + KH*c)*DuDt)
          : Value(KH*H + mA*DuDt + KH*c*(DuDt - a_));

        Value a = a_;
        double change = 0.0, size = 1.0;
        for (int it = 0; it < 50; ++it)
        {
            const Value v = v_ + 0.5*h_*(a_ + a);
            const Value aNew = (sys_.force(v, tNew) + known)/inertia;
            change = norm(aNew - a);
            size = norm(aNew) + 1e-300;
            a = aNew;
            if (change <= 1e-14*size) break;
        }
        if (!(change <= 1e-14*size))        // also when NaN
        {
            if constexpr (std::is_floating_point_v<Value>)
            {
                a = bisect(tNew, known, inertia);
            }
            else if (!(change <= 1e-8*size))
            {
                throw std::runtime_error
                (
                    "riser::HistoryStepper: the implicit step did not converge"
                    " (a force too stiff for the step h)"
                );
            }
        }
        v_ = v_ + 0.5*h_*(a_ + a);
        a_ = a;
        t_ = tNew;
        history_.push(DuDt - a_);
    }

private:
    //- s* of the finite-Re kernel at the step's start (infinite: classical)
    double ageScale() const
    {
        if constexpr (givesHistoryAgeScale<System>::value)
        {
            if (history_.law() == HistoryKernelLaw::meiAdrian)
            {
                return sys_.historyAgeScale(v_, t_);
            }
        }
        return HUGE_VAL;
    }

    static double norm(double x) { return std::abs(x); }

    //- The scalar step's acceleration: the root of the residual
    //  inertia a - F(v_n + h/2 (a_n + a)) - known, which grows with a
    double bisect(double tNew, double known, double inertia) const
    {
        auto residual = [&](double a)
        {
            return inertia*a - sys_.force(v_ + 0.5*h_*(a_ + a), tNew) - known;
        };
        double lo = a_, hi = a_;
        double width = std::abs(a_) + std::abs(known)/inertia + 1.0;
        for (int k = 0; residual(lo) > 0.0; ++k, width *= 2.0)
        {
            if (k == 2000) throw std::runtime_error("riser::HistoryStepper: no bracket for the step");
            lo = a_ - width;
        }
        for (int k = 0; residual(hi) < 0.0; ++k, width *= 2.0)
        {
            if (k == 2000) throw std::runtime_error("riser::HistoryStepper: no bracket for the step");
            hi = a_ + width;
        }
        if (!(residual(lo) <= 0.0 && residual(hi) >= 0.0))
        {
            throw std::runtime_error("riser::HistoryStepper: the step's force is not a number");
        }
        for (int k = 0; k < 200 && hi - lo > 1e-15*(std::abs(lo) + std::abs(hi)); ++k)
        {
            const double mid = 0.5*(lo + hi);
            (residual(mid) < 0.0 ? lo : hi) = mid;
        }
        return 0.5*(lo + hi);
    }
    template<class V> static double norm(const V& x) { return x.norm(); }

    //- m dv/dt = F + m_A (Du/Dt - dv/dt) at t0, without the history term
    static Value initialAcceleration(const System& s, const Value& v0, double t0)
    {
        return (s.force(v0, t0) + s.addedMass()*s.carrierAcceleration(t0))
              /(s.mass() + s.addedMass());
    }

    const System& sys_;
    bool implicit_;
    double h_;
    double t_;
    Value v_;
    Value a_;
    HistoryIntegral<Value> history_;
};

} // namespace riser

#endif
