// riserCore: the particle table's schema, the one both engines write (the
// cloud function riserParticleTable of riserParcelFoam and the mesh-free
// engine riserParticle): one row per particle and output time, white-space
// separated, SI units, after comment lines of which the last names the
// columns:
//   t origProc origId       time, the particle's processor and index at birth
//   x y z Ux Uy Uz          position and velocity in the lab
//   xr yr Urx Ury Urz       position relative to the riser's axis (its x, y),
//                           velocity relative to the riser
//   lift                    height gained since release (unwrapped across the
//                           ends of a periodic riser)
//   Fc_x Fc_y Fc_z          wall contact force
//   deltaN deltaT           wall overlap (0 out of contact), tangential spring
//   F_<force>_x _y _z       each selected force, by the name the case selects
//                           it by
//
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef RISERCORE_OUTPUT_PARTICLETABLE_HPP
#define RISERCORE_OUTPUT_PARTICLETABLE_HPP

#include "riser/riserMotion.hpp"
#include "vector.hpp"

#include <string>
#include <vector>

namespace riser {

struct ParticleTableRow
{
    double t = 0.0;
    long origProc = 0, origId = 0;
    Vector x = Vector::Zero(), U = Vector::Zero();          //!< lab
    Vector xRel = Vector::Zero(), URel = Vector::Zero();    //!< relative to the riser
    double lift = 0.0;
    Vector contactForce = Vector::Zero();
    double deltaN = 0.0, deltaT = 0.0;
    std::vector<Vector> forces;     //!< in the order of the table's force names

    //- The kinematic columns of a particle at lab position x and velocity U
    ParticleTableRow(double time, long proc, long id, const Vector& xLab, const Vector& ULab,
                     const RiserMotion& riser)
    :
        t(time), origProc(proc), origId(id), x(xLab), U(ULab),
        xRel(riser.toRiserFrame(xLab, time)), URel(riser.relativeVelocity(xLab, ULab, time))
    {}
};

//- The column names, for the forces named
inline std::vector<std::string> particleTableColumns(const std::vector<std::string>& forceNames)
{
    std::vector<std::string> c
    {
        "t", "origProc", "origId", "x", "y", "z", "Ux", "Uy", "Uz", "xr", "yr",
        "Urx", "Ury", "Urz", "lift", "Fc_x", "Fc_y", "Fc_z", "deltaN", "deltaT"
    };
    for (const std::string& n : forceNames)
    {
        for (const char* axis : {"_x", "_y", "_z"}) c.push_back("F_" + n + axis);
    }
    return c;
}

//- The table's header: a title line, then the line of column names
inline std::string particleTableHeader(const std::string& title,
                                       const std::vector<std::string>& forceNames)
{
    std::string header = "# " + title + "\n#";
    for (const std::string& column : particleTableColumns(forceNames))
    {
        header += ' ' + column;
    }
    return header + '\n';
}

//- The row's values, in the order of particleTableColumns
inline std::vector<double> particleTableValues(const ParticleTableRow& r)
{
    std::vector<double> v
    {
        r.t, double(r.origProc), double(r.origId),
        r.x.x(), r.x.y(), r.x.z(), r.U.x(), r.U.y(), r.U.z(),
        r.xRel.x(), r.xRel.y(), r.URel.x(), r.URel.y(), r.URel.z(),
        r.lift, r.contactForce.x(), r.contactForce.y(), r.contactForce.z(),
        r.deltaN, r.deltaT
    };
    for (const Vector& F : r.forces)
    {
        v.insert(v.end(), {F.x(), F.y(), F.z()});
    }
    return v;
}

//- Write the row as a line of the table to a stream (std::ostream or
//  OpenFOAM's Ostream), in the stream's number format
template<class Stream>
void writeParticleTableRow(Stream& os, const ParticleTableRow& r)
{
    const std::vector<double> values = particleTableValues(r);
    os << values[0];
    for (std::size_t i = 1; i < values.size(); ++i)
    {
        os << ' ' << values[i];
    }
    os << '\n';
}

} // namespace riser

#endif
