/*---------------------------------------------------------------------------*\
  riserFoam: particle transport in vibrating risers, on OpenFOAM
  License: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "RiserTransportStatistics.H"
#include "particleForceEvaluation.H"
#include "particleStateExchange.H"
#include "checkedEntry.H"
#include "cloudOutputFile.H"
#include "coreVector.H"
#include "output/transportStatistics.hpp"

#include <limits>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

template<class CloudType>
const Foam::FixedList<Foam::word, 4>
Foam::RiserTransportStatistics<CloudType>::exchangeNames_
({"in", "added", "out", "removed"});


// * * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * //

template<class CloudType>
void Foam::RiserTransportStatistics<CloudType>::contactTally::add
(
    const scalar completed,
    const scalar speed,
    const label bin,
    const label slice
)
{
    contacts += completed;
    impacts += 1;
    speedSum += speed;
    speedMax = max(speedMax, speed);
    histogram[bin] += 1;
    slices[slice] += completed;
}


template<class CloudType>
void Foam::RiserTransportStatistics<CloudType>::contactTally::reduceAll()
{
    reduce(contacts, sumOp<scalar>());
    reduce(impacts, sumOp<scalar>());
    reduce(speedSum, sumOp<scalar>());
    reduce(speedMax, maxOp<scalar>());
    reduce(energy, sumOp<scalar>());
    riserCompatibility::listCombineAll(histogram, plusEqOp<scalar>());
    riserCompatibility::listCombineAll(slices, plusEqOp<scalar>());
}


template<class CloudType>
void Foam::RiserTransportStatistics<CloudType>::contactTally::clear()
{
    contacts = impacts = speedSum = speedMax = energy = 0;
    histogram = Zero;
    slices = Zero;
}


template<class CloudType>
Foam::word Foam::RiserTransportStatistics<CloudType>::prefixed
(
    const word& prefix,
    const word& name
)
{
    std::string capitalised(name);
    capitalised[0] = char(toupper(capitalised[0]));
    return word(prefix + capitalised);
}


template<class CloudType>
Foam::word Foam::RiserTransportStatistics<CloudType>::propertyName
(
    const bool pair,
    const word& name
)
{
    if (!pair)
    {
        return name == "energy" ? word("wallEnergy") : name;
    }
    return prefixed("pair", name);
}


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
    z0 << riser_.section().z0;
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
    const std::string slices =
        std::to_string(axialBins_) + " slices of equal length from z = "
      + z0.str() + " m";
    axialVelocityFile_ = open
    (
        "axialVelocity",
        "riserTransportStatistics: mean particle velocity along the riser"
        " relative to it, Urz, in each of " + slices + " (nan: empty)",
        riser::profileColumns("Urz_z", axialBins_)
    );
    axialSlipFile_ = open
    (
        "axialSlip",
        "riserTransportStatistics: mean axial slip v_z - u_z against the"
        " carrier in each of " + slices + " (nan: empty)",
        riser::profileColumns("slipz_z", axialBins_)
    );
    std::vector<std::string> contactColumns =
        riser::profileColumns("wall_z", axialBins_);
    const std::vector<std::string> pairColumns =
        riser::profileColumns("pair_z", axialBins_);
    // after the time column
    contactColumns.insert(contactColumns.end(), pairColumns.begin() + 1, pairColumns.end());
    axialContactsFile_ = open
    (
        "axialContacts",
        "riserTransportStatistics: wall and pair contacts completed since"
        " the previous sample in each of " + slices + ", by the slice of"
        " the parcel at the end of the step it completed them in",
        contactColumns
    );
    impactFile_ = open
    (
        "impactSpeeds",
        "riserTransportStatistics: wall impacts since the previous sample by"
        " impact speed, bins of " + width.str() + " m/s from 0 (the last:"
        " all faster)",
        riser::profileColumns("n_", impactSpeedBins_)
    );
    std::vector<std::string> balanceColumns = riser::profileColumns("ores_z", axialBins_);
    for (const word& name : exchangeNames_)
    {
        const std::vector<std::string> block =
            riser::profileColumns(name + "_z", axialBins_);
        balanceColumns.insert(balanceColumns.end(), block.begin() + 1, block.end());
    }
    axialBalanceFile_ = open
    (
        "axialBalance",
        "riserTransportStatistics: ores (n_p) in each of " + slices + " at the"
        " sample; since the previous sample, come from another slice (in),"
        " new to the cloud (added), gone to another slice (out), gone from"
        " the cloud (removed): ores = previous ores + in + added - out -"
        " removed",
        balanceColumns
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
typename Foam::RiserTransportStatistics<CloudType>::parcelState
Foam::RiserTransportStatistics<CloudType>::stateOf
(
    typename CloudType::parcelType& p
) const
{
    const contactTrace& trace = p.contacts();
    parcelState s;
    s[0] = trace.wallContacts;
    s[1] = trace.pairContacts;
    s[2] = trace.wallEnergy;
    s[3] = trace.pairEnergy;
    s[4] = sliceOf(p);
    s[5] = p.nParticle();
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
Foam::scalarList Foam::RiserTransportStatistics<CloudType>::followParcels()
{
    CloudType& cloud = this->owner();
    labelPairList missing;
    for (const auto& p : cloud)
    {
        const labelPair key(p.origProc(), p.origId());
        if (!parcels_.found(key))
        {
            missing.append(key);
        }
    }
    claimParticleStates(parcels_, missing);

    scalarList& entered = exchange_[0];
    scalarList& added = exchange_[1];
    scalarList& left = exchange_[2];
    scalarList& removed = exchange_[3];
    scalarList volume(axialBins_, Zero);
    HashTable<parcelState, labelPair, labelPairHash> states(2*cloud.size());
    for (auto& p : cloud)
    {
        const labelPair key(p.origProc(), p.origId());
        const parcelState now = stateOf(p);
        const label slice = label(now[4]);
        const scalar n = p.nParticle();
        volume[slice] += n*p.volume();
        states.insert(key, now);

        const auto found = parcels_.cfind(key);
        if (!found.found())
        {
            // new to the cloud: an empty trace, added in its slice
            added[slice] += n;
            countContacts(p, parcelState(Zero), now, slice);
            continue;
        }
        const parcelState& last = found.val();
        if (label(last[4]) != slice)
        {
            left[label(last[4])] += n;
            entered[slice] += n;
        }
        countContacts(p, last, now, slice);
    }
    // the parcels of the last step no processor holds now left the cloud
    forAllConstIters(parcels_, iter)
    {
        if (!states.found(iter.key()))
        {
            removed[label(iter.val()[4])] += iter.val()[5];
        }
    }
    parcels_.transfer(states);
    riserCompatibility::listCombineAll(volume, plusEqOp<scalar>());
    return volume;
}


template<class CloudType>
void Foam::RiserTransportStatistics<CloudType>::countContacts
(
    const typename CloudType::parcelType& p,
    const parcelState& last,
    const parcelState& now,
    const label slice
)
{
    const contactTrace& trace = p.contacts();
    if (now[0] > last[0])
    {
        wall_.add
        (
            now[0] - last[0], trace.wallImpactSpeed, speedBin(trace.wallImpactSpeed),
            slice
        );
    }
    if (now[1] > last[1])
    {
        // each contact is completed by both its parcels
        pair_.add
        (
            0.5*(now[1] - last[1]), trace.pairImpactSpeed,
            speedBin(trace.pairImpactSpeed), slice
        );
    }
    wall_.energy += p.nParticle()*(now[2] - last[2]);
    pair_.energy += p.nParticle()*(now[3] - last[3]);
}


template<class CloudType>
Foam::label Foam::RiserTransportStatistics<CloudType>::sliceOf
(
    typename CloudType::parcelType& p
) const
{
    const endOfStep<typename CloudType::parcelType> done(p);
    return
        riser::axialBin
        (
            p.position().z(), riser_.section().z0, riser_.section().length,
            axialBins_
        );
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
    const riser::RiserFlow& flow = riser_.flow();
    const scalar R = flow.radius();
    const scalar nan = std::numeric_limits<scalar>::quiet_NaN();

    scalar parcels = 0, particles = 0, volume = 0, axialMomentum = 0;
    vector URel = Zero, slip = Zero;
    scalarList radialVolume(radialBins_, Zero);
    scalarList sliceParticles(axialBins_, Zero);
    scalarList sliceUrz(axialBins_, Zero);
    scalarList sliceSlipz(axialBins_, Zero);
    typename CloudType::parcelType::trackingData td(cloud);
    for (auto& p : cloud)
    {
        const label slice = sliceOf(p);
        const endOfStep<typename CloudType::parcelType> done(p);
        const scalar n = p.nParticle();
        const riser::Vector x = toCore(p.position());
        const scalar h = flow.motion().radialOffset(x, t).norm();
        const vector Ur =
            fromCore(flow.motion().relativeVelocity(x, toCore(p.U()), t));
        p.setCellValues(cloud, td);

        parcels += 1;
        particles += n;
        volume += n*p.volume();
        radialVolume[riser::radialBin(h, R, radialBins_)] += n*p.volume();
        const vector slipp = p.U() - carrier_.velocity(p, td.Uc());
        URel += n*Ur;
        slip += n*slipp;
        axialMomentum += n*p.mass()*Ur.z();
        sliceParticles[slice] += n;
        sliceUrz[slice] += n*Ur.z();
        sliceSlipz[slice] += n*slipp.z();
    }
    reduce(parcels, sumOp<scalar>());
    reduce(particles, sumOp<scalar>());
    reduce(volume, sumOp<scalar>());
    reduce(axialMomentum, sumOp<scalar>());
    reduce(URel, sumOp<vector>());
    reduce(slip, sumOp<vector>());
    Pstream::listCombineGather(radialVolume, plusEqOp<scalar>());
    Pstream::listCombineGather(sliceParticles, plusEqOp<scalar>());
    Pstream::listCombineGather(sliceUrz, plusEqOp<scalar>());
    Pstream::listCombineGather(sliceSlipz, plusEqOp<scalar>());
    wall_.reduceAll();
    pair_.reduceAll();
    for (scalarList& list : exchange_)
    {
        riserCompatibility::listCombineAll(list, plusEqOp<scalar>());
    }

    if (Pstream::master())
    {
        riser::TransportStatisticsRow row;
        row.t = t;
        row.parcels = parcels;
        row.particles = particles;
        row.Cv = volume/riser_.section().volume;
        row.URel = particles > 0 ? toCore(URel/particles) : toCore(vector::one*nan);
        row.slip = particles > 0 ? toCore(slip/particles) : toCore(vector::one*nan);
        row.liftingEfficiency =
            flow.centreLineSpeed() > 0 ? row.URel.z()/flow.centreLineSpeed() : nan;
        row.massFlux = axialMomentum/riser_.section().volume;
        const scalar interval = t - lastSample_;
        row.contacts = wall_.contacts;
        row.contactRate =
            parcels > 0 && interval > 0 ? wall_.contacts/interval/parcels : 0;
        row.impacts = wall_.impacts;
        row.impactSpeedMean = wall_.impacts > 0 ? wall_.speedSum/wall_.impacts : nan;
        row.impactSpeedMax = wall_.impacts > 0 ? wall_.speedMax : nan;
        row.wallEnergy = wall_.energy;
        row.pairContacts = pair_.contacts;
        row.pairContactRate =
            parcels > 0 && interval > 0 ? 2*pair_.contacts/interval/parcels : 0;
        row.pairImpacts = pair_.impacts;
        row.pairImpactSpeedMean =
            pair_.impacts > 0 ? pair_.speedSum/pair_.impacts : nan;
        row.pairImpactSpeedMax = pair_.impacts > 0 ? pair_.speedMax : nan;
        row.pairEnergy = pair_.energy;
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
        writeProfile(radialFile_(), radialVolume/(riser_.section().volume/radialBins_));
        writeProfile(axialFile_(), axialVolume/(riser_.section().volume/axialBins_));
        const auto sliceMeans = [&](const scalarList& sums)
        {
            scalarList means(axialBins_);
            forAll(means, k)
            {
                means[k] =
                    sliceParticles[k] > 0 ? sums[k]/sliceParticles[k] : nan;
            }
            return means;
        };
        writeProfile(axialVelocityFile_(), sliceMeans(sliceUrz));
        writeProfile(axialSlipFile_(), sliceMeans(sliceSlipz));
        scalarList contacts(wall_.slices);
        contacts.append(pair_.slices);
        writeProfile(axialContactsFile_(), contacts);
        scalarList balance(sliceParticles);
        for (const scalarList& list : exchange_)
        {
            balance.append(list);
        }
        writeProfile(axialBalanceFile_(), balance);
        writeProfile(impactFile_(), wall_.histogram);
        writeProfile(pairImpactFile_(), pair_.histogram);
        transportFile_().flush();
    }

    lastSample_ = t;
    wall_.clear();
    pair_.clear();
    for (scalarList& list : exchange_)
    {
        list = Zero;
    }
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
    carrier_(carrierFlow::ofCloud(owner)),
    riser_(riserModel::New(owner.mesh())),
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
    lastSample_(owner.time().startTime().value())
{
    wall_.histogram.setSize(impactSpeedBins_, Zero);
    pair_.histogram.setSize(impactSpeedBins_, Zero);
    wall_.slices.setSize(axialBins_, Zero);
    pair_.slices.setSize(axialBins_, Zero);
    for (scalarList& list : exchange_)
    {
        list.setSize(axialBins_, Zero);
    }
    checkedEntry::allowedKeys
    (
        this->coeffDict(),
        {
            "type", "interval", "radialBins", "axialBins", "blockageFraction",
            "impactSpeedBins", "impactSpeedBinWidth"
        }
    );
    riser_.flow();

    // a restart: the interval in progress and the blocked time so far
    this->getModelProperty("lastSample", lastSample_);
    this->getModelProperty("blockedTime", blockedTime_);
    if (Pstream::master())
    {
        for (const bool pair : {false, true})
        {
            contactTally& tally = pair ? pair_ : wall_;
            const auto get = [&](const word& name, auto& value)
            {
                this->getModelProperty(propertyName(pair, name), value);
            };
            get("contacts", tally.contacts);
            get("impacts", tally.impacts);
            get("impactSpeedSum", tally.speedSum);
            get("impactSpeedMax", tally.speedMax);
            scalarList histogram;
            get("impactHistogram", histogram);
            if (histogram.size() == impactSpeedBins_)
            {
                tally.histogram = histogram;
            }
            scalarList slices;
            get("axialContacts", slices);
            if (slices.size() == axialBins_)
            {
                tally.slices = slices;
            }
            get("energy", tally.energy);
        }
        forAll(exchange_, k)
        {
            scalarList slices;
            this->getModelProperty(prefixed("axial", exchangeNames_[k]), slices);
            if (slices.size() == axialBins_)
            {
                exchange_[k] = slices;
            }
        }

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
    riser_(s.riser_),
    interval_(s.interval_),
    radialBins_(s.radialBins_),
    axialBins_(s.axialBins_),
    blockageFraction_(s.blockageFraction_),
    impactSpeedBins_(s.impactSpeedBins_),
    impactSpeedBinWidth_(s.impactSpeedBinWidth_),
    parcels_(s.parcels_),
    started_(s.started_),
    lastSample_(s.lastSample_),
    wall_(s.wall_),
    pair_(s.pair_),
    exchange_(s.exchange_),
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
    // read with the parcels, are not this run's; the parcels read are in
    // their slices, not added
    for (auto& p : this->owner())
    {
        parcels_.set(labelPair(p.origProc(), p.origId()), stateOf(p));
    }
    started_ = true;
}


template<class CloudType>
void Foam::RiserTransportStatistics<CloudType>::postEvolve
(
    RISER_EVOLVE_HOOK_PARAMETER(typename CloudType::parcelType::trackingData)
)
{
    const scalarList volume = followParcels();
    const scalar sliceVolume = riser_.section().volume/axialBins_;
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
    this->setModelProperty("lastSample", lastSample_);
    this->setModelProperty("blockedTime", blockedTime_);
    for (const bool pair : {false, true})
    {
        contactTally& tally = pair ? pair_ : wall_;
        tally.reduceAll();
        const auto set = [&](const word& name, const auto& value)
        {
            this->setModelProperty(propertyName(pair, name), value);
        };
        set("contacts", tally.contacts);
        set("impacts", tally.impacts);
        set("impactSpeedSum", tally.speedSum);
        set("impactSpeedMax", tally.speedMax);
        set("impactHistogram", tally.histogram);
        set("axialContacts", tally.slices);
        set("energy", tally.energy);
        if (!Pstream::master())
        {
            tally.clear();
        }
    }
    forAll(exchange_, k)
    {
        riserCompatibility::listCombineAll(exchange_[k], plusEqOp<scalar>());
        this->setModelProperty(prefixed("axial", exchangeNames_[k]), exchange_[k]);
        if (!Pstream::master())
        {
            exchange_[k] = Zero;
        }
    }
}


// ************************************************************************* //
