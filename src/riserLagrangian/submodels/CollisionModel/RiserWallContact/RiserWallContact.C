/*---------------------------------------------------------------------------*\
  riserFoam: particle transport in vibrating risers, on OpenFOAM
  License: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "RiserWallContact.H"
#include "modelEntries.H"
#include "cloudOutputFile.H"
#include "coreVector.H"
#include "HistoryParcel.H"
#include "granular/nearPairs.hpp"
#include "granular/granularSystem.hpp"
#include "RiserCloud.H"
#include "ListListOps.H"

#include <algorithm>
#include <cmath>

#include <numeric>
#include <vector>

// * * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * //

template<class CloudType>
Foam::autoPtr<riser::HertzMindlin>
Foam::RiserWallContact<CloudType>::readWallLaw() const
{
    if (!modelEntries::wallContactOn(this->coeffDict()))
    {
        return nullptr;
    }
    return autoPtr<riser::HertzMindlin>
    (
        new riser::HertzMindlin
        (
            modelEntries::contactParameters
            (
                this->coeffDict(), this->owner().constProps().dict()
            )
        )
    );
}


template<class CloudType>
Foam::OFstream& Foam::RiserWallContact<CloudType>::contactFile()
{
    if (!contactFile_.valid())
    {
        contactFile_ =
            cloudOutputFile
            (
                this->owner().mesh(), this->owner().name(), typeName, "contacts",
                "# riserWallContact: one completed particle-wall contact a line\n"
                "# velocities relative to the wall [m/s], spin [rad/s], SI units;"
                " J: the wall force's impulse [N s]\n"
                "# origProc origId tStart tEnd duration overlapMax"
                " normalForceMax Uin_x Uin_y Uin_z Uout_x Uout_y Uout_z"
                " omegaIn_x omegaIn_y omegaIn_z omegaOut_x omegaOut_y omegaOut_z"
                " UnIn UnOut J_x J_y J_z\n",
                3   // tEnd: a contact is kept when it ended by the start time
            );
    }
    return contactFile_();
}


template<class CloudType>
Foam::scalar Foam::RiserWallContact<CloudType>::readAddedMassCoeff() const
{
    typedef typename CloudType::kinematicCloudType kinematicCloudType;
    scalar CA = 0;
    for (const auto& force : this->owner().forces())
    {
        if (force.type() == "virtualMass")
        {
            FatalErrorInFunction
                << "particle force virtualMass with collisionModel "
                << typeName << ": the wall contact accelerates m_p + C_A m_f"
                << " with the C_A of riserAddedMass; replace virtualMass by"
                << " riserAddedMass { CA 0.5; }" << exit(FatalError);
        }
        const auto* addedMass =
            dynamic_cast<const RiserAddedMassForce<kinematicCloudType>*>(&force);
        if (addedMass)
        {
            CA = addedMass->CA();
        }
    }
    return CA;
}


template<class CloudType>
Foam::scalar Foam::RiserWallContact<CloudType>::effectiveMass
(
    const parcelType& p
) const
{
    const scalar m = p.mass();
    return m + addedMassCoeff_*m*this->owner().rho()[p.cell()]/p.rho();
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::RiserWallContact<CloudType>::RiserWallContact
(
    const dictionary& dict,
    CloudType& owner
)
:
    CollisionModel<CloudType>(dict, owner, typeName),
    carrier_(carrierFlow::New(owner.U())),
    wallLaw_(readWallLaw()),
    rotation_(this->coeffDict().lookupOrDefault("rotation", Switch(false))),
    stepsPerContact_
    (
        checkedEntry::count(this->coeffDict(), "stepsPerContact", 10, 10000, 40)
    ),
    maxSubCycles_
    (
        checkedEntry::count(this->coeffDict(), "maxSubCycles", 1, 100000000, 100000)
    ),
    aloneMeshFree_
    (
        this->coeffDict().found("aloneAtWall")
     && checkedEntry::choice<bool>
        (
            this->coeffDict(), "aloneAtWall", {{"tracked", false}, {"meshFree", true}}
        )
    ),
    addedMassCoeff_(readAddedMassCoeff()),
    pairOverlapMax_(0),
    section_(riserSection(owner.mesh())),
    cellAxisDistance_
    (
        owner.mesh().changing() ? scalarField() : cellAxisDistances(owner.mesh())
    )
{
    if (this->coeffDict().found("pairs"))
    {
        pairLaw_.reset
        (
            new riser::HertzMindlin
            (
                modelEntries::pairContactParameters
                (
                    this->coeffDict(), this->owner().constProps().dict()
                )
            )
        );
    }

    // the riser must exist: FatalError here rather than at the first step
    carrier_.riser();

    Info<< "    riserWallContact: wall contact ";
    if (wallLaw_.valid())
    {
        Info<< "(normal damping ratio " << wallLaw_->normalDampingRatio()
            << ", particles alone at the wall "
            << (aloneMeshFree_ ? "sub-stepped without the mesh" : "tracked")
            << ")";
    }
    else
    {
        Info<< "off";
    }
    Info<< ", pair contact " << (pairLaw_.valid() ? "on" : "off")
        << ", rotation " << rotation_
        << ", inertia m_p + " << addedMassCoeff_ << " m_f" << endl;
    // the contact table is opened (and, on a restart, continued up to the
    // start time) now, not at the first completed contact: a restart after
    // which no contact ends must not keep the rows after its start
    contactFile();
}


template<class CloudType>
Foam::RiserWallContact<CloudType>::RiserWallContact
(
    const RiserWallContact<CloudType>& cm
)
:
    CollisionModel<CloudType>(cm),
    carrier_(cm.carrier_),
    wallLaw_(cm.wallLaw_.valid() ? new riser::HertzMindlin(cm.wallLaw_()) : nullptr),
    rotation_(cm.rotation_),
    stepsPerContact_(cm.stepsPerContact_),
    maxSubCycles_(cm.maxSubCycles_),
    aloneMeshFree_(cm.aloneMeshFree_),
    addedMassCoeff_(cm.addedMassCoeff_),
    pairLaw_(cm.pairLaw_.valid() ? new riser::HertzMindlin(cm.pairLaw_()) : nullptr),
    needs_(cm.needs_),
    pairOverlapMax_(cm.pairOverlapMax_),
    section_(cm.section_),
    cellAxisDistance_(cm.cellAxisDistance_),
    events_(cm.events_),
    pairEvents_(cm.pairEvents_),
    lost_(cm.lost_)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
Foam::scalarField Foam::RiserWallContact<CloudType>::cellAxisDistances
(
    const polyMesh& mesh
)
{
    const pointField& points = mesh.points();
    const faceList& faces = mesh.faces();
    const labelList& owner = mesh.faceOwner();
    const labelList& neighbour = mesh.faceNeighbour();
    auto axisDistance = [](const point& x)
    {
        return Foam::sqrt(sqr(x.x()) + sqr(x.y()));
    };

    // the centre, then the points of each face of the cell
    scalarField h(mesh.nCells());
    forAll(h, celli)
    {
        h[celli] = axisDistance(mesh.cellCentres()[celli]);
    }
    forAll(faces, facei)
    {
        scalar hf = 0;
        for (const label pointi : faces[facei])
        {
            hf = max(hf, axisDistance(points[pointi]));
        }
        h[owner[facei]] = max(h[owner[facei]], hf);
        if (facei < mesh.nInternalFaces())
        {
            h[neighbour[facei]] = max(h[neighbour[facei]], hf);
        }
    }
    return h;
}


template<class CloudType>
void Foam::RiserWallContact<CloudType>::checkMeshUnchanged() const
{
    const polyMesh& mesh = this->owner().mesh();
    if (mesh.changing() || cellAxisDistance_.size() != mesh.nCells())
    {
        cellAxisDistance_.clear();
    }
}


template<class CloudType>
bool Foam::RiserWallContact<CloudType>::clearOfWall
(
    const parcelType& p,
    const scalar axisOffset,
    const scalar reach
) const
{
    // the particle's distance from the axis is at most its cell's from the
    // z axis plus the axis' offset; the tolerance is far beyond the
    // round-off of the particle's coordinates in its tetrahedron
    const riser::RiserFlow& flow = carrier_.riser();
    return
        cellAxisDistance_.size()
     && flow.radius() - (cellAxisDistance_[p.cell()] + axisOffset) - 0.5*p.d()
      > reach + 1e-6*flow.diameter();
}



template<class CloudType>
Foam::label Foam::RiserWallContact<CloudType>::nearWallSubCycles
(
    const parcelType& p,
    const scalar axisOffset
) const
{
    const Time& time = this->owner().mesh().time();
    const riser::RiserFlow& flow = carrier_.riser();
    const riser::Wall& wall = carrier_.wall();
    const scalar dt = time.deltaTValue();
    const scalar t0 = time.value() - dt;

    if (!(p.d() < flow.diameter()))
    {
        FatalErrorInFunction
            << "particle " << p.origId() << " of diameter " << p.d()
            << " is not smaller than the riser diameter D = "
            << flow.diameter() << " (constant/riserProperties)"
            << exit(FatalError);
    }
    const scalar speed = mag(p.U()) + flow.motion().maxSpeed();
    if (!wallLaw_.valid() || clearOfWall(p, axisOffset, speed*dt))
    {
        return 0;
    }
    const scalar gap = wall.distance(toCore(p.position()), t0) - 0.5*p.d();
    if (p.age() == 0 && gap <= 0)
    {
        // injected in this step (a parcel that moved between processors
        // is older): released touching or overlapping the wall
        FatalErrorInFunction
            << "particle " << p.origId() << " (processor " << p.origProc()
            << ") of diameter " << p.d() << " is released at "
            << p.position() << " at t = " << t0 << " touching or"
            << " overlapping the riser wall: overlap " << -gap
            << " >= 0; release it at least d/2 from the wall"
            << exit(FatalError);
    }
    if (gap > speed*dt)
    {
        return 0;
    }
    const riser::ContactBody body(0.5*p.d(), effectiveMass(p));
    const scalar tc = wallLaw_->contactTime(body, max(speed, SMALL));
    // as a scalar first: no overflow of the label
    const scalar needed = ceil(stepsPerContact_*dt/tc);
    checkNeeded
    (
        needed, labelPair(p.origProc(), p.origId()), p.position(), tc,
        "wall contact"
    );
    return max(label(needed), label(1));
}


template<class CloudType>
void Foam::RiserWallContact<CloudType>::checkNeeded
(
    const scalar needed,
    const labelPair& key,
    const vector& position,
    const scalar tc,
    const string& what
) const
{
    if (!(needed <= maxSubCycles_))
    {
        FatalErrorInFunction
            << "particle " << key.second() << " (processor " << key.first()
            << ") at " << position << " needs " << needed
            << " sub-cycles of the step deltaT = "
            << this->owner().mesh().time().deltaTValue() << " to resolve"
            << " its " << what.c_str() << " (contact time " << tc << " s, "
            << stepsPerContact_ << " sub-cycles each), more than"
            << " maxSubCycles = " << maxSubCycles_ << ": reduce deltaT or"
            << " raise maxSubCycles" << exit(FatalError);
    }
}


template<class CloudType>
template<class PairFunction>
void Foam::RiserWallContact<CloudType>::forEachNearPair
(
    const std::vector<riser::Vector>& x,
    const scalar cutoff,
    const PairFunction& f
) const
{
    riser::NearPairs pairs;
    if (section_.periodic)
    {
        pairs.setPeriodic(section_.z0, section_.length);
    }
    pairs.forEachPair(x, cutoff, f);
}


namespace Foam
{
    //- The lists of all processors joined, in processor order, on every
    //  processor
    template<class T>
    List<T> gatheredFromAll(const UList<T>& local)
    {
        List<List<T>> all(Pstream::nProcs());
        all[Pstream::myProcNo()] = local;
        Pstream::gatherList(all);
        Pstream::scatterList(all);
        return ListListOps::combine<List<T>>(all, accessOp<List<T>>());
    }
}


template<class CloudType>
void Foam::RiserWallContact<CloudType>::checkCloudRunsThis() const
{
    const bool riserCloud =
        dynamic_cast<const RiserCloud<CloudType>*>(&this->owner());
    if (aloneMeshFree_ && !riserCloud)
    {
        FatalIOErrorInFunction(this->coeffDict())
            << "entry 'aloneAtWall' = meshFree with a stock colliding cloud:"
            << " only the riser cloud (riserParcelFoam) sub-steps particles"
            << " without the mesh; remove it or set tracked"
            << exit(FatalIOError);
    }
    if (pairLaw_.valid() && Pstream::parRun() && !riserCloud)
    {
        FatalIOErrorInFunction(this->coeffDict())
            << "entry 'pairs' (particle-particle contact) in a parallel run"
            << " of a stock colliding cloud: across processor boundaries"
            << " pairs are handled by the riser cloud (riserParcelFoam)"
            << " only; run serially or with riserParcelFoam"
            << exit(FatalIOError);
    }
}


template<class CloudType>
void Foam::RiserWallContact<CloudType>::prepareSubCycles() const
{
    checkCloudRunsThis();
    const Time& time = this->owner().mesh().time();
    const scalar dt = time.deltaTValue();
    preparedIndex_ = time.timeIndex();
    checkMeshUnchanged();
    const scalar axisOffset =
        mag(carrier_.riser().motion().axisPosition(time.value() - dt));

    // this processor's particles: key, wall need
    const label nOwn = this->owner().size();
    List<labelPair> ownKeys(nOwn);
    labelList ownNeed(nOwn);
    {
        label i = 0;
        for (const parcelType& p : this->owner())
        {
            ownKeys[i] = labelPair(p.origProc(), p.origId());
            ownNeed[i] = nearWallSubCycles(p, axisOffset);
            ++i;
        }
    }
    needs_.clear();
    if (!pairLaw_.valid())
    {
        forAll(ownKeys, i)
        {
            needs_.set
            (
                ownKeys[i],
                subCycleNeed{ownNeed[i], aloneMeshFree_ && ownNeed[i] > 0}
            );
        }
        return;
    }

    // with pairs: the clusters of the particles of all processors (each
    // processor finds the same), by key order
    List<vector> ownX(nOwn), ownU(nOwn);
    List<scalar> ownD(nOwn), ownM(nOwn);
    labelList ownNew(nOwn);
    {
        label i = 0;
        for (const parcelType& p : this->owner())
        {
            ownX[i] = p.position();
            ownU[i] = p.U();
            ownD[i] = p.d();
            ownM[i] = effectiveMass(p);
            // injected in this step (a parcel that moved between
            // processors is older)
            ownNew[i] = p.age() == 0;
            ++i;
        }
    }
    // (in the same order on every processor: processor by processor)
    const List<labelPair> allKeys = gatheredFromAll(ownKeys);
    const List<vector> allX = gatheredFromAll(ownX), allU = gatheredFromAll(ownU);
    const List<scalar> allD = gatheredFromAll(ownD), allM = gatheredFromAll(ownM);
    const labelList allNeed = gatheredFromAll(ownNeed);
    const labelList allNew = gatheredFromAll(ownNew);
    const std::size_t n = allKeys.size();

    std::vector<riser::Vector> x(n);
    std::vector<label> need(allNeed.begin(), allNeed.end());
    scalar rMax = 0, uMax = 0;
    for (std::size_t i = 0; i < n; ++i)
    {
        x[i] = toCore(allX[i]);
        rMax = max(rMax, 0.5*allD[i]);
        uMax = max(uMax, mag(allU[i]));
    }

    // clusters of particles that may touch within the step: union-find
    std::vector<std::size_t> root(n);
    std::iota(root.begin(), root.end(), std::size_t(0));
    auto find = [&root](std::size_t i)
    {
        while (root[i] != i)
        {
            root[i] = root[root[i]];
            i = root[i];
        }
        return i;
    };
    // within a step a contact can speed a particle up to about twice the
    // fastest particle's speed, so a pair may close by 4 U_max dt: a reach
    // from each pair's own speeds would miss a resting particle struck by
    // a neighbour and left to overlap the next
    const scalar reach = 4*uMax*dt;
    forEachNearPair(x, 2*rMax + reach + SMALL, [&](std::size_t i, std::size_t j, scalar dz)
    {
        const label p = i, q = j;
        const scalar gap =
            (x[j] + riser::Vector(0, 0, dz) - x[i]).norm() - 0.5*(allD[p] + allD[q]);
        if (gap > reach)
        {
            return;
        }
        if (gap <= 0 && (allNew[p] || allNew[q]))
        {
            FatalErrorInFunction
                << "particles " << allKeys[p].second() << " (processor "
                << allKeys[p].first() << ") at " << allX[p] << " and "
                << allKeys[q].second() << " (processor " << allKeys[q].first()
                << ") at " << allX[q] << ", of diameters " << allD[p]
                << " and " << allD[q] << ", are released touching or"
                << " overlapping each other: overlap " << -gap << " >= 0;"
                << " release them at least (d_p + d_q)/2 apart"
                << exit(FatalError);
        }
        // the largest impact speed the pair can reach in the step
        const scalar speed = max(mag(allU[p]) + mag(allU[q]), 2*uMax);
        const riser::ContactBody body =
            riser::pairBody(0.5*allD[p], allM[p], 0.5*allD[q], allM[q]);
        const scalar tc = pairLaw_->contactTime(body, max(speed, SMALL));
        const scalar needed = ceil(stepsPerContact_*dt/tc);
        checkNeeded
        (
            needed, allKeys[p], allX[p], tc,
            "contact with particle " + Foam::name(allKeys[q].second())
          + " (processor " + Foam::name(allKeys[q].first()) + ")"
        );
        const label k = max(label(needed), label(1));
        need[i] = max(need[i], k);
        need[j] = max(need[j], k);
        root[find(i)] = find(j);
    });
    std::vector<label> clusterNeed(n, 0), clusterSize(n, 0);
    for (std::size_t i = 0; i < n; ++i)
    {
        clusterNeed[find(i)] = max(clusterNeed[find(i)], need[i]);
        ++clusterSize[find(i)];
    }
    // (every processor keeps the needs of all: the gathered lists hold them)
    for (std::size_t i = 0; i < n; ++i)
    {
        const label k = find(i);
        needs_.set
        (
            allKeys[i],
            subCycleNeed
            {
                clusterNeed[k],
                clusterSize[k] > 1 || (aloneMeshFree_ && clusterNeed[k] > 0)
            }
        );
    }
}


template<class CloudType>
const typename Foam::RiserWallContact<CloudType>::subCycleNeed&
Foam::RiserWallContact<CloudType>::need(const parcelType& p) const
{
    const auto iter = needs_.cfind(labelPair(p.origProc(), p.origId()));
    if (!iter.found())
    {
        FatalErrorInFunction
            << "particle " << p.origId() << " (processor " << p.origProc()
            << ") was not in the cloud when its need of sub-cycles was"
            << " prepared" << exit(FatalError);
    }
    return *iter;
}


template<class CloudType>
Foam::label Foam::RiserWallContact<CloudType>::subCycles(const parcelType& p) const
{
    return max(need(p).n, label(1));
}


template<class CloudType>
bool Foam::RiserWallContact<CloudType>::meshFree(const parcelType& p) const
{
    return need(p).meshFree;
}


template<class CloudType>
Foam::label Foam::RiserWallContact<CloudType>::nSubCycles() const
{
    // the riser cloud prepared the needs of the step's start (a group of
    // them is moving now); a stock colliding cloud asks here first
    if (preparedIndex_ != this->owner().mesh().time().timeIndex())
    {
        prepareSubCycles();
    }
    label nSub = 1, nNear = 0;
    for (const parcelType& p : this->owner())
    {
        const label n = need(p).n;
        if (n > 0)
        {
            ++nNear;
            nSub = max(nSub, n);
        }
    }
    reduce(nSub, maxOp<label>());
    reduce(nNear, sumOp<label>());

    if (nNear)
    {
        Info<< "    riserWallContact: " << nNear << " particle(s) near "
            << (pairLaw_.valid() ? "a contact" : "the wall") << endl;
    }
    if (pairLaw_.valid())
    {
        Info<< "    riserWallContact: largest pair overlap in this run "
            << returnReduce(pairOverlapMax_, maxOp<scalar>())
            << " of the smaller diameter" << endl;
    }
    return nSub;
}


template<class CloudType>
riser::ContactSide Foam::RiserWallContact<CloudType>::contactSide
(
    const parcelType& p
) const
{
    return riser::ContactSide
    {
        toCore(p.U()),
        rotation_ ? toCore(p.omega()) : riser::Vector::Zero(),
        0.5*p.d()
    };
}


template<class CloudType>
void Foam::RiserWallContact<CloudType>::collidePairs()
{
    const scalar dt = this->owner().mesh().time().deltaTValue();

    std::vector<parcelType*> parcels;
    std::vector<riser::Vector> x;
    parcels.reserve(this->owner().size());
    x.reserve(this->owner().size());
    scalar rMax = 0;
    for (parcelType& p : this->owner())
    {
        parcels.push_back(&p);
        x.push_back(toCore(p.position()));
        rMax = max(rMax, 0.5*p.d());
    }
    if (parcels.size() < 2)
    {
        return;
    }

    forEachNearPair(x, 2*rMax, [&](std::size_t a, std::size_t b, scalar dz)
    {
        // the pair in a fixed order, so that the spring is read in one frame
        const bool aFirst =
            labelPair(parcels[a]->origProc(), parcels[a]->origId())
          < labelPair(parcels[b]->origProc(), parcels[b]->origId());
        parcelType& p = aFirst ? *parcels[a] : *parcels[b];
        parcelType& q = aFirst ? *parcels[b] : *parcels[a];
        // q's image nearest to p
        const riser::Vector image(0, 0, aFirst ? dz : -dz);
        const scalar Rp = 0.5*p.d(), Rq = 0.5*q.d();
        const riser::PairGeometry geo =
            riser::pairGeometry
            (
                toCore(p.position()), Rp, toCore(q.position()) + image, Rq
            );
        if (geo.overlap <= 0)
        {
            return;
        }
        // the spring in p's frame (n from p to q); q keeps its negative
        vector& spring =
            p.collisionRecords().matchPairRecord(q.origProc(), q.origId()).collisionData();
        const scalar mp = effectiveMass(p), mq = effectiveMass(q);
        const riser::ContactStep c =
            riser::stepContact
            (
                *pairLaw_, riser::pairBody(Rp, mp, Rq, mq), geo.overlap, geo.normal,
                contactSide(p), contactSide(q), toCore(spring), dt
            );
        spring = fromCore(c.law.springAfter);
        q.collisionRecords().matchPairRecord(p.origProc(), p.origId()).collisionData() =
            -spring;

        const vector F = fromCore(c.force);
        // each parcel divides f by its m_p: the force on m_p + C_A m_f
        p.f() += (p.mass()/mp)*F;
        q.f() -= (q.mass()/mq)*F;
        if (rotation_)
        {
            p.torque() += fromCore(c.torqueI);
            q.torque() += fromCore(c.torqueJ);
        }
        pairOverlapMax_ = max(pairOverlapMax_, geo.overlap/min(p.d(), q.d()));
    });
}


template<class CloudType>
void Foam::RiserWallContact<CloudType>::checkInside
(
    const labelPair& key,
    const scalar overlap,
    const scalar R,
    const scalar t
)
{
    if (overlap > R && lost_.insert(key))
    {
        WarningInFunction
            << "particle " << key << " has its centre outside the pipe at t = "
            << t << ": " << overlap - R << " beyond the wall; "
            << lost_.size() << " particle(s) lost so far" << endl;
    }
}


template<class CloudType>
typename Foam::RiserWallContact<CloudType>::pairKey
Foam::RiserWallContact<CloudType>::makePairKey
(
    const labelPair& a,
    const labelPair& b
)
{
    const labelPair& lo = a < b ? a : b;
    const labelPair& hi = a < b ? b : a;
    pairKey k;
    k[0] = lo.first();
    k[1] = lo.second();
    k[2] = hi.first();
    k[3] = hi.second();
    return k;
}


template<class CloudType>
riser::PairContactState Foam::RiserWallContact<CloudType>::pairHandOver
(
    const labelPair& a,
    const labelPair& b,
    const vector& spring
) const
{
    riser::PairContactState c;
    c.spring = toCore(spring);
    const auto iter = pairEvents_.cfind(makePairKey(a, b));
    if (iter.found())
    {
        // kept in the lower particle's frame
        c.force = toCore(a < b ? (*iter).force : -(*iter).force);
        c.forceKnown = true;
        c.approachSpeed = (*iter).approachSpeed;
    }
    return c;
}


template<class CloudType>
typename Foam::RiserWallContact<CloudType>::contactEvent&
Foam::RiserWallContact<CloudType>::wallContactGoesOn
(
    const labelPair& key,
    const scalar t,
    const scalar h,
    const scalar overlap,
    const vector& F,
    const scalar normalForce,
    const vector& Urel,
    const vector& n,
    const vector& spin
)
{
    auto iter = events_.find(key);
    if (!iter.found())
    {
        events_.insert
        (
            key,
            contactEvent
            {
                t - h, overlap, normalForce, Urel, Urel & n, spin,
                vector::zero, n, vector::zero, h*F
            }
        );
        return events_[key];
    }
    contactEvent& e = *iter;
    e.overlapMax = max(e.overlapMax, overlap);
    e.normalForceMax = max(e.normalForceMax, normalForce);
    e.impulse += h*F;
    return e;
}


template<class CloudType>
void Foam::RiserWallContact<CloudType>::wallContactEnds
(
    parcelType& p,
    const labelPair& key,
    const scalar t,
    const vector& Uout,
    const vector& n,
    const vector& spin
)
{
    auto iter = events_.find(key);
    if (!iter.found())
    {
        return;
    }
    const contactEvent& e = *iter;
    contactFile()
        << key.first() << ' ' << key.second() << ' '
        << e.start << ' ' << t << ' ' << t - e.start << ' '
        << e.overlapMax << ' ' << e.normalForceMax << ' '
        << e.velocityIn.x() << ' ' << e.velocityIn.y() << ' '
        << e.velocityIn.z() << ' '
        << Uout.x() << ' ' << Uout.y() << ' ' << Uout.z() << ' '
        << e.spinIn.x() << ' ' << e.spinIn.y() << ' ' << e.spinIn.z() << ' '
        << spin.x() << ' ' << spin.y() << ' ' << spin.z() << ' '
        << e.normalSpeedIn << ' ' << -(Uout & n) << ' '
        << e.impulse.x() << ' ' << e.impulse.y() << ' ' << e.impulse.z()
        << endl;
    recordWallContact(p, e.overlapMax, e.normalSpeedIn);
    events_.erase(iter);
}


template<class CloudType>
Foam::contactSteps
Foam::RiserWallContact<CloudType>::meshFreeContacts
(
    const UList<parcelType*>& parcels,
    const UList<linearisedAcceleration>& fluidAcceleration,
    const UList<vector>& startOffset,
    const label nSubNeeded
)
{
    const Time& time = this->owner().mesh().time();
    const riser::Wall& wall = carrier_.wall();
    const scalar dt = time.deltaTValue();
    const scalar t0 = time.value() - dt;
    const label nOwn = parcels.size();
    const bool walls = wallLaw_.valid();

    // this processor's particles at the step's start: state, springs
    // (pair records flattened: owner, other, spring) and contact forces
    List<labelPair> keys(nOwn);
    List<vector> x(nOwn), xStart(nOwn), U(nOwn), omega(nOwn), a(nOwn), Uc(nOwn),
        F(nOwn), T(nOwn), wallSpring(nOwn);
    List<scalar> R(nOwn), mEff(nOwn), mP(nOwn), inertia(nOwn), drag(nOwn);
    labelList touchingWall(nOwn, 0);
    DynamicList<labelPair> recordOwner, recordOther;
    DynamicList<vector> recordSpring;
    forAll(parcels, i)
    {
        const parcelType& p = *parcels[i];
        keys[i] = labelPair(p.origProc(), p.origId());
        x[i] = p.position();
        xStart[i] = x[i] + startOffset[i];
        U[i] = p.U();
        omega[i] = rotation_ ? p.omega() : vector::zero;
        a[i] = fluidAcceleration[i].a0;
        drag[i] = fluidAcceleration[i].rate;
        Uc[i] = fluidAcceleration[i].Uc;
        R[i] = 0.5*p.d();
        mEff[i] = effectiveMass(p);
        mP[i] = p.mass();
        inertia[i] = p.momentOfInertia();
        F[i] = p.f()*(mEff[i]/p.mass());
        T[i] = rotation_ ? p.torque() : vector::zero;
        wallSpring[i] = vector::zero;
        for (const auto& record : p.collisionRecords().wallRecords())
        {
            wallSpring[i] = record.collisionData();
            touchingWall[i] = 1;
        }
        for (const auto& record : p.collisionRecords().pairRecords())
        {
            recordOwner.append(keys[i]);
            recordOther.append
            (
                labelPair(record.origProcOfOther(), record.origIdOfOther())
            );
            recordSpring.append(record.collisionData());
        }
    }

    // the clusters of this group on all processors: every processor steps
    // all of them and keeps what is its own. They enter the engine in the
    // order of their positions (by z, then x, then y), which does not
    // depend on the decomposition (their keys do: each processor numbers
    // the particles it injects), so that the contact forces are summed in
    // the same order in a serial and a parallel run.
    const List<labelPair> allKeys = gatheredFromAll(keys);
    const List<vector> allX = gatheredFromAll(x), allU = gatheredFromAll(U);
    const List<vector> allXStart = gatheredFromAll(xStart);
    std::vector<label> order(allX.size());
    std::iota(order.begin(), order.end(), label(0));
    std::sort
    (
        order.begin(), order.end(),
        [&allX](label a, label b)
        {
            const vector& p = allX[a];
            const vector& q = allX[b];
            return
                p.z() < q.z()
             || (p.z() == q.z() && (p.x() < q.x() || (p.x() == q.x() && p.y() < q.y())));
        }
    );
    const List<vector> allOmega = gatheredFromAll(omega), allA = gatheredFromAll(a);
    const List<vector> allUc = gatheredFromAll(Uc);
    const List<scalar> allDrag = gatheredFromAll(drag);
    const List<vector> allF = gatheredFromAll(F), allT = gatheredFromAll(T);
    const List<vector> allWallSpring = gatheredFromAll(wallSpring);
    const List<scalar> allR = gatheredFromAll(R), allM = gatheredFromAll(mEff);
    const List<scalar> allInertia = gatheredFromAll(inertia);
    const List<scalar> allMp = gatheredFromAll(mP);
    const labelList allTouchingWall = gatheredFromAll(touchingWall);
    const List<labelPair> allRecordOwner = gatheredFromAll(recordOwner);
    const List<labelPair> allRecordOther = gatheredFromAll(recordOther);
    const List<vector> allRecordSpring = gatheredFromAll(recordSpring);
    const std::size_t n = order.size();

    auto optionalLaw = [](const autoPtr<riser::HertzMindlin>& law)
    {
        return
            law.valid()
          ? std::optional<riser::HertzMindlin>(law())
          : std::optional<riser::HertzMindlin>();
    };
    riser::GranularSystem grains
    (
        optionalLaw(pairLaw_), optionalLaw(wallLaw_), riser::Vector::Zero(),
        rotation_
    );
    if (walls)
    {
        grains.addWall(wall);
    }
    if (section_.periodic)
    {
        grains.setPeriodic(section_.z0, section_.length);
    }
    grains.setTime(t0);
    // the same grains without contacts: their free motion under the fluid
    // acceleration, integrated alike (a grain that touches nothing moves
    // exactly as its free one)
    riser::GranularSystem free(std::nullopt, std::nullopt, riser::Vector::Zero(), rotation_);
    // the explicit drag of the sub-steps stays stable: drag h <= 1 (the same
    // on every processor: the gathered rates)
    label nSub = max(nSubNeeded, label(1));
    for (const scalar rate : allDrag)
    {
        nSub = max(nSub, label(ceil(rate*dt)));
    }
    const scalar h = dt/nSub;
    HashTable<label, labelPair, labelPair::Hash<>> grainOf(2*n);
    std::vector<riser::Vector> grainF(n), grainT(n);
    for (std::size_t i = 0; i < n; ++i)
    {
        const label k = order[i];
        grainOf.insert(allKeys[k], label(i));
        riser::Grain g
        {
            toCore(allXStart[k]), toCore(allU[k]), toCore(allOmega[k]), allR[k], allM[k]
        };
        g.accel = toCore(allA[k]);
        g.drag = allDrag[k];
        g.carrierVelocity = toCore(allUc[k]);
        g.inertia = allInertia[k];
        grains.addGrain(g);
        free.addGrain(g);
        grainF[i] = toCore(allF[k]);
        grainT[i] = toCore(allT[k]);
    }
    for (std::size_t i = 0; i < n; ++i)
    {
        if (walls && allTouchingWall[order[i]])
        {
            // with the force of its last evaluation, when this processor
            // kept it (its own particles: for their dissipation tally)
            const label k = order[i];
            const auto e = events_.cfind(allKeys[k]);
            if (e.found())
            {
                grains.setWallContact
                (
                    i, 0, toCore(allWallSpring[k]), toCore((*e).force)
                );
            }
            else
            {
                grains.setWallSpring(i, 0, toCore(allWallSpring[k]));
            }
        }
    }
    forAll(allRecordOwner, r)
    {
        // each pair once, from the record of the particle first in order
        // (the spring in its frame), with what pairEvents_ kept of it
        const auto i = grainOf.cfind(allRecordOwner[r]);
        const auto j = grainOf.cfind(allRecordOther[r]);
        if (i.found() && j.found() && *i < *j)
        {
            grains.setPairContact
            (
                *i, *j,
                pairHandOver
                (
                    allRecordOwner[r], allRecordOther[r], allRecordSpring[r]
                )
            );
        }
    }
    grains.setContactForces(grainF, grainT);

    // this processor's particles among the grains; their wall contacts in
    // progress, as collide() keeps them
    std::vector<label> ownGrain(nOwn);
    std::vector<bool> inContact(nOwn);
    forAll(parcels, i)
    {
        ownGrain[i] = grainOf[keys[i]];
        inContact[i] = events_.found(keys[i]);
    }

    for (label k = 1; k <= nSub; ++k)
    {
        grains.step(h);
        free.step(h);
        const scalar t = t0 + k*h;
        pairOverlapMax_ = max(pairOverlapMax_, grains.largestPairOverlap());
        forAll(parcels, i)
        {
            if (!walls)
            {
                break;
            }
            const riser::WallContactState& c = grains.wallContact(ownGrain[i], 0);
            if (!c.touching && !inContact[i])
            {
                continue;
            }
            const riser::Grain& g = grains.grains()[ownGrain[i]];
            const riser::ContactPoint cp = wall.contactPoint(g.x, g.radius, t);
            const vector nw = fromCore(cp.normal);
            // (the velocity the force was evaluated with, as a tracked
            // particle's collide() sees it: the half-step one)
            const vector Urel = fromCore(c.velocity);
            const vector spin = fromCore(g.omega);
            if (c.touching)
            {
                checkInside(keys[i], c.overlap, g.radius, t);
                wallContactGoesOn
                (
                    keys[i], t, h, c.overlap, fromCore(c.force), c.normalForce,
                    Urel, nw, spin
                );
                inContact[i] = true;
            }
            else
            {
                wallContactEnds(*parcels[i], keys[i], t, Urel, nw, spin);
                inContact[i] = false;
            }
        }
    }

    // The contact trace of the flow step (contactTrace.H): each grain's
    // dissipation in wall and pair contacts, and its completed pair
    // contacts, to its parcel; and what the next flow step is handed of the
    // contacts in progress: the walls' last forces (in events_), the pairs'
    // approach speeds and last forces (pairEvents_, renewed for the pairs
    // of these particles)
    {
        forAll(parcels, i)
        {
            const label gi = ownGrain[i];
            addWallEnergy(*parcels[i], grains.wallEnergy(gi));
            recordPairContacts
            (
                *parcels[i], label(grains.pairContactsCompleted(gi)),
                grains.pairImpactSpeed(gi), grains.pairEnergy(gi)
            );
            if (!walls)
            {
                continue;
            }
            const riser::WallContactState& c = grains.wallContact(gi, 0);
            auto e = events_.find(keys[i]);
            if (c.touching && e.found())
            {
                (*e).force = fromCore(c.force);
                (*e).normal = fromCore(c.normal);
                (*e).wallVelocity = fromCore(c.wallVelocity);
            }
        }
        DynamicList<pairKey> ended;
        forAllConstIters(pairEvents_, iter)
        {
            const pairKey& k = iter.key();
            if
            (
                grainOf.found(labelPair(k[0], k[1]))
             || grainOf.found(labelPair(k[2], k[3]))
            )
            {
                ended.append(k);
            }
        }
        for (const pairKey& k : ended)
        {
            pairEvents_.erase(k);
        }
        grains.forEachPairContactState
        (
            [&](std::size_t i, std::size_t j, const riser::PairContactState& c)
            {
                // in the frame of the lower (origProc, origId); every
                // processor keeps the pairs of all (it steps them all)
                const labelPair& ki = allKeys[order[i]];
                const labelPair& kj = allKeys[order[j]];
                const bool iLower = ki < kj;
                pairEvents_.set
                (
                    makePairKey(ki, kj),
                    pairContactEvent
                    {
                        c.approachSpeed,
                        fromCore(iLower ? c.force : riser::Vector(-c.force))
                    }
                );
            }
        );
    }


    // what the contacts added to the free motion of every particle of the
    // group (a particle may change processor in its move through the mesh),
    // and the state handed back to this processor's particles
    contactSteps result(2*n);
    for (std::size_t i = 0; i < n; ++i)
    {
        const label k = order[i];
        const riser::Grain& g = grains.grains()[i];
        const riser::Grain& gFree = free.grains()[i];
        contactStep c;
        // the track from the particle's position, x + U dt, is given what
        // puts it where the engine left it (up to the track's own share of
        // the fluid's a dt^2/2: above); the velocity gets the contacts'
        // change on top of the fluid forces' own
        c.x = fromCore(g.x);
        c.dx = c.x - allX[k] - dt*allU[k];
        c.dU = fromCore(riser::Vector(g.v - gFree.v));
        c.dL = allInertia[k]*fromCore(riser::Vector(g.omega - gFree.omega));
        c.f = (allMp[k]/allM[k])*fromCore(grains.contactForce(i));
        c.torque = rotation_ ? fromCore(grains.contactTorque(i)) : vector::zero;
        result.insert(allKeys[k], c);
    }
    HashTable<parcelType*, labelPair, labelPair::Hash<>> ownParcel(2*nOwn);
    forAll(parcels, i)
    {
        parcelType& p = *parcels[i];
        ownParcel.insert(keys[i], &p);
        const label gi = ownGrain[i];
        const riser::Grain& g = grains.grains()[gi];
        p.collisionRecords() =
            typename std::decay<decltype(p.collisionRecords())>::type();
        if (walls && grains.wallContact(gi, 0).touching)
        {
            const riser::ContactPoint cp =
                wall.contactPoint(g.x, g.radius, time.value());
            p.collisionRecords().matchWallRecord
            (
                0.99*g.radius*fromCore(cp.normal), g.radius
            ).collisionData() = fromCore(grains.wallSpring(gi, 0));
        }
    }
    label acrossProcessors = 0;
    grains.forEachPairContact
    (
        [&](std::size_t i, std::size_t j, const riser::Vector& spring)
        {
            const labelPair& ki = allKeys[order[i]];
            const labelPair& kj = allKeys[order[j]];
            const auto p = ownParcel.cfind(ki);
            if (p.found())
            {
                (*p)->collisionRecords().matchPairRecord(kj.first(), kj.second())
                    .collisionData() = fromCore(spring);
            }
            const auto q = ownParcel.cfind(kj);
            if (q.found())
            {
                (*q)->collisionRecords().matchPairRecord(ki.first(), ki.second())
                    .collisionData() = -fromCore(spring);
            }
            acrossProcessors += (p.found() != q.found());
        }
    );
    if (Pstream::parRun())
    {
        // (each such pair is counted by both of its processors)
        Info<< "    riserWallContact: " << grains.pairContacts()
            << " pair(s) in contact, "
            << returnReduce(acrossProcessors, sumOp<label>())/2
            << " across processor boundaries" << endl;
    }
    for (parcelType* p : parcels)
    {
        // as after collide(): kept, marked not accessed
        p->collisionRecords().update();
    }
    return result;
}


template<class CloudType>
void Foam::RiserWallContact<CloudType>::collide()
{
    const Time& time = this->owner().mesh().time();
    const riser::Wall& wall = carrier_.wall();
    const scalar t = time.value();
    const scalar dt = time.deltaTValue();
    checkMeshUnchanged();
    const scalar axisOffset = mag(carrier_.riser().motion().axisPosition(t));

    for (parcelType& p : this->owner())
    {
        // no wall contact, or certainly apart from the wall and in no wall
        // contact that might end now: no wall force, nothing to record
        if
        (
            !wallLaw_.valid()
         || (
                clearOfWall(p, axisOffset, 0)
             && (events_.empty() || !events_.found(labelPair(p.origProc(), p.origId())))
            )
        )
        {
            p.f() = Zero;
            p.torque() = Zero;
            continue;
        }

        // the contact force the previous sub-cycle left, on the effective
        // inertia (the start of this sub-cycle's dissipation trapezoid)
        const scalar mEff = effectiveMass(p);
        const vector Fprev = (mEff/p.mass())*p.f();
        p.f() = Zero;
        p.torque() = Zero;

        const scalar Rp = 0.5*p.d();
        const riser::ContactPoint cp = wall.contactPoint(toCore(p.position()), Rp, t);
        const vector Uwall = fromCore(cp.velocity);
        const labelPair key(p.origProc(), p.origId());

        checkInside(key, cp.overlap, Rp, t);

        const vector spin = rotation_ ? p.omega() : vector::zero;
        const scalar overlap = cp.overlap;
        const vector n = fromCore(cp.normal);

        // F_prev's part of the trapezoid, with its own evaluation's normal
        // and wall velocity (those of now for a contact in progress at a
        // restart: events_ is not stored)
        const auto event = events_.cfind(key);
        const vector nPrev = event.found() ? (*event).normal : n;
        const vector UwallPrev = event.found() ? (*event).wallVelocity : Uwall;
        const scalar workBefore =
            Fprev
          & fromCore
            (
                riser::contactVelocity
                (
                    contactSide(p), riser::wallSide(toCore(UwallPrev)), toCore(nPrev)
                )
            );

        if (overlap <= 0)
        {
            addWallEnergy(p, -0.5*dt*workBefore);
            wallContactEnds(p, key, t, p.U() - Uwall, n, spin);
            // no record accessed: update() below drops the tangential spring
            continue;
        }

        // the tangential spring, kept in the current tangent plane
        vector& spring =
            p.collisionRecords().matchWallRecord(0.99*Rp*n, Rp).collisionData();
        const riser::ContactStep c =
            riser::stepContact
            (
                *wallLaw_, riser::ContactBody(Rp, mEff), overlap, toCore(n),
                contactSide(p), riser::wallSide(cp.velocity), toCore(spring), dt
            );
        spring = fromCore(c.law.springAfter);

        const vector F = fromCore(c.force);
        // the parcel divides f by m_p: the force on m_p + C_A m_f
        p.f() = (p.mass()/mEff)*F;
        if (rotation_)
        {
            p.torque() = fromCore(c.torqueI);
        }

        addWallEnergy(p, -0.5*dt*(workBefore + c.power));
        contactEvent& e =
            wallContactGoesOn
            (
                key, t, dt, overlap, F, mag(fromCore(c.law.normal)), p.U() - Uwall, n, spin
            );
        e.force = F;
        e.normal = n;
        e.wallVelocity = Uwall;
    }

    // (in the riser cloud the particles moved here are alone: those that
    // may touch each other are sub-stepped without the mesh)
    if (pairLaw_.valid() && !dynamic_cast<const RiserCloud<CloudType>*>(&this->owner()))
    {
        collidePairs();
    }
    // drop the springs of the contacts that were not touched (ended)
    for (parcelType& p : this->owner())
    {
        p.collisionRecords().update();
    }
}


// ************************************************************************* //
