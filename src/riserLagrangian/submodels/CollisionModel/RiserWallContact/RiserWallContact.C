/*---------------------------------------------------------------------------*\
  riserFoam: particle transport in vibrating risers, on OpenFOAM
  License: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "RiserWallContact.H"
#include "modelEntries.H"
#include "coreVector.H"
#include "HistoryParcel.H"
#include "granular/nearPairs.hpp"
#include "granular/granularSystem.hpp"
#include "granular/clusterPlan.hpp"
#include "RiserCloud.H"
#include "UIPstream.H"
#include "UOPstream.H"

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
    carrier_(carrierFlow::ofCloud(owner)),
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
    section_(riserSection(owner.mesh())),
    cellAxisDistance_
    (
        owner.mesh().changing() ? scalarField() : cellAxisDistances(owner.mesh())
    ),
    ledger_(owner.mesh(), owner.name(), typeName)
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
    section_(cm.section_),
    cellAxisDistance_(cm.cellAxisDistance_),
    ledger_(cm.ledger_)
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


template<class CloudType>
Foam::scalar Foam::RiserWallContact<CloudType>::pairGap
(
    const riser::Vector& xa,
    const labelPair& ka,
    const scalar Ra,
    const riser::Vector& xb,
    const labelPair& kb,
    const scalar Rb
) const
{
    return
        riser::nearestImage
        (
            ka < kb ? riser::Vector(xb - xa) : riser::Vector(xa - xb),
            section_.periodic ? section_.length : 0
        ).norm()
      - (Ra + Rb);
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

    // with pairs: the clusters. Each processor finds the pairs of its own
    // particles, with copies of the other processors' particles near its
    // own (ghosts: nearProcessors), and the clusters' needs (each
    // cluster's largest) spread across the processors by exchanging the
    // needs of the particles each holds as another's ghosts until none
    // grows
    List<vector> ownX(nOwn);
    // per particle: position (3), key (2), U (3), d, m_eff, need,
    // injected now (sent to the other processors as one row of numbers)
    const label nData = 12;
    List<scalar> ownData(nData*nOwn);
    scalar rMax = 0, uMax = 0;
    {
        label i = 0;
        for (const parcelType& p : this->owner())
        {
            ownX[i] = p.position();
            scalar* d = &ownData[nData*i];
            d[0] = ownX[i].x();
            d[1] = ownX[i].y();
            d[2] = ownX[i].z();
            d[3] = p.origProc();
            d[4] = p.origId();
            d[5] = p.U().x();
            d[6] = p.U().y();
            d[7] = p.U().z();
            d[8] = p.d();
            d[9] = effectiveMass(p);
            d[10] = ownNeed[i];
            // injected in this step (a parcel that moved between
            // processors is older)
            d[11] = p.age() == 0;
            rMax = max(rMax, 0.5*p.d());
            uMax = max(uMax, mag(p.U()));
            ++i;
        }
    }
    reduce(rMax, maxOp<scalar>());
    reduce(uMax, maxOp<scalar>());
    // within a step a contact can speed a particle up to about twice the
    // fastest particle's speed, so a pair may close by 4 U_max dt: a reach
    // from each pair's own speeds would miss a resting particle struck by
    // a neighbour and left to overlap the next
    const scalar reach = 4*uMax*dt;
    reach_ = reach;
    radiusMax_ = rMax;
    const scalar cutoff = 2*rMax + reach + SMALL;

    // this processor's particles (0 .. nOwn - 1), then the ghosts
    const labelListList send =
        nearProcessors(ownX, cutoff, section_.periodic ? section_.length : 0);
    List<List<scalar>> ghostData;
    {
        labelListList sendRows(send.size());
        forAll(send, proc)
        {
            sendRows[proc].setSize(nData*send[proc].size());
            forAll(send[proc], k)
            {
                for (label c = 0; c < nData; ++c)
                {
                    sendRows[proc][nData*k + c] = nData*send[proc][k] + c;
                }
            }
        }
        ghostData = exchanged(sendRows, ownData);
    }
    DynamicList<labelPair> keys(nOwn);
    DynamicList<vector> X(nOwn), U(nOwn);
    DynamicList<scalar> D(nOwn), M(nOwn);
    DynamicList<label> need(nOwn), injected(nOwn);
    auto add = [&](const scalar* d)
    {
        X.append(vector(d[0], d[1], d[2]));
        keys.append(labelPair(label(d[3]), label(d[4])));
        U.append(vector(d[5], d[6], d[7]));
        D.append(d[8]);
        M.append(d[9]);
        need.append(label(d[10]));
        injected.append(label(d[11]));
    };
    for (label i = 0; i < nOwn; ++i)
    {
        add(&ownData[nData*i]);
    }
    // (the ghosts of each processor in its order)
    labelListList ghostIndex(ghostData.size());
    forAll(ghostData, proc)
    {
        ghostIndex[proc].setSize(ghostData[proc].size()/nData);
        forAll(ghostIndex[proc], k)
        {
            ghostIndex[proc][k] = X.size();
            add(&ghostData[proc][nData*k]);
        }
    }
    const std::size_t n = X.size();
    std::vector<riser::Vector> x(n);
    for (std::size_t i = 0; i < n; ++i)
    {
        x[i] = toCore(X[i]);
    }

    // clusters of particles that may touch within the step, each with its
    // largest need (the core's planner)
    riser::ClusterPlan plan(std::vector<long>(need.begin(), need.end()));
    forEachNearPair(x, cutoff, [&](std::size_t i, std::size_t j, scalar)
    {
        const label p = i, q = j;
        const scalar gap = pairGap(x[p], keys[p], 0.5*D[p], x[q], keys[q], 0.5*D[q]);
        if (gap > reach)
        {
            return;
        }
        if (gap <= 0 && (injected[p] || injected[q]))
        {
            FatalErrorInFunction
                << "particles " << keys[p].second() << " (processor "
                << keys[p].first() << ") at " << X[p] << " and "
                << keys[q].second() << " (processor " << keys[q].first()
                << ") at " << X[q] << ", of diameters " << D[p]
                << " and " << D[q] << ", are released touching or"
                << " overlapping each other: overlap " << -gap << " >= 0;"
                << " release them at least (d_p + d_q)/2 apart"
                << exit(FatalError);
        }
        // the largest impact speed the pair can reach in the step
        const scalar speed = max(mag(U[p]) + mag(U[q]), 2*uMax);
        const riser::ContactBody body = riser::pairBody(0.5*D[p], M[p], 0.5*D[q], M[q]);
        const scalar tc = pairLaw_->contactTime(body, max(speed, SMALL));
        const scalar needed = ceil(stepsPerContact_*dt/tc);
        checkNeeded
        (
            needed, keys[p], X[p], tc,
            "contact with particle " + Foam::name(keys[q].second())
          + " (processor " + Foam::name(keys[q].first()) + ")"
        );
        plan.join(i, j, max(label(needed), label(1)));
    });

    // each cluster's largest need, spread across the processors: each
    // processor raises the ghosts to the needs their own processors found,
    // until no need grows anywhere
    for (bool grown = true; grown; )
    {
        grown = plan.spread(nOwn);
        List<label> ownNeeds(nOwn);
        forAll(ownNeeds, i)
        {
            ownNeeds[i] = plan.need(i);
        }
        const List<List<label>> ghostNeed = exchanged(send, ownNeeds);
        forAll(ghostNeed, proc)
        {
            forAll(ghostNeed[proc], k)
            {
                grown = plan.raise(ghostIndex[proc][k], ghostNeed[proc][k]) || grown;
            }
        }
        reduce(grown, orOp<bool>());
    }
    for (label i = 0; i < nOwn; ++i)
    {
        needs_.set
        (
            keys[i],
            subCycleNeed
            {
                label(plan.need(i)),
                plan.clustered(i) || (aloneMeshFree_ && plan.need(i) > 0)
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
            << returnReduce(ledger_.pairOverlapMax(), maxOp<scalar>())
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
        ledger_.pairOverlap(geo.overlap/min(p.d(), q.d()));
    });
}


template<class CloudType>
riser::PairContactState Foam::RiserWallContact<CloudType>::pairHandOver
(
    const grainPairSpring& s
)
{
    riser::PairContactState c;
    c.spring = toCore(s.spring);
    if (s.recorded)
    {
        c.force = toCore(s.force);
        c.forceKnown = true;
        c.approachSpeed = s.approachSpeed;
    }
    return c;
}


template<class CloudType>
Foam::wallContactRecord* Foam::RiserWallContact<CloudType>::wallRecord
(
    parcelType& p,
    const bool start
)
{
    if (contactsInProgress* carried = carriedContacts(p))
    {
        return carried->wall.active || start ? &carried->wall : nullptr;
    }
    return ledger_.stockRecord(labelPair(p.origProc(), p.origId()), start);
}


template<class CloudType>
void Foam::RiserWallContact<CloudType>::wallContactEnds
(
    parcelType& p,
    contactTrace& trace,
    const scalar t,
    const vector& Uout,
    const vector& n,
    const vector& spin
)
{
    const wallContactRecord* record = wallRecord(p);
    if (!record)
    {
        return;
    }
    const labelPair key(p.origProc(), p.origId());
    ledger_.wallContactEnds(key, *record, trace, t, Uout, n, spin);
    if (contactsInProgress* carried = carriedContacts(p))
    {
        carried->wall = wallContactRecord();
    }
    else
    {
        ledger_.dropStockRecord(key);
    }
}


template<class CloudType>
void Foam::RiserWallContact<CloudType>::grainStates
(
    const UList<parcelType*>& parcels,
    const UList<linearisedAcceleration>& fluidAcceleration,
    const UList<vector>& startOffset,
    List<grainState>& grains,
    List<grainPairSpring>& springs
) const
{
    grains.setSize(parcels.size());
    DynamicList<grainPairSpring> pairSprings;
    forAll(parcels, i)
    {
        const parcelType& p = *parcels[i];
        grainState& m = grains[i];
        m = grainState();
        m.key = labelPair(p.origProc(), p.origId());
        m.processor = Pstream::myProcNo();
        m.x = p.position();
        m.xStart = m.x + startOffset[i];
        m.U = p.U();
        m.omega = rotation_ ? p.omega() : vector::zero;
        m.a = fluidAcceleration[i].a0;
        m.drag = fluidAcceleration[i].rate;
        m.Uc = fluidAcceleration[i].Uc;
        m.R = 0.5*p.d();
        m.mEff = effectiveMass(p);
        m.mP = p.mass();
        m.inertia = p.momentOfInertia();
        m.F = p.f()*(m.mEff/p.mass());
        m.T = rotation_ ? p.torque() : vector::zero;
        for (const auto& record : p.collisionRecords().wallRecords())
        {
            m.wallSpring = record.collisionData();
            m.touchingWall = true;
        }
        const contactsInProgress* carried = carriedContacts(*parcels[i]);
        for (const auto& record : p.collisionRecords().pairRecords())
        {
            grainPairSpring s;
            s.key = m.key;
            s.other = labelPair(record.origProcOfOther(), record.origIdOfOther());
            s.spring = record.collisionData();
            if (carried)
            {
                for (const pairContactRecord& r : carried->pairs)
                {
                    if (r.other == s.other)
                    {
                        s.recorded = true;
                        s.approachSpeed = r.approachSpeed;
                        s.force = r.force;
                    }
                }
            }
            pairSprings.append(s);
        }
    }
    springs.transfer(pairSprings);
}


template<class CloudType>
void Foam::RiserWallContact<CloudType>::haloOf
(
    const UList<grainState>& all,
    labelList& local,
    labelListList& send,
    labelListList& recv
) const
{
    const label me = Pstream::myProcNo();
    const label nProcs = Pstream::nProcs();
    std::vector<bool> inHalo(all.size(), false);
    // (processor, own particle in its halo), each possibly many times
    std::vector<std::pair<label, label>> sends;
    if (pairLaw_.valid() && nProcs > 1)
    {
        // the pairs of particles of two processors that may touch within
        // the step: each is in the other's halo (both processors evaluate
        // the same expression on the same numbers, so each finds the pair
        // alike, and what one sends the other expects)
        std::vector<riser::Vector> x(all.size());
        forAll(all, k)
        {
            x[k] = toCore(all[k].x);
        }
        forEachNearPair(x, 2*radiusMax_ + reach_ + SMALL, [&](std::size_t a, std::size_t b, scalar)
        {
            const grainState& p = all[a];
            const grainState& q = all[b];
            if (p.processor == q.processor || (p.processor != me && q.processor != me))
            {
                return;
            }
            const scalar gap = pairGap(x[a], p.key, p.R, x[b], q.key, q.R);
            if (gap > reach_)
            {
                return;
            }
            if (p.processor == me)
            {
                inHalo[b] = true;
                sends.emplace_back(q.processor, label(a));
            }
            else
            {
                inHalo[a] = true;
                sends.emplace_back(p.processor, label(b));
            }
        });
    }
    std::sort(sends.begin(), sends.end());
    sends.erase(std::unique(sends.begin(), sends.end()), sends.end());
    DynamicList<label> grains;
    forAll(all, k)
    {
        if (all[k].processor == me || inHalo[k])
        {
            grains.append(k);
        }
    }
    // in the order of their positions (by z, then x, then y), which does
    // not depend on the decomposition (the keys do: each processor numbers
    // the particles it injects), so that the contact forces are summed in
    // the same order in a serial and a parallel run, and a pair across
    // processors is evaluated alike on both
    std::sort
    (
        grains.begin(), grains.end(),
        [&all](label a, label b)
        {
            const vector& p = all[a].x;
            const vector& q = all[b].x;
            return
                p.z() < q.z()
             || (p.z() == q.z() && (p.x() < q.x() || (p.x() == q.x() && p.y() < q.y())));
        }
    );
    local.transfer(grains);
    labelList localOf(all.size(), -1);
    forAll(local, i)
    {
        localOf[local[i]] = i;
    }
    send.setSize(nProcs);
    recv.setSize(nProcs);
    List<DynamicList<label>> s(nProcs), r(nProcs);
    for (const std::pair<label, label>& ps : sends)
    {
        s[ps.first].append(localOf[ps.second]);
    }
    forAll(all, k)
    {
        if (inHalo[k])
        {
            r[all[k].processor].append(localOf[k]);
        }
    }
    for (label proc = 0; proc < nProcs; ++proc)
    {
        send[proc].transfer(s[proc]);
        recv[proc].transfer(r[proc]);
    }
}


template<class CloudType>
Foam::List<Foam::contactStep>
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
    const label me = Pstream::myProcNo();
    const bool walls = wallLaw_.valid();

    // the group's particles at the step's start: this processor's (in the
    // order of parcels), then, with pairs, copies of the other processors'
    // near the box of its own (each processor's in its order), with their
    // pair springs
    List<grainState> all;
    List<grainPairSpring> springs;
    {
        List<grainState> own;
        List<grainPairSpring> ownSprings;
        grainStates(parcels, fluidAcceleration, startOffset, own, ownSprings);
        DynamicList<grainState> grains(own);
        DynamicList<grainPairSpring> pairSprings(ownSprings);
        if (pairLaw_.valid() && Pstream::parRun())
        {
            List<vector> x(own.size());
            HashTable<label, labelPair, labelPair::Hash<>> ownOf(2*own.size());
            forAll(own, i)
            {
                x[i] = own[i].x;
                ownOf.insert(own[i].key, i);
            }
            const labelListList send = nearProcessors
            (
                x, 2*radiusMax_ + reach_ + SMALL, section_.periodic ? section_.length : 0
            );
            // (the springs of the particles sent)
            List<labelList> sendSprings(send.size());
            forAll(send, proc)
            {
                if (send[proc].empty())
                {
                    continue;
                }
                std::vector<bool> sent(own.size(), false);
                for (const label i : send[proc])
                {
                    sent[i] = true;
                }
                DynamicList<label> k;
                forAll(ownSprings, s)
                {
                    if (sent[ownOf[ownSprings[s].key]])
                    {
                        k.append(s);
                    }
                }
                sendSprings[proc].transfer(k);
            }
            for (const List<grainState>& g : exchanged(send, own))
            {
                grains.append(g);
            }
            for (const List<grainPairSpring>& g : exchanged(sendSprings, ownSprings))
            {
                pairSprings.append(g);
            }
        }
        all.transfer(grains);
        springs.transfer(pairSprings);
    }
    // the explicit drag of the sub-steps stays stable: drag h <= 1 (the
    // same on every processor: the largest rate)
    label nSub = max(nSubNeeded, label(1));
    for (const grainState& m : all)
    {
        nSub = max(nSub, label(ceil(m.drag*dt)));
    }
    reduce(nSub, maxOp<label>());
    const scalar h = dt/nSub;

    // this processor steps its own particles and its halo's copies of the
    // others' near them; after each move the copies are given the state
    // their processors moved them to
    labelList local;
    labelListList send, recv;
    haloOf(all, local, send, recv);
    bool halo = false;
    for (const labelList& s : send)
    {
        halo = halo || s.size();
    }
    // (no processor holds a halo: no exchange)
    halo = returnReduce(halo, orOp<bool>());
    const label n = local.size();

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
    // the own grains without contacts: their free motion under the fluid
    // acceleration, integrated alike (a grain that touches nothing moves
    // exactly as its free one)
    riser::GranularSystem free(std::nullopt, std::nullopt, riser::Vector::Zero(), rotation_);
    HashTable<label, labelPair, labelPair::Hash<>> grainOf(2*n);
    std::vector<riser::Vector> grainF(n), grainT(n);
    // the own grains: grain index, parcel (by the order of parcels: all
    // holds this processor's in that order) and free grain
    DynamicList<label> ownGrain(parcels.size());
    DynamicList<parcelType*> ownParcel(parcels.size());
    // (all holds this processor's particles first, in the order of
    // parcels)
    const label firstOwn = 0;
    labelList ownIndex(n, -1);
    forAll(local, i)
    {
        const grainState& m = all[local[i]];
        grainOf.insert(m.key, i);
        riser::Grain g{toCore(m.xStart), toCore(m.U), toCore(m.omega), m.R, m.mEff};
        g.accel = toCore(m.a);
        g.drag = m.drag;
        g.carrierVelocity = toCore(m.Uc);
        g.inertia = m.inertia;
        grains.addGrain(g);
        grainF[i] = toCore(m.F);
        grainT[i] = toCore(m.T);
        if (m.processor == me)
        {
            free.addGrain(g);
            ownIndex[i] = ownGrain.size();
            ownGrain.append(i);
            ownParcel.append(parcels[local[i] - firstOwn]);
        }
    }
    forAll(local, i)
    {
        const grainState& m = all[local[i]];
        if (walls && m.touchingWall)
        {
            // with the force of its last evaluation, when its particle is
            // this processor's (for its dissipation tally)
            const wallContactRecord* e =
                ownIndex[i] >= 0 ? wallRecord(*ownParcel[ownIndex[i]]) : nullptr;
            if (e)
            {
                grains.setWallContact(i, 0, toCore(m.wallSpring), toCore(e->force));
            }
            else
            {
                grains.setWallSpring(i, 0, toCore(m.wallSpring));
            }
        }
    }
    for (const grainPairSpring& s : springs)
    {
        // each pair once, from the record of the particle first in order
        // (the spring in its frame), with what that particle carries of it
        const auto i = grainOf.cfind(s.key);
        const auto j = grainOf.cfind(s.other);
        if (i.found() && j.found() && *i < *j)
        {
            grains.setPairContact(*i, *j, pairHandOver(s));
        }
    }
    grains.setContactForces(grainF, grainT);

    // the halo's copies given their processors' state after each move
    // (each processor knows what it sends and receives: messages of known
    // sizes, posted at once, without a collective)
    List<List<vector>> outgoing(send.size()), incoming(recv.size());
    forAll(send, proc)
    {
        outgoing[proc].setSize(3*send[proc].size());
        incoming[proc].setSize(3*recv[proc].size());
    }
    auto exchangeHalo = [&](std::vector<riser::Grain>& g)
    {
        if (!halo)
        {
            return;
        }
        const label requests = UPstream::nRequests();
        forAll(recv, proc)
        {
            if (recv[proc].size())
            {
                UIPstream::read
                (
                    Pstream::commsTypes::nonBlocking, proc,
                    reinterpret_cast<char*>(incoming[proc].data()),
                    incoming[proc].byteSize()
                );
            }
        }
        forAll(send, proc)
        {
            List<vector>& state = outgoing[proc];
            forAll(send[proc], s)
            {
                const riser::Grain& p = g[send[proc][s]];
                state[3*s] = fromCore(p.x);
                state[3*s + 1] = fromCore(p.v);
                state[3*s + 2] = fromCore(p.omega);
            }
            if (state.size())
            {
                UOPstream::write
                (
                    Pstream::commsTypes::nonBlocking, proc,
                    reinterpret_cast<const char*>(state.cdata()), state.byteSize()
                );
            }
        }
        UPstream::waitRequests(requests);
        forAll(recv, proc)
        {
            const List<vector>& state = incoming[proc];
            forAll(recv[proc], r)
            {
                riser::Grain& p = g[recv[proc][r]];
                p.x = toCore(state[3*r]);
                p.v = toCore(state[3*r + 1]);
                p.omega = toCore(state[3*r + 2]);
            }
        }
    };

    // the sub-steps; the own particles' wall contacts in progress, as
    // collide() keeps them
    std::vector<bool> inContact(ownGrain.size());
    forAll(ownGrain, i)
    {
        inContact[i] = wallRecord(*ownParcel[i]) != nullptr;
    }
    List<contactTrace> trace(ownGrain.size());
    for (label k = 1; k <= nSub; ++k)
    {
        grains.step(h, exchangeHalo);
        free.step(h);
        const scalar t = t0 + k*h;
        ledger_.pairOverlap(grains.largestPairOverlap());
        forAll(ownGrain, i)
        {
            if (!walls)
            {
                break;
            }
            const label gi = ownGrain[i];
            const riser::WallContactState& c = grains.wallContact(gi, 0);
            if (!c.touching && !inContact[i])
            {
                continue;
            }
            const labelPair& key = all[local[gi]].key;
            const riser::Grain& g = grains.grains()[gi];
            const riser::ContactPoint cp = wall.contactPoint(g.x, g.radius, t);
            const vector nw = fromCore(cp.normal);
            // (the velocity the force was evaluated with, as a tracked
            // particle's collide() sees it: the half-step one)
            const vector Urel = fromCore(c.velocity);
            const vector spin = fromCore(g.omega);
            if (c.touching)
            {
                ledger_.checkInside(key, c.overlap, g.radius, t);
                contactLedger::wallContactGoesOn
                (
                    *wallRecord(*ownParcel[i], true), t, h, c.overlap, fromCore(c.force),
                    c.normalForce, Urel, nw, spin
                );
                inContact[i] = true;
            }
            else
            {
                wallContactEnds(*ownParcel[i], trace[i], t, Urel, nw, spin);
                inContact[i] = false;
            }
        }
    }

    // The contact trace of the flow step (contactTrace.H) of each own
    // particle, its wall contact's last force, springs; and what the
    // contacts added to its free motion
    // (in the order of parcels)
    List<contactStep> ownSteps(parcels.size());
    forAll(ownGrain, i)
    {
        const label gi = ownGrain[i];
        const grainState& m = all[local[gi]];
        parcelType& p = *ownParcel[i];
        const riser::Grain& g = grains.grains()[gi];
        const riser::Grain& gFree = free.grains()[i];
        trace[i].wallEnergy = grains.wallEnergy(gi);
        trace[i].recordPairContacts
        (
            label(grains.pairContactsCompleted(gi)), grains.pairImpactSpeed(gi)
        );
        trace[i].pairEnergy = grains.pairEnergy(gi);
        addContactTrace(p, trace[i]);
        p.collisionRecords() =
            typename std::decay<decltype(p.collisionRecords())>::type();
        if (walls)
        {
            const riser::WallContactState& c = grains.wallContact(gi, 0);
            wallContactRecord* e = wallRecord(p);
            if (c.touching && e)
            {
                e->force = fromCore(c.force);
                e->normal = fromCore(c.normal);
                e->wallVelocity = fromCore(c.wallVelocity);
            }
            if (c.touching)
            {
                const riser::ContactPoint cp =
                    wall.contactPoint(g.x, g.radius, time.value());
                p.collisionRecords().matchWallRecord
                (
                    0.99*g.radius*fromCore(cp.normal), g.radius
                ).collisionData() = fromCore(grains.wallSpring(gi, 0));
            }
        }
        // the track from the particle's position, x + U dt, is given what
        // puts it where the engine left it (up to the track's own share of
        // the fluid's a dt^2/2: RiserCloud); the velocity gets the
        // contacts' change on top of the fluid forces' own
        contactStep c;
        c.x = fromCore(g.x);
        c.dx = c.x - m.x - dt*m.U;
        c.dU = fromCore(riser::Vector(g.v - gFree.v));
        c.dL = m.inertia*fromCore(riser::Vector(g.omega - gFree.omega));
        c.f = (m.mP/m.mEff)*fromCore(grains.contactForce(gi));
        c.torque = rotation_ ? fromCore(grains.contactTorque(gi)) : vector::zero;
        ownSteps[local[gi] - firstOwn] = c;
    }

    // the pair contacts in progress: each own particle's springs, and its
    // record of them (contactsInProgress.H: carried to the next step, to
    // another processor, across a restart), renewed
    for (parcelType* p : ownParcel)
    {
        if (contactsInProgress* carried = carriedContacts(*p))
        {
            carried->pairs.clear();
        }
    }
    label pairsInContact = 0, acrossProcessors = 0;
    grains.forEachPairContactState
    (
        [&](std::size_t i, std::size_t j, const riser::PairContactState& state)
        {
            const grainState& a = all[local[i]];
            const grainState& b = all[local[j]];
            // (the state is i's: its spring, and the force on i)
            auto keep = [&state](parcelType& p, const labelPair& other, const scalar sign)
            {
                p.collisionRecords()
                    .matchPairRecord(other.first(), other.second())
                    .collisionData() = sign*fromCore(state.spring);
                if (contactsInProgress* carried = carriedContacts(p))
                {
                    pairContactRecord r;
                    r.other = other;
                    r.approachSpeed = state.approachSpeed;
                    r.force = sign*fromCore(state.force);
                    carried->pairs.append(r);
                }
            };
            if (a.processor == me)
            {
                keep(*ownParcel[ownIndex[i]], b.key, 1);
                ++pairsInContact;
                acrossProcessors += a.processor != b.processor;
            }
            if (b.processor == me)
            {
                keep(*ownParcel[ownIndex[j]], a.key, -1);
            }
        }
    );
    for (parcelType* p : parcels)
    {
        // as after collide(): kept, marked not accessed
        p->collisionRecords().update();
    }
    if (Pstream::parRun())
    {
        Info<< "    riserWallContact: "
            << returnReduce(pairsInContact, sumOp<label>()) << " pair(s) in contact, "
            << returnReduce(acrossProcessors, sumOp<label>())
            << " across processor boundaries" << endl;
    }

    return ownSteps;
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
             && !wallRecord(p)
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

        ledger_.checkInside(key, cp.overlap, Rp, t);

        const vector spin = rotation_ ? p.omega() : vector::zero;
        const scalar overlap = cp.overlap;
        const vector n = fromCore(cp.normal);

        // F_prev's part of the trapezoid, with its own evaluation's normal
        // and wall velocity (those of now for a contact in progress not
        // recorded: a stock parcel's at a restart, or a cloud written
        // without its contacts in progress)
        const wallContactRecord* event = wallRecord(p);
        const vector nPrev = event ? event->normal : n;
        const vector UwallPrev = event ? event->wallVelocity : Uwall;
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
            contactTrace trace;
            trace.wallEnergy = -0.5*dt*workBefore;
            wallContactEnds(p, trace, t, p.U() - Uwall, n, spin);
            addContactTrace(p, trace);
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

        contactTrace trace;
        trace.wallEnergy = -0.5*dt*(workBefore + c.power);
        addContactTrace(p, trace);
        wallContactRecord& e = *wallRecord(p, true);
        contactLedger::wallContactGoesOn
        (
            e, t, dt, overlap, F, mag(fromCore(c.law.normal)), p.U() - Uwall, n, spin
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
