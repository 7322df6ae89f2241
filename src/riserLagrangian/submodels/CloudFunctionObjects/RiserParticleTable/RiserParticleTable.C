/*---------------------------------------------------------------------------*\
  riserFoam: particle transport in vibrating risers, on OpenFOAM
  License: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "RiserParticleTable.H"
#include "particleForceEvaluation.H"
#include "checkedEntry.H"
#include "cloudOutputFile.H"
#include "boundBox.H"

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
        os  << "# riserParticleTable, SI units; relative: to the riser axis"
            << " and velocity" << nl
            << "# t origProc origId x y z Ux Uy Uz xr yr Urx Ury Urz lift"
            << " Fc_x Fc_y Fc_z deltaN deltaT";
        for (const auto& force : this->owner().forces())
        {
            const word n = "F_" + force.type();
            os  << ' ' << n << "_x " << n << "_y " << n << "_z";
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
    interval_(this->coeffDict().template lookupOrDefault<label>("interval", 1)),
    length_(boundBox(owner.mesh().points()).span().z())
{
    checkedEntry::checkRange
    (
        this->coeffDict(), "interval", interval_, 1, true, VGREAT, true
    );
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
    const riser::RiserFlow& flow = carrier_.riser();
    const riser::RiserFlow& motion = carrier_.riserMotion();
    const bool labFrame = carrier_.frame() == carrierFlow::simulationFrame::lab;
    const scalar xc = motion.axisPosition(t), Ur = motion.riserVelocity(t);

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
        const scalar lift = x.z() + offset - z0_[key];

        // lab and relative position and velocity
        const point xLab = labFrame ? x : x + vector(xc, 0, 0);
        const vector ULab = labFrame ? p.U() : p.U() + vector(Ur, 0, 0);
        const vector xRel = xLab - vector(xc, 0, 0);
        const vector URel = ULab - vector(Ur, 0, 0);

        // wall overlap and tangential spring
        const scalar h =
            Foam::sqrt(sqr(x.x() - flow.axisPosition(t)) + sqr(x.y()));
        const scalar deltaN = max(0, h + 0.5*p.d() - flow.radius());
        scalar deltaT = 0;
        for (const auto& record : p.collisionRecords().wallRecords())
        {
            deltaT = max(deltaT, mag(record.collisionData()));
        }

        os  << t << ' ' << key.first() << ' ' << key.second() << ' '
            << xLab.x() << ' ' << xLab.y() << ' ' << xLab.z() << ' '
            << ULab.x() << ' ' << ULab.y() << ' ' << ULab.z() << ' '
            << xRel.x() << ' ' << xRel.y() << ' '
            << URel.x() << ' ' << URel.y() << ' ' << URel.z() << ' '
            << lift << ' '
            << p.f().x() << ' ' << p.f().y() << ' ' << p.f().z() << ' '
            << deltaN << ' ' << deltaT;
        for (const vector& F : particleForces(cloud, p, td, dt))
        {
            os  << ' ' << F.x() << ' ' << F.y() << ' ' << F.z();
        }
        os  << nl;
    }
    cloud.forces().cacheFields(false);
    os.flush();
}


// ************************************************************************* //
