// riserCore: the mean axial speed w(r) of a pipe flow about its axis, other
// than Poiseuille's (riser::RiserFlow's own): the turbulent closed form
// (riser::TurbulentPipeProfile) or samples of a precursor run
// (riser::TabulatedPipeProfile). The carrier asks for the speed and its
// radial gradient at a distance r from the axis; the forces of one
// evaluation of a particle ask at one r in turn, so both are computed
// together and the last r's kept (a cache: not for use from several
// threads at once).
//
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef RISERCORE_CARRIER_PIPEPROFILE_HPP
#define RISERCORE_CARRIER_PIPEPROFILE_HPP

#include <cmath>

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
    double speed(double r) const { return at(r).speed; }
    //- dw/dr at distance r from the axis [1/s]
    double gradient(double r) const { return at(r).gradient; }

protected:
    struct Values
    {
        double speed, gradient;
    };

    //- w and dw/dr at distance r from the axis
    virtual Values compute(double r) const = 0;

private:
    const Values& at(double r) const
    {
        if (!(r == lastR_))
        {
            last_ = compute(r);
            lastR_ = r;
        }
        return last_;
    }

    mutable double lastR_ = NAN;
    mutable Values last_ = {0, 0};
};

} // namespace riser

#endif
