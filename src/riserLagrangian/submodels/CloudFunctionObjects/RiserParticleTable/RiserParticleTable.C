/*---------------------------------------------------------------------------*\
  riserFoam: particle transport in vibrating risers, on OpenFOAM
  License: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "RiserParticleTable.H"
#include "particleForceEvaluation.H"
#include "checkedEntry.H"
#include "cloudOutputFile.H"
#include "particleStateExchange.H"
#include "coreVector.H"
#include "output/particleTable.hpp"
#include "IOField.H"

// * * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * //

template<class CloudType>
Foam::OFstream& Foam::RiserParticleTable<CloudType>::file()
{
    if (!file_.valid())
    {
        std::vector<std::string> forceNames;
        for (const auto& force : this->owner().forces())
        {
            forceNames.push_back(force.type());
        }
        const std::string header = riser::particleTableHeader
        (
            "riserParticleTable, SI units; relative: to the riser axis and"
            " velocity",
            forceNames
        );
        file_ =
            cloudOutputFile
            (
                this->owner().mesh(), this->owner().name(), typeName,
                "particles", header, 0
            );
    }
    return file_();
}


template<class CloudType>
void Foam::RiserParticleTable<CloudType>::readOrigins()
{
    CloudType& cloud = this->owner();
    IOobject io(riserCompatibility::cloudFieldIO(cloud, "liftOrigin", IOobject::MUST_READ));
    if (io.typeHeaderOk<IOField<scalar>>(true))
    {
        restartOrigins_.reset(new scalarField(IOField<scalar>(io)));
    }
}


template<class CloudType>
void Foam::RiserParticleTable<CloudType>::updateLift()
{
    CloudType& cloud = this->owner();

    // particles new here: released in this step, or come from another
    // processor, whose origins the processors exchange
    labelPairList missing;
    for (const auto& p : cloud)
    {
        const labelPair key(p.origProc(), p.origId());
        if (!lift_.found(key))
        {
            missing.append(key);
        }
    }
    claimParticleStates(lift_, missing);

    // the section's length, to unwrap heights across cyclic ends
    const scalar length = riser_.section().length;
    for (auto& p : cloud)
    {
        const labelPair key(p.origProc(), p.origId());
        const endOfStep<typename CloudType::parcelType> done(p);
        const scalar z = p.position().z();
        if (!lift_.found(key))
        {
            // released in this step: from the start of its first move
            const scalar z0 = released_.lookup(key, z);
            lift_.insert(key, vector2D(z0, z0));
        }

        // unwrap the height across the ends of a cyclic riser
        vector2D& state = lift_[key];
        const scalar jump = z - state.y();
        if (jump > 0.5*length) state.x() += length;
        if (jump < -0.5*length) state.x() -= length;
        state.y() = z;
    }
    released_.clear();
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
    riser_(riserModel::New(owner.mesh())),
    interval_(checkedEntry::count(this->coeffDict(), "interval", 1, 1000000000, 1))
{
    checkedEntry::allowedKeys(this->coeffDict(), {"type", "interval"});
    riser_.flow();   // FatalError now if there is no riser
    readOrigins();
}


template<class CloudType>
Foam::RiserParticleTable<CloudType>::RiserParticleTable
(
    const RiserParticleTable<CloudType>& t
)
:
    CloudFunctionObject<CloudType>(t),
    riser_(t.riser_),
    interval_(t.interval_),
    calls_(t.calls_),
    lift_(t.lift_),
    released_(t.released_),
    restartOrigins_
    (
        t.restartOrigins_.valid()
      ? new scalarField(t.restartOrigins_())
      : nullptr
    )
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
Foam::scalarField Foam::RiserParticleTable<CloudType>::origins() const
{
    const CloudType& cloud = this->owner();
    scalarField z0(cloud.size());
    label i = 0;
    for (const auto& p : cloud)
    {
        z0[i++] = lift_[labelPair(p.origProc(), p.origId())].x();
    }
    return z0;
}


template<class CloudType>
void Foam::RiserParticleTable<CloudType>::write()
{
    const CloudType& cloud = this->owner();
    IOField<scalar>
    (
        riserCompatibility::cloudFieldIO(cloud, "liftOrigin", IOobject::NO_READ),
        origins()
    ).write(cloud.size() > 0);
}


template<class CloudType>
void Foam::RiserParticleTable<CloudType>::writeObjects
(
    objectRegistry& obr
) const
{
    // on every processor or none: vtkCloud gathers the fields by name
    const CloudType& cloud = this->owner();
    bool known = true;
    for (const auto& p : cloud)
    {
        known = known && lift_.found(labelPair(p.origProc(), p.origId()));
    }
    if (returnReduce(known, andOp<bool>()))
    {
        cloud::createIOField<scalar>("liftOrigin", cloud.size(), obr) = origins();
    }
}


template<class CloudType>
void Foam::RiserParticleTable<CloudType>::preEvolve
(
    RISER_EVOLVE_HOOK_PARAMETER(typename CloudType::parcelType::trackingData)
)
{
    CloudFunctionObject<CloudType>::preEvolve(RISER_EVOLVE_HOOK_ARGUMENT);
    if (calls_ > 0)
    {
        return;
    }
    CloudType& cloud = this->owner();
    const word startTime = cloud.time().timeName(cloud.time().startTime().value());
    if (!restartOrigins_.valid())
    {
        if (cloud.size())
        {
            Info<< "    " << typeName << ": no liftOrigin written at "
                << startTime << "; the lifts start there" << endl;
        }
        return;
    }
    const scalarField& origins = restartOrigins_();
    if (origins.size() != cloud.size())
    {
        FatalErrorInFunction
            << "Field liftOrigin of cloud " << cloud.name() << " at time "
            << startTime << " holds " << origins.size() << " values for "
            << cloud.size() << " particles" << exit(FatalError);
    }
    label i = 0;
    for (const auto& p : cloud)
    {
        lift_.set
        (
            labelPair(p.origProc(), p.origId()),
            vector2D(origins[i++], p.position().z())
        );
    }
    restartOrigins_.clear();
}


template<class CloudType>
void Foam::RiserParticleTable<CloudType>::noteRelease
(
    const typename CloudType::parcelType& p,
    const point& position0
)
{
    const labelPair key(p.origProc(), p.origId());
    if (!lift_.found(key) && !released_.found(key))
    {
        released_.insert(key, position0.z());
    }
}


template<class CloudType>
void Foam::RiserParticleTable<CloudType>::postEvolve
(
    RISER_EVOLVE_HOOK_PARAMETER(typename CloudType::parcelType::trackingData)
)
{
    updateLift();
    CloudFunctionObject<CloudType>::postEvolve(RISER_EVOLVE_HOOK_ARGUMENT);
    if (calls_++ % interval_ != 0)
    {
        return;
    }

    CloudType& cloud = this->owner();
    const Time& time = cloud.mesh().time();
    const scalar t = time.value();
    const scalar dt = time.deltaTValue();
    const riser::RiserMotion& motion = riser_.motion();
    const riser::Wall& wall = riser_.wall();
    const bool labFrame = riser_.frame() == riserModel::simulationFrame::lab;

    OFstream& os = file();
    cloud.forces().cacheFields(true);
    typename CloudType::parcelType::trackingData forceTd(cloud);
    for (auto& p : cloud)
    {
        const labelPair key(p.origProc(), p.origId());
        const endOfStep<typename CloudType::parcelType> done(p);
        const point x = p.position();

        riser::ParticleTableRow row
        (
            t, key.first(), key.second(),
            labFrame ? toCore(x) : motion.toLabFrame(toCore(x), t),
            labFrame ? toCore(p.U()) : motion.labVelocity(toCore(x), toCore(p.U()), t),
            motion
        );
        row.lift = x.z() - lift_[key].x();
        row.contactForce = toCore(p.f());
        row.deltaN = max(0, wall.overlap(toCore(x), 0.5*p.d(), t));
        for (const auto& record : p.collisionRecords().wallRecords())
        {
            row.deltaT = max(row.deltaT, mag(record.collisionData()));
        }
        for (const vector& F : particleForces(cloud, p, forceTd, dt))
        {
            row.forces.push_back(toCore(F));
        }
        riser::writeParticleTableRow(os, row);
    }
    cloud.forces().cacheFields(false);
    os.flush();
}


// ************************************************************************* //
