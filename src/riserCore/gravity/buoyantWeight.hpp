// riserCore: the buoyant weight of a particle (doc/theory.md section 1),
//   F_G = (m_p - m_f) g,
// its weight less that of the fluid it displaces (the hydrostatic part of
// the fluid's pressure; the rest of the fluid stress is fluidStressForce).
//
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef RISERCORE_GRAVITY_BUOYANTWEIGHT_HPP
#define RISERCORE_GRAVITY_BUOYANTWEIGHT_HPP

#include "vector.hpp"

namespace riser {

inline Vector buoyantWeight(double mass, double fluidMass, const Vector& g)
{
    return (mass - fluidMass)*g;
}

} // namespace riser

#endif
