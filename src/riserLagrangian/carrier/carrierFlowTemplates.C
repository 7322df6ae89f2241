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
    carrierFlow& carrier = New(cloud.U());
    carrier.seenMean_.schemes = cloud.solution().interpolationSchemes();
    return carrier;
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
    const point& x = position(p);
    const scalar t = riser_.particleTime(p.stepFraction());
    vector u = fromCore(riser_.flow().velocity(toCore(x), riser_.at(x.z(), t).flow));
    if (riser_.shearedFrame())
    {
        // seen from the sheared frame, whose velocity along the particle's
        // path holds v_z times the riser's slope, the carrier (which
        // follows the slope at its own axial speed) moves sideways at
        // (u_z - v_z) times the slope
        const riser::AxisState& lab = riser_.labState(x.z(), t);
        u += (u.z() - p.U().z())*vector(lab.slope.x(), lab.slope.y(), 0);
    }
    if (p.tTurb() > 0)
    {
        u += seenFluctuation(p, Uc);
    }
    return u;
}


template<class ParcelType>
Foam::vector Foam::carrierFlow::seenFluctuation
(
    const ParcelType& p,
    const vector& Uc
) const
{
    seenMean& m = seenMean_;
    if
    (
        !m.interp
     || m.eventNo != U_.eventNo()
     || (mesh_.moving() && m.timeIndex != mesh_.time().timeIndex())
    )
    {
        if (m.schemes.empty())
        {
            FatalErrorInFunction
                << "the exact carrier of " << U_.name() << " under a dispersion"
                << " model needs the cloud's interpolation schemes"
                << " (carrierFlow::ofCloud)" << abort(FatalError);
        }
        m.interp.reset(interpolation<vector>::New(m.schemes, U_).ptr());
        m.eventNo = U_.eventNo();
        m.timeIndex = mesh_.time().timeIndex();
    }
    if (!m.key.matchOrTake(p, mesh_.time().timeIndex()))
    {
        m.mean = m.interp->interpolate(p.coordinates(), p.currentTetIndices());
    }
    return Uc - m.mean;
}


template<class ParcelType>
Foam::vector Foam::carrierFlow::vorticity(const ParcelType& p) const
{
    if (!exact())
    {
        return interpolate(vorticity_, p);
    }
    const point& x = position(p);
    const scalar t = riser_.particleTime(p.stepFraction());
    const riser::AxisState& s = riser_.at(x.z(), t).flow;
    vector omega = fromCore(riser_.flow().vorticity(toCore(x), s));
    if (riser_.shearedFrame())
    {
        // the vorticity the riser's variation along z adds (the same in
        // either frame: the sheared frame translates)
        omega += fromCore
        (
            riser_.flow().shearVorticity
            (
                riser::RiserMotion::radialOffset(toCore(x), s),
                riser_.labState(x.z(), t)
            )
        );
    }
    return omega;
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
    // no position of a riser the same at every height (riserModel::height);
    // in the lab, a riser varying along z adds its shear along the
    // fluid's path, which depends on the radius
    const scalar t = riser_.particleTime(p.stepFraction());
    const riser::AxisState& s = riser_.at(riser_.height(p), t).flow;
    vector DuDt =
        riser_.flow().motion().uniformAlongAxis()
      ? fromCore(riser_.flow().materialDerivative(s))
      : fromCore(riser_.flow().materialDerivative(toCore(position(p)), s));
    if (riser_.shearedFrame())
    {
        // relative to the particle's frame: the fluid's path through the
        // sheared frame at its axial speed u_z, less the particle's at
        // v_z (the forces add the latter, riserModel::frameAcceleration)
        // (a sheared riser varies along z: s is the state at x_z)
        const point& x = position(p);
        const scalar uz = riser_.flow().velocity(toCore(x), s).z();
        DuDt +=
            riser_.frameAcceleration(x.z(), t, uz)
          - riser_.frameAcceleration(x.z(), t, p.U().z());
    }
    return DuDt;
}


// ************************************************************************* //
