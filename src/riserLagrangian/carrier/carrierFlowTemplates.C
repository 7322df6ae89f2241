/*---------------------------------------------------------------------------*\
  riserFoam: particle transport in vibrating risers, on OpenFOAM
  License: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "carrierFlow.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

template<class CloudType>
Foam::carrierFlow& Foam::carrierFlow::ofCloud(const CloudType& cloud)
{
    riserModel::ofCloud(cloud);
    return New(cloud.U());
}


template<class ParcelType>
const Foam::point& Foam::carrierFlow::position(const ParcelType& p) const
{
    positionCache& c = lastPosition_;
    if (!c.key.matchOrTake(p, mesh_.time().timeIndex()))
    {
        c.position = p.position();
    }
    return c.position;
}


template<class ParcelType>
Foam::vector Foam::carrierFlow::interpolate
(
    const cachedField& c,
    const ParcelType& p
) const
{
    return interpolator(c).interpolate(p.coordinates(), p.currentTetIndices());
}


template<class ParcelType>
Foam::vector Foam::carrierFlow::velocity
(
    const ParcelType& p,
    const vector& Uc
) const
{
    if (!exact())
    {
        // U at the particle's time: linear in time over the flow step
        const scalar lag = 1 - p.stepFraction();
        vector u = Uc;
        if (lag != 0 && !(velocityChange_.field && steadyStep_))
        {
            u -= lag*interpolate(velocityChange_, p);
        }
        if (movingRiserLab())
        {
            // the riser's velocity at the particle's time in place of the
            // wall's, which the carrier moves with over the step
            if (wall_.timeIndex != mesh_.time().timeIndex())
            {
                FatalErrorInFunction
                    << "carrier velocity requested outside"
                    << " cacheVelocityChange(true/false)" << abort(FatalError);
            }
            u +=
                riserVelocity
                (
                    riser_.height(p), riser_.particleTime(p.stepFraction())
                )
              - (wall_.end - lag*(wall_.end - wall_.start));
        }
        return u;
    }
    return fromCore
    (
        riser_.flow().velocity
        (
            toCore(position(p)),
            riser_.at(position(p).z(), riser_.particleTime(p.stepFraction())).flow
        )
    );
}


template<class ParcelType>
Foam::vector Foam::carrierFlow::vorticity(const ParcelType& p) const
{
    if (!exact())
    {
        return interpolate(vorticity_, p);
    }
    return fromCore
    (
        riser_.flow().vorticity
        (
            toCore(position(p)),
            riser_.at(position(p).z(), riser_.particleTime(p.stepFraction())).flow
        )
    );
}


template<class ParcelType>
Foam::vector Foam::carrierFlow::materialDerivative
(
    const ParcelType& p,
    const scalar dt
) const
{
    if (!exact())
    {
        return
            interpolate(materialDerivative_, p)
          + riserAcceleration
            (
                riser_.height(p), riser_.particleTime(p.stepFraction()), dt
            );
    }
    // Du/Dt of the riser flow is the riser's acceleration at the height:
    // no position of a riser the same at every height (riserModel::height)
    return fromCore
    (
        riser_.flow().materialDerivative
        (
            riser_.at(riser_.height(p), riser_.particleTime(p.stepFraction())).flow
        )
    );
}


// ************************************************************************* //
