// riserCore: the Basset history integral
//
//     H(t) = w(0) / sqrt(t) + int_0^t g(tau) / sqrt(t - tau) dtau,   g = dw/dtau,
//
// on a uniform time grid t_n = n h, for a scalar or vector slip w. The first
// term is the initial-slip term: a particle released with slip w(0) != 0
// starts with a jump of w, whose derivative is a delta at tau = 0.
//
// Quadrature: g is linear between grid points, and each slab is integrated
// exactly against the kernel. The weight of the value g_{n-k} (lag k) is
// sqrt(h) W_k with, in rationalised form (no cancellation at large k),
//     L(k) = (2/3)(2p + q)/(p + q)^2,  p = sqrt(k+1), q = sqrt(k)   (slab k..k+1)
//     R(k) = (2/3)(p + 2q)/(p + q)^2,  p = sqrt(k),   q = sqrt(k-1) (slab k-1..k)
//     W_0 = L(0) = 4/3,  W_k = L(k) + R(k) (0 < k < n),  W_n = R(n),
// the window weights of van Hinsberg, ten Thije Boonkkamp & Clercx,
// J. Comput. Phys. 230, 1465 (2011), here in a form that keeps its digits.
//
// Methods:
//   fullHistory - the weights over the whole history: exact for piecewise-
//       linear g, cost and memory O(n) per step (the reference).
//   windowTail - the same weights over a window of the last N steps, and
//       the kernel beyond the window replaced by m = 10 exponentials
//           1/sqrt(s) ~ sum_i a_i sqrt(e / T_i) exp(-s / (2 T_i)),
//           T_i = t~_i t_win,  t_win = N h  (van Hinsberg et al. 2011),
//       each carried by a one-term recurrence, with the slab leaving the
//       window integrated exactly for linear g: cost and memory O(N + m)
//       per step, independent of the history length.
//
// The newest value g_n enters with the weight (4/3) sqrt(h): a solver treats
// it implicitly (together with the added mass) by asking for the known
// part, knownPart(), and the newest weight, newestWeight(), and then
// committing the value it solved for with push(). The step h is constant:
// a solver that changes its step starts a new history or resamples it.
//
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef RISERCORE_BASSET_HISTORYINTEGRAL_HPP
#define RISERCORE_BASSET_HISTORYINTEGRAL_HPP

#include "../checks.hpp"

#include <array>
#include <cmath>
#include <deque>

namespace riser {

enum class HistoryMethod { fullHistory, windowTail };

//- Exponential-tail constants: times t~_i (in window times) and weights a_i
//  of van Hinsberg, ten Thije Boonkkamp & Clercx (2011), m = 10.
struct HistoryTailConstants
{
    static constexpr int m = 10;
    static constexpr std::array<double, m> t{
        0.1, 0.3, 1.0, 3.0, 10.0, 40.0, 190.0, 1000.0, 6500.0, 50000.0};
    static constexpr std::array<double, m> a{
        0.23477481312586, 0.28549576238194, 0.28479416718255, 0.26149775537574,
        0.32056200511938, 0.35354490689146, 0.39635904496921, 0.42253908596514,
        0.48317384225265, 0.63661146557001};
};

//- Weight of lag k in units of sqrt(h), for a history of n steps.
inline double historyWeight(long k, long n)
{
    auto left = [](double kk)    // slab kk .. kk+1, value at kk
    {
        const double p = std::sqrt(kk + 1.0), q = std::sqrt(kk);
        return 2.0/3.0*(2.0*p + q)/((p + q)*(p + q));
    };
    auto right = [](double kk)   // slab kk-1 .. kk, value at kk
    {
        const double p = std::sqrt(kk), q = std::sqrt(kk - 1.0);
        return 2.0/3.0*(p + 2.0*q)/((p + q)*(p + q));
    };
    if (k == 0) return left(0.0);
    if (k == n) return right(double(k));
    return left(double(k)) + right(double(k));
}

template<class Value>
class HistoryIntegral
{
public:
    //- method, step h > 0, window N >= 2 steps (windowTail only), initial
    //  slip w0 (zero: no initial-slip term), g0 = dw/dt at t = 0+.
    HistoryIntegral(HistoryMethod method, double h, long window,
                    const Value& w0, const Value& g0)
    :
        method_(method), h_(h), N_(window), w0_(w0)
    {
        requirePositive("riser::HistoryIntegral", "h", h);
        if (windowed())
        {
            requireInRange("riser::HistoryIntegral", "window", double(window),
                           2.0, Bound::closed, HUGE_VAL, Bound::open);
            const double tWin = N_*h_;
            for (int i = 0; i < Tail::m; ++i)
            {
                const double T = Tail::t[i]*tWin;
                const double c = 0.5/T;
                const double x = c*h_;
                decay_[i] = std::exp(-x);
                amplitude_[i] =
                    Tail::a[i]*std::sqrt(std::exp(1.0)/T)*std::exp(-c*tWin);
                // exact slab integrals of exp(-c s) and s exp(-c s), s in [0, h]
                I0_[i] = -std::expm1(-x)/c;
                I1_[i] = (x < 1e-2
                    ? x*x*(0.5 - x*(1.0/3.0 - x*(1.0/8.0 - x/30.0)))
                    : -std::expm1(-x) - x*std::exp(-x))/(c*c);
                tail_[i] = w0_*0.0;
            }
        }
        g_.push_back(g0);
    }

    //- History values held (memory per particle, in values of Value).
    long stored() const { return long(g_.size()) + (windowed() ? Tail::m : 0); }

    //- H at the current time (after at least one push).
    Value value() const
    {
        const long n = n_;
        Value H = w0_*(1.0/std::sqrt(n*h_));
        const long span = windowed() ? std::min(n, N_) : n;
        const long size = long(g_.size());
        const double sh = std::sqrt(h_);
        for (long j = 0; j < size; ++j)
        {
            H += g_[j]*(sh*historyWeight(size - 1 - j, span));
        }
        if (windowed())
        {
            for (int i = 0; i < Tail::m; ++i) H += tail_[i]*amplitude_[i];
        }
        return H;
    }

    //- Weight of the newest value at the next time: (4/3) sqrt(h).
    double newestWeight() const { return 4.0/3.0*std::sqrt(h_); }

    //- H at the next time without the newest value's part:
    //  H(t_{n+1}) = knownPart() + newestWeight() g_{n+1}.
    Value knownPart() const
    {
        HistoryIntegral next(*this);
        next.push(w0_*0.0);
        return next.value();
    }

    //- Commit g_{n+1} = dw/dt at the next time and advance to it.
    void push(const Value& g)
    {
        g_.push_back(g);
        if (windowed() && long(g_.size()) > N_ + 1)
        {
            // the slab between the two oldest values leaves the window
            const Value& ga = g_[0];
            const Value& gb = g_[1];
            for (int i = 0; i < Tail::m; ++i)
            {
                tail_[i] = tail_[i]*decay_[i] + gb*I0_[i] + (ga - gb)*(I1_[i]/h_);
            }
            g_.pop_front();
        }
        ++n_;
    }

private:
    using Tail = HistoryTailConstants;

    bool windowed() const { return method_ == HistoryMethod::windowTail; }

    HistoryMethod method_;
    double h_;
    long N_;
    Value w0_;
    long n_ = 0;
    std::deque<Value> g_;       // g at the nodes of the window (or all)
    std::array<double, Tail::m> decay_{}, amplitude_{}, I0_{}, I1_{};
    std::array<Value, Tail::m> tail_{};
};

} // namespace riser

#endif
