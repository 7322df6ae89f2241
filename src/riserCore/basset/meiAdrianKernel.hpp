// riserCore: the finite-Reynolds-number history kernel of Mei & Adrian
// (J. Fluid Mech. 237, 323, 1992), as the classical kernel times a factor.
//
// The history force of a sphere of diameter d at particle Reynolds number
// Re, in the notation of Basset's force
//     F_H = 3 pi mu d int_0^t K(t - tau) dw/dtau dtau,
// has Basset's kernel K_B(s) = sqrt(tau_D / (4 pi s)), tau_D = d^2/nu, and
// Mei & Adrian's
//     K(s) = [ (4 pi s/tau_D)^(1/4) + (pi Re^3 s^2 / (f_H^3 tau_D^2))^(1/2) ]^-2,
//     f_H  = 0.75 + 0.105 Re.
// Written as K(s) = K_B(s) psi(s/s*), with
//     psi(x) = (1 + x^(3/4))^-2,
//     s* = (4 pi)^(1/3) pi^(-2/3) (f_H/Re)^2 tau_D,
// the age at which the kernel's two terms are equal: younger changes of the
// slip act as in creeping flow (psi -> 1), older ones decay as s^-2 instead
// of s^-1/2. s* -> infinity as Re -> 0 (the classical kernel); at large Re
// s* -> 0.0120 tau_D (1.2 s for a 10 mm ore in water, 12 ms for a 1 mm
// grain). The kernel was fitted by Mei & Adrian to their computations of
// oscillating flow past a sphere at Re up to 100 (their validity range; at
// larger Re it is an extrapolation).
//
// The window-and-tail quadrature (historyIntegral.hpp) takes the kernel at
// the particle's current Re for its whole history (the tail's sums hold the
// slip changes, not the kernel), with the exponential tail's weights for
// psi fitted here: for each ratio rho = s*/t_win the ten weights b_i of
//     psi(s/s*)/sqrt(s) ~ sum_i b_i sqrt(e/T_i) exp(-s/(2 T_i)),  s >= t_win,
// are the least-squares fit, in units of the classical kernel (its
// absolute error on psi), over 1 <= s/t_win <= 1e4 (as the classical
// re-fit), tabulated at 20 ratios a decade for 1e-3 <= rho <= 1e9 and
// interpolated linearly in log rho. Beyond the table's ends the end rows
// hold: below, the tail is less than 3e-5 of the classical kernel; above,
// psi differs from 1 by less than 4e-4 on the fitted ages.
//
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef RISERCORE_BASSET_MEIADRIANKERNEL_HPP
#define RISERCORE_BASSET_MEIADRIANKERNEL_HPP

#include "checks.hpp"

#include <Eigen/Dense>

#include <array>
#include <cmath>
#include <vector>

namespace riser {

//- psi(x) = (1 + x^(3/4))^-2, the finite-Re kernel over the classical one at
//  age x s*
inline double meiAdrianFactor(double x)
{
    const double r = 1.0 + std::pow(x, 0.75);
    return 1.0/(r*r);
}

//- s*, the age [s] beyond which the kernel departs from the classical one,
//  at particle Reynolds number Re >= 0 and viscous time tau_D = d^2/nu > 0
//  (infinite at Re = 0)
inline double meiAdrianAgeScale(double Re, double tauD)
{
    requireNonNegative("riser::meiAdrianAgeScale", "Re_p", Re);
    requirePositive("riser::meiAdrianAgeScale", "tau_D", tauD);
    if (Re == 0.0) return HUGE_VAL;
    const double fH = 0.75 + 0.105*Re, ratio = fH/Re;
    return std::cbrt(4.0*M_PI)*std::pow(M_PI, -2.0/3.0)*ratio*ratio*tauD;
}

//- The exponential tail's weights b_i for psi at ratio rho = s*/t_win, for
//  the tail times t~_i (in window times) of the quadrature
template<int m>
class MeiAdrianTail
{
public:
    static constexpr double logLow = -3.0, logHigh = 9.0;
    static constexpr int perDecade = 20;
    static constexpr int rows = int((logHigh - logLow)*perDecade) + 1;

    explicit MeiAdrianTail(const std::array<double, m>& times)
    {
        // the fit's ages s/t_win on a logarithmic grid, and the basis
        const int ages = 4000;
        Eigen::MatrixXd A(ages, m);
        std::vector<double> sigma(ages);
        for (int r = 0; r < ages; ++r)
        {
            sigma[r] = std::pow(10.0, 4.0*r/(ages - 1));
            for (int i = 0; i < m; ++i)
            {
                A(r, i) = std::sqrt(sigma[r]*std::exp(1.0)/times[i])
                         *std::exp(-0.5*sigma[r]/times[i]);
            }
        }
        Eigen::MatrixXd targets(ages, rows);
        for (int k = 0; k < rows; ++k)
        {
            const double rho = std::pow(10.0, logLow + double(k)/perDecade);
            for (int r = 0; r < ages; ++r) targets(r, k) = meiAdrianFactor(sigma[r]/rho);
        }
        const Eigen::MatrixXd b = A.colPivHouseholderQr().solve(targets);
        for (int k = 0; k < rows; ++k)
        {
            for (int i = 0; i < m; ++i) table_[k][i] = b(i, k);
        }
    }

    //- b_i at rho = s*/t_win > 0 (infinite: the top row)
    std::array<double, m> weights(double rho) const
    {
        const double u = (std::log10(rho) - logLow)*perDecade;
        if (!(u < rows - 1)) return table_[rows - 1];      // also rho = inf
        if (u <= 0.0) return table_[0];
        const int k = int(u);
        const double f = u - k;
        std::array<double, m> out;
        for (int i = 0; i < m; ++i) out[i] = (1.0 - f)*table_[k][i] + f*table_[k + 1][i];
        return out;
    }

private:
    std::array<std::array<double, m>, rows> table_;
};

} // namespace riser

#endif
