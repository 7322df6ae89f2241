/*---------------------------------------------------------------------------*\
  riserFoam: particle transport in vibrating risers, on OpenFOAM
  License: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "carrierFlow.H"
#include "coreVector.H"

#include <type_traits>
#include <utility>

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace Foam
{
namespace carrierFlowDetail
{
    //- Are the cloud's particles colliding parcels (with collision
    //  records: a colliding cloud)? (The models are made for the cloud's
    //  kinematic layer, which has no collision model of its own to ask.)
    template<class CloudType, class = void>
    struct collides : std::false_type {};

    template<class CloudType>
    struct collides
    <
        CloudType,
        std::void_t
        <
            decltype(std::declval<typename CloudType::parcelType&>().collisionRecords())
        >
    >
    :
        std::true_type {};
}
}


template<class CloudType>
Foam::carrierFlow& Foam::carrierFlow::ofCloud(const CloudType& cloud)
{
    const dictionary& models = cloud.subModelProperties();
    if (!carrierFlowDetail::collides<CloudType>::value && models.found("collisionModel"))
    {
        const word type(models.get<word>("collisionModel"));
        if (type != "none")
        {
            FatalIOErrorInFunction(models)
                << "entry 'collisionModel' = " << type << " in the cloud "
                << cloud.name() << ", whose particles do not collide (a"
                << " cloud without a collision model, as MPPICFoam's and"
                << " uncoupledKinematicParcelFoam's): it would be ignored."
                << " Remove it (the wall is then the patchInteractionModel's),"
                << " or run a colliding cloud: riserParcelFoam,"
                << " riserCoupledFoam, DPMFoam, icoUncoupledKinematicParcelFoam"
                << exit(FatalIOError);
        }
    }
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
        if (lag == 0 || (velocityChange_.field && steadyStep_))
        {
            return Uc;
        }
        return Uc - lag*interpolate(velocityChange_, p);
    }
    return fromCore
    (
        riser_->velocity
        (
            toCore(position(p)),
            motionAt(particleTime(p.stepFraction())).flow
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
        riser_->vorticity
        (
            toCore(position(p)),
            motionAt(particleTime(p.stepFraction())).flow
        )
    );
}


template<class ParcelType>
Foam::vector Foam::carrierFlow::materialDerivative(const ParcelType& p) const
{
    if (!exact())
    {
        return interpolate(materialDerivative_, p);
    }
    // Du/Dt of the riser flow is uniform, (dU_r/dt, 0, 0): no position
    // (on a moving mesh position() costs two cell-centre evaluations)
    return fromCore
    (
        riser_->materialDerivative
        (
            motionAt(particleTime(p.stepFraction())).flow
        )
    );
}


// ************************************************************************* //
