/*---------------------------------------------------------------------------*\
  riserFoam: particle transport in vibrating risers, on OpenFOAM
  License: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "ParticleForceFields.H"
#include "checkedEntry.H"
#include "particleForceEvaluation.H"
#include "IOField.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::ParticleForceFields<CloudType>::ParticleForceFields
(
    const dictionary& dict,
    CloudType& owner,
    const word& modelName
)
:
    CloudFunctionObject<CloudType>(dict, owner, modelName, typeName)
{
    checkedEntry::allowedKeys(this->coeffDict(), {"type"});
}


template<class CloudType>
Foam::ParticleForceFields<CloudType>::ParticleForceFields
(
    const ParticleForceFields<CloudType>& pff
)
:
    CloudFunctionObject<CloudType>(pff),
    names_(pff.names_),
    values_(pff.values_),
    timeIndex_(pff.timeIndex_)
{}


// * * * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * //

template<class CloudType>
void Foam::ParticleForceFields<CloudType>::write()
{
    CloudType& cloud = this->owner();
    auto& forces = cloud.forces();
    const scalar dt = cloud.db().time().deltaTValue();

    PtrList<IOField<vector>> fields(forces.size());
    forAll(forces, i)
    {
        fields.set
        (
            i,
            new IOField<vector>
            (
                riserCompatibility::cloudFieldIO(cloud, "F_" + forces[i].type(), IOobject::NO_READ),
                cloud.size()
            )
        );
    }

    forces.cacheFields(true);
    typename CloudType::parcelType::trackingData td(cloud);
    label j = 0;
    for (auto& p : cloud)
    {
        const List<vector> F = particleForces(cloud, p, td, dt);
        forAll(forces, i)
        {
            fields[i][j] = F[i];
        }
        ++j;
    }
    forces.cacheFields(false);

    names_.setSize(fields.size());
    values_.setSize(fields.size());
    forAll(fields, i)
    {
        fields[i].write(cloud.size() > 0);
        names_[i] = fields[i].name();
        values_[i].transfer(fields[i]);
    }
    timeIndex_ = cloud.db().time().timeIndex();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
void Foam::ParticleForceFields<CloudType>::writeObjects
(
    objectRegistry& obr
) const
{
    const CloudType& cloud = this->owner();
    if (timeIndex_ != cloud.db().time().timeIndex())
    {
        return;
    }
    forAll(names_, i)
    {
        cloud::createIOField<vector>(names_[i], cloud.size(), obr) = values_[i];
    }
}


// ************************************************************************* //
