/*---------------------------------------------------------------------------*\
  riserFoam: particle transport in vibrating risers, on OpenFOAM
  License: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "RiserTransportStatistics.H"
#include "particleForceEvaluation.H"
#include "particleStateExchange.H"
#include "checkedEntry.H"
#include "cloudOutputFile.H"
#include "boundBox.H"
#include "coreVector.H"
#include "output/transportStatistics.hpp"
#include "mathematicalConstants.H"

#include <limits>

// * * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * //

template<class CloudType>
void Foam::RiserTransportStatistics<CloudType>::openFiles()
{
    const CloudType& cloud = this->owner();
    const auto open = [&](const word& base, const std::string& title,
                          const std::vector<std::string>& columns)
    {
        return cloudOutputFile
        (
            cloud.mesh(), cloud.name(), typeName, base,
            riser::statisticsHeader(title, columns), 0, false
        );
    };
    std::ostringstream z0, width;
    z0 << z0_;
    width << impactSpeedBinWidth_;
    transportFile_ = open
    (
        "transport",
        "riserTransportStatistics: the cloud at each sample, its wall and pair"
        " contacts since the previous one; SI units, velocities relative to"
        " the riser",
        riser::transportStatisticsColumns()
    );
    radialFile_ = open
    (
        "radialProfile",
        "riserTransportStatistics: solids volume fraction of "
      + std::to_string(radialBins_) + " annuli of equal area, from the axis",
        riser::profileColumns("Cv_r", radialBins_)
    );
    axialFile_ = open
    (
        "axialProfile",
        "riserTransportStatistics: solids volume fraction of "
      + std::to_string(axialBins_) + " slices of equal length, from z = "
      + z0.str() + " m",
        riser::profileColumns("Cv_z", axialBins_)
    );
    impactFile_ = open
    (
        "impactSpeeds",
        "riserTransportStatistics: wall impacts since the previous sample by"
        " impact speed, bins of " + width.str() + " m/s from 0 (the last:"
        " all faster)",
        riser::profileColumns("n_", impactSpeedBins_)
    );
    pairImpactFile_ = open
    (
        "pairImpactSpeeds",
        "riserTransportStatistics: pair impacts since the previous sample by"
        " approach speed, bins of " + width.str() + " m/s from 0 (the last:"
        " all faster)",
        riser::profileColumns("n_", impactSpeedBins_)
    );
}


template<class CloudType>
typename Foam::RiserTransportStatistics<CloudType>::traceState
Foam::RiserTransportStatistics<CloudType>::stateOf(const contactTrace& trace)
{
    traceState s;
    s[0] = trace.wallContacts;
    s[1] = trace.pairContacts;
    s[2] = trace.wallEnergy;
    s[3] = trace.pairEnergy;
    return s;
}


template<class CloudType>
Foam::label Foam::RiserTransportStatistics<CloudType>::speedBin
(
    const scalar speed
) const
{
    return
        label
        (
            min(scalar(impactSpeedBins_ - 1), max(0, speed)/impactSpeedBinWidth_)
        );
}


template<class CloudType>
void Foam::RiserTransportStatistics<CloudType>::countContacts()
{
    CloudType& cloud = this->owner();
    labelPairList missing;
    for (const auto& p : cloud)
    {
        const labelPair key(p.origProc(), p.origId());
        if (!traces_.found(key))
        {
            missing.append(key);
        }
    }
    claimParticleStates(traces_, missing);

    // a parcel new to the cloud starts from an empty trace
    const traceState none(Zero);
    HashTable<traceState, labelPair, labelPair::Hash<>> states(2*cloud.size());
    for (const auto& p : cloud)
    {
        const labelPair key(p.origProc(), p.origId());
        const contactTrace& trace = p.contacts();
        const traceState last = traces_.lookup(key, none);
        const traceState now = stateOf(trace);

        if (now[0] > last[0])
        {
            contacts_ += now[0] - last[0];
            impacts_ += 1;
            impactSpeedSum_ += trace.wallImpactSpeed;
            impactSpeedMax_ = max(impactSpeedMax_, trace.wallImpactSpeed);
            impactHistogram_[speedBin(trace.wallImpactSpeed)] += 1;
        }
        if (now[1] > last[1])
        {
            // each contact is completed by both its parcels
            pairContacts_ += 0.5*(now[1] - last[1]);
            pairImpacts_ += 1;
            pairImpactSpeedSum_ += trace.pairImpactSpeed;
            pairImpactSpeedMax_ = max(pairImpactSpeedMax_, trace.pairImpactSpeed);
            pairImpactHistogram_[speedBin(trace.pairImpactSpeed)] += 1;
        }
        wallEnergy_ += p.nParticle()*(now[2] - last[2]);
        pairEnergy_ += p.nParticle()*(now[3] - last[3]);
        states.insert(key, now);
    }
    traces_.transfer(states);
}


template<class CloudType>
Foam::scalarList
Foam::RiserTransportStatistics<CloudType>::axialVolumes()
{
    scalarList volume(axialBins_, Zero);
    for (auto& p : this->owner())
    {
        const endOfStep<typename CloudType::parcelType> done(p);
        const label bin =
            riser::axialBin(p.position().z(), z0_, length_, axialBins_);
        volume[bin] += p.nParticle()*p.volume();
    }
    Pstream::listCombineGather(volume, plusEqOp<scalar>());
    Pstream::listCombineScatter(volume);
    return volume;
}


template<class CloudType>
bool Foam::RiserTransportStatistics<CloudType>::sampleDue() const
{
    const Time& time = this->owner().time();
    if (interval_ <= 0)
    {
        return time.writeTime();
    }
    const scalar halfStep = 0.5*time.deltaTValue();
    const scalar next =
        interval_*(std::floor((lastSample_ + halfStep)/interval_) + 1);
    return time.value() + halfStep >= next;
}


template<class CloudType>
void Foam::RiserTransportStatistics<CloudType>::sample
(
    const scalarList& axialVolume,
    const label blockedBins
)
{
    CloudType& cloud = this->owner();
    const scalar t = cloud.time().value();
    const riser::RiserFlow& flow = carrier_.riser();
    const scalar R = flow.radius();
    const scalar area = constant::mathematical::pi*R*R;
    const scalar nan = std::numeric_limits<scalar>::quiet_NaN();

    scalar parcels = 0, particles = 0, volume = 0, axialMomentum = 0;
    vector URel = Zero, slip = Zero;
    scalarList radialVolume(radialBins_, Zero);
    typename CloudType::parcelType::trackingData td(cloud);
    for (auto& p : cloud)
    {
        const endOfStep<typename CloudType::parcelType> done(p);
        const scalar n = p.nParticle();
        const riser::Vector x = toCore(p.position());
        const scalar h = flow.motion().radialOffset(x, t).norm();
        const vector Ur =
            fromCore(flow.motion().relativeVelocity(toCore(p.U()), t));
        p.setCellValues(cloud, td);

        parcels += 1;
        particles += n;
        volume += n*p.volume();
        radialVolume[riser::radialBin(h, R, radialBins_)] += n*p.volume();
        URel += n*Ur;
        slip += n*(p.U() - carrier_.velocity(p, td.Uc()));
        axialMomentum += n*p.mass()*Ur.z();
    }
    reduce(parcels, sumOp<scalar>());
    reduce(particles, sumOp<scalar>());
    reduce(volume, sumOp<scalar>());
    reduce(axialMomentum, sumOp<scalar>());
    reduce(URel, sumOp<vector>());
    reduce(slip, sumOp<vector>());
    Pstream::listCombineGather(radialVolume, plusEqOp<scalar>());
    reduce(contacts_, sumOp<scalar>());
    reduce(impacts_, sumOp<scalar>());
    reduce(impactSpeedSum_, sumOp<scalar>());
    reduce(impactSpeedMax_, maxOp<scalar>());
    Pstream::listCombineGather(impactHistogram_, plusEqOp<scalar>());
    reduce(wallEnergy_, sumOp<scalar>());
    reduce(pairContacts_, sumOp<scalar>());
    reduce(pairImpacts_, sumOp<scalar>());
    reduce(pairImpactSpeedSum_, sumOp<scalar>());
    reduce(pairImpactSpeedMax_, maxOp<scalar>());
    Pstream::listCombineGather(pairImpactHistogram_, plusEqOp<scalar>());
    reduce(pairEnergy_, sumOp<scalar>());

    if (Pstream::master())
    {
        riser::TransportStatisticsRow row;
        row.t = t;
        row.parcels = parcels;
        row.particles = particles;
        row.Cv = volume/(area*length_);
        row.URel = particles > 0 ? toCore(URel/particles) : toCore(vector::one*nan);
        row.slip = particles > 0 ? toCore(slip/particles) : toCore(vector::one*nan);
        row.liftingEfficiency =
            flow.centreLineSpeed() > 0 ? row.URel.z()/flow.centreLineSpeed() : nan;
        row.massFlux = axialMomentum/length_/area;
        row.contacts = contacts_;
        row.contactRate =
            parcels > 0 && t > lastSample_ ? contacts_/(t - lastSample_)/parcels : 0;
        row.impacts = impacts_;
        row.impactSpeedMean = impacts_ > 0 ? impactSpeedSum_/impacts_ : nan;
        row.impactSpeedMax = impacts_ > 0 ? impactSpeedMax_ : nan;
        row.wallEnergy = wallEnergy_;
        row.pairContacts = pairContacts_;
        row.pairContactRate =
            parcels > 0 && t > lastSample_
          ? 2*pairContacts_/(t - lastSample_)/parcels
          : 0;
        row.pairImpacts = pairImpacts_;
        row.pairImpactSpeedMean =
            pairImpacts_ > 0 ? pairImpactSpeedSum_/pairImpacts_ : nan;
        row.pairImpactSpeedMax = pairImpacts_ > 0 ? pairImpactSpeedMax_ : nan;
        row.pairEnergy = pairEnergy_;
        row.blockedBins = blockedBins;
        row.blockedTime = blockedTime_;
        riser::writeStatisticsRow
        (
            transportFile_(), riser::transportStatisticsValues(row)
        );

        const auto writeProfile = [t](OFstream& os, const scalarList& values)
        {
            std::vector<double> row{t};
            row.insert(row.end(), values.begin(), values.end());
            riser::writeStatisticsRow(os, row);
            os.flush();
        };
        writeProfile(radialFile_(), radialVolume/(area*length_/radialBins_));
        writeProfile(axialFile_(), axialVolume/(area*length_/axialBins_));
        writeProfile(impactFile_(), impactHistogram_);
        writeProfile(pairImpactFile_(), pairImpactHistogram_);
        transportFile_().flush();
    }

    lastSample_ = t;
    contacts_ = 0;
    impacts_ = 0;
    impactSpeedSum_ = 0;
    impactSpeedMax_ = 0;
    impactHistogram_ = Zero;
    wallEnergy_ = 0;
    pairContacts_ = 0;
    pairImpacts_ = 0;
    pairImpactSpeedSum_ = 0;
    pairImpactSpeedMax_ = 0;
    pairImpactHistogram_ = Zero;
    pairEnergy_ = 0;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::RiserTransportStatistics<CloudType>::RiserTransportStatistics
(
    const dictionary& dict,
    CloudType& owner,
    const word& modelName
)
:
    CloudFunctionObject<CloudType>(dict, owner, modelName, typeName),
    carrier_(carrierFlow::New(owner.U())),
    interval_
    (
        checkedEntry::inRange(this->coeffDict(), "interval", 0, false, 1e9, true, 0)
    ),
    radialBins_(checkedEntry::count(this->coeffDict(), "radialBins", 1, 1000, 10)),
    axialBins_(checkedEntry::count(this->coeffDict(), "axialBins", 1, 1000000, 10)),
    blockageFraction_
    (
        checkedEntry::inRange
        (
            this->coeffDict(), "blockageFraction", 0, false, 1, true, 0.5
        )
    ),
    impactSpeedBins_
    (
        checkedEntry::count(this->coeffDict(), "impactSpeedBins", 1, 1000, 20)
    ),
    impactSpeedBinWidth_
    (
        checkedEntry::inRange
        (
            this->coeffDict(), "impactSpeedBinWidth", 0, false, 100, true, 0.1
        )
    ),
    z0_(boundBox(owner.mesh().points()).min().z()),
    length_(boundBox(owner.mesh().points()).span().z()),
    lastSample_(owner.time().startTime().value()),
    impactHistogram_(impactSpeedBins_, Zero),
    pairImpactHistogram_(impactSpeedBins_, Zero)
{
    checkedEntry::allowedKeys
    (
        this->coeffDict(),
        {
            "type", "interval", "radialBins", "axialBins", "blockageFraction",
            "impactSpeedBins", "impactSpeedBinWidth"
        }
    );
    carrier_.riser();

    // a restart: the interval in progress and the blocked time so far
    this->getModelProperty("lastSample", lastSample_);
    this->getModelProperty("blockedTime", blockedTime_);
    if (Pstream::master())
    {
        this->getModelProperty("contacts", contacts_);
        this->getModelProperty("impacts", impacts_);
        this->getModelProperty("impactSpeedSum", impactSpeedSum_);
        this->getModelProperty("impactSpeedMax", impactSpeedMax_);
        scalarList histogram;
        this->getModelProperty("impactHistogram", histogram);
        if (histogram.size() == impactSpeedBins_)
        {
            impactHistogram_ = histogram;
        }
        this->getModelProperty("wallEnergy", wallEnergy_);
        this->getModelProperty("pairContacts", pairContacts_);
        this->getModelProperty("pairImpacts", pairImpacts_);
        this->getModelProperty("pairImpactSpeedSum", pairImpactSpeedSum_);
        this->getModelProperty("pairImpactSpeedMax", pairImpactSpeedMax_);
        scalarList pairHistogram;
        this->getModelProperty("pairImpactHistogram", pairHistogram);
        if (pairHistogram.size() == impactSpeedBins_)
        {
            pairImpactHistogram_ = pairHistogram;
        }
        this->getModelProperty("pairEnergy", pairEnergy_);

        // opened now: a restart after which no sample is taken must not
        // keep the rows after its start
        openFiles();
    }
}


template<class CloudType>
Foam::RiserTransportStatistics<CloudType>::RiserTransportStatistics
(
    const RiserTransportStatistics<CloudType>& s
)
:
    CloudFunctionObject<CloudType>(s),
    carrier_(s.carrier_),
    interval_(s.interval_),
    radialBins_(s.radialBins_),
    axialBins_(s.axialBins_),
    blockageFraction_(s.blockageFraction_),
    impactSpeedBins_(s.impactSpeedBins_),
    impactSpeedBinWidth_(s.impactSpeedBinWidth_),
    z0_(s.z0_),
    length_(s.length_),
    traces_(s.traces_),
    started_(s.started_),
    lastSample_(s.lastSample_),
    contacts_(s.contacts_),
    impacts_(s.impacts_),
    impactSpeedSum_(s.impactSpeedSum_),
    impactSpeedMax_(s.impactSpeedMax_),
    impactHistogram_(s.impactHistogram_),
    wallEnergy_(s.wallEnergy_),
    pairContacts_(s.pairContacts_),
    pairImpacts_(s.pairImpacts_),
    pairImpactSpeedSum_(s.pairImpactSpeedSum_),
    pairImpactSpeedMax_(s.pairImpactSpeedMax_),
    pairImpactHistogram_(s.pairImpactHistogram_),
    pairEnergy_(s.pairEnergy_),
    blockedTime_(s.blockedTime_)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
void Foam::RiserTransportStatistics<CloudType>::preEvolve
(
    RISER_EVOLVE_HOOK_PARAMETER(typename CloudType::parcelType::trackingData)
)
{
    CloudFunctionObject<CloudType>::preEvolve(RISER_EVOLVE_HOOK_ARGUMENT);
    if (started_)
    {
        return;
    }
    // the contacts completed (and the energy dissipated) before the start,
    // read with the parcels, are not this run's
    for (const auto& p : this->owner())
    {
        traces_.set(labelPair(p.origProc(), p.origId()), stateOf(p.contacts()));
    }
    started_ = true;
}


template<class CloudType>
void Foam::RiserTransportStatistics<CloudType>::postEvolve
(
    RISER_EVOLVE_HOOK_PARAMETER(typename CloudType::parcelType::trackingData)
)
{
    countContacts();

    const scalarList volume = axialVolumes();
    const scalar sliceVolume =
        constant::mathematical::pi*sqr(carrier_.riser().radius())
       *length_/axialBins_;
    label blockedBins = 0;
    for (const scalar V : volume)
    {
        blockedBins += (V/sliceVolume > blockageFraction_);
    }
    if (blockedBins)
    {
        blockedTime_ += this->owner().time().deltaTValue();
    }

    if (sampleDue())
    {
        sample(volume, blockedBins);
    }
    CloudFunctionObject<CloudType>::postEvolve(RISER_EVOLVE_HOOK_ARGUMENT);
}


template<class CloudType>
void Foam::RiserTransportStatistics<CloudType>::write()
{
    // the processors' counts summed, kept by the master
    scalar contacts = contacts_, impacts = impacts_;
    scalar speedSum = impactSpeedSum_, speedMax = impactSpeedMax_;
    scalarList histogram(impactHistogram_);
    reduce(contacts, sumOp<scalar>());
    reduce(impacts, sumOp<scalar>());
    reduce(speedSum, sumOp<scalar>());
    reduce(speedMax, maxOp<scalar>());
    Pstream::listCombineGather(histogram, plusEqOp<scalar>());
    Pstream::listCombineScatter(histogram);
    scalar wallEnergy = wallEnergy_, pairContacts = pairContacts_;
    scalar pairImpacts = pairImpacts_, pairSpeedSum = pairImpactSpeedSum_;
    scalar pairSpeedMax = pairImpactSpeedMax_, pairEnergy = pairEnergy_;
    scalarList pairHistogram(pairImpactHistogram_);
    reduce(wallEnergy, sumOp<scalar>());
    reduce(pairContacts, sumOp<scalar>());
    reduce(pairImpacts, sumOp<scalar>());
    reduce(pairSpeedSum, sumOp<scalar>());
    reduce(pairSpeedMax, maxOp<scalar>());
    reduce(pairEnergy, sumOp<scalar>());
    Pstream::listCombineGather(pairHistogram, plusEqOp<scalar>());
    Pstream::listCombineScatter(pairHistogram);

    this->setModelProperty("lastSample", lastSample_);
    this->setModelProperty("blockedTime", blockedTime_);
    this->setModelProperty("contacts", contacts);
    this->setModelProperty("impacts", impacts);
    this->setModelProperty("impactSpeedSum", speedSum);
    this->setModelProperty("impactSpeedMax", speedMax);
    this->setModelProperty("impactHistogram", histogram);
    this->setModelProperty("wallEnergy", wallEnergy);
    this->setModelProperty("pairContacts", pairContacts);
    this->setModelProperty("pairImpacts", pairImpacts);
    this->setModelProperty("pairImpactSpeedSum", pairSpeedSum);
    this->setModelProperty("pairImpactSpeedMax", pairSpeedMax);
    this->setModelProperty("pairImpactHistogram", pairHistogram);
    this->setModelProperty("pairEnergy", pairEnergy);

    if (!Pstream::master())
    {
        contacts = impacts = speedSum = speedMax = 0;
        histogram = Zero;
        wallEnergy = pairContacts = pairImpacts = pairSpeedSum = 0;
        pairSpeedMax = pairEnergy = 0;
        pairHistogram = Zero;
    }
    contacts_ = contacts;
    impacts_ = impacts;
    impactSpeedSum_ = speedSum;
    impactSpeedMax_ = speedMax;
    impactHistogram_ = histogram;
    wallEnergy_ = wallEnergy;
    pairContacts_ = pairContacts;
    pairImpacts_ = pairImpacts;
    pairImpactSpeedSum_ = pairSpeedSum;
    pairImpactSpeedMax_ = pairSpeedMax;
    pairImpactHistogram_ = pairHistogram;
    pairEnergy_ = pairEnergy;
}


// ************************************************************************* //
