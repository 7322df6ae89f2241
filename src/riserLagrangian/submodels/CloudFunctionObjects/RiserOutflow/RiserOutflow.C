/*---------------------------------------------------------------------------*\
  riserFoam: particle transport in vibrating risers, on OpenFOAM
  License: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "RiserOutflow.H"
#include "cloudOutputFile.H"
#include "checkedEntry.H"
#include "coreVector.H"
#include "HashSet.H"
#include "output/transportStatistics.hpp"
#include "wallPolyPatch.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class CloudType>
bool Foam::RiserOutflow<CloudType>::mayLeaveThrough(const polyPatch& pp)
{
    return !polyPatch::constraintType(pp.type());
}


template<class CloudType>
bool Foam::RiserOutflow<CloudType>::open(const polyPatch& pp)
{
    return mayLeaveThrough(pp) && !isA<wallPolyPatch>(pp);
}


template<class CloudType>
Foam::label Foam::RiserOutflow<CloudType>::injected() const
{
    label n = 0;
    for (const auto& injector : this->owner().injectors())
    {
        n += injector.parcelsAddedTotal();
    }
    return n;
}


template<class CloudType>
void Foam::RiserOutflow<CloudType>::noteArrival
(
    const typename CloudType::parcelType& p,
    const point&
)
{
    if (!p.onBoundaryFace())
    {
        return;
    }
    const polyBoundaryMesh& patches = p.mesh().boundaryMesh();
    const label patchi = patches.whichPatch(p.face());
    if (!mayLeaveThrough(patches[patchi]))
    {
        return;
    }
    const Time& time = p.mesh().time();
    const scalar t =
        time.value() - (1 - p.stepFraction())*time.deltaTValue();
    const riser::Vector Ur =
        riser_.flow().motion().relativeVelocity
        (
            toCore(p.position()), toCore(p.U()), t
        );
    arrivals_.append
    (
        arrival
        {
            labelPair(p.origProc(), p.origId()), patchi, t, p.d(),
            p.nParticle(), p.age(), Ur.z()
        }
    );
}


template<class CloudType>
Foam::label Foam::RiserOutflow<CloudType>::writeDepartures()
{
    // this processor's arrivals, the last of each parcel
    HashTable<arrival, labelPair, labelPairHash> last(2*arrivals_.size() + 1);
    for (const arrival& a : arrivals_)
    {
        last.set(a.key, a);
    }
    arrivals_.clear();

    List<labelPairList> keys(Pstream::nProcs());
    keys[Pstream::myProcNo()] = last.sortedToc();
    riserCompatibility::allGatherList(keys);
    label total = 0;
    for (const labelPairList& list : keys)
    {
        total += list.size();
    }
    if (total == 0)
    {
        return 0;
    }

    // which of them some processor's cloud still holds
    HashSet<labelPair, labelPairHash> held(2*this->owner().size() + 1);
    for (const auto& p : this->owner())
    {
        held.insert(labelPair(p.origProc(), p.origId()));
    }
    labelList kept(total, 0);
    label i = 0;
    for (const labelPairList& list : keys)
    {
        for (const labelPair& key : list)
        {
            kept[i++] = held.found(key);
        }
    }
    riserCompatibility::listCombineAll(kept, maxEqOp<label>());

    label start = 0;
    for (label proc = 0; proc < Pstream::myProcNo(); ++proc)
    {
        start += keys[proc].size();
    }
    const polyBoundaryMesh& patches = this->owner().mesh().boundaryMesh();
    const labelPairList& mine = keys[Pstream::myProcNo()];
    label departed = 0;
    forAll(mine, j)
    {
        if (kept[start + j])
        {
            continue;
        }
        const arrival& a = last[mine[j]];
        file_() << a.t << ' ' << patches[a.patch].name().c_str() << ' '
            << a.key.first() << ' ' << a.key.second() << ' ' << a.d << ' '
            << a.nParticle << ' ' << a.transitTime << ' ' << a.Urz << nl;
        left_[a.patch] += 1;
        transitSum_[a.patch] += a.transitTime;
        ++departed;
    }
    file_().flush();
    return returnReduce(departed, sumOp<label>());
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::RiserOutflow<CloudType>::RiserOutflow
(
    const dictionary& dict,
    CloudType& owner,
    const word& modelName
)
:
    CloudFunctionObject<CloudType>(dict, owner, modelName, typeName),
    riser_(riserModel::ofCloud(owner)),
    left_(owner.mesh().boundaryMesh().size(), Zero),
    transitSum_(owner.mesh().boundaryMesh().size(), Zero)
{
    checkedEntry::allowedKeys(this->coeffDict(), {"type"});
    riser_.flow();   // FatalError now if there is no riser
    bool anyOpen = false;
    for (const polyPatch& pp : owner.mesh().boundaryMesh())
    {
        anyOpen = anyOpen || open(pp);
    }
    if (!anyOpen)
    {
        FatalIOErrorInFunction(dict)
            << "riserOutflow in the cloud " << owner.name() << ": the mesh"
            << " has no open patch (one neither a wall nor a constraint such"
            << " as cyclic) for ores to leave through: a periodic or closed"
            << " riser has no outflow. Give it open ends (riserMesh -ends"
            << " wall, the outlet of type patch)" << exit(FatalIOError);
    }
    file_ = cloudOutputFile
    (
        owner.mesh(), owner.name(), typeName, "outflow",
        riser::statisticsHeader
        (
            "riserOutflow: the parcels that left the mesh through a"
            " patch; SI units, Urz relative to the riser",
            {"t", "patch", "origProc", "origId", "d", "nParticle",
             "transitTime", "Urz"}
        ),
        0
    );
}


template<class CloudType>
Foam::RiserOutflow<CloudType>::RiserOutflow(const RiserOutflow<CloudType>& o)
:
    CloudFunctionObject<CloudType>(o),
    riser_(o.riser_),
    arrivals_(o.arrivals_),
    lastParcels_(o.lastParcels_),
    lastInjected_(o.lastInjected_),
    left_(o.left_),
    transitSum_(o.transitSum_),
    file_(nullptr)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
void Foam::RiserOutflow<CloudType>::postEvolve
(
    RISER_EVOLVE_HOOK_PARAMETER(typename CloudType::parcelType::trackingData)
)
{
    const CloudType& cloud = this->owner();
    const label departed = writeDepartures();
    const label parcels = returnReduce(cloud.size(), sumOp<label>());
    const label added = injected();
    if (lastParcels_ >= 0)
    {
        const label expected = lastParcels_ + (added - lastInjected_) - departed;
        if (parcels != expected)
        {
            WarningInFunction
                << "riserOutflow: the cloud " << cloud.name() << " holds "
                << parcels << " parcels at t = " << cloud.time().value()
                << " s where " << expected << " were expected ("
                << lastParcels_ << " at the previous step, "
                << added - lastInjected_ << " injected, " << departed
                << " left through patches): " << expected - parcels
                << " removed otherwise (lost in tracking)" << endl;
        }
    }
    lastParcels_ = parcels;
    lastInjected_ = added;
    CloudFunctionObject<CloudType>::postEvolve(RISER_EVOLVE_HOOK_ARGUMENT);
}


template<class CloudType>
void Foam::RiserOutflow<CloudType>::write()
{
    labelList left(left_);
    scalarList transitSum(transitSum_);
    riserCompatibility::listCombineAll(left, plusEqOp<label>());
    riserCompatibility::listCombineAll(transitSum, plusEqOp<scalar>());
    const polyBoundaryMesh& patches = this->owner().mesh().boundaryMesh();
    forAll(patches, patchi)
    {
        if (open(patches[patchi]) || left[patchi] > 0)
        {
            Info<< "riserOutflow: " << left[patchi] << " parcels left "
                << this->owner().name() << " through " << patches[patchi].name()
                << " since the run started";
            if (left[patchi] > 0)
            {
                Info<< ", mean transit time "
                    << transitSum[patchi]/left[patchi] << " s";
            }
            Info<< endl;
        }
    }
}


// ************************************************************************* //
