/*---------------------------------------------------------------------------*\
  riserFoam: particle transport in vibrating risers, on OpenFOAM
  License: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "RiserWallContact.H"
#include "modelEntries.H"
#include "cloudOutputFile.H"
#include "coreVector.H"
#include "HistoryParcel.H"

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
    addedMassCoeff_(readAddedMassCoeff())
{
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
    events_(cm.events_),
    lost_(cm.lost_)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
Foam::label Foam::RiserWallContact<CloudType>::nearWallSubCycles
(
    const parcelType& p
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
    const scalar speed = mag(p.U()) + flow.motion().maxSpeed();
    if (gap > speed*dt)
    {
        return 0;
    }
    const riser::ContactBody body(0.5*p.d(), effectiveMass(p));
    const scalar tc = law_.contactTime(body, max(speed, SMALL));
    // as a scalar first: no overflow of the label
    const scalar needed = ceil(stepsPerContact_*dt/tc);
    if (!(needed <= maxSubCycles_))
    {
        FatalErrorInFunction
            << "particle " << p.origId() << " (processor " << p.origProc()
            << ") at " << p.position() << " needs " << needed
            << " sub-cycles of the step deltaT = " << dt << " to resolve"
            << " its wall contact (contact time " << tc << " s, "
            << stepsPerContact_ << " sub-cycles each), more than"
            << " maxSubCycles = " << maxSubCycles_ << ": reduce deltaT or"
            << " raise maxSubCycles" << exit(FatalError);
    }
    return max(label(needed), label(1));
}


template<class CloudType>
Foam::label Foam::RiserWallContact<CloudType>::subCycles(const parcelType& p) const
{
    return max(nearWallSubCycles(p), label(1));
}


template<class CloudType>
Foam::label Foam::RiserWallContact<CloudType>::nSubCycles() const
{
    label nSub = 1, nNear = 0;
    for (const parcelType& p : this->owner())
    {
        const label n = nearWallSubCycles(p);
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
        Info<< "    riserWallContact: " << nNear << " particle(s) near the wall"
            << endl;
    }
    return nSub;
}


template<class CloudType>
void Foam::RiserWallContact<CloudType>::collide()
{
    const Time& time = this->owner().mesh().time();
    const riser::Wall& wall = carrier_.wall();
    const scalar t = time.value();
    const scalar dt = time.deltaTValue();

    for (parcelType& p : this->owner())
    {
        p.f() = Zero;
        p.torque() = Zero;

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
            // no record accessed: update() drops the tangential spring
            p.collisionRecords().update();
            continue;
        }

        const vector n = fromCore(cp.normal);
        const vector U = p.U() - Uwall + (spin ^ (Rp*n));

        // the tangential spring, kept in the current tangent plane
        vector& spring =
            p.collisionRecords().matchWallRecord(0.99*Rp*n, Rp).collisionData();
        const vector inPlane = spring - (spring & n)*n;
        const scalar magInPlane = mag(inPlane);
        spring =
            (magInPlane > VSMALL ? mag(spring)/magInPlane*inPlane : vector::zero)
          + (U - (U & n)*n)*dt;

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
        p.collisionRecords().update();

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
}


// ************************************************************************* //
