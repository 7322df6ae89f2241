// riserCore: the restitution of an impact in a liquid, from its Stokes
// number (the `wet` treatment of a contact; doc/theory.md section 3.10).
//
// A sphere that meets a wall (or another sphere) in a liquid loses part of
// its approach speed to the liquid squeezed out of the gap, the more so the
// smaller its inertia against the viscous force. Measured against the
// impact Stokes number St, the restitution of the impact in the liquid
// follows
//
//   e / e_dry = exp(-b / St)   for St >= St_c,     e = 0 below St_c
//
// with b = 35, fitted to the wall impacts of Joseph et al. (J. Fluid Mech.
// 433, 329, 2001), Gondret et al. (Phys. Fluids 14, 643, 2002) and their own
// by Legendre, Zenit, Daniel & Guiraud (Chem. Eng. Sci. 61, 3543, 2006),
// with St = (rho_p + rho_f/2) v d / (9 mu), v the normal approach speed,
// and St_c = 10, below which Joseph et al. saw no rebound. At St_c the fit
// gives e = 0.030 e_dry: the cut-off removes a rebound too small to matter.
//
// The inertia (rho_p + rho_f/2) pi d^3/6 is the particle's with the added
// mass of C_A = 1/2, and St = M v / (6 pi mu R^2) with M that inertia and R
// the radius. Between two spheres the same form with the pair's M_eq (the
// reduced inertia) and R_eq (the reduced radius), as Yang & Hunt (Phys.
// Fluids 18, 121506, 2006) collapse pair impacts onto the wall's: so
// stokesNumber() takes the ContactBody the law sees, whose mass must be the
// inertia with C_A = 1/2 (the callers check it).
//
// The restitution is imposed through the contact's normal damping: each
// contact is given the damping ratio that makes a dry Hertz–Tsuji impact
// rebound with e(St) of its approach speed (restitution.hpp: the closed form,
// exact when the dashpot may pull). e = 0 takes the closed form's limit
// alpha = sqrt(5), at which the overlap closes without a rebound: the
// particle stays at the wall (or the pair together) until other forces pull
// it away. With the normal force clipped at zero (noTension) e = 0 has no
// finite damping ratio, so the wet treatment needs tensionAllowed.
//
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef RISERCORE_CONTACT_WETRESTITUTION_HPP
#define RISERCORE_CONTACT_WETRESTITUTION_HPP

#include "checks.hpp"

#include <cmath>

namespace riser {

struct WetRestitution
{
    double viscosity;               //!< the liquid's mu [Pa s]
    double stokesScale = 35.0;      //!< b (Legendre et al. 2006)
    double criticalStokes = 10.0;   //!< St_c (Joseph et al. 2001)

    void check() const
    {
        requirePositive("riser::WetRestitution", "mu", viscosity);
        requireInRange("riser::WetRestitution", "stokesScale", stokesScale,
                       0.0, Bound::closed, 1e3, Bound::closed);
        requireInRange("riser::WetRestitution", "criticalStokes", criticalStokes,
                       0.0, Bound::closed, 1e4, Bound::closed);
    }

    //- St = M v / (6 pi mu R^2) of an impact at normal approach speed v of
    //  a body of inertia M and radius R (v <= 0: 0)
    double stokesNumber(double inertia, double radius, double v) const
    {
        return v > 0.0 ? inertia*v/(6.0*M_PI*viscosity*radius*radius) : 0.0;
    }

    //- Damping ratio of the Hertz–Tsuji contact (tension allowed) that
    //  rebounds with e(St) for the dry restitution eDry: sqrt(5) L /
    //  sqrt(pi^2 + L^2) with L = -ln e = b/St - ln eDry; below St_c (e = 0):
    //  its limit sqrt(5)
    double dampingRatio(double eDry, double St) const
    {
        if (St < criticalStokes || St <= 0.0) return std::sqrt(5.0);
        const double L = stokesScale/St - std::log(eDry);
        return std::sqrt(5.0)*L/std::sqrt(M_PI*M_PI + L*L);
    }
};

} // namespace riser

#endif
