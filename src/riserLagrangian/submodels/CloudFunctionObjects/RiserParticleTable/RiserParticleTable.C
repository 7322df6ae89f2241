/*---------------------------------------------------------------------------*\
  riserFoam: particle transport in vibrating risers, on OpenFOAM
  License: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "RiserParticleTable.H"
#include "particleForceEvaluation.H"
#include "checkedEntry.H"
#include "cloudOutputFile.H"
#include "boundBox.H"
#include "coreVector.H"
#include "output/particleTable.hpp"

// * * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * //

template<class CloudType>
Foam::OFstream& Foam::RiserParticleTable<CloudType>::file()
{
    if (!file_.valid())
    {
        file_ =
            cloudOutputFile
            (
                this->owner().mesh(), this->owner().name(), typeName, "particles"
            );
        OFstream& os = file_();
        std::vector<std::string> forceNames;
        for (const auto& force : this->owner().forces())
        {
            forceNames.push_back(force.type());
        }
        os  << "# riserParticleTable, SI units; relative: to the riser axis"
            << " and velocity" << nl << '#';
        for (const std::string& column : riser::particleTableColumns(forceNames))
        {
            os  << ' ' << column.c_str();
        }
        os  << nl;
    }
    return file_();
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::RiserParticleTable<CloudType>::RiserParticleTable
(
    const dictionary& dict,
    CloudType& owner,
    const word& modelName
)
:
    CloudFunctionObject<CloudType>(dict, owner, modelName, typeName),
    carrier_(carrierFlow::New(owner.mesh())),
    interval_(checkedEntry::count(this->coeffDict(), "interval", 1, 1000000000, 1)),
    length_(boundBox(owner.mesh().points()).span().z())
{
    checkedEntry::allowedKeys(this->coeffDict(), {"type", "interval"});
    carrier_.riser();
}


template<class CloudType>
Foam::RiserParticleTable<CloudType>::RiserParticleTable
(
    const RiserParticleTable<CloudType>& t
)
:
    CloudFunctionObject<CloudType>(t),
    carrier_(t.carrier_),
    interval_(t.interval_),
    calls_(t.calls_),
    length_(t.length_),
    z0_(t.z0_),
    lastZ_(t.lastZ_),
    offset_(t.offset_)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
void Foam::RiserParticleTable<CloudType>::postEvolve()
{
    CloudFunctionObject<CloudType>::postEvolve();
    if (calls_++ % interval_ != 0)
    {
        return;
    }

    CloudType& cloud = this->owner();
    const Time& time = cloud.mesh().time();
    const scalar t = time.value();
    const scalar dt = time.deltaTValue();
    const riser::RiserMotion& motion = carrier_.riserMotion();
    const riser::Wall& wall = carrier_.wall();
    const bool labFrame = carrier_.frame() == carrierFlow::simulationFrame::lab;

    OFstream& os = file();
    cloud.forces().cacheFields(true);
    typename CloudType::parcelType::trackingData td(cloud);
    for (auto& p : cloud)
    {
        const labelPair key(p.origProc(), p.origId());
        const endOfStep<typename CloudType::parcelType> done(p);
        const point x = p.position();

        // unwrap the height across the ends of a cyclic riser
        if (!z0_.found(key))
        {
            z0_.insert(key, x.z());
            lastZ_.insert(key, x.z());
            offset_.insert(key, 0);
        }
        scalar& offset = offset_[key];
        const scalar jump = x.z() - lastZ_[key];
        if (jump > 0.5*length_) offset -= length_;
        if (jump < -0.5*length_) offset += length_;
        lastZ_[key] = x.z();

        riser::ParticleTableRow row
        (
            t, key.first(), key.second(),
            labFrame ? toCore(x) : motion.toLabFrame(toCore(x), t),
            labFrame ? toCore(p.U()) : motion.labVelocity(toCore(p.U()), t),
            motion
        );
        row.lift = x.z() + offset - z0_[key];
        row.contactForce = toCore(p.f());
        row.deltaN = max(0, wall.overlap(toCore(x), 0.5*p.d(), t));
        for (const auto& record : p.collisionRecords().wallRecords())
        {
            row.deltaT = max(row.deltaT, mag(record.collisionData()));
        }
        for (const vector& F : particleForces(cloud, p, td, dt))
        {
            row.forces.push_back(toCore(F));
        }
        const std::vector<double> values = riser::particleTableValues(row);
        os  << values[0];
        for (std::size_t i = 1; i < values.size(); ++i)
        {
            os  << ' ' << values[i];
        }
        os  << nl;
    }
    cloud.forces().cacheFields(false);
    os.flush();
}


// ************************************************************************* //
