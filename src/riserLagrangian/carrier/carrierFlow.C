/*---------------------------------------------------------------------------*\
  riserFoam: particle transport in vibrating risers, on OpenFOAM
  License: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "carrierFlow.H"
#include "checkedEntry.H"
#include "fvcCurl.H"
#include "fvcDdt.H"
#include "fvcGrad.H"
#include "fvMesh.H"
#include "IOdictionary.H"
#include "unitConversion.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(carrierFlow, 0);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

namespace
{
    // The name under which the carrier of field U is registered
    Foam::word registeredName(const Foam::volVectorField& U)
    {
        return Foam::carrierFlow::typeName + '(' + U.name() + ')';
    }
}


Foam::carrierFlow::carrierFlow
(
    const volVectorField& U,
    const bool forceInterpolated
)
:
    regIOobject
    (
        IOobject
        (
            registeredName(U),
            U.mesh().time().constant(),
            U.mesh(),
            IOobject::NO_READ,
            IOobject::NO_WRITE
        )
    ),
    mesh_(U.mesh()),
    U_(U),
    evaluation_(evaluation::interpolated),
    frame_(simulationFrame::lab),
    flowSteady_(false)
{
    IOobject io
    (
        "riserProperties",
        mesh_.time().constant(),
        mesh_,
        IOobject::MUST_READ,
        IOobject::NO_WRITE,
        false
    );

    if (io.typeHeaderOk<IOdictionary>(true))
    {
        const IOdictionary dict(io);
        motion_.reset(new riser::RiserFlow(readRiser(dict)));
        frame_ = dict.found("frame")
          ? checkedEntry::choice<simulationFrame>
            (
                dict, "frame",
                {{"lab", simulationFrame::lab}, {"riser", simulationFrame::riser}}
            )
          : simulationFrame::lab;
        riser_.reset
        (
            frame_ == simulationFrame::lab
          ? new riser::RiserFlow(*motion_)
          : new riser::RiserFlow
            (
                motion_->diameter(), motion_->centreLineSpeed(), riser::RiserMotion::atRest()
            )
        );
        flowSteady_ = riser_->motion().omega() == 0;
        if (flowSteady_)
        {
            lastMotion_.flow = riser_->motion().state(0);
        }
        if (dict.found("carrier"))
        {
            evaluation_ = checkedEntry::choice<evaluation>
            (
                dict, "carrier",
                {{"exact", evaluation::exact},
                 {"interpolated", evaluation::interpolated}}
            );
        }

        // a computed flow is the mesh's: the analytic one would replace it
        const dictionary& solvers =
            static_cast<const fvSolution&>(mesh_).subOrEmptyDict("solvers");
        if (exact() && !forceInterpolated && solvers.found(U_.name()))
        {
            FatalIOErrorInFunction(dict)
                << "entry 'carrier' = exact, but system/fvSolution has a solver"
                << " for the carrier " << U_.name() << ": a computed flow must be"
                << " interpolated (set carrier interpolated)"
                << exit(FatalIOError);
        }
    }
    if (forceInterpolated)
    {
        evaluation_ = evaluation::interpolated;
    }

    Info<< "Carrier flow of " << U_.name() << ": "
        << (exact() ? "exact (analytic riser)" : "interpolated")
        << (frame_ == simulationFrame::riser ? ", riser frame" : "")
        << endl;
}


// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::carrierFlow& Foam::carrierFlow::New(const volVectorField& U)
{
    const fvMesh& mesh = U.mesh();
    const word name(registeredName(U));
    if (!mesh.foundObject<carrierFlow>(name))
    {
        carrierFlow* ptr = new carrierFlow(U);
        ptr->store();
    }
    return mesh.lookupObjectRef<carrierFlow>(name);
}


const Foam::scalar Foam::carrierFlow::maxDiameter = 10;
const Foam::scalar Foam::carrierFlow::maxSpeed = 100;
const Foam::scalar Foam::carrierFlow::maxAmplitude = 10;
const Foam::scalar Foam::carrierFlow::maxFrequency = 1000;
const Foam::scalar Foam::carrierFlow::maxAcceleration = 1e4;


void Foam::carrierFlow::checkWallMotion
(
    const dictionary& dict,
    const scalar A,
    const scalar f
)
{
    const scalar omega = constant::mathematical::twoPi*f;
    if (A*omega > maxSpeed || A*omega*omega > maxAcceleration)
    {
        FatalIOErrorInFunction(dict)
            << "entries 'A' = " << A << " m and 'f' = " << f << " Hz (omega = "
            << omega << " rad/s) give the wall a speed A omega = " << A*omega
            << " m/s and an acceleration A omega^2 = " << A*omega*omega
            << " m/s^2; a riser's are at most " << maxSpeed << " m/s and "
            << maxAcceleration << " m/s^2" << nl << exit(FatalIOError);
    }
}


riser::RiserFlow Foam::carrierFlow::readRiser(const dictionary& dict)
{
    using checkedEntry::dimensionedInRange;
    using constant::mathematical::twoPi;

    checkedEntry::allowedKeys
    (
        dict,
        {"D", "uCentre", "A", "f", "omega", "phi0", "frame", "carrier", "drive"}
    );
    const scalar D =
        dimensionedInRange(dict, "D", dimLength, 0, false, maxDiameter, true);
    const scalar uCentre =
        dimensionedInRange(dict, "uCentre", dimVelocity, 0, true, maxSpeed, true);
    const scalar A =
        dimensionedInRange(dict, "A", dimLength, 0, true, maxAmplitude, true);

    const bool hasF = dict.found("f"), hasOmega = dict.found("omega");
    if (hasF == hasOmega)
    {
        FatalIOErrorInFunction(dict)
            << "give exactly one of the entries 'f' [Hz] and 'omega' [rad/s]"
            << exit(FatalIOError);
    }
    const scalar omega = hasF
      ? twoPi
       *dimensionedInRange(dict, "f", dimless/dimTime, 0, true, maxFrequency, true)
      : dimensionedInRange
        (
            dict, "omega", dimless/dimTime, 0, true, twoPi*maxFrequency, true
        );
    checkWallMotion(dict, A, omega/twoPi);

    const scalar phi0 =
        checkedEntry::inRange(dict, "phi0", -twoPi, true, twoPi, true, 0);

    return riser::RiserFlow(D, uCentre, A, omega, phi0);
}


// * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * * //

const riser::RiserFlow& Foam::carrierFlow::riser() const
{
    if (!riser_)
    {
        FatalErrorInFunction
            << "no analytic riser: constant/riserProperties is missing"
            << exit(FatalError);
    }
    return *riser_;
}


const riser::RiserMotion& Foam::carrierFlow::riserMotion() const
{
    riser();
    return motion_->motion();
}


Foam::tmp<Foam::volVectorField> Foam::carrierFlow::buildVorticity() const
{
    return fvc::curl(U_);
}


Foam::tmp<Foam::volVectorField> Foam::carrierFlow::meshVelocity() const
{
    // The mean velocity of each cell's (and boundary face's) points over the
    // step: exact for a translating or rotating mesh at the centroid to
    // second order. (fvc::reconstruct(mesh.phi()) gave wrong values in
    // cells next to the curved wall of the riser O-grid on v1912.)
    const pointField& p = mesh_.points();
    const pointField& p0 = mesh_.oldPoints();
    const scalar rDeltaT = 1/mesh_.time().deltaTValue();

    tmp<volVectorField> tUmesh
    (
        new volVectorField
        (
            IOobject("carrierMeshVelocity", mesh_.time().timeName(), mesh_),
            mesh_,
            dimensionedVector(dimVelocity, Zero)
        )
    );
    volVectorField& Umesh = tUmesh.ref();

    auto mean = [&](const labelUList& pointLabels)
    {
        vector sum(Zero);
        for (const label pointi : pointLabels)
        {
            sum += p[pointi] - p0[pointi];
        }
        return rDeltaT*sum/pointLabels.size();
    };

    vectorField& Ui = Umesh.primitiveFieldRef();
    forAll(Ui, celli)
    {
        Ui[celli] = mean(mesh_.cellPoints()[celli]);
    }
    forAll(Umesh.boundaryField(), patchi)
    {
        fvPatchVectorField& Up = Umesh.boundaryFieldRef()[patchi];
        const label start = mesh_.boundaryMesh()[patchi].start();
        forAll(Up, facei)
        {
            Up[facei] = mean(mesh_.faces()[start + facei]);
        }
    }
    return tUmesh;
}


Foam::tmp<Foam::volVectorField>
Foam::carrierFlow::buildMaterialDerivative() const
{
    if (mesh_.moving())
    {
        // convect with the velocity relative to the moving cells
        return fvc::ddt(U_) + ((U_ - meshVelocity()) & fvc::grad(U_));
    }
    return fvc::ddt(U_) + (U_ & fvc::grad(U_));
}


Foam::tmp<Foam::volVectorField> Foam::carrierFlow::buildVelocityChange() const
{
    tmp<volVectorField> tchange(U_ - U_.oldTime());
    steadyStep_ = gMax(mag(tchange().primitiveField())()) == 0;
    return tchange;
}


const Foam::interpolation<Foam::vector>&
Foam::carrierFlow::interpolator(const cachedField& c) const
{
    if (!c.field)
    {
        FatalErrorInFunction
            << "carrier field requested outside cacheFields(true/false)"
            << abort(FatalError);
    }
    if (!c.interp)
    {
        c.interp.reset(interpolation<vector>::New(c.scheme, *c.field).ptr());
    }
    return *c.interp;
}


void Foam::carrierFlow::cache
(
    cachedField& c,
    const bool store,
    const dictionary& interpolationSchemes,
    const word& name,
    tmp<volVectorField> (carrierFlow::*build)() const
)
{
    if (exact())
    {
        return;
    }
    if (store)
    {
        if (c.users++ == 0)
        {
            c.field.reset(new volVectorField(name, (this->*build)()));
            // interpolated with the scheme the cloud uses for U
            c.scheme = interpolationSchemes.get<word>(U_.name());
        }
    }
    else if (c.users > 0 && --c.users == 0)
    {
        c.interp.reset();
        c.field.reset();
    }
}


void Foam::carrierFlow::cacheVorticity
(
    const bool store,
    const dictionary& schemes
)
{
    cache(vorticity_, store, schemes, "carrierVorticity", &carrierFlow::buildVorticity);
}


void Foam::carrierFlow::cacheMaterialDerivative
(
    const bool store,
    const dictionary& schemes
)
{
    cache
    (
        materialDerivative_, store, schemes,
        "carrierMaterialDerivative", &carrierFlow::buildMaterialDerivative
    );
}


void Foam::carrierFlow::cacheVelocityChange
(
    const bool store,
    const dictionary& schemes
)
{
    cache
    (
        velocityChange_, store, schemes,
        "carrierVelocityChange", &carrierFlow::buildVelocityChange
    );
}


// ************************************************************************* //
