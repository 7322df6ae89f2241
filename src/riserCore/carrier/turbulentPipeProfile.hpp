// riserCore: the mean axial velocity of fully developed turbulent flow in a
// pipe, smooth or rough (doc/theory.md section 2.7), the analytic carrier of
// a riser at sea (Re 1e4 to 1e6).
//
// Friction: the Darcy friction factor f of the Colebrook-White formula
// (Colebrook, J. Inst. Civ. Eng. 11, 133-156, 1939),
//   1/sqrt(f) = -2 log10( (k_s/D)/3.7 + 2.51/(Re sqrt(f)) ),
// which for a smooth pipe (k_s = 0) is Prandtl-Karman's
//   1/sqrt(f) = 2 log10(Re sqrt(f)) - 0.8  (to 0.3 %, the 2.51 and 0.8
// being two roundings of the same constant); the friction velocity
// u_tau = U_b sqrt(f/8), Re = U_b D / nu.
//
// Profile: with y = R - r the distance from the wall, y+ = y u_tau/nu,
// eta = y/R,
//   u+ = U_R(y+) - dU(k_s+) (1 - exp(-y+/chi)) + (2 Pi/kappa) sin^2(pi eta/2)
//        - (g/3) eta^3,
// - U_R: Reichardt's law of the wall (Reichardt, ZAMM 31, 208-219, 1951),
//     (1/kappa) ln(1 + kappa y+) + C (1 - exp(-y+/chi) - (y+/chi) exp(-y+/3)),
//   from the wall (u+ = y+) through the buffer layer to the log law
//   u+ = (1/kappa) ln y+ + B, kappa = 0.41, B = 5.2 (Pope, Turbulent Flows,
//   2000, sec. 7.1.4), chi = 11 (Reichardt's), C = B - ln(kappa)/kappa;
// - dU: the log law's shift by the roughness of sand-grain height k_s,
//   (1/kappa) ln(1 + 0.3 k_s+) (the roughness function of Colebrook's
//   formula, Jimenez, Annu. Rev. Fluid Mech. 36, 173-196, 2004), ramped in
//   over the viscous layer so that u = 0 at the wall;
// - the wake sin^2(pi eta/2) of Coles (J. Fluid Mech. 1, 191-226, 1956) and
//   the cubic of Guo & Julien (J. Hydraul. Res. 41, 493-501, 2003) that
//   makes the slope zero on the axis: g = R+ dU_R/dy+ at y+ = R+ (minus the
//   ramp's slope there), so that du/dr = 0 at r = 0 exactly;
// - the wake's strength Pi from the bulk speed: the mean of u over the
//   cross-section is U_b (u+ is linear in Pi: one division, no iteration).
// The gradient dw/dr is the same closed form differentiated.
//
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef RISERCORE_CARRIER_TURBULENTPIPEPROFILE_HPP
#define RISERCORE_CARRIER_TURBULENTPIPEPROFILE_HPP

#include "carrier/pipeProfile.hpp"
#include "checks.hpp"

#include <cmath>
#include <stdexcept>

namespace riser {

//- The Darcy friction factor of Colebrook-White at Reynolds number Re and
//  relative roughness k_s/D (fixed-point iteration on 1/sqrt(f), which
//  contracts by ~0.1 an iteration; to 1e-14)
inline double colebrookFrictionFactor(double Re, double relativeRoughness)
{
    requireInRange("riser::colebrookFrictionFactor", "Re", Re, 2000.0, Bound::closed, 1e9,
                   Bound::closed);
    requireInRange("riser::colebrookFrictionFactor", "k_s/D", relativeRoughness, 0.0,
                   Bound::closed, 0.5, Bound::open);
    double x = 7.0;     // 1/sqrt(f): f = 0.02
    for (int i = 0; i < 100; ++i)
    {
        const double next = -2.0*std::log10(relativeRoughness/3.7 + 2.51*x/Re);
        if (std::abs(next - x) < 1e-14*x)
        {
            x = next;
            break;
        }
        x = next;
    }
    return 1.0/(x*x);
}

class TurbulentPipeProfile final : public PipeProfile
{
public:
    //- The log law's constants, u+ = (1/kappa) ln y+ + B (Pope, Turbulent
    //  Flows, 2000, sec. 7.1.4), and Reichardt's: chi, and C, which gives
    //  his law the intercept B
    static constexpr double kappa = 0.41, B = 5.2, chi = 11.0;

    //- D: pipe diameter [m]; uBulk: bulk speed [m/s]; nu: kinematic
    //  viscosity [m^2/s]; roughness: sand-grain height k_s [m], [0, D/2)
    TurbulentPipeProfile(double D, double uBulk, double nu, double roughness)
    :
        R_(0.5*D), uBulk_(uBulk), nu_(nu), ks_(roughness)
    {
        const char* law = "riser::TurbulentPipeProfile";
        requirePositive(law, "D", D);
        requirePositive(law, "U_b", uBulk);
        requirePositive(law, "nu", nu);
        requireInRange(law, "k_s", roughness, 0.0, Bound::closed, R_, Bound::open);
        Re_ = uBulk*D/nu;
        requireInRange(law, "Re", Re_, 4000.0, Bound::closed, 1e8, Bound::closed);
        f_ = colebrookFrictionFactor(Re_, ks_/D);
        uTau_ = uBulk*std::sqrt(f_/8.0);
        Rplus_ = R_*uTau_/nu_;
        const double ksPlus = ks_*uTau_/nu_;
        shift_ = std::log(1.0 + 0.3*ksPlus)/kappa;
        // the cubic's coefficient: the inner part's slope in eta on the
        // axis (eta = 1)
        g_ = Rplus_*innerSlope(Rplus_);
        // Pi from the bulk: U_b/u_tau = I0 + Pi I1, the means over the
        // section of the profile without the wake and of the wake's
        // (2/kappa) sin^2 part
        const double I0 = sectionMean([this](double yp) { return basePlus(yp); });
        const double I1 = sectionMean
        (
            [this](double yp)
            {
                const double s = std::sin(0.5*M_PI*yp/Rplus_);
                return 2.0/kappa*s*s;
            }
        );
        Pi_ = (uBulk_/uTau_ - I0)/I1;
        uCentre_ = speedAt(0.0);
    }

    const char* type() const override { return "turbulent"; }
    double radius() const override { return R_; }
    double bulkSpeed() const { return uBulk_; }
    double reynolds() const { return Re_; }
    double frictionFactor() const { return f_; }
    double frictionVelocity() const { return uTau_; }
    //- R+ = R u_tau / nu, the friction Reynolds number
    double frictionReynolds() const { return Rplus_; }
    //- The wake's strength Pi
    double wakeStrength() const { return Pi_; }
    double centreLineSpeed() const override { return uCentre_; }

    //- u+ at y+ (from the wall)
    double uPlus(double yPlus) const
    {
        const double eta = yPlus/Rplus_;
        const double s = std::sin(0.5*M_PI*eta);
        return basePlus(yPlus) + 2.0*Pi_/kappa*s*s;
    }

protected:
    Values compute(double r) const override { return {speedAt(r), gradientAt(r)}; }

private:
    //- The axial speed w at distance r from the axis (|r| <= R; beyond,
    //  the wall's zero: the log law has no continuation)
    double speedAt(double r) const
    {
        const double y = R_ - std::abs(r);
        if (y <= 0.0) return 0.0;
        return uTau_*uPlus(y*uTau_/nu_);
    }

    //- dw/dr at r >= 0 (<= 0 from the axis to the wall; 0 on the axis; on
    //  a smooth wall -u_tau^2/nu)
    double gradientAt(double r) const
    {
        // at and beyond the wall, the wall's value
        const double y = std::max(R_ - std::abs(r), 0.0);
        const double yPlus = y*uTau_/nu_, eta = y/R_;
        // du+/dy+ of each part; dw/dr = -u_tau (u_tau/nu) du+/dy+
        const double dPlus =
            innerSlope(yPlus)
          - g_*eta*eta/Rplus_
          + Pi_/kappa*M_PI/Rplus_*std::sin(M_PI*eta);
        return -uTau_*uTau_/nu_*dPlus;
    }

    //- Reichardt's law less the ramped roughness shift, at y+
    double innerPlus(double yp) const
    {
        const double e = std::exp(-yp/chi);
        return std::log(1.0 + kappa*yp)/kappa + C_*(1.0 - e - yp/chi*std::exp(-yp/3.0))
             - shift_*(1.0 - e);
    }

    //- d(innerPlus)/dy+
    double innerSlope(double yp) const
    {
        const double e = std::exp(-yp/chi), e3 = std::exp(-yp/3.0);
        return 1.0/(1.0 + kappa*yp)
             + C_*(e/chi - e3/chi + yp/(3.0*chi)*e3)
             - shift_*e/chi;
    }

    //- The profile without the wake: inner law and the cubic
    double basePlus(double yp) const
    {
        const double eta = yp/Rplus_;
        return innerPlus(yp) - g_/3.0*eta*eta*eta;
    }

    //- The mean over the cross-section of a function of y+:
    //  (2/R^2) int_0^R F r dr with r = R (1 - eta), by Gauss-Legendre on
    //  intervals graded towards the wall (the viscous layer is 1e-4 R
    //  thick at Re 1e6)
    template<class F>
    double sectionMean(const F& fn) const
    {
        static const double x[5] = {-0.9061798459386640, -0.5384693101056831, 0.0,
                                    0.5384693101056831, 0.9061798459386640};
        static const double w[5] = {0.2369268850561891, 0.4786286704993665,
                                    0.5688888888888889, 0.4786286704993665,
                                    0.2369268850561891};
        // eta from 1e-9 R... geometric intervals from the wall: eta_k =
        // 1e-8 * q^k up to 1 (and [0, 1e-8] where u+ = y+ to 1e-9)
        const int n = 400;
        const double e0 = 1e-8, q = std::pow(1.0/e0, 1.0/n);
        double sum = 0.0, a = 0.0, b = e0;
        for (int k = 0; k <= n; ++k)
        {
            const double mid = 0.5*(a + b), half = 0.5*(b - a);
            for (int i = 0; i < 5; ++i)
            {
                const double eta = mid + half*x[i];
                sum += w[i]*half*fn(eta*Rplus_)*(1.0 - eta);
            }
            a = b;
            b = std::min(1.0, b*q);
            if (a >= 1.0) break;
        }
        return 2.0*sum;
    }

    double R_, uBulk_, nu_, ks_;
    //- Reichardt's C, which gives his law the intercept B
    const double C_ = B - std::log(kappa)/kappa;
    double Re_ = 0, f_ = 0, uTau_ = 0, Rplus_ = 0, shift_ = 0, g_ = 0, Pi_ = 0;
    double uCentre_ = 0;
};

} // namespace riser

#endif
