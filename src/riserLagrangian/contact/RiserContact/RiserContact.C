/*---------------------------------------------------------------------------*\
  riserFoam: particle transport in vibrating risers, on OpenFOAM
  License: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "RiserContact.H"
#include "modelEntries.H"
#include "coreVector.H"
#include "HistoryParcel.H"
#include "granular/nearPairs.hpp"
#include "granular/granularSystem.hpp"
#include "granular/clusterPlan.hpp"
#include "UIPstream.H"
#include "UOPstream.H"

#include <algorithm>
#include <sstream>
#include <cmath>
#include <limits>
#include <vector>

// * * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * //

template<class CloudType>
Foam::autoPtr<riser::HertzMindlin>
Foam::RiserContact<CloudType>::readWallLaw() const
{
    if (!modelEntries::wallContactOn(this->coeffDict()))
    {
        return nullptr;
    }
    riser::HertzMindlinParameters law =
        modelEntries::contactParameters
        (
            this->coeffDict(), this->owner().constProps().dict()
        );
    wetContact(this->coeffDict(), law);
    return autoPtr<riser::HertzMindlin>(new riser::HertzMindlin(law));
}


template<class CloudType>
void Foam::RiserContact<CloudType>::wetContact
(
    const dictionary& parent,
    riser::HertzMindlinParameters& law
) const
{
    if (!parent.found("wet"))
    {
        return;
    }
    // the carrier's dynamic viscosity, one value (the Stokes number of an
    // impact is the contact's, not the cell's)
    const volScalarField& mu = this->owner().mu();
    const scalar muMin = gMin(mu.primitiveField());
    const scalar muMax = gMax(mu.primitiveField());
    if (!(muMin > 0) || muMax - muMin > 1e-9*muMax)
    {
        FatalIOErrorInFunction(parent.subDict("wet"))
            << "entry 'wet': the carrier's dynamic viscosity " << mu.name()
            << " lies in [" << muMin << ", " << muMax << "] Pa s; a wet"
            << " contact needs one positive value" << exit(FatalIOError);
    }
    modelEntries::wetContact(parent, this->coeffDict(), muMax, law);
}


template<class CloudType>
Foam::scalar Foam::RiserContact<CloudType>::wallFilmGap(const scalar R) const
{
    return wallLaw_.valid() ? wallLaw_->filmGap(R) : 0;
}


template<class CloudType>
Foam::scalar Foam::RiserContact<CloudType>::pairReach
(
    const scalar Ra,
    const scalar Rb
) const
{
    return
        reach_
      + pairLaw_->filmGap(Ra*Rb/(Ra + Rb));
}


template<class CloudType>
Foam::scalar Foam::RiserContact<CloudType>::pairCutoff() const
{
    // (R* of two radii up to R_max is at most R_max/2)
    return
        2*radiusMax_ + reach_ + SMALL
      + pairLaw_->filmGap(0.5*radiusMax_);
}


template<class CloudType>
Foam::scalar Foam::RiserContact<CloudType>::readAddedMassCoeff() const
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
Foam::scalar Foam::RiserContact<CloudType>::effectiveMass
(
    const parcelType& p
) const
{
    const scalar m = p.mass();
    return m + addedMassCoeff_*m*this->owner().rho()[p.cell()]/p.rho();
}


template<class CloudType>
Foam::scalar Foam::RiserContact<CloudType>::bodyAccelerationBound() const
{
    return
        mag(this->owner().g().value())
      + 2*riser_.flow().motion().maxAcceleration();
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::RiserContact<CloudType>::RiserContact
(
    const dictionary& dict,
    CloudType& owner
)
:
    RiserContact(dict, owner, typeName)
{}


template<class CloudType>
Foam::RiserContact<CloudType>::RiserContact
(
    const dictionary& dict,
    CloudType& owner,
    const word& type
)
:
    CollisionModel<CloudType>(dict, owner, type),
    riser_(riserModel::ofCloud(owner)),
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
        checkedEntry::choiceOrDefault
        (
            this->coeffDict(), "aloneAtWall",
            {{"tracked", false}, {"meshFree", true}}, false
        )
    ),
    addedMassCoeff_(readAddedMassCoeff()),
    cellAxisDistance_
    (
        owner.mesh().changing() ? scalarField() : cellAxisDistances(owner.mesh())
    ),
    ledger_(owner.mesh(), owner.name(), type)
{
    if (this->coeffDict().found("pairs"))
    {
        riser::HertzMindlinParameters law =
            modelEntries::pairContactParameters
            (
                this->coeffDict(), this->owner().constProps().dict()
            );
        wetContact(this->coeffDict().subDict("pairs"), law);
        if ((law.wet || law.film) && !riserCloud)
        {
            FatalIOErrorInFunction(this->coeffDict().subDict("pairs"))
                << "entry 'wet' of pairs in a stock colliding cloud: its pair"
                << " contacts keep no approach speed and are searched only"
                << " among touching particles, not within a film; wet pairs"
                << " need the riser cloud (riserParcelFoam, riserCoupledFoam)"
                << exit(FatalIOError);
        }
        pairLaw_.reset(new riser::HertzMindlin(law));
    }
    // the Stokes number of the wet restitution (Legendre et al. 2006) is
    // built on m_p + m_f/2, the inertia the contacts accelerate with C_A 1/2
    if
    (
        (wallLaw_.valid() && wallLaw_->wet())
     || (pairLaw_.valid() && pairLaw_->wet())
    )
    {
        modelEntries::requireWetInertia(this->coeffDict(), addedMassCoeff_);
    }

    // the riser must exist: FatalError here rather than at the first step
    riser_.flow();
    // the coefficients under the model's other name (riserWallContact, its
    // old one) would be ignored
    const word other = (type == typeName ? word("riserWallContact") : typeName) + "Coeffs";
    if (dict.found(other))
    {
        FatalIOErrorInFunction(dict)
            << "entry '" << other << "' beside collisionModel " << type
            << ": the coefficients of the model's other name would be"
            << " ignored; keep " << type << "Coeffs alone" << exit(FatalIOError);
    }
    if (riserCloud)
    {
        // the riser cloud moves its particles by the needs of this model
        this->announce(&owner);
    }
    else
    {
        // the contact records of a restart, before the stock cloud reads
        // them (the riser cloud's parcel checks its own)
        contactRecords::check(owner);
    }

    Info<< "    riserContact: wall contact ";
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
    // a wet law as the log states it
    auto wetness = [](const riser::HertzMindlin& law) -> std::string
    {
        std::ostringstream s;
        if (law.wet())
        {
            s << "wet (e = e_n exp(-" << law.wet()->stokesScale
              << "/St), none below St " << law.wet()->criticalStokes << ")";
        }
        else if (law.film())
        {
            s << "wet (lubrication film from " << law.film()->cutoff
              << " R* to " << law.film()->roughness << " R*, L = "
              << law.film()->logRatio() << ": no rebound below St "
              << law.film()->criticalStokes(law.dryRestitution()) << ")";
        }
        return s.str();
    };
    if (wallLaw_.valid() && (wallLaw_->wet() || wallLaw_->film()))
    {
        Info<< ", " << wetness(*wallLaw_).c_str();
    }
    Info<< ", pair contact " << (pairLaw_.valid() ? "on" : "off");
    if (pairLaw_.valid() && (pairLaw_->wet() || pairLaw_->film()))
    {
        Info<< " (" << wetness(*pairLaw_).c_str() << ")";
    }
    Info
        << ", rotation " << rotation_
        << ", inertia m_p + " << addedMassCoeff_ << " m_f" << endl;
}


template<class CloudType>
Foam::RiserContact<CloudType>::RiserContact
(
    const RiserContact<CloudType>& cm
)
:
    CollisionModel<CloudType>(cm),
    localSubCycling<parcelType>(cm),
    riser_(cm.riser_),
    wallLaw_(cm.wallLaw_.valid() ? new riser::HertzMindlin(cm.wallLaw_()) : nullptr),
    rotation_(cm.rotation_),
    stepsPerContact_(cm.stepsPerContact_),
    maxSubCycles_(cm.maxSubCycles_),
    aloneMeshFree_(cm.aloneMeshFree_),
    addedMassCoeff_(cm.addedMassCoeff_),
    pairLaw_(cm.pairLaw_.valid() ? new riser::HertzMindlin(cm.pairLaw_()) : nullptr),
    needs_(cm.needs_),
    cellAxisDistance_(cm.cellAxisDistance_),
    ledger_(cm.ledger_)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
void Foam::RiserContact<CloudType>::checkCloudRunsThis() const
{
    if (aloneMeshFree_ && !riserCloud)
    {
        FatalIOErrorInFunction(this->coeffDict())
            << "entry 'aloneAtWall' = meshFree with a stock colliding cloud:"
            << " only the riser cloud (riserParcelFoam) sub-steps particles"
            << " without the mesh; remove it or set tracked"
            << exit(FatalIOError);
    }
}


template<class CloudType>
const typename Foam::RiserContact<CloudType>::subCycleNeed&
Foam::RiserContact<CloudType>::need(const parcelType& p) const
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
Foam::label Foam::RiserContact<CloudType>::subCycles(const parcelType& p) const
{
    return max(need(p).n, label(1));
}


template<class CloudType>
bool Foam::RiserContact<CloudType>::meshFree(const parcelType& p) const
{
    return need(p).meshFree;
}


template<class CloudType>
Foam::label Foam::RiserContact<CloudType>::nSubCycles() const
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
        Info<< "    riserContact: " << nNear << " particle(s) near "
            << (pairLaw_.valid() ? "a contact" : "the wall") << endl;
    }
    const label deferred = returnReduce(deferredContacts_, sumOp<label>());
    if (deferred)
    {
        Info<< "    riserContact: " << deferred << " wall contact(s) begun"
            << " in the last step, which their plan did not foresee, left"
            << " to this step's sub-cycles" << endl;
    }
    deferredContacts_ = 0;
    if (pairLaw_.valid())
    {
        Info<< "    riserContact: largest pair overlap in this run "
            << returnReduce(ledger_.pairOverlapMax(), maxOp<scalar>())
            << " of the smaller diameter" << endl;
    }
    return nSub;
}


template<class CloudType>
bool Foam::RiserContact<CloudType>::unresolvedStart
(
    const parcelType& p,
    const riser::ContactBody& body,
    const scalar vn,
    const scalar dt
) const
{
    // (the plan gives a contact it foresees stepsPerContact sub-cycles of
    // its contact time at a speed at least vn; the factor 2 leaves those)
    return
        need(p).n == 0
     && stepsPerContact_*dt > 2*wallLaw_->contactTime(body, max(mag(vn), SMALL));
}


template<class CloudType>
riser::ContactSide Foam::RiserContact<CloudType>::contactSide
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
void Foam::RiserContact<CloudType>::collidePairs()
{
    const scalar dt = this->owner().mesh().time().deltaTValue();
    const scalar period = riser_.section().period();

    // this processor's particles, then, in parallel, copies of the other
    // processors' particles near the box of its own (nearProcessors: their
    // state only, none of their springs); a pair across a processor
    // boundary is evaluated alike on both processors (the particle of the
    // lower key first), each keeping its own particle's spring and force
    std::vector<parcelType*> parcels;
    DynamicList<grainState> bodies(this->owner().size());
    scalar rMax = 0;
    for (parcelType& p : this->owner())
    {
        parcels.push_back(&p);
        grainState m;
        m.key = labelPair(p.origProc(), p.origId());
        m.processor = Pstream::myProcNo();
        m.x = p.position();
        m.U = p.U();
        m.omega = rotation_ ? p.omega() : vector::zero;
        m.R = 0.5*p.d();
        m.mEff = effectiveMass(p);
        bodies.append(m);
        rMax = max(rMax, m.R);
    }
    const label nOwn = parcels.size();
    if (Pstream::parRun())
    {
        reduce(rMax, maxOp<scalar>());
        List<vector> x(nOwn);
        forAll(x, i)
        {
            x[i] = bodies[i].x;
        }
        const labelListList send = nearProcessors(x, 2*rMax + SMALL, period);
        std::size_t bytesSent = 0;
        for (const List<grainState>& g : exchanged(send, bodies, bytesSent))
        {
            bodies.append(g);
        }
    }
    if (bodies.size() < 2)
    {
        return;
    }

    std::vector<riser::Vector> x(bodies.size());
    forAll(bodies, i)
    {
        x[i] = toCore(bodies[i].x);
    }
    forEachNearPair(x, 2*rMax, [&](std::size_t a, std::size_t b, scalar)
    {
        if (label(a) >= nOwn && label(b) >= nOwn)
        {
            return;
        }
        // the pair in a fixed order, so that the spring is read in one frame
        const bool aFirst = bodies[a].key < bodies[b].key;
        const label i = aFirst ? a : b, j = aFirst ? b : a;
        const grainState& p = bodies[i];
        const grainState& q = bodies[j];
        // q's image nearest to p
        const riser::Vector xp = toCore(p.x);
        const riser::PairGeometry geo =
            riser::pairGeometry
            (
                xp, p.R, xp + riser::nearestImage(toCore(q.x) - xp, period), q.R
            );
        if (geo.overlap <= 0)
        {
            return;
        }
        // the spring in p's frame (n from p to q), kept by each particle of
        // the pair this processor holds (q keeps its negative)
        auto springOf = [&](const label own, const grainState& other) -> vector*
        {
            return
                own < nOwn
              ? &parcels[own]->collisionRecords().matchPairRecord
                (
                    other.key.first(), other.key.second()
                ).collisionData()
              : nullptr;
        };
        vector* springP = springOf(i, q);
        vector* springQ = springOf(j, p);
        const vector spring = springP ? *springP : -*springQ;
        const riser::ContactStep c =
            riser::stepContact
            (
                *pairLaw_, riser::pairBody(p.R, p.mEff, q.R, q.mEff), geo.overlap,
                geo.normal,
                riser::ContactSide{toCore(p.U), toCore(p.omega), p.R},
                riser::ContactSide{toCore(q.U), toCore(q.omega), q.R},
                toCore(spring),
                // (no approach speed kept: a wet pair law is refused here)
                std::numeric_limits<scalar>::quiet_NaN(), dt
            );
        const vector after = fromCore(c.law.springAfter);
        const vector F = fromCore(c.force);
        // each parcel divides f by its m_p: the force on m_p + C_A m_f
        if (springP)
        {
            parcelType& own = *parcels[i];
            *springP = after;
            own.f() += (own.mass()/p.mEff)*F;
            if (rotation_)
            {
                own.torque() += fromCore(c.torqueI);
            }
        }
        if (springQ)
        {
            parcelType& own = *parcels[j];
            *springQ = -after;
            own.f() -= (own.mass()/q.mEff)*F;
            if (rotation_)
            {
                own.torque() += fromCore(c.torqueJ);
            }
        }
        ledger_.pairOverlap(geo.overlap/(2*min(p.R, q.R)));
    });
}


template<class CloudType>
Foam::wallContactRecord* Foam::RiserContact<CloudType>::wallRecord
(
    parcelType& p,
    const bool start
)
{
    if (contactsInProgress* carried = carriedContacts(p))
    {
        if (start)
        {
            return &carried->startWall();
        }
        wallContactRecord* e = carried->wall();
        return e && e->active ? e : nullptr;
    }
    return ledger_.stockRecord(labelPair(p.origProc(), p.origId()), start);
}


template<class CloudType>
void Foam::RiserContact<CloudType>::wallContactEnds
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
        carried->endWall();
    }
    else
    {
        ledger_.dropStockRecord(key);
    }
}


template<class CloudType>
void Foam::RiserContact<CloudType>::collide()
{
    const Time& time = this->owner().mesh().time();
    const riser::Wall& wall = riser_.wall();
    const scalar t = time.value();
    const scalar dt = time.deltaTValue();
    checkMeshUnchanged();
    const scalar axisOffset = riser_.flow().motion().axisOffsetBound(t);

    // a stock parcel's wall contact in progress, kept here, follows the
    // parcel to the processor it moved to
    if (!riserCloud && wallLaw_.valid() && Pstream::parRun())
    {
        label held = 0;
        for (const parcelType& p : this->owner())
        {
            held += ledger_.stockRecord(labelPair(p.origProc(), p.origId()), false) != nullptr;
        }
        if (returnReduce(ledger_.nStockRecords() - held, sumOp<label>()))
        {
            HashSet<labelPair, labelPairHash> own(2*this->owner().size());
            for (const parcelType& p : this->owner())
            {
                own.insert(labelPair(p.origProc(), p.origId()));
            }
            ledger_.handOverStockRecords(own);
        }
    }

    const scalar wallSpeed = riser_.flow().motion().maxSpeed();
    for (parcelType& p : this->owner())
    {
        // no wall contact, or certainly apart from the wall (and from its
        // film, lubricated, within this sub-cycle) and in no wall contact
        // that might end now: no wall force, nothing to record
        if
        (
            !wallLaw_.valid()
         || (
                clearOfWall
                (
                    p, axisOffset,
                    wallLaw_->film()
                  ? wallFilmGap(0.5*p.d()) + (mag(p.U()) + wallSpeed)*dt
                  : 0
                )
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

        const riser::ContactBody body(Rp, mEff);
        if (overlap <= 0)
        {
            // apart: the kernel's film force if lubricated (else none), and
            // no record (a contact begins at touch)
            const riser::ContactStep c =
                riser::stepContact
                (
                    *wallLaw_, body, overlap, toCore(n), contactSide(p),
                    riser::wallSide(cp.velocity), riser::Vector::Zero(), 0, dt
                );
            p.f() = (p.mass()/mEff)*fromCore(c.force);
            contactTrace trace;
            trace.wallEnergy = -0.5*dt*(workBefore + c.power);
            wallContactEnds(p, trace, t, p.U() - Uwall, n, spin);
            addContactTrace(p, trace);
            // no record accessed: update() below drops the tangential spring
            continue;
        }

        if (!event && unresolvedStart(p, body, (p.U() - Uwall) & n, dt))
        {
            // a contact the plan did not foresee, beginning in a step too
            // long for it. The riser cloud leaves it to the next step,
            // whose plan sub-cycles it from this overlap (its start a
            // fraction of a step late); a stock cloud's sub-cycles are
            // those of the whole cloud, planned for the step: refused
            if (!riserCloud)
            {
                FatalErrorInFunction
                    << "particle " << p.origId() << " (processor "
                    << p.origProc() << ") at " << p.position() << " began"
                    << " a wall contact at t = " << t << " (overlap "
                    << overlap << " m, normal speed "
                    << mag((p.U() - Uwall) & n) << " m/s) in a collision"
                    << " step of " << dt << " s, too long to resolve it,"
                    << " which the step's plan did not foresee; reduce"
                    << " deltaT" << exit(FatalError);
            }
            ++deferredContacts_;
            continue;
        }

        // the tangential spring, kept in the current tangent plane
        vector& spring =
            p.collisionRecords().matchWallRecord(0.99*Rp*n, Rp).collisionData();
        // the normal approach speed at the contact's start (a new one: now)
        const scalar approachSpeed = event ? event->normalSpeedIn : (p.U() - Uwall) & n;
        const riser::ContactStep c =
            riser::stepContact
            (
                *wallLaw_, body, overlap, toCore(n),
                contactSide(p), riser::wallSide(cp.velocity), toCore(spring),
                approachSpeed, dt
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
    if (pairLaw_.valid() && !riserCloud)
    {
        collidePairs();
    }
    // drop the springs of the contacts that were not touched (ended), and
    // the pair contacts in progress with them
    for (parcelType& p : this->owner())
    {
        p.collisionRecords().update();
        if (contactsInProgress* carried = carriedContacts(p))
        {
            carried->keepPairs
            (
                [&p](const labelPair& other)
                {
                    return
                        p.collisionRecords().checkPairRecord
                        (
                            other.first(), other.second()
                        );
                }
            );
        }
    }
}


// * * * * * * * * * * * * * * * * Other parts * * * * * * * * * * * * * * * //

#include "RiserContactPlan.C"
#include "RiserContactMeshFree.C"

// ************************************************************************* //
