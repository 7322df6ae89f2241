/*---------------------------------------------------------------------------*\
  riserFoam: particle transport in vibrating risers, on OpenFOAM
  License: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "RiserSaffmanMeiLiftForce.H"
#include "lift/saffmanMeiLift.hpp"

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
    carrier_(carrierFlow::New(mesh))
{}


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
    carrier_.cacheVorticity(store, this->owner().solution().interpolationSchemes());
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
    const vector Omega = carrier_.vorticity(p);
    const scalar magOmega = mag(Omega);
    if (magOmega < VSMALL)
    {
        return forceSuSp(Zero, 0);
    }
    const vector w = carrier_.velocity(p, td.Uc()) - p.U();
    const scalar rho = td.rhoc(), d = p.d();
    const scalar Rep = rho*mag(w)*d/muc;
    const scalar Res = rho*sqr(d)*magOmega/muc;

    // (pi d^3/8) rho C_L = (pi d^2/8) sqrt(rho mu/|Omega|) [C_L sqrt(Re_s)]
    const scalar coeff =
        constant::mathematical::pi/8*sqr(d)*sqrt(rho*muc/magOmega)
       *riser::saffmanMeiCoefficientTimesSqrtRes(Rep, Res);

    return forceSuSp(coeff*(w ^ Omega), 0);
}


// ************************************************************************* //
