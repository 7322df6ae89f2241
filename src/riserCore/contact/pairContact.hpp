// riserCore: Hertz–Mindlin contact between two spheres, with the law of
// contact/hertzMindlin.hpp (one law, two bodies). For spheres i and j of
// radii R_i, R_j, masses m_i, m_j and materials (E_i, nu_i), (E_j, nu_j):
//
//   R_eq = R_i R_j / (R_i + R_j),   M_eq = m_i m_j / (m_i + m_j),
//   E_eq, G_eq as for the wall, with the second sphere's material in the
//   wall's place (contact/hertzMindlin.hpp),
//   n = (x_j - x_i)/|x_j - x_i|,    delta_n = R_i + R_j - |x_j - x_i|,
//   U = v_i - v_j + omega_i x (R_i n) + omega_j x (R_j n)
//       (velocity of sphere i's contact point relative to sphere j's:
//       riser::contactVelocity in contact/contactKernel.hpp),
//
// and the force F returned by HertzMindlin::force acts on i, -F on j
// (Newton's third law: the pair exchanges momentum only). The torques about
// the centres are R_i n x F_t on i and R_j n x F_t on j (Johnson, Contact
// Mechanics, 1985, ch. 4; Tsuji et al., Powder Technol. 71, 239, 1992;
// doc/theory.md section 5).
//
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef RISERCORE_CONTACT_PAIRCONTACT_HPP
#define RISERCORE_CONTACT_PAIRCONTACT_HPP

#include "contact/hertzMindlin.hpp"

namespace riser {

//- The pair as the one body the contact law sees: R_eq and M_eq
inline ContactBody pairBody(double Ri, double mi, double Rj, double mj)
{
    requirePositive("riser::pairBody", "R_i", Ri);
    requirePositive("riser::pairBody", "R_j", Rj);
    requirePositive("riser::pairBody", "m_i", mi);
    requirePositive("riser::pairBody", "m_j", mj);
    return ContactBody(Ri*Rj/(Ri + Rj), mi*mj/(mi + mj));
}

//- Geometry of the pair seen from sphere i: overlap (< 0: the gap) and
//  unit normal from i towards j
struct PairGeometry
{
    double overlap;
    Vector normal;
    double separation;   //!< |x_j - x_i|
};

inline PairGeometry pairGeometry(const Vector& xi, double Ri, const Vector& xj, double Rj)
{
    const Vector d = xj - xi;
    const double s = d.norm();
    // coincident centres: no direction is preferred; +z is taken
    const Vector n = s > 0.0 ? Vector(d/s) : Vector(0.0, 0.0, 1.0);
    return PairGeometry{(Ri + Rj) - s, n, s};
}

} // namespace riser

#endif
