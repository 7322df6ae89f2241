/*---------------------------------------------------------------------------*\
  riserFoam: particle transport in vibrating risers, on OpenFOAM
  License: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "ParticleForceFields.H"
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
{}


template<class CloudType>
Foam::ParticleForceFields<CloudType>::ParticleForceFields
(
    const ParticleForceFields<CloudType>& pff
)
:
    CloudFunctionObject<CloudType>(pff)
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
                cloud.fieldIOobject("F_" + forces[i].type(), IOobject::NO_READ),
                cloud.size()
            )
        );
    }

    forces.cacheFields(true);
    typename CloudType::parcelType::trackingData td(cloud);
    label j = 0;
    for (auto& p : cloud)
    {
        // The particle is at its end-of-step state, but the colliding
        // cloud's closing velocity half-step leaves stepFraction at 0: mark
        // the step as done while the forces are evaluated, so that the
        // exact carrier is evaluated at the current time.
        const scalar stepFraction = p.stepFraction();
        p.stepFraction() = 1;
        p.setCellValues(cloud, td);
        const scalar mass = p.mass();
        const scalar Re = p.Re(td);
        forAll(forces, i)
        {
            const forceSuSp F =
                forces[i].calcCoupled(p, td, dt, mass, Re, td.muc())
              + forces[i].calcNonCoupled(p, td, dt, mass, Re, td.muc());
            fields[i][j] = F.Su() + F.Sp()*(td.Uc() - p.U());
        }
        p.stepFraction() = stepFraction;
        ++j;
    }
    forces.cacheFields(false);

    for (const auto& field : fields)
    {
        field.write(cloud.size() > 0);
    }
}


// ************************************************************************* //
