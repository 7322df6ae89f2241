/*---------------------------------------------------------------------------*\
  riserFoam: particle transport in vibrating risers, on OpenFOAM
  License: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "RiserOreInjection.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::RiserOreInjection<CloudType>::RiserOreInjection
(
    const dictionary& dict,
    CloudType& owner,
    const word& modelName,
    const word& modelType,
    std::initializer_list<const char*> ownKeys
)
:
    InjectionModel<CloudType>(dict, owner, modelName, modelType),
    riser_(riserModel::ofCloud(owner)),
    source_
    (
        std::make_shared<oreSource>
        (
            this->coeffDict(), riser_, owner.constProps().dict(), ownKeys,
            this->parcelBasis_ == InjectionModel<CloudType>::pbFixed,
            this->nParticleFixed_
        )
    )
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
void Foam::RiserOreInjection<CloudType>::setPositionAndCell
(
    const label parcelI,
    const label,
    const scalar,
    vector& position,
    label& cellOwner,
    label& tetFacei,
    label& tetPti
)
{
    // about the riser's axis where the mesh is now
    const vector& place = places_[parcelI];
    position = axisPoint(place.z(), this->owner().mesh().time().value()) + place;
    this->findCellAtPosition(cellOwner, tetFacei, tetPti, position, true);
}


template<class CloudType>
void Foam::RiserOreInjection<CloudType>::setProperties
(
    const label parcelI,
    const label,
    const scalar,
    typename CloudType::parcelType& parcel
)
{
    parcel.d() = diameters_[parcelI];
    parcel.rho() = densities_[parcelI];
    parcel.U() =
        source_->velocity(parcel.position(), this->owner().mesh().time().value());
}


// ************************************************************************* //
