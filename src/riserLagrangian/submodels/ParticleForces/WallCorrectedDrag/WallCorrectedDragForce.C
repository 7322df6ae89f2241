/*---------------------------------------------------------------------------*\
  riserFoam: particle transport in vibrating risers, on OpenFOAM
  License: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "WallCorrectedDragForce.H"
#include "modelEntries.H"

// * * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * //

template<class CloudType>
const riser::WallFactors&
Foam::WallCorrectedDragForce<CloudType>::wallFactors(const scalar d) const
{
    if (d != lastDiameter_)
    {
        if (!(d > 0 && d < pipeDiameter_))
        {
            FatalErrorInFunction
                << "particle diameter " << d << " outside (0, pipeDiameter = "
                << pipeDiameter_ << ") in " << this->coeffs().name()
                << exit(FatalError);
        }
        lastFactors_ = riser::WallFactors(d/pipeDiameter_);
        lastDiameter_ = d;
    }
    return lastFactors_;
}


template<class CloudType>
Foam::scalar
Foam::WallCorrectedDragForce<CloudType>::carrierFraction(const label celli) const
{
    // riserCoupledFoam's alphac; DPMFoam's and MPPICFoam's alpha.<phase>,
    // the phase of the carrier's velocity (U.water: alpha.water)
    const word phase(this->owner().U().group());
    const word grouped(IOobject::groupName("alpha", phase.empty() ? word("<phase>") : phase));
    for (const word& name : {word("alphac"), grouped})
    {
        if (this->mesh().template foundObject<volScalarField>(name))
        {
            return this->mesh().template lookupObject<volScalarField>(name)[celli];
        }
    }
    FatalIOErrorInFunction(this->coeffs())
        << "entry 'voidage' of " << this->coeffs().name() << " needs the"
        << " carrier's volume fraction: alphac (riserCoupledFoam) or "
        << grouped << " (DPMFoam, MPPICFoam); this solver has neither"
        << " (one-way: the carrier is not displaced by the particles). Use"
        << " 'voidage none;' or leave it out" << exit(FatalIOError);
    return 1;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::WallCorrectedDragForce<CloudType>::WallCorrectedDragForce
(
    CloudType& owner,
    const fvMesh& mesh,
    const dictionary& dict
)
:
    ParticleForce<CloudType>(owner, mesh, dict, typeName, true),
    carrier_(carrierFlow::ofCloud(owner)),
    law_(modelEntries::dragLaw(this->coeffs())),
    voidage_(modelEntries::dragVoidage(this->coeffs())),
    pipeDiameter_
    (
        modelEntries::pipeDiameter
        (
            this->coeffs(),
            riserModel::New(mesh).found()
          ? &riserModel::New(mesh).flow() : nullptr
        )
    ),
    lastDiameter_(-1),
    lastFactors_(0)
{
    if (voidage_ != riser::Voidage::none && carrier_.exact())
    {
        FatalIOErrorInFunction(this->coeffs())
            << "entry 'voidage' of " << this->coeffs().name() << " with"
            << " 'carrier exact' (constant/riserProperties): the analytic"
            << " carrier is one-way and has no volume fraction; use"
            << " 'voidage none;' or a computed carrier (riserCoupledFoam)"
            << exit(FatalIOError);
    }
}


template<class CloudType>
Foam::WallCorrectedDragForce<CloudType>::WallCorrectedDragForce
(
    const WallCorrectedDragForce<CloudType>& df
)
:
    ParticleForce<CloudType>(df),
    carrier_(df.carrier_),
    law_(df.law_),
    voidage_(df.voidage_),
    pipeDiameter_(df.pipeDiameter_),
    lastDiameter_(df.lastDiameter_),
    lastFactors_(df.lastFactors_)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
void Foam::WallCorrectedDragForce<CloudType>::cacheFields(const bool store)
{
    carrier_.cacheVelocityChange
    (
        store, this->owner().solution().interpolationSchemes()
    );
}


template<class CloudType>
Foam::forceSuSp Foam::WallCorrectedDragForce<CloudType>::calcCoupled
(
    const typename CloudType::parcelType& p,
    const typename CloudType::parcelType::trackingData& td,
    const scalar dt,
    const scalar mass,
    const scalar Re,
    const scalar muc
) const
{
    const riser::WallFactors& factors = wallFactors(p.d());

    // F = (pi d^2/8) rho C_D |w| w = Sp w, with u the carrier at the
    // particle's time: the exact one, or the interpolated one, which is the
    // cloud's Uc (the step's end, whose slip the cloud's Re is) unless the
    // particle is inside a step of a changing carrier. The part Sp Uc is
    // the cloud's, the rest Su
    const vector u = carrier_.velocity(p, td.Uc());
    const scalar ReU =
        !carrier_.exact() && u == td.Uc()
      ? Re
      : riser::particleReynolds(td.rhoc(), mag(u - p.U()), p.d(), muc);
    const scalar eps =
        voidage_ == riser::Voidage::none ? 1 : carrierFraction(p.cell());
    const scalar Sp =
        riser::suspensionDragFactor(law_, factors, p.d(), muc, ReU, voidage_, eps);
    return forceSuSp(Sp*(u - td.Uc()), Sp);
}


// ************************************************************************* //
