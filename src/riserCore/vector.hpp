// riserCore: the 3-vector of the physics core (Eigen, value semantics).
//
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef RISERCORE_VECTOR_HPP
#define RISERCORE_VECTOR_HPP

#include <Eigen/Core>
#include <Eigen/Geometry>   // cross products

namespace riser {

using Vector = Eigen::Vector3d;

} // namespace riser

#endif
