// riserCore: the schema of the transport-statistics tables of a cloud of
// ores in a riser section of diameter D and length L (the cloud function
// riserTransportStatistics of riserParcelFoam; doc/theory.md section 12).
// One row per sample, white-space separated, SI units, after comment lines
// of which the last names the columns.
//
// transport.dat, the cloud's state at the sample time and its wall and pair
// (particle-particle) contacts since the previous sample:
//   t                       time
//   parcels particles       parcels in the section, particles they stand for
//   Cv                      in-situ solids volume fraction,
//                           sum n_p V_p / V, V the section's volume
//                           (the mesh's, riserSection.H)
//   Urx Ury Urz             mean particle velocity relative to the riser
//                           (weighted by n_p)
//   slipx slipy slipz       mean slip v_p - u(x_p) against the carrier at
//                           each particle (weighted by n_p)
//   liftingEfficiency       Urz / u_cm (nan without carrier flow, u_cm = 0)
//   massFlux                solids mass flux through the section,
//                           sum n_p m_p v_z,rel / V [kg/m^2/s]
//   contacts                wall contacts completed since the previous sample
//   contactRate             contacts / (t - t_previous) / parcels [1/s]
//   impacts                 of these, the ones whose impact speed is known
//   impactSpeedMean impactSpeedMax   their normal impact speed UnIn [m/s]
//                           (nan without impacts)
//   wallEnergy              energy dissipated in wall contacts since the
//                           previous sample, sum n_p dE_p [J]
//   pairContacts            pair contacts completed since the previous
//                           sample, each contact once (half the sum of the
//                           parcels' completed pair contacts)
//   pairContactRate         2 pairContacts / (t - t_previous) / parcels
//                           [1/s]: pair contacts per parcel and second
//   pairImpacts             the parcels' pair contacts whose approach speed
//                           is known (a contact is met by both its parcels)
//   pairImpactSpeedMean pairImpactSpeedMax   their normal speed of approach
//                           at the contact's start [m/s] (nan without)
//   pairEnergy              energy dissipated in pair contacts since the
//                           previous sample, sum n_p dE_p [J]
//   blockedBins             axial bins whose Cv exceeds blockageFraction
//   blockedTime             time so far with some axial bin above it [s]
//
// radialProfile.dat: t and Cv_r0 .. Cv_r<n-1>, the solids fraction of n
// annuli of equal area about the riser axis, the innermost first (annulus
// k holds n (r/R)^2 in [k, k+1)).
// axialProfile.dat: t and Cv_z0 .. Cv_z<m-1>, the solids fraction of m
// slices of equal length, the lowest first.
// axialVelocity.dat: t and Urz_z0 .. Urz_z<m-1>, the mean particle
// velocity along the riser relative to it in each slice (weighted by n_p;
// nan in an empty slice); over u_cm, the slice's lifting efficiency.
// axialSlip.dat: t and slipz_z0 .. slipz_z<m-1>, the mean axial slip
// v_z - u_z against the carrier in each slice (nan in an empty slice).
// axialContacts.dat: t, wall_z0 .. wall_z<m-1> and pair_z0 .. pair_z<m-1>,
// the wall and pair contacts completed since the previous sample in each
// slice, by the slice of the parcel at the end of the step it completed
// them in (they add up to contacts and pairContacts).
// impactSpeeds.dat: t and n_0 .. n_<k-1>, the impacts since the previous
// sample whose speed lies in [i w, (i+1) w) (the last bin: all faster).
// pairImpactSpeeds.dat: the same for the pair impacts (pairImpacts), by
// their approach speed, in the same bins.
//
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef RISERCORE_OUTPUT_TRANSPORTSTATISTICS_HPP
#define RISERCORE_OUTPUT_TRANSPORTSTATISTICS_HPP

#include "vector.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace riser {

struct TransportStatisticsRow
{
    double t = 0.0;
    double parcels = 0.0, particles = 0.0;
    double Cv = 0.0;
    Vector URel = Vector::Zero();
    Vector slip = Vector::Zero();
    double liftingEfficiency = 0.0;
    double massFlux = 0.0;
    double contacts = 0.0, contactRate = 0.0;
    double impacts = 0.0, impactSpeedMean = 0.0, impactSpeedMax = 0.0;
    double wallEnergy = 0.0;
    double pairContacts = 0.0, pairContactRate = 0.0;
    double pairImpacts = 0.0, pairImpactSpeedMean = 0.0, pairImpactSpeedMax = 0.0;
    double pairEnergy = 0.0;
    double blockedBins = 0.0, blockedTime = 0.0;
};

//- The column names of transport.dat
inline std::vector<std::string> transportStatisticsColumns()
{
    return
    {
        "t", "parcels", "particles", "Cv", "Urx", "Ury", "Urz", "slipx", "slipy", "slipz",
        "liftingEfficiency", "massFlux", "contacts", "contactRate", "impacts",
        "impactSpeedMean", "impactSpeedMax", "wallEnergy", "pairContacts",
        "pairContactRate", "pairImpacts", "pairImpactSpeedMean", "pairImpactSpeedMax",
        "pairEnergy", "blockedBins", "blockedTime"
    };
}

//- The row's values, in the order of transportStatisticsColumns
inline std::vector<double> transportStatisticsValues(const TransportStatisticsRow& r)
{
    return
    {
        r.t, r.parcels, r.particles, r.Cv, r.URel.x(), r.URel.y(), r.URel.z(),
        r.slip.x(), r.slip.y(), r.slip.z(), r.liftingEfficiency, r.massFlux,
        r.contacts, r.contactRate, r.impacts, r.impactSpeedMean, r.impactSpeedMax,
        r.wallEnergy, r.pairContacts, r.pairContactRate, r.pairImpacts,
        r.pairImpactSpeedMean, r.pairImpactSpeedMax, r.pairEnergy,
        r.blockedBins, r.blockedTime
    };
}

//- The columns of a profile table: t, then prefix0 .. prefix<n-1>
inline std::vector<std::string> profileColumns(const std::string& prefix, int n)
{
    std::vector<std::string> c{"t"};
    for (int i = 0; i < n; ++i) c.push_back(prefix + std::to_string(i));
    return c;
}

//- A table's header: a title line, then the line of column names
inline std::string statisticsHeader(const std::string& title,
                                    const std::vector<std::string>& columns)
{
    std::string header = "# " + title + "\n#";
    for (const std::string& column : columns) header += ' ' + column;
    return header + '\n';
}

//- Write the values as a line of a table (std::ostream or OpenFOAM's
//  Ostream), in the stream's number format
template<class Stream>
void writeStatisticsRow(Stream& os, const std::vector<double>& values)
{
    for (std::size_t i = 0; i < values.size(); ++i)
    {
        if (i) os << ' ';
        os << values[i];
    }
    os << '\n';
}

//- The annulus of equal area (n of them in the radius R) that holds a
//  centre at distance h from the axis; a centre at or beyond R counts in
//  the outermost
inline int radialBin(double h, double R, int n)
{
    const double k = std::floor(n*(h/R)*(h/R));
    return int(std::min(double(n - 1), std::max(0.0, k)));
}

//- The slice (n of equal length between z0 and z0 + L) that holds height z;
//  a height outside (a particle on an end face) counts in the nearest
inline int axialBin(double z, double z0, double L, int n)
{
    const double k = std::floor(n*(z - z0)/L);
    return int(std::min(double(n - 1), std::max(0.0, k)));
}

} // namespace riser

#endif
