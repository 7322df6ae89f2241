// Closed forms for a sphere with linear (Stokes) drag, added mass and the
// Basset force, and that sphere as a System of riser::HistoryStepper
// (StokesSphere); shared by the core tests, the case-test oracles and the
// Basset benchmark (validation/basset).
//
// Settling from rest in quiescent fluid (the Laplace-transform solution of
// the Basset-Boussinesq-Oseen equation): with M = m_p + m_f/2,
// alpha = (linear drag coefficient)/M, gamma = 6 pi a^2 sqrt(rho_f mu)/M,
// G = (m_p - m_f) g/M, V_t = G/alpha and lambda_1,2 the roots of
// lambda^2 + gamma lambda + alpha = 0,
//   V/V_t = 1 + [lambda_2 E(lambda_1, t) - lambda_1 E(lambda_2, t)]/(lambda_1 - lambda_2),
//   E(lambda, t) = exp(lambda^2 t) erfc(-lambda sqrt(t)).
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef RISER_TESTS_BASSETCLOSEDFORMS_HPP
#define RISER_TESTS_BASSETCLOSEDFORMS_HPP

#include <cmath>
#include <complex>
#include <vector>

namespace oracle {

using cplx = std::complex<double>;

// Faddeeva function w(z) = exp(-z^2) erfc(-iz), by Weideman's rational
// series (SIAM J. Numer. Anal. 31, 1497, 1994) with N = 32 terms (about
// 1e-13 accurate), its coefficients from a direct discrete Fourier transform;
// for Im z < 0 by w(z) = 2 exp(-z^2) - w(-z).
inline cplx faddeeva(cplx z)
{
    constexpr int N = 32, M = 2*N;
    static const std::vector<double> a = []
    {
        const double L = std::sqrt(N/std::sqrt(2.0));
        std::vector<double> g(2*M, 0.0);
        for (int j = 0; j < 2*M; ++j)
        {
            const int k = j < M ? j : j - 2*M;
            if (k == -M) continue;
            const double t = L*std::tan(0.5*k*M_PI/M);
            g[j] = std::exp(-t*t)*(L*L + t*t);
        }
        std::vector<double> coeff(N + 1, 0.0);
        for (int m = 1; m <= N; ++m)
        {
            double re = 0.0;
            for (int j = 0; j < 2*M; ++j) re += g[j]*std::cos(2.0*M_PI*j*m/(2*M));
            coeff[m] = re/(2*M);
        }
        return coeff;
    }();
    if (z.imag() < 0) return 2.0*std::exp(-z*z) - faddeeva(-z);
    const double L = std::sqrt(N/std::sqrt(2.0));
    const cplx iz(-z.imag(), z.real());
    const cplx Z = (L + iz)/(L - iz);
    cplx p = 0.0;
    for (int m = N; m >= 1; --m) p = p*Z + a[m];
    return 2.0*p/((L - iz)*(L - iz)) + (1.0/std::sqrt(M_PI))/(L - iz);
}

// E(lambda, t) = exp(lambda^2 t) erfc(-lambda sqrt(t)) = w(-i lambda sqrt(t))
inline cplx E(cplx lambda, double t)
{
    return faddeeva(cplx(0.0, -1.0)*lambda*std::sqrt(t));
}

//- Settling velocity from rest at time t (see top); alpha, gamma, G as there
inline double settlingFromRest(double alpha, double gamma, double G, double t)
{
    const cplx root = std::sqrt(cplx(gamma*gamma - 4.0*alpha, 0.0));
    const cplx l1 = 0.5*(-gamma + root), l2 = 0.5*(-gamma - root);
    const cplx ratio = 1.0 + (l2*E(l1, t) - l1*E(l2, t))/(l1 - l2);
    return G/alpha*ratio.real();
}

// A sphere of radius a, density ratio beta = rho_p/rho_f, in water, with
// Stokes drag, added mass C_A = 1/2, Basset (classical C_H = 6), buoyant
// weight, and (for a moving carrier) the fluid-stress force.
struct StokesSphere
{
    using Value = double;
    double a, rhoP, rhoF = 1000.0, mu = 1e-3, g = 9.81;
    double U = 0.0, omega = 0.0;         // carrier u = U cos(omega t)
    double CH = 6.0;                     // Basset coefficient (0: no Basset)

    double mp() const { return rhoP*4.0/3.0*M_PI*a*a*a; }
    double mf() const { return rhoF*4.0/3.0*M_PI*a*a*a; }
    double mass() const { return mp(); }
    double addedMass() const { return 0.5*mf(); }
    double historyCoefficient() const { return CH*a*a*std::sqrt(M_PI*rhoF*mu); }
    double carrierVelocity(double t) const { return U*std::cos(omega*t); }
    double carrierAcceleration(double t) const { return -U*omega*std::sin(omega*t); }
    double force(double v, double t) const
    {
        return 6.0*M_PI*mu*a*(carrierVelocity(t) - v) + (mp() - mf())*g
             + mf()*carrierAcceleration(t);
    }
};

// Settling from rest in quiescent fluid: the closed form of
// settlingFromRest with the Stokes drag 6 pi mu a.
inline double settlingClosedForm(const StokesSphere& s, double t)
{
    const double M = s.mp() + 0.5*s.mf();
    const double alpha = 6.0*M_PI*s.mu*s.a/M;
    const double gamma = 6.0*M_PI*s.a*s.a*std::sqrt(s.rhoF*s.mu)/M;
    const double G = (s.mp() - s.mf())*s.g/M;
    return oracle::settlingFromRest(alpha, gamma, G, t);
}

} // namespace oracle

#endif
