// riserCore: a fixed flat wall through point p with unit normal m pointing
// into the domain (for a closed end of a riser section, or a box face):
//   distance = (x - p) . m,   normal = -m,   velocity = 0.
//
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef RISERCORE_WALL_PLANEWALL_HPP
#define RISERCORE_WALL_PLANEWALL_HPP

#include "wall/wall.hpp"

#include "checks.hpp"

namespace riser {

class PlaneWall final : public Wall
{
public:
    //- p: a point of the plane; m: its normal into the domain (normalised)
    PlaneWall(const Vector& p, const Vector& m)
    :
        p_(p), m_(m.normalized())
    {
        requirePositive("riser::PlaneWall", "|m|", m.norm());
    }

    double distance(const Vector& x, double) const override
    {
        return (x - p_).dot(m_);
    }

    Vector normal(const Vector&, double) const override
    {
        return -m_;
    }

    Vector velocity(const Vector&, double) const override
    {
        return Vector::Zero();
    }

private:
    Vector p_, m_;
};

} // namespace riser

#endif
