// A sphere falling from rest in a liquid at rest under gravity, drag, added
// mass and a history force, by full-history product integration: the
// reference for the library's history quadrature (window + tail, and the
// finite-Re kernel), shared by the core tests and validation/tenCate.
//
// Kernels, F_H = 3 pi mu d int K(t - tau) dw/dtau dtau, tau_D = d^2/nu:
//   classical (Basset):      K = sqrt(tau_D/(4 pi s));
//   finite Re (Mei & Adrian, J. Fluid Mech. 237, 323, 1992):
//       K = [(4 pi s/tau_D)^(1/4) + (pi Re^3 s^2/(f_H^3 tau_D^2))^(1/2)]^-2,
//       f_H = 0.75 + 0.105 Re,
// written here as the paper prints it (the library writes it as the
// classical kernel times a factor of s/s*).
//
// Scheme (independent of the library's): the slip's change is constant over
// each step (the velocity linear), each step's weight int K ds is taken by
// 4-point Gauss-Legendre in sqrt(s) (exact for the classical kernel), and
// the velocity is stepped by implicit Euler, solved by fixed-point iteration;
// the finite-Re kernel's weights are those of the Re at the new velocity,
// for the whole history. Cost O(n) per iteration and step (O(n^2) a fall).
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef RISER_TESTS_HISTORYFALL_HPP
#define RISER_TESTS_HISTORYFALL_HPP

#include <algorithm>
#include <cmath>
#include <functional>
#include <stdexcept>
#include <vector>

namespace oracle {

//- K(s) of the classical or the finite-Re kernel (see top)
inline double historyKernel(bool finiteRe, double s, double tauD, double Re)
{
    const double slow = std::sqrt(4.0*M_PI*s/tauD);
    if (!finiteRe) return 1.0/slow;
    const double fH = 0.75 + 0.105*Re;
    const double fast = std::sqrt(M_PI*Re*Re*Re*s*s/(fH*fH*fH*tauD*tauD));
    return std::pow(std::sqrt(slow) + fast, -2.0);
}

//- The falling sphere: diameter [m], densities [kg/m^3], viscosity [Pa s],
//  gravity [m/s^2], added-mass coefficient, and its drag [N] at descent
//  speed V >= 0 (opposing it)
struct FallingSphere
{
    double d, rhoP, rhoF, mu, g, CA;
    std::function<double(double V)> drag;

    double mp() const { return rhoP*M_PI*d*d*d/6.0; }
    double mf() const { return rhoF*M_PI*d*d*d/6.0; }
    double reynolds(double V) const { return rhoF*std::abs(V)*d/mu; }
};

//- The descent speeds [m/s] at t = k h from release, until the sphere has
//  fallen 'distance' [m] or 'steps' steps are done
inline std::vector<double> historyFall(const FallingSphere& s, bool finiteRe, double h,
                                       double distance, long steps = -1)
{
    static const double node[4] = {-0.8611363115940526, -0.3399810435848563,
                                   0.3399810435848563, 0.8611363115940526};
    static const double weight[4] = {0.3478548451374538, 0.6521451548625461,
                                     0.6521451548625461, 0.3478548451374538};
    const double M = s.mp() + s.CA*s.mf(), W = (s.mp() - s.mf())*s.g;
    const double tauD = s.d*s.d*s.rhoF/s.mu, KH = 3.0*M_PI*s.mu*s.d;
    //- int_{kh}^{(k+1)h} K ds, s = q^2
    const auto stepWeight = [&](size_t k, double Re)
    {
        const double a = std::sqrt(k*h), b = std::sqrt((k + 1)*h);
        double sum = 0.0;
        for (int g = 0; g < 4; ++g)
        {
            const double q = 0.5*(a + b) + 0.5*(b - a)*node[g];
            sum += weight[g]*2.0*q*historyKernel(finiteRe, q*q, tauD, Re);
        }
        return 0.5*(b - a)*sum;
    };
    std::vector<double> u{0.0}, W_k;            // descent speeds; weights by age
    double fallen = 0.0;
    while (fallen < distance && (steps < 0 || long(u.size()) <= steps))
    {
        const size_t n = u.size() - 1;
        double next = u[n];
        bool converged = false;
        for (int it = 0; it < 200 && !converged; ++it)
        {
            const double Re = s.reynolds(next);
            // the finite-Re kernel's weights follow the current Re; the
            // classical kernel's do not, and each is taken once
            if (finiteRe) W_k.clear();
            while (W_k.size() <= n) W_k.push_back(stepWeight(W_k.size(), Re));
            double FH = W_k[0]*(next - u[n]);
            for (size_t j = 0; j < n; ++j) FH += W_k[n - j]*(u[j + 1] - u[j]);
            FH *= KH/h;
            const double update = u[n] + h/M*(W - s.drag(next) - FH);
            converged = std::abs(update - next) < 1e-13;
            next = update;
        }
        if (!converged)
        {
            throw std::runtime_error("oracle::historyFall: a step did not converge");
        }
        fallen += 0.5*h*(u[n] + next);
        u.push_back(next);
    }
    return u;
}

} // namespace oracle

#endif
