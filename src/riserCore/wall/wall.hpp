// riserCore: the interface every wall shape presents to the particles
// (doc/theory.md section 3). A contact model, a check of the mesh, the
// particle table or the mesh-free engine asks a wall only these questions,
// at a point x and time t:
//   distance(x, t)  the distance from x to the wall, > 0 on the fluid's side
//   normal(x, t)    the unit normal from x towards the wall (out of the fluid)
//   velocity(x, t)  the velocity of the wall's point nearest to x
// and from them the overlap of a sphere of radius r centred at x,
//   delta_n = r - distance(x, t)   (> 0 in contact, < 0: the gap),
// and the contact point a contact law consumes (overlap, normal, wall
// velocity). A new wall shape is a new class derived from Wall; its callers
// do not change. A contact between two particles presents the same
// ContactPoint (overlap of the two spheres, normal from one centre to the
// other, the other's velocity at the contact) to the same contact law.
//
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef RISERCORE_WALL_WALL_HPP
#define RISERCORE_WALL_WALL_HPP

#include "vector.hpp"

namespace riser {

//- What a contact law needs of the body a particle touches
struct ContactPoint
{
    double overlap;     //!< delta_n [m]: > 0 in contact, < 0 the gap
    Vector normal;      //!< unit normal from the particle's centre towards the body
    Vector velocity;    //!< the body's velocity at the contact [m/s]
};

class Wall
{
public:
    virtual ~Wall() = default;

    //- Distance from x to the wall at time t (> 0 on the fluid's side)
    virtual double distance(const Vector& x, double t) const = 0;

    //- Unit normal from x towards the nearest wall point
    virtual Vector normal(const Vector& x, double t) const = 0;

    //- Velocity of the wall point nearest to x
    virtual Vector velocity(const Vector& x, double t) const = 0;

    //- Overlap of a sphere of radius r centred at x (< 0: the gap);
    //  r - distance(x, t), unless a shape has a better-conditioned form
    virtual double overlap(const Vector& x, double r, double t) const
    {
        return r - distance(x, t);
    }

    //- The contact point of a sphere of radius r centred at x (a shape
    //  may evaluate its motion once for the three)
    virtual ContactPoint contactPoint(const Vector& x, double r, double t) const
    {
        return ContactPoint{overlap(x, r, t), normal(x, t), velocity(x, t)};
    }
};

} // namespace riser

#endif
