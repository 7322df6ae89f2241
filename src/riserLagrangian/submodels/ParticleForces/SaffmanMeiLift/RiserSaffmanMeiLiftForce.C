/*---------------------------------------------------------------------------*\
  riserFoam: particle transport in vibrating risers, on OpenFOAM
  License: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "RiserSaffmanMeiLiftForce.H"
#include "modelEntries.H"
#include "lift/saffmanMeiLift.hpp"
#include "coreVector.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::RiserSaffmanMeiLiftForce<CloudType>::RiserSaffmanMeiLiftForce
(
    CloudType& owner,
    const fvMesh& mesh,
    const dictionary& dict
)
:
    ParticleForce<CloudType>(owner, mesh, dict, typeName, false),
    carrier_(carrierFlow::ofCloud(owner))
{
    modelEntries::noCoeffs(dict, typeName);
}


template<class CloudType>
Foam::RiserSaffmanMeiLiftForce<CloudType>::RiserSaffmanMeiLiftForce
(
    const RiserSaffmanMeiLiftForce<CloudType>& lf
)
:
    ParticleForce<CloudType>(lf),
    carrier_(lf.carrier_)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
void Foam::RiserSaffmanMeiLiftForce<CloudType>::cacheFields(const bool store)
{
    const dictionary& schemes = this->owner().solution().interpolationSchemes();
    carrier_.cacheVorticity(store, schemes);
    carrier_.cacheVelocityChange(store, schemes);
}


template<class CloudType>
Foam::forceSuSp Foam::RiserSaffmanMeiLiftForce<CloudType>::calcCoupled
(
    const typename CloudType::parcelType& p,
    const typename CloudType::parcelType::trackingData& td,
    const scalar dt,
    const scalar mass,
    const scalar Re,
    const scalar muc
) const
{
    const vector w = carrier_.velocity(p, td.Uc()) - p.U();
    return forceSuSp
    (
        fromCore
        (
            riser::saffmanMeiLiftForce
            (
                p.d(), td.rhoc(), muc, toCore(w), toCore(carrier_.vorticity(p))
            )
        ),
        0
    );
}


// ************************************************************************* //
