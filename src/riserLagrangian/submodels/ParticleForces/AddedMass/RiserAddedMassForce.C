/*---------------------------------------------------------------------------*\
  riserFoam: particle transport in vibrating risers, on OpenFOAM
  License: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "RiserAddedMassForce.H"
#include "modelEntries.H"
#include "addedMass/addedMass.hpp"
#include "coreVector.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::RiserAddedMassForce<CloudType>::RiserAddedMassForce
(
    CloudType& owner,
    const fvMesh& mesh,
    const dictionary& dict
)
:
    RiserFluidStressForce<CloudType>(owner, mesh, dict, typeName, true),
    CA_(modelEntries::addedMassCoefficient(this->coeffs()))
{}


template<class CloudType>
Foam::RiserAddedMassForce<CloudType>::RiserAddedMassForce
(
    const RiserAddedMassForce<CloudType>& f
)
:
    RiserFluidStressForce<CloudType>(f),
    CA_(f.CA_)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
Foam::forceSuSp Foam::RiserAddedMassForce<CloudType>::calcCoupled
(
    const typename CloudType::parcelType& p,
    const typename CloudType::parcelType::trackingData& td,
    const scalar dt,
    const scalar mass,
    const scalar Re,
    const scalar muc
) const
{
    // C_A rho_c V_p Du/Dt: relative accelerations, the same in either frame
    return forceSuSp
    (
        fromCore
        (
            riser::addedMassForce
            (
                CA_, mass*td.rhoc()/p.rho(),
                toCore(this->carrier_.materialDerivative(p, dt))
            )
        ),
        0
    );
}


template<class CloudType>
Foam::scalar Foam::RiserAddedMassForce<CloudType>::massAdd
(
    const typename CloudType::parcelType& p,
    const typename CloudType::parcelType::trackingData& td,
    const scalar mass
) const
{
    return riser::addedMassInertia(CA_, mass*td.rhoc()/p.rho());
}


// ************************************************************************* //
