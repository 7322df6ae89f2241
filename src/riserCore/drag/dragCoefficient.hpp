// riserCore: drag coefficient of a sphere in a pipe, corrected for the wall.
//
// Two laws share the wall factors of Clift, Grace & Weber, "Bubbles, drops
// and particles" (1978), ch. 9, as used by Wei, Duan, Wang & Zhou, Phys.
// Fluids 35, 113311 (2023), with alpha = d/D the ratio of sphere to pipe
// diameter:
//
//   K    = (1 - 0.75857 a^5) / (1 - 2.1050 a + 2.0865 a^3 - 1.7068 a^5 + 0.72603 a^6)
//   K_F1 = 1 / (1 - 1.6 a^1.6)
//   K_F2 = (1 + 1.45 a^4.5) / (1 - a^2)^2
//
// paper (DragLaw::paper): the piecewise correlation of the paper,
//   C_D = 24 K / Re                       Re <= 1
//       = (24 / Re)(Re^(2/3) / 6 + K)     1 < Re < 100
//       = 0.42 K_F1                       100 <= Re < 1e5
//       = 0.42 K_F2                       Re >= 1e5
// The paper states the third branch up to Re = 600 and leaves 600..1e5
// open; the branch is extended to close the gap. The correlation jumps at
// Re = 100 (about 1.10 -> 0.42 for a -> 0): kept, as it is the paper's model.
//
// continuous (DragLaw::continuous): the standard drag curve of Clift &
// Gauvin (1970), C_std = 24/Re (1 + 0.15 Re^0.687) + 0.42 / (1 + 42500 Re^-1.16)
// (fits the standard curve to Re ~ 3e5), with the wall factors applied to the
// part each of them was measured for: the creeping-flow factor K to the Stokes
// part 24/Re, the Newton-regime factor K_F1 to the inertial excess,
//   C_D = 24 K / Re + K_F1 (C_std - 24 / Re).
// It tends to the paper's law for Re -> 0 (24 K / Re) and in the Newton
// regime (0.42 K_F1 up to the drag crisis, which it does not model), and is
// smooth in between.
//
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef RISERCORE_DRAG_DRAGCOEFFICIENT_HPP
#define RISERCORE_DRAG_DRAGCOEFFICIENT_HPP

#include "checks.hpp"
#include "vector.hpp"

#include <cmath>

namespace riser {

enum class DragLaw { paper, continuous };

//- Wall factors of a sphere of diameter ratio a = d/D in a pipe.
struct WallFactors
{
    double K;   //!< creeping flow
    double KF1; //!< intermediate and Newton regime
    double KF2; //!< beyond the drag crisis

    explicit WallFactors(double a)
    {
        requireInRange("riser::WallFactors", "d/D", a, 0.0, Bound::closed, 1.0, Bound::open);
        const double a2 = a*a, a3 = a2*a, a5 = a3*a2, a6 = a5*a;
        K = (1.0 - 0.75857*a5)/(1.0 - 2.1050*a + 2.0865*a3 - 1.7068*a5 + 0.72603*a6);
        KF1 = 1.0/(1.0 - 1.6*std::pow(a, 1.6));
        KF2 = (1.0 + 1.45*std::pow(a, 4.5))/((1.0 - a2)*(1.0 - a2));
    }
};

//- The Re_p at which the paper's correlation jumps (end of its second branch).
constexpr double paperDragJumpRe = 100.0;

//- Standard drag curve of Clift & Gauvin (1970), unbounded fluid.
inline double standardDragCoefficient(double Re)
{
    requirePositive("riser::standardDragCoefficient", "Re_p", Re);
    return 24.0/Re*(1.0 + 0.15*std::pow(Re, 0.687))
         + 0.42/(1.0 + 42500.0*std::pow(Re, -1.16));
}

//- Drag coefficient, wall-corrected, for particle Reynolds number Re > 0.
inline double dragCoefficient(DragLaw law, double Re, const WallFactors& w)
{
    requirePositive("riser::dragCoefficient", "Re_p", Re);
    if (law == DragLaw::continuous)
    {
        return 24.0*w.K/Re + w.KF1*(standardDragCoefficient(Re) - 24.0/Re);
    }
    if (Re <= 1.0)              return 24.0*w.K/Re;
    if (Re < paperDragJumpRe)   return 24.0/Re*(std::cbrt(Re*Re)/6.0 + w.K);
    if (Re < 1e5)               return 0.42*w.KF1;
    return 0.42*w.KF2;
}

//- C_D Re_p, finite as Re_p -> 0 (24 K): what a drag force with
//  F = (pi/8) mu d C_D Re_p w needs, with no division by a vanishing slip.
inline double dragCoefficientTimesRe(DragLaw law, double Re, const WallFactors& w)
{
    requireNonNegative("riser::dragCoefficientTimesRe", "Re_p", Re);
    if (Re == 0.0) return 24.0*w.K;
    return dragCoefficient(law, Re, w)*Re;
}

//- The particle Reynolds number Re_p = rho |w| d / mu for slip speed |w|
inline double particleReynolds(double rho, double slip, double d, double mu)
{
    return rho*slip*d/mu;
}

//- The drag force's factor: F_D = (pi/8) d^2 rho C_D |w| w = c w with
//  c = (pi d mu / 8) C_D Re_p, Re_p = rho d |w| / mu. A semi-implicit
//  integration (OpenFOAM's particle forces) uses c itself.
inline double dragFactor(DragLaw law, const WallFactors& w, double d, double mu, double Re)
{
    return M_PI*d*mu/8.0*dragCoefficientTimesRe(law, Re, w);
}

//- Voidage functions of the drag in a suspension of carrier volume
//  fraction eps (none: the single sphere's drag), with Re_s = eps Re_p the
//  Reynolds number of the superficial slip:
//    - wenYu:    Wen & Yu (1966), eps^-chi with chi = 3.65;
//    - diFelice: Di Felice (1994), chi = 3.7 - 0.65 exp(-(1.5 - log10 Re_s)^2/2);
//    - rong:     Rong, Dong & Yu (2013), Chem. Eng. Sci. 99, 44-58, fitted to
//                lattice-Boltzmann simulations of flow through random packings
//                of uniform spheres,
//                  chi = 2.65 (eps + 1) - (5.3 - 3.5 eps) eps^2 exp(-(1.5 - log10 Re_s)^2/2),
//                Di Felice's form with a porosity-dependent level and dip: chi
//                tends to 2.65 (eps + 1) away from log10 Re_s = 1.5 (5.3 at
//                eps = 1, about 4.5 at eps = 0.7). Its simulations span dense
//                to moderate porosities (about 0.37-0.8) and Re up to about
//                1000 (ranges as cited, not re-checked against the paper);
//                more dilute suspensions and larger Re_s (the 10 mm ore
//                settles at Re_s ~ 4000) are an extrapolation of it.
//  All three correlate the drag F_A of Anderson & Jackson's model A (the
//  particle also feels -V grad p): F_A = F_1(eps w) eps^-chi, F_1 the single
//  sphere's drag at the superficial slip eps w. With the fluid stress taken
//  as rho_f V Du/Dt (model B; Zhou, Kuang, Chu & Yu 2010) the drag is
//  F_B = F_A/eps = c(Re_s) eps^-chi w, c the single sphere's dragFactor
//  evaluated at Re_s: suspensionDragFactor.
enum class Voidage { none, wenYu, diFelice, rong };

//- The exponent chi of the voidage function at the carrier volume fraction
//  eps and the superficial Reynolds number Re_s >= 0. At Re_s = 0 (Stokes
//  limit) the exponential dip of Di Felice's and Rong's chi vanishes:
//  3.7 and 2.65 (eps + 1).
inline double voidageExponent(Voidage v, double eps, double ReS)
{
    // exp(-(1.5 - log10 Re_s)^2/2), the dip about Re_s = 10^1.5; 0 at Re_s = 0
    const auto dip = [ReS]()
    {
        if (!(ReS > 0))
        {
            return 0.0;
        }
        const double t = 1.5 - std::log10(ReS);
        return std::exp(-0.5*t*t);
    };
    switch (v)
    {
        case Voidage::wenYu:
            return 3.65;
        case Voidage::diFelice:
            return 3.7 - 0.65*dip();
        case Voidage::rong:
            return 2.65*(eps + 1.0) - (5.3 - 3.5*eps)*eps*eps*dip();
        case Voidage::none:
            break;
    }
    return 0;
}

//- The drag factor c of a sphere in a suspension of carrier volume
//  fraction eps in (0, 1] (model B, see Voidage): F_D = c w with
//  c = dragFactor(Re_s) eps^-chi(Re_s), Re_s = eps Re; dragFactor itself
//  for Voidage::none
inline double suspensionDragFactor(DragLaw law, const WallFactors& w, double d, double mu,
                                   double Re, Voidage v, double eps)
{
    if (v == Voidage::none)
    {
        return dragFactor(law, w, d, mu, Re);
    }
    const double ReS = eps*Re;
    return dragFactor(law, w, d, mu, ReS)*std::pow(eps, -voidageExponent(v, eps, ReS));
}

//- The drag force F_D = c w on a sphere of diameter d with slip
//  w = u - v in a fluid of density rho and viscosity mu
inline Vector dragForce(DragLaw law, const WallFactors& factors, double d, double rho,
                        double mu, const Vector& w)
{
    return dragFactor(law, factors, d, mu, particleReynolds(rho, w.norm(), d, mu))*w;
}

} // namespace riser

#endif
