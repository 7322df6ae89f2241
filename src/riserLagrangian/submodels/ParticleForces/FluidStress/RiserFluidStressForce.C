/*---------------------------------------------------------------------------*\
  riserFoam: particle transport in vibrating risers, on OpenFOAM
  License: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "RiserFluidStressForce.H"
#include "modelEntries.H"
#include "fluidStress/fluidStress.hpp"
#include "coreVector.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::RiserFluidStressForce<CloudType>::RiserFluidStressForce
(
    CloudType& owner,
    const fvMesh& mesh,
    const dictionary& dict,
    const word& forceType,
    const bool readCoeffs
)
:
    ParticleForce<CloudType>(owner, mesh, dict, forceType, readCoeffs),
    carrier_(carrierFlow::ofCloud(owner)),
    riser_(riserModel::New(mesh))
{
    if (!readCoeffs)
    {
        modelEntries::noCoeffs(dict, forceType);
    }
}


template<class CloudType>
Foam::RiserFluidStressForce<CloudType>::RiserFluidStressForce
(
    const RiserFluidStressForce<CloudType>& f
)
:
    ParticleForce<CloudType>(f),
    carrier_(f.carrier_),
    riser_(f.riser_)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
void Foam::RiserFluidStressForce<CloudType>::cacheFields(const bool store)
{
    carrier_.cacheMaterialDerivative
    (
        store,
        this->owner().solution().interpolationSchemes()
    );
}


template<class CloudType>
Foam::forceSuSp Foam::RiserFluidStressForce<CloudType>::calcCoupled
(
    const typename CloudType::parcelType& p,
    const typename CloudType::parcelType::trackingData& td,
    const scalar dt,
    const scalar mass,
    const scalar Re,
    const scalar muc
) const
{
    // rho_c V_p Du/Dt, V_p = mass/rho_p, with the fluid's inertial
    // acceleration (the frame's acceleration added in the riser frame)
    const vector a =
        carrier_.materialDerivative(p, dt)
      + riser_.frameAcceleration
        (
            riser_.height(p), riser_.particleTime(p.stepFraction()), p.U().z()
        );
    return forceSuSp
    (
        fromCore(riser::fluidStressForce(mass*td.rhoc()/p.rho(), toCore(a))),
        0
    );
}


// ************************************************************************* //
