// riserCore: the mean axial speed w(r) of a pipe flow about its axis, other
// than Poiseuille's (riser::RiserFlow's own): the turbulent closed form
// (riser::TurbulentPipeProfile) or samples of a precursor run
// (riser::TabulatedPipeProfile). The carrier asks for the speed and its
// radial gradient at a distance r from the axis.
//
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef RISERCORE_CARRIER_PIPEPROFILE_HPP
#define RISERCORE_CARRIER_PIPEPROFILE_HPP

namespace riser {

class PipeProfile
{
public:
    virtual ~PipeProfile() = default;

    //- The profile's name in constant/riserProperties (entry 'profile')
    virtual const char* type() const = 0;
    //- The pipe's radius R [m]
    virtual double radius() const = 0;
    //- w on the axis [m/s]
    virtual double centreLineSpeed() const = 0;
    //- w at distance r from the axis [m/s]
    virtual double speed(double r) const = 0;
    //- dw/dr at distance r from the axis [1/s]
    virtual double gradient(double r) const = 0;
};

} // namespace riser

#endif
