// riserCore: the forces of the law of motion of one particle in the riser
// (doc/theory.md section 1), listed once. Each has the name under which a
// case selects it (the particle force, or the collision model for the wall
// contact); the mesh-free engine, its force budget and both particle tables
// take the list and the names from here.
//
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef RISERCORE_MOTION_FORCELIST_HPP
#define RISERCORE_MOTION_FORCELIST_HPP

#include "drag/dragCoefficient.hpp"
#include "vector.hpp"

#include <array>
#include <string>

namespace riser {

//- The forces of the law of motion
enum class Force { drag, lift, addedMass, fluidStress, gravity, contact };

inline constexpr int nForces = 6;

//- Every force, in the order of the enumeration
inline constexpr std::array<Force, nForces> allForces =
{
    Force::drag, Force::lift, Force::addedMass, Force::fluidStress, Force::gravity,
    Force::contact
};

//- The name a case selects each force by
inline constexpr std::array<const char*, nForces> forceNames =
{
    "wallCorrectedDrag", "riserSaffmanMeiLift", "riserAddedMass", "riserFluidStress",
    "gravity", "riserContact"
};

inline const char* forceName(Force f) { return forceNames[int(f)]; }

//- The force of a name, or false
inline bool forceNamed(const std::string& name, Force& f)
{
    for (Force k : allForces)
    {
        if (name == forceName(k)) { f = k; return true; }
    }
    return false;
}

//- Which of the fluid and body forces act, and their coefficients (the
//  wall contact acts when the law has a contact law)
struct ForceSelection
{
    std::array<bool, nForces> on{{true, true, true, true, true, false}};
    DragLaw dragLaw = DragLaw::paper;
    double pipeDiameter = 0.0;      //!< for the wall factors (0: the riser's)
    double CA = 0.5;                //!< added-mass coefficient

    bool operator[](Force f) const { return on[int(f)]; }
    bool& operator[](Force f) { return on[int(f)]; }

    //- No force at all
    static ForceSelection none()
    {
        ForceSelection s;
        s.on.fill(false);
        return s;
    }
};

//- Every force at one state, and the contact's state
struct ForceReport
{
    std::array<Vector, nForces> F{};
    double overlap = 0.0;           //!< delta_n of the wall contact (> 0 in contact)
    bool sliding = false;

    ForceReport() { for (Vector& f : F) f.setZero(); }

    const Vector& operator[](Force f) const { return F[int(f)]; }
    Vector& operator[](Force f) { return F[int(f)]; }

    //- The sum of the forces: the right-hand side of the law of motion
    //  (the added mass's explicit part included)
    Vector total() const
    {
        Vector sum = F[0];
        for (int k = 1; k < nForces; ++k) sum += F[k];
        return sum;
    }
};

} // namespace riser

#endif
