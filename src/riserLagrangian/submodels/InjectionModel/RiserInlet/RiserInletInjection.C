/*---------------------------------------------------------------------------*\
  riserFoam: particle transport in vibrating risers, on OpenFOAM
  License: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "RiserInletInjection.H"
#include "cyclicPolyPatch.H"
#include "riserFoamVersion.H"

// * * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * //

template<class CloudType>
void Foam::RiserInletInjection<CloudType>::place(const scalar t, const scalar dt)
{
    oreSource& source = *this->source_;
    const scalar gap = source.gap();
    // every ore within reach of a new one: below the slab of the step
    // (release speeds are at most 100 m/s) and an ore's reach above it
    const scalar zReach = z0_ + 2*(source.maxDiameter() + gap) + 100*dt;

    List<List<vector>> nearAll(Pstream::nProcs());
    List<scalarList> nearAllD(Pstream::nProcs());
    {
        DynamicList<vector> x;
        DynamicList<scalar> d;
        for (const auto& p : this->owner())
        {
            const point xp = p.position();
            const vector offset = xp - this->axisPoint(xp.z(), t);
            if (offset.z() < zReach)
            {
                x.append(offset);
                d.append(p.d());
            }
        }
        nearAll[Pstream::myProcNo()].transfer(x);
        nearAllD[Pstream::myProcNo()].transfer(d);
    }
    riserCompatibility::allGatherList(nearAll);
    riserCompatibility::allGatherList(nearAllD);
    const DynamicList<vector>& places = this->places_;
    const DynamicList<scalar>& diameters = this->diameters_;
    DynamicList<vector> nearX;
    DynamicList<scalar> nearD;
    for (label proci = 0; proci < Pstream::nProcs(); ++proci)
    {
        nearX.append(nearAll[proci]);
        nearD.append(nearAllD[proci]);
    }
    // whether an ore of radius r at x keeps the gap from the ores at xs of
    // diameters ds
    auto keepsGap = [gap]
    (
        const vector& x, const scalar r, const UList<vector>& xs,
        const UList<scalar>& ds
    )
    {
        forAll(xs, j)
        {
            const scalar reach = r + 0.5*ds[j] + gap;
            if (magSqr(x - xs[j]) < reach*reach)
            {
                return false;
            }
        }
        return true;
    };

    const scalar t1 = t - this->SOI_;
    scalar due =
        massFlowRate_*min(t1, duration_) - this->massInjected_;
    while (due >= 0.5*next_.rho*next_.volume())
    {
        const scalar r = 0.5*next_.d;
        bool done = false;
        for (label attempt = 0; attempt < source.maxAttempts() && !done; ++attempt)
        {
            vector x = source.discPoint(next_.d);
            const scalar rise = max
            (
                scalar(0), source.velocity(this->axisPoint(z0_, t) + x, t).z()*dt
            );
            x.z() = z0_ + r + gap + rise*source.uniform01();
            done =
                keepsGap(x, r, nearX, nearD)
             && keepsGap(x, r, places, diameters);
            if (done)
            {
                this->addOre(x, next_);
            }
        }
        if (!done)
        {
            FatalIOErrorInFunction(this->coeffDict())
                << "entry 'massFlowRate' = " << massFlowRate_ << " kg/s: at t = "
                << t << " an ore (d = " << next_.d << " m) found no place at the"
                << " inlet in " << source.maxAttempts() << " attempts, with "
                << places.size() << " ores released in this step and "
                << nearX.size() << " near the inlet: the stream is too dense for the"
                << " inlet, or its release velocity does not carry it into the"
                << " riser; lower massFlowRate or release the ores faster"
                << nl << exit(FatalIOError);
        }
        due -= next_.rho*next_.volume();
        next_ = source.draw();
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::RiserInletInjection<CloudType>::RiserInletInjection
(
    const dictionary& dict,
    CloudType& owner,
    const word& modelName
)
:
    RiserOreInjection<CloudType>
    (
        dict, owner, modelName, typeName, {"duration", "massFlowRate"}
    ),
    duration_
    (
        checkedEntry::inRange(this->coeffDict(), "duration", 0, false, VGREAT, true)
    ),
    massFlowRate_
    (
        checkedEntry::inRange
        (
            this->coeffDict(), "massFlowRate", 0, false, VGREAT, true
        )
    ),
    z0_(0),
    next_(this->source_->draw())
{
    const polyMesh& mesh = owner.mesh();
    for (const polyPatch& patch : mesh.boundaryMesh())
    {
        if (isA<cyclicPolyPatch>(patch))
        {
            FatalIOErrorInFunction(this->coeffDict())
                << "riserInlet needs an open riser; the mesh has the cyclic"
                << " patch " << patch.name() << " (a periodic riser has no"
                << " inlet: fill it with riserFill)" << nl
                << exit(FatalIOError);
        }
    }
    if (!this->source_->carrierVelocity())
    {
        const vector U0 = this->source_->velocity(Zero, owner.db().time().value());
        if (U0.z() < 0)
        {
            FatalIOErrorInFunction(this->coeffDict())
                << "entry 'U0' = " << U0 << ": riserInlet releases the ores"
                << " into the riser at the inlet disc, so U0's z component"
                << " must be >= 0 (allowed: [0, 100] m/s); with U0_z < 0"
                << " they would leave through the inlet" << nl
                << exit(FatalIOError);
        }
    }
    z0_ = this->riser_.section().z0;
    const scalar D = this->riser_.flow().diameter();
    this->source_->checkDiameters
    (
        this->coeffDict(),
        D - 2*this->source_->gap(),
        "riser D = " + Foam::name(D) + " m"
    );
    this->volumeTotal_ = massFlowRate_*duration_;
    Info<< "    riserInlet: " << massFlowRate_ << " kg/s of ores through the"
        << " inlet disc at z = " << z0_ << " m from t = " << this->SOI_
        << " s for " << duration_ << " s" << endl;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
Foam::label Foam::RiserInletInjection<CloudType>::parcelsToInject
(
    const scalar time0,
    const scalar time1
)
{
    this->clearOres();
    if (time0 < duration_ && time1 > time0)
    {
        place(this->SOI_ + time1, time1 - time0);
    }
    return this->places_.size();
}


template<class CloudType>
Foam::scalar Foam::RiserInletInjection<CloudType>::volumeToInject
(
    const scalar,
    const scalar
)
{
    // the ores parcelsToInject placed for this step
    scalar V = 0;
    for (const scalar d : this->diameters_)
    {
        V += constant::mathematical::pi/6*pow3(d);
    }
    return V;
}


// ************************************************************************* //
