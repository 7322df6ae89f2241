// riserCore: the added mass of a sphere (doc/theory.md section 1). The
// fluid around an accelerating sphere is accelerated with it:
//   F_A = C_A m_f (Du/Dt - dv/dt),
// m_f = rho_f V_p the displaced fluid's mass, C_A = 1/2 for a sphere in an
// unbounded fluid. The dv/dt part is moved to the left-hand side of the law
// of motion (it adds C_A m_f to the inertia); the explicit part is
// C_A m_f Du/Dt, with Du/Dt the carrier's material derivative in the frame
// of the simulation (relative accelerations: the same in any frame).
//
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef RISERCORE_ADDEDMASS_ADDEDMASS_HPP
#define RISERCORE_ADDEDMASS_ADDEDMASS_HPP

#include "vector.hpp"

namespace riser {

//- The inertia the added mass adds to the particle's, C_A m_f
inline double addedMassInertia(double CA, double fluidMass)
{
    return CA*fluidMass;
}

//- The explicit part C_A m_f Du/Dt
inline Vector addedMassForce(double CA, double fluidMass, const Vector& DuDt)
{
    return addedMassInertia(CA, fluidMass)*DuDt;
}

} // namespace riser

#endif
