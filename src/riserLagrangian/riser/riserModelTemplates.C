/*---------------------------------------------------------------------------*\
  riserFoam: particle transport in vibrating risers, on OpenFOAM
  License: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "riserModel.H"

#include <type_traits>
#include <utility>

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace Foam
{
namespace riserModelDetail
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

    //- Are the cloud's particles HistoryParcels, which take the sheared
    //  frame's slope crossing (HistoryParcel::addSlopeCrossing)?
    template<class CloudType, class = void>
    struct followsShear : std::false_type {};

    template<class CloudType>
    struct followsShear
    <
        CloudType,
        std::void_t
        <
            decltype(std::declval<typename CloudType::parcelType&>().historyStarted())
        >
    >
    :
        std::true_type {};
}
}


template<class CloudType>
const Foam::riserModel& Foam::riserModel::ofCloud(const CloudType& cloud)
{
    const dictionary& models = cloud.subModelProperties();
    if (!riserModelDetail::collides<CloudType>::value && models.found("collisionModel"))
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
    const riserModel& riser = New(cloud.mesh());
    if (!riserModelDetail::followsShear<CloudType>::value && riser.shearedFrame())
    {
        FatalIOErrorInFunction(riser.dict())
            << "the riser's motion (type " << riser.motion().type()
            << ") varies along its length, and the cloud " << cloud.name()
            << " is one of OpenFOAM's own: its particles do not take the"
            << " sheared frame's slope crossing (doc/theory.md section 2.6)."
            << " Run this riser with riserParcelFoam or riserParticle"
            << nl << exit(FatalIOError);
    }
    return riser;
}


// ************************************************************************* //
