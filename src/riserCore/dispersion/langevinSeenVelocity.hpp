// riserCore: the fluid velocity a particle sees in RAS turbulence, a
// Langevin model (doc/theory.md section 6.2). The fluctuation of the fluid
// at the particle, u' = sigma chi, sigma = sqrt(2k/3), follows the normalised
// Langevin equation
//   d chi = (-chi/T + grad sigma) dt + sqrt(2/T) dW,
// which, written for u', is Thomson's (1987) well-mixed model of Gaussian
// isotropic inhomogeneous turbulence,
//   du'_i = (-u'_i/T + d_i sigma^2/2 + u'_i u'_j d_j sigma^2/(2 sigma^2)) dt
//           + sqrt(2 sigma^2/T) dW_i:
// tracers released uniformly stay uniform, with no spurious drift towards
// weak turbulence. The time scale is the Lagrangian integral time
//   T_L = nu_t/(Sc_t sigma^2),
// chosen so that tracers spread with the carrier's eddy diffusivity,
// D = sigma^2 T_L = nu_t/Sc_t (Taylor 1921), shortened for a particle
// falling through the eddies by the crossing-trajectory factor
//   T = T_L / sqrt(1 + (beta |w|/sigma)^2)     (Csanady 1963),
// w the particle's velocity relative to the fluid it sees.
//
// Over a step dt, with grad sigma and T held, chi - T grad sigma is an
// Ornstein-Uhlenbeck process; its end value and its mean over the step are
// drawn jointly from their exact Gaussian distribution (Gillespie 1996,
// Phys. Rev. E 54, 2084): no step-size limit, and the step mean carries the
// right spreading however long the step is against T.
//
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef RISERCORE_DISPERSION_LANGEVINSEENVELOCITY_HPP
#define RISERCORE_DISPERSION_LANGEVINSEENVELOCITY_HPP

#include "vector.hpp"

#include <algorithm>
#include <cmath>

namespace riser {

//- The Lagrangian integral time nu_t/(Sc_t sigma^2) (tracer diffusivity
//  sigma^2 T_L equal to the eddy diffusivity nu_t/Sc_t)
inline double lagrangianTime(double nut, double Sct, double sigma)
{
    return nut/(Sct*sigma*sigma);
}

//- The time scale of the fluid seen by a particle whose velocity relative
//  to it has magnitude slip (Csanady 1963, isotropic form; beta = 0: none)
inline double crossingTrajectoryTime
(
    double TL,
    double beta,
    double slip,
    double sigma
)
{
    const double r = beta*slip/sigma;
    return TL/std::sqrt(1.0 + r*r);
}

//- The normalised fluctuation at the step's end and its mean over the step
struct LangevinStep
{
    Vector chiEnd;
    Vector chiMean;
};

//- The joint moments of one step of a unit-variance Ornstein-Uhlenbeck
//  process of time scale T over dt, from an end value v0: the end value
//  a v0 + sx xi1 and the step mean m v0 + (cx xi1 + sm xi2)
struct OrnsteinUhlenbeckStep
{
    double a;   // e^{-h}, h = dt/T: the end value's memory
    double sx;  // the end value's standard deviation, sqrt(1 - a^2)
    double m;   // the step mean's memory, (1 - a)/h
    double cx;  // the step mean's part correlated with the end value
    double sm;  // the step mean's remaining standard deviation

    OrnsteinUhlenbeckStep(double T, double dt)
    {
        const double h = dt/T;
        a = std::exp(-h);
        const double oneMinusA = -std::expm1(-h);
        const double oneMinusA2 = -std::expm1(-2*h);
        sx = std::sqrt(oneMinusA2);
        m = oneMinusA/h;
        // the variance of the step integral over T^2: 2h - 3 + 4a - a^2,
        // by its series below h = 1e-2 (the closed form cancels there; the
        // first omitted term, 31 h^7/1260, is 4e-10 of the sum at 1e-2)
        const double h2 = h*h, h3 = h2*h;
        const double varI =
            h < 1e-2
          ? h3*(2.0/3 - h/2 + 7*h2/30 - h3/12 + 31*h2*h2/1260)
          : 2*h - 3 + 4*a - a*a;
        // covariance of the integral with the end value, over T: (1 - a)^2
        const double covI = oneMinusA*oneMinusA;
        cx = covI/(sx*h);
        sm = std::sqrt(std::max(varI - covI*covI/oneMinusA2, 0.0))/h;
    }
};

//- One step of the normalised Langevin model from chi0, with grad sigma,
//  the time scale T and dt > 0; xi1 and xi2: independent standard normal
//  3-vectors
inline LangevinStep langevinStep
(
    const Vector& chi0,
    const Vector& gradSigma,
    double T,
    double dt,
    const Vector& xi1,
    const Vector& xi2
)
{
    const OrnsteinUhlenbeckStep ou(T, dt);
    const Vector centre = T*gradSigma;
    const Vector v0 = chi0 - centre;
    return
    {
        centre + ou.a*v0 + ou.sx*xi1,
        centre + ou.m*v0 + ou.cx*xi1 + ou.sm*xi2
    };
}

} // namespace riser

#endif
