/*---------------------------------------------------------------------------*\
  riserFoam: particle transport in vibrating risers, on OpenFOAM
  License: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "LangevinDispersionRAS.H"
#include "checkedEntry.H"
#include "coreVector.H"
#include "dispersion/langevinSeenVelocity.hpp"
#include "turbulenceModel.H"
#include "fvcGrad.H"
#include "riserModel.H"
#include "carrier/tabulatedPipeProfile.hpp"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::LangevinDispersionRAS<CloudType>::LangevinDispersionRAS
(
    const dictionary& dict,
    CloudType& owner
)
:
    DispersionModel<CloudType>(owner),
    Sct_(checkedEntry::inRange(coeffs(dict), "Sct", 0.1, true, 10, true, 0.7)),
    beta_(checkedEntry::inRange(coeffs(dict), "beta", 0, true, 10, true, 1))
{
    checkedEntry::allowedKeys(coeffs(dict), {"Sct", "beta"});
}


template<class CloudType>
Foam::LangevinDispersionRAS<CloudType>::LangevinDispersionRAS
(
    const LangevinDispersionRAS<CloudType>& dm
)
:
    DispersionModel<CloudType>(dm),
    Sct_(dm.Sct_),
    beta_(dm.beta_)
{}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class CloudType>
const Foam::dictionary& Foam::LangevinDispersionRAS<CloudType>::coeffs
(
    const dictionary& dict
)
{
    const word name(typeName + "Coeffs");
    return dict.found(name) ? dict.subDict(name) : dictionary::null;
}


template<class CloudType>
void Foam::LangevinDispersionRAS<CloudType>::cache()
{
    if (keepProfileFields_ && sigma_.valid())
    {
        return;
    }
    // The carrier's turbulence model, looked up at the first step (the
    // coupled solvers build it after the cloud)
    const fvMesh& mesh = this->owner().mesh();
    const word name
    (
        IOobject::groupName
        (
            turbulenceModel::propertiesName, this->owner().U().group()
        )
    );
    const turbulenceModel* turbulence = mesh.findObject<turbulenceModel>(name);
    if (!turbulence || turbulence->get<word>("simulationType") == "laminar")
    {
        const riser::TabulatedPipeProfile* profile = tabulatedProfile();
        if (!profile)
        {
            FatalIOErrorInFunction(this->owner().subModelProperties())
                << "entry 'dispersionModel' = " << typeName << " in the cloud "
                << this->owner().name() << " needs the carrier's turbulence"
                << " (k and nut of a RAS model, constant/" << name << ", or of"
                << " the analytic carrier's profile tabulated,"
                << " constant/riserProperties): "
                << (turbulence ? "the carrier is laminar" : "this solver has no"
                    " turbulence model, and the riser's carrier no tabulated"
                    " profile")
                << ". Use 'dispersionModel none;', a RAS carrier"
                << " (riserCoupledFoam, DPMFoam, MPPICFoam,"
                << " uncoupledKinematicParcelFoam) or profile tabulated"
                << nl << exit(FatalIOError);
        }
        cacheProfile(*profile);
        return;
    }

    const tmp<volScalarField> tk(turbulence->k());
    sigma_.reset
    (
        new volScalarField
        (
            "langevinSigma",
            sqrt(2.0/3.0*max(tk(), dimensionedScalar("zero", tk().dimensions(), 0)))
        )
    );
    gradSigma_.reset
    (
        new volVectorField("langevinGradSigma", fvc::grad(sigma_()))
    );
    nut_.reset(new volScalarField("langevinNut", turbulence->nut()));
}


template<class CloudType>
const riser::TabulatedPipeProfile*
Foam::LangevinDispersionRAS<CloudType>::tabulatedProfile() const
{
    const riserModel& riser = riserModel::New(this->owner().mesh());
    if (!riser.found())
    {
        return nullptr;
    }
    return dynamic_cast<const riser::TabulatedPipeProfile*>(riser.flow().profile());
}


template<class CloudType>
void Foam::LangevinDispersionRAS<CloudType>::cacheProfile
(
    const riser::TabulatedPipeProfile& profile
)
{
    const fvMesh& mesh = this->owner().mesh();
    const riser::RiserFlow& flow = riserModel::New(mesh).flow();
    const scalar t = mesh.time().value();
    auto newField = [&](const word& field, const dimensionSet& dims)
    {
        return new volScalarField
        (
            IOobject
            (
                field, mesh.time().timeName(), mesh,
                IOobject::NO_READ, IOobject::NO_WRITE, false
            ),
            mesh,
            dimensionedScalar("zero", dims, 0)
        );
    };
    sigma_.reset(newField("langevinSigma", dimVelocity));
    nut_.reset(newField("langevinNut", dimViscosity));
    // sigma and nu_t at a point's distance from the axis
    auto set = [&](const point& x, scalar& sigma, scalar& nut)
    {
        const scalar r = mag(fromCore(flow.motion().radialOffset(toCore(x), t)));
        sigma = Foam::sqrt(2.0/3.0*profile.turbulentEnergy(r));
        nut = profile.eddyViscosity(r);
    };
    forAll(mesh.C(), celli)
    {
        set(mesh.C()[celli], sigma_()[celli], nut_()[celli]);
    }
    forAll(mesh.boundary(), patchi)
    {
        fvPatchScalarField& sp = sigma_->boundaryFieldRef()[patchi];
        fvPatchScalarField& np = nut_->boundaryFieldRef()[patchi];
        if (sp.coupled())
        {
            continue;
        }
        forAll(sp, facei)
        {
            set(mesh.Cf().boundaryField()[patchi][facei], sp[facei], np[facei]);
        }
    }
    sigma_->correctBoundaryConditions();
    nut_->correctBoundaryConditions();
    gradSigma_.reset
    (
        new volVectorField("langevinGradSigma", fvc::grad(sigma_()))
    );
    keepProfileFields_ = !mesh.moving();
}


template<class CloudType>
Foam::vector Foam::LangevinDispersionRAS<CloudType>::normalVector() const
{
    Random& rnd = this->owner().rndGen();
    const scalar x = rnd.GaussNormal<scalar>();
    const scalar y = rnd.GaussNormal<scalar>();
    const scalar z = rnd.GaussNormal<scalar>();
    return vector(x, y, z);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
void Foam::LangevinDispersionRAS<CloudType>::cacheFields(const bool store)
{
    if (store)
    {
        cache();
    }
    else if (!keepProfileFields_)
    {
        sigma_.clear();
        gradSigma_.clear();
        nut_.clear();
    }
}


template<class CloudType>
Foam::vector Foam::LangevinDispersionRAS<CloudType>::update
(
    const scalar dt,
    const label celli,
    const vector& U,
    const vector& Uc,
    vector& UTurb,
    scalar& tTurb
)
{
    if (!sigma_.valid())
    {
        cache();
    }
    const scalar sigma = sigma_()[celli];
    const scalar nut = nut_()[celli];
    if (!(sigma > 0) || !(nut > 0))
    {
        // no turbulence here: the mean carrier, and a fresh draw where
        // there is turbulence again
        UTurb = Zero;
        tTurb = 0;
        return Uc;
    }

    // the normalised fluctuation: carried, or drawn from its stationary
    // distribution (a new parcel, or one from a cell without turbulence)
    const vector chi0 = tTurb > 0 ? UTurb/tTurb : normalVector();
    if (!(dt > 0))
    {
        UTurb = sigma*chi0;
        tTurb = sigma;
        return Uc + UTurb;
    }

    const scalar slip = mag(U - Uc - sigma*chi0);
    const scalar T = riser::crossingTrajectoryTime
    (
        riser::lagrangianTime(nut, Sct_, sigma), beta_, slip, sigma
    );
    const vector xi1 = normalVector();
    const vector xi2 = normalVector();
    const riser::LangevinStep step = riser::langevinStep
    (
        toCore(chi0), toCore(gradSigma_()[celli]), T, dt, toCore(xi1), toCore(xi2)
    );
    UTurb = sigma*fromCore(step.chiEnd);
    tTurb = sigma;
    return Uc + sigma*fromCore(step.chiMean);
}


// ************************************************************************* //
