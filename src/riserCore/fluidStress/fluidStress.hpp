// riserCore: the fluid stress (pressure-gradient and viscous-stress) force
// on a sphere (doc/theory.md section 1): the force that would accelerate
// the displaced fluid with the carrier,
//   F_S = m_f a_f,
// m_f = rho_f V_p, a_f the fluid's acceleration in an inertial frame: Du/Dt
// in the lab frame; Du/Dt + a_r in the riser frame (the riser's
// acceleration a_r; the fictitious force on the particle is separate).
//
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef RISERCORE_FLUIDSTRESS_FLUIDSTRESS_HPP
#define RISERCORE_FLUIDSTRESS_FLUIDSTRESS_HPP

#include "vector.hpp"

namespace riser {

//- F_S = m_f a_f for the fluid's inertial acceleration a_f
inline Vector fluidStressForce(double fluidMass, const Vector& inertialAcceleration)
{
    return fluidMass*inertialAcceleration;
}

} // namespace riser

#endif
