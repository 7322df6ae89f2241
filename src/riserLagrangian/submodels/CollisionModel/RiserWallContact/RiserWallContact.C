/*---------------------------------------------------------------------------*\
  riserFoam: particle transport in vibrating risers, on OpenFOAM
  License: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "RiserWallContact.H"
#include "modelEntries.H"
#include "cloudOutputFile.H"
#include "coreVector.H"
#include "HistoryParcel.H"
#include "granular/cellList.hpp"

#include <numeric>
#include <vector>

// * * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * //

template<class CloudType>
riser::HertzMindlin Foam::RiserWallContact<CloudType>::readLaw() const
{
    return riser::HertzMindlin
    (
        modelEntries::contactParameters
        (
            this->coeffDict(), this->owner().constProps().dict()
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
                "# velocities relative to the wall [m/s], spin [rad/s], SI units\n"
                "# origProc origId tStart tEnd duration overlapMax"
                " normalForceMax Uin_x Uin_y Uin_z Uout_x Uout_y Uout_z"
                " omegaIn_x omegaIn_y omegaIn_z omegaOut_x omegaOut_y omegaOut_z"
                " UnIn UnOut\n",
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
    law_(readLaw()),
    rotation_(this->coeffDict().lookupOrDefault("rotation", Switch(false))),
    stepsPerContact_
    (
        checkedEntry::count(this->coeffDict(), "stepsPerContact", 10, 10000, 40)
    ),
    maxSubCycles_
    (
        checkedEntry::count(this->coeffDict(), "maxSubCycles", 1, 100000000, 100000)
    ),
    addedMassCoeff_(readAddedMassCoeff()),
    pairsInContact_(0),
    pairOverlapMax_(0),
    section_(riserSection(owner.mesh())),
    cellAxisDistance_
    (
        owner.mesh().changing() ? scalarField() : cellAxisDistances(owner.mesh())
    )
{
    if (this->coeffDict().found("pairs"))
    {
        if (Pstream::parRun())
        {
            FatalIOErrorInFunction(this->coeffDict())
                << "entry 'pairs' (particle-particle contact) in a parallel"
                << " run: pair contact runs on one processor in this version"
                << " (pairs across processor boundaries are not exchanged);"
                << " run serially or remove 'pairs'" << exit(FatalIOError);
        }
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

    Info<< "    riserWallContact: normal damping ratio "
        << law_.normalDampingRatio() << ", rotation " << rotation_
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
    law_(cm.law_),
    rotation_(cm.rotation_),
    stepsPerContact_(cm.stepsPerContact_),
    maxSubCycles_(cm.maxSubCycles_),
    addedMassCoeff_(cm.addedMassCoeff_),
    pairLaw_(cm.pairLaw_.valid() ? new riser::HertzMindlin(cm.pairLaw_()) : nullptr),
    pairsInContact_(cm.pairsInContact_),
    pairOverlapMax_(cm.pairOverlapMax_),
    section_(cm.section_),
    cellAxisDistance_(cm.cellAxisDistance_),
    events_(cm.events_),
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
    if (clearOfWall(p, axisOffset, speed*dt))
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
    const scalar tc = law_.contactTime(body, max(speed, SMALL));
    // as a scalar first: no overflow of the label
    const scalar needed = ceil(stepsPerContact_*dt/tc);
    checkNeeded(needed, p, tc, "wall contact");
    return max(label(needed), label(1));
}


template<class CloudType>
void Foam::RiserWallContact<CloudType>::checkNeeded
(
    const scalar needed,
    const parcelType& p,
    const scalar tc,
    const word& what
) const
{
    if (!(needed <= maxSubCycles_))
    {
        FatalErrorInFunction
            << "particle " << p.origId() << " (processor " << p.origProc()
            << ") at " << p.position() << " needs " << needed
            << " sub-cycles of the step deltaT = "
            << this->owner().mesh().time().deltaTValue() << " to resolve"
            << " its " << what << " (contact time " << tc << " s, "
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
    const std::size_t n = x.size();
    // the centres, and images shifted by +-L of those within the cutoff of
    // an end of a periodic section
    std::vector<riser::Vector> all(x);
    std::vector<std::size_t> original(n);
    std::iota(original.begin(), original.end(), std::size_t(0));
    std::vector<scalar> shift(n, 0);
    if (section_.periodic)
    {
        const scalar L = section_.length;
        for (std::size_t i = 0; i < n; ++i)
        {
            if (x[i].z() - section_.z0 < cutoff)
            {
                all.push_back(x[i] + riser::Vector(0, 0, L));
                original.push_back(i);
                shift.push_back(L);
            }
            if (section_.z0 + L - x[i].z() < cutoff)
            {
                all.push_back(x[i] - riser::Vector(0, 0, L));
                original.push_back(i);
                shift.push_back(-L);
            }
        }
    }
    riser::CellList cells;
    cells.build(all, cutoff);
    cells.forEachPair([&](std::size_t a, std::size_t b)
    {
        if (a >= n && b >= n)
        {
            return;     // two images: the pair is met through its originals
        }
        if (a >= n)
        {
            std::swap(a, b);
        }
        const std::size_t i = original[a], j = original[b];
        // a pair across the ends appears twice (i with j's image, j with
        // i's): kept once, with the image of the larger index
        if (i == j || (b >= n && j < i))
        {
            return;
        }
        f(i, j, shift[b]);
    });
}


template<class CloudType>
Foam::labelList Foam::RiserWallContact<CloudType>::contactNeeds() const
{
    const Time& time = this->owner().mesh().time();
    const scalar dt = time.deltaTValue();
    checkMeshUnchanged();
    const scalar axisOffset =
        mag(carrier_.riser().motion().axisPosition(time.value() - dt));

    std::vector<const parcelType*> parcels;
    parcels.reserve(this->owner().size());
    labelList need(this->owner().size());
    for (const parcelType& p : this->owner())
    {
        need[parcels.size()] = nearWallSubCycles(p, axisOffset);
        parcels.push_back(&p);
    }
    const std::size_t n = parcels.size();

    if (pairLaw_.valid() && n > 1)
    {
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

        std::vector<riser::Vector> x(n);
        scalar rMax = 0, uMax = 0;
        for (std::size_t i = 0; i < n; ++i)
        {
            x[i] = toCore(parcels[i]->position());
            rMax = max(rMax, 0.5*parcels[i]->d());
            uMax = max(uMax, mag(parcels[i]->U()));
        }
        // within a step a contact can speed a particle up to about twice
        // the fastest particle's speed, so a pair may close by 4 U_max dt:
        // a reach from each pair's own speeds would miss a resting
        // particle struck by a neighbour and left to overlap the next
        uMax = returnReduce(uMax, maxOp<scalar>());
        const scalar reach = 4*uMax*dt;
        forEachNearPair(x, 2*rMax + reach + SMALL, [&](std::size_t i, std::size_t j, scalar dz)
        {
            const parcelType& p = *parcels[i];
            const parcelType& q = *parcels[j];
            const scalar gap =
                (x[j] + riser::Vector(0, 0, dz) - x[i]).norm() - 0.5*(p.d() + q.d());
            if (gap > reach)
            {
                return;
            }
            // the largest impact speed the pair can reach in the step
            const scalar speed = max(mag(p.U()) + mag(q.U()), 2*uMax);
            const riser::ContactBody body =
                riser::pairBody
                (
                    0.5*p.d(), effectiveMass(p), 0.5*q.d(), effectiveMass(q)
                );
            const scalar tc = pairLaw_->contactTime(body, max(speed, SMALL));
            const scalar needed = ceil(stepsPerContact_*dt/tc);
            checkNeeded(needed, p, tc, "contact with particle " + Foam::name(q.origId()));
            const label k = max(label(needed), label(1));
            need[i] = max(need[i], k);
            need[j] = max(need[j], k);
            root[find(i)] = find(j);
        });
        std::vector<label> clusterNeed(n, 0);
        for (std::size_t i = 0; i < n; ++i)
        {
            clusterNeed[find(i)] = max(clusterNeed[find(i)], need[i]);
        }
        for (std::size_t i = 0; i < n; ++i)
        {
            need[i] = clusterNeed[find(i)];
        }
    }
    return need;
}


template<class CloudType>
Foam::labelList Foam::RiserWallContact<CloudType>::subCycles() const
{
    labelList need(contactNeeds());
    for (label& n : need)
    {
        n = max(n, label(1));
    }
    return need;
}


template<class CloudType>
Foam::label Foam::RiserWallContact<CloudType>::nSubCycles() const
{
    label nSub = 1, nNear = 0;
    for (const label n : contactNeeds())
    {
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


namespace Foam
{
    //- The tangential spring of a contact turned into the plane normal to n
    //  (its length kept) and grown by the tangential relative velocity of
    //  the contact point over dt
    inline vector advancedSpring
    (
        const vector& spring,
        const vector& n,
        const vector& U,
        const scalar dt
    )
    {
        const vector inPlane = spring - (spring & n)*n;
        const scalar magInPlane = mag(inPlane);
        return
            (magInPlane > VSMALL ? mag(spring)/magInPlane*inPlane : vector::zero)
          + (U - (U & n)*n)*dt;
    }
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
    pairsInContact_ = 0;
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
        const vector n = fromCore(geo.normal);
        const vector U =
            rotation_
          ? fromCore
            (
                riser::pairContactVelocity
                (
                    geo, toCore(p.U()), toCore(p.omega()), Rp,
                    toCore(q.U()), toCore(q.omega()), Rq
                )
            )
          : p.U() - q.U();

        // the spring in p's frame (n from p to q); q keeps its negative
        vector& spring =
            p.collisionRecords().matchPairRecord(q.origProc(), q.origId()).collisionData();
        spring = advancedSpring(spring, n, U, dt);

        const scalar mp = effectiveMass(p), mq = effectiveMass(q);
        const riser::ContactForce c =
            pairLaw_->force
            (
                riser::pairBody(Rp, mp, Rq, mq),
                geo.overlap, geo.normal, toCore(U), toCore(spring)
            );
        spring = fromCore(c.springAfter);
        q.collisionRecords().matchPairRecord(p.origProc(), p.origId()).collisionData() =
            -spring;

        const vector F = fromCore(c.normal) + fromCore(c.tangential);
        // each parcel divides f by its m_p: the force on m_p + C_A m_f
        p.f() += (p.mass()/mp)*F;
        q.f() -= (q.mass()/mq)*F;
        if (rotation_)
        {
            const vector Ft = fromCore(c.tangential);
            p.torque() += (Rp*n) ^ Ft;
            q.torque() += (Rq*n) ^ Ft;
        }
        ++pairsInContact_;
        pairOverlapMax_ = max(pairOverlapMax_, geo.overlap/min(p.d(), q.d()));
    });
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
        p.f() = Zero;
        p.torque() = Zero;

        // certainly apart from the wall and in no contact that might end
        // now: nothing to do
        if
        (
            clearOfWall(p, axisOffset, 0)
         && (events_.empty() || !events_.found(labelPair(p.origProc(), p.origId())))
        )
        {
            continue;
        }

        const scalar Rp = 0.5*p.d();
        const riser::ContactPoint cp = wall.contactPoint(toCore(p.position()), Rp, t);
        const vector Uwall = fromCore(cp.velocity);
        const labelPair key(p.origProc(), p.origId());

        if (cp.overlap > Rp && lost_.insert(key))
        {
            WarningInFunction
                << "particle " << key << " has its centre outside the pipe at t = "
                << t << ": " << cp.overlap - Rp << " beyond the wall; "
                << lost_.size() << " particle(s) lost so far" << endl;
        }

        const vector spin = rotation_ ? p.omega() : vector::zero;
        const scalar overlap = cp.overlap;

        if (overlap <= 0)
        {
            auto iter = events_.find(key);
            if (iter.found())
            {
                const contactEvent& e = *iter;
                const vector Uout = p.U() - Uwall;
                contactFile()
                    << key.first() << ' ' << key.second() << ' '
                    << e.start << ' ' << t << ' ' << t - e.start << ' '
                    << e.overlapMax << ' ' << e.normalForceMax << ' '
                    << e.velocityIn.x() << ' ' << e.velocityIn.y() << ' '
                    << e.velocityIn.z() << ' '
                    << Uout.x() << ' ' << Uout.y() << ' ' << Uout.z() << ' '
                    << e.spinIn.x() << ' ' << e.spinIn.y() << ' '
                    << e.spinIn.z() << ' '
                    << spin.x() << ' ' << spin.y() << ' ' << spin.z() << ' '
                    << e.normalSpeedIn << ' '
                    << -(Uout & fromCore(cp.normal)) << endl;
                recordWallContact(p, e.overlapMax, e.normalSpeedIn);
                events_.erase(iter);
            }
            // no record accessed: update() below drops the tangential spring
            continue;
        }

        const vector n = fromCore(cp.normal);
        const vector U = p.U() - Uwall + (spin ^ (Rp*n));

        // the tangential spring, kept in the current tangent plane
        vector& spring =
            p.collisionRecords().matchWallRecord(0.99*Rp*n, Rp).collisionData();
        spring = advancedSpring(spring, n, U, dt);

        const scalar mEff = effectiveMass(p);
        const riser::ContactForce c =
            law_.force
            (
                riser::ContactBody(Rp, mEff),
                overlap, toCore(n), toCore(U), toCore(spring)
            );
        spring = fromCore(c.springAfter);

        const vector Fn = fromCore(c.normal);
        const vector Ft = fromCore(c.tangential);
        // the parcel divides f by m_p: the force on m_p + C_A m_f
        p.f() = (p.mass()/mEff)*(Fn + Ft);
        if (rotation_)
        {
            p.torque() = (Rp*n) ^ Ft;
        }

        auto iter = events_.find(key);
        if (!iter.found())
        {
            events_.insert
            (
                key,
                contactEvent
                {
                    t - dt, overlap, mag(Fn), p.U() - Uwall, (p.U() - Uwall) & n,
                    spin
                }
            );
        }
        else
        {
            contactEvent& e = *iter;
            e.overlapMax = max(e.overlapMax, overlap);
            e.normalForceMax = max(e.normalForceMax, mag(Fn));
        }
    }

    if (pairLaw_.valid())
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
