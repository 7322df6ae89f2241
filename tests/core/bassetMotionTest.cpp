// Tests of the history stepper (src/riserCore/motion) against closed forms
// for a sphere with Stokes drag, added mass and the Basset force.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "motion/historyStepper.hpp"
#include "bassetClosedForms.hpp"

#include <gtest/gtest.h>
#include <cmath>
#include <complex>
#include <stdexcept>
#include <type_traits>
#include <vector>

using namespace riser;
using oracle::cplx;
using oracle::faddeeva;

using oracle::StokesSphere;
using oracle::settlingClosedForm;

namespace {

double settlingError(HistoryMethod method, double h, long window, double tEnd,
                     const StokesSphere& s)
{
    HistoryStepper<StokesSphere> stepper(s, method, h, window, 0.0);
    double worst = 0.0;
    const long n = std::lround(tEnd/h);
    for (long k = 1; k <= n; ++k)
    {
        stepper.step();
        worst = std::max(worst, std::abs(stepper.velocity() - settlingClosedForm(s, k*h)));
    }
    return worst/settlingClosedForm(s, tEnd);
}

} // namespace

// The oracle itself: w(1) = exp(-1) erfc(-i) = 0.36787944117144233
// + 0.60715770584139372 i (Abramowitz & Stegun, table 7.9), w on the real
// axis of the imaginary part gives exp(x^2) erfc(x), and the settling
// solution starts at rest and tends to the Stokes terminal velocity.
TEST(BassetMotion, OracleChecks)
{
    const cplx w1 = faddeeva(cplx(1.0, 0.0));
    EXPECT_NEAR(w1.real(), 0.36787944117144233, 1e-12);
    EXPECT_NEAR(w1.imag(), 0.60715770584139372, 1e-12);
    for (double x : {0.1, 1.0, 3.0})
    {
        EXPECT_NEAR(faddeeva(cplx(0.0, x)).real(), std::exp(x*x)*std::erfc(x), 1e-12);
    }
    const StokesSphere s{5e-4, 2000.0};
    EXPECT_NEAR(settlingClosedForm(s, 1e-12), 0.0, 1e-6);
    // long-time asymptote from the Laplace transform at small s:
    // V/V_t = 1 - gamma/(alpha sqrt(pi t)) + O(t^-3/2)
    const double M = s.mp() + 0.5*s.mf();
    const double alpha = 6.0*M_PI*s.mu*s.a/M;
    const double gamma = 6.0*M_PI*s.a*s.a*std::sqrt(s.rhoF*s.mu)/M;
    const double Vt = (s.mp() - s.mf())*s.g/(6.0*M_PI*s.mu*s.a);
    for (double t : {200.0, 800.0})
    {
        const double asymptote = 1.0 - gamma/(alpha*std::sqrt(M_PI*t));
        EXPECT_NEAR(settlingClosedForm(s, t)/Vt, asymptote, 2.0/(alpha*t*std::sqrt(t)))
            << "t = " << t;
    }
}

// Settling from rest: both methods follow the closed form. The exact
// solution has a t^(1/2) singularity at release (v = G t - c t^(3/2) + ...,
// so g = dw/dt ~ t^(1/2)): interpolating g linearly on a uniform grid, and
// the trapezoidal rule for v, are then of order 3/2, not 2, for any smooth-
// data scheme; measured 1.46-1.47. The window method (0.1 s window) adds
// its tail-kernel error, well below 1e-3 of the weight's share it carries.
TEST(BassetMotion, SettlingFromRestMatchesTheClosedForm)
{
    const StokesSphere s{5e-4, 2000.0};        // complex roots: gamma^2 < 4 alpha
    const double tEnd = 1.0;
    const double e1 = settlingError(HistoryMethod::fullHistory, 4e-3, 0, tEnd, s);
    const double e2 = settlingError(HistoryMethod::fullHistory, 2e-3, 0, tEnd, s);
    const double e3 = settlingError(HistoryMethod::fullHistory, 1e-3, 0, tEnd, s);
    std::printf("full history: max relative error %.3e %.3e %.3e, orders %.2f %.2f\n",
                e1, e2, e3, std::log2(e1/e2), std::log2(e2/e3));
    EXPECT_GT(std::log2(e2/e3), 1.4);
    EXPECT_LT(e3, 3e-4);

    const double tWin = 0.1;
    const double f1 = settlingError(HistoryMethod::windowTail, 4e-3, std::lround(tWin/4e-3), tEnd, s);
    const double f2 = settlingError(HistoryMethod::windowTail, 2e-3, std::lround(tWin/2e-3), tEnd, s);
    const double f3 = settlingError(HistoryMethod::windowTail, 1e-3, std::lround(tWin/1e-3), tEnd, s);
    std::printf("window 0.1 s: max relative error %.3e %.3e %.3e\n", f1, f2, f3);
    EXPECT_LT(f3, 5e-4);
    EXPECT_LT(std::abs(f3 - e3), 2e-4);
}

// Stability: a light particle (rho_p/rho_f = 0.1, a rising bubble-like
// sphere) with a step h = 0.02 s. With the newest history weight lagged the
// scheme multiplies errors by about -K_H c/(m + m_A) = -1.6 each step and
// blows up; treated implicitly beside the added mass it stays bounded and
// converges to the closed form (h is 0.6 response times here, so the first
// steps are coarse: the check is boundedness and the error at t = 2 s).
TEST(BassetMotion, LightParticleNeedsTheImplicitNewestWeight)
{
    const StokesSphere s{5e-4, 100.0};
    const double h = 0.02;
    const double KHc = s.historyCoefficient()*4.0/3.0*std::sqrt(h);
    EXPECT_GT(KHc/(s.mass() + s.addedMass()), 1.0);

    HistoryStepper<StokesSphere> lagged(s, HistoryMethod::fullHistory, h, 0, 0.0, 0.0,
                                        NewestHistoryWeight::lagged);
    HistoryStepper<StokesSphere> implicit(s, HistoryMethod::fullHistory, h, 0, 0.0);
    const double Vt = std::abs(settlingClosedForm(s, 2.0));
    double largest = 0.0;
    for (int k = 1; k <= 100; ++k)
    {
        lagged.step();
        implicit.step();
        largest = std::max(largest, std::abs(implicit.velocity()));
    }
    const double finalError = std::abs(implicit.velocity() - settlingClosedForm(s, 2.0))/Vt;
    std::printf("light particle: lagged |v| = %.3e after 2 s; implicit: largest |v| %.3f V, "
                "error at 2 s %.3e\n", std::abs(lagged.velocity()), largest/Vt, finalError);
    EXPECT_TRUE(!std::isfinite(lagged.velocity()) || std::abs(lagged.velocity()) > 1e3*Vt);
    EXPECT_LT(largest, 1.5*Vt);
    EXPECT_LT(finalError, 0.01);
}

// A particle in a uniform carrier oscillating as U cos(omega t) (Stokes
// drag, added mass, fluid stress, Basset; no weight): the periodic state has
//   V/U = [1 + sqrt(i s) + i s/3] / [1 + sqrt(i s) + (2 beta + 1) i s/9],
//   s = omega a^2/nu, beta = rho_p/rho_f
// (the frequency-domain solution: the history integral of e^{i omega t} is
// sqrt(i pi omega) e^{i omega t}). Started without slip, the transient
// decays algebraically (Basset, ~t^-3/2), and the 400-step window adds the
// tail kernel's error (< 3e-3 of the tail part of a Basset force that is
// itself a fraction of the drag): after 40 periods the amplitude and phase
// over the last two periods must match within 5e-4 (measured: 5e-5, 1e-6).
TEST(BassetMotion, OscillatingCarrierMatchesTheClosedForm)
{
    StokesSphere s{5e-4, 2000.0};
    s.g = 0.0;
    s.U = 0.1;
    s.omega = 4.0;                                    // s = omega a^2/nu = 1
    const double nu = s.mu/s.rhoF;
    const double sNum = s.omega*s.a*s.a/nu, beta = s.rhoP/s.rhoF;
    const cplx is(0.0, sNum);
    const cplx expected = (1.0 + std::sqrt(is) + is/3.0)/(1.0 + std::sqrt(is) + (2.0*beta + 1.0)*is/9.0);

    const double period = 2.0*M_PI/s.omega, h = period/2000.0;
    HistoryStepper<StokesSphere> stepper(s, HistoryMethod::windowTail, h, 400, s.U);
    const long perPeriod = 2000, periods = 40;
    cplx projection = 0.0;
    for (long k = 1; k <= perPeriod*periods; ++k)
    {
        stepper.step();
        if (k > perPeriod*(periods - 2))
        {
            // V = (1/T) int v e^{-i omega t} dt * 2 over whole periods
            projection += stepper.velocity()*std::exp(cplx(0.0, -s.omega*k*h));
        }
    }
    const cplx measured = projection*(2.0/(2*perPeriod))/s.U;
    std::printf("V/U measured |%.6f| arg %.6f, closed form |%.6f| arg %.6f\n",
                std::abs(measured), std::arg(measured), std::abs(expected), std::arg(expected));
    EXPECT_NEAR(std::abs(measured)/std::abs(expected), 1.0, 5e-4);
    EXPECT_NEAR(std::arg(measured), std::arg(expected), 5e-4);
}

namespace {

//- A stiff linear drag, F = -c v, no added mass and no history: the
//  trapezoidal rule's step is then v_{n+1} = v_n (1 - q)/(1 + q) with
//  q = c h/(2 m), and its fixed-point iteration diverges for q > 1
template<class V>
struct StiffDrag
{
    using Value = V;
    double m, c;
    double mass() const { return m; }
    double addedMass() const { return 0.0; }
    double historyCoefficient() const { return 0.0; }
    static Value zero()
    {
        if constexpr (std::is_floating_point_v<V>) return 0.0;
        else return V::Zero();
    }
    Value carrierVelocity(double) const { return zero(); }
    Value carrierAcceleration(double) const { return zero(); }
    Value force(const Value& v, double) const { return Value(-c*v); }
};

} // namespace

// A force too stiff for the fixed-point iteration (q = c h/(2 m) = 50):
// a scalar step solves its monotone equation by bisection and lands on the
// trapezoidal rule's closed form to round-off (1e-12 relative over 20
// steps, each step's bisection to 1e-15); a vector step throws rather than
// keep an unconverged acceleration, and so does a scalar step whose force
// is not a number.
TEST(BassetMotion, StiffForceIsSolvedOrRefused)
{
    const double m = 1e-3, c = 10.0, h = 1e-2, q = c*h/(2.0*m);
    const StiffDrag<double> scalarLaw{m, c};
    HistoryStepper<StiffDrag<double>> scalar(scalarLaw, HistoryMethod::windowTail, h, 2, 1.0);
    double v = 1.0;
    for (int k = 0; k < 20; ++k)
    {
        scalar.step();
        v *= (1.0 - q)/(1.0 + q);
        EXPECT_NEAR(scalar.velocity(), v, 1e-12*std::abs(v)) << "step " << k;
    }
    const StiffDrag<Eigen::Vector3d> vectorLaw{m, c};
    HistoryStepper<StiffDrag<Eigen::Vector3d>> vector
        (vectorLaw, HistoryMethod::windowTail, h, 2, Eigen::Vector3d(1.0, 0.0, 0.0));
    EXPECT_THROW(vector.step(), std::runtime_error);
    // a force that is not a number is refused, not stepped
    const StiffDrag<double> nanLaw{m, std::nan("")};
    HistoryStepper<StiffDrag<double>> nanStepper(nanLaw, HistoryMethod::windowTail, h, 2, 1.0);
    EXPECT_THROW(nanStepper.step(), std::runtime_error);
}
