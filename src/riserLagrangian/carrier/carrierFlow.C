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
#include "wallFvPatch.H"

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
    riser_(riserModel::New(U.mesh())),
    evaluation_(evaluation::interpolated)
{
    if (riser_.exactCarrier() && !forceInterpolated)
    {
        // a computed flow is the mesh's: the analytic one would replace it
        const dictionary& solvers =
            static_cast<const fvSolution&>(mesh_).subOrEmptyDict("solvers");
        if (solvers.found(U_.name()))
        {
            FatalIOErrorInFunction(riser_.dict())
                << "entry 'carrier' = exact, but system/fvSolution has a solver"
                << " for the carrier " << U_.name() << ": a computed flow must be"
                << " interpolated (set carrier interpolated)"
                << exit(FatalIOError);
        }
        evaluation_ = evaluation::exact;
    }

    Info<< "Carrier flow of " << U_.name() << ": "
        << (exact() ? "exact (analytic riser)" : "interpolated")
        << (
               riser_.frame() == riserModel::simulationFrame::riser
             ? ", riser frame" : ""
           )
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


// * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * * //

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


bool Foam::carrierFlow::movingRiserLab() const
{
    return
        riser_.found()
     && riser_.frame() == riserModel::simulationFrame::lab
     && riser_.motion().maxSpeed() > 0;
}


Foam::vector Foam::carrierFlow::wallMean(const volVectorField& U) const
{
    vector sum(Zero);
    scalar area = 0;
    forAll(U.boundaryField(), patchi)
    {
        if (isA<wallFvPatch>(mesh_.boundary()[patchi]))
        {
            const scalarField& magSf = mesh_.magSf().boundaryField()[patchi];
            sum += gSum(magSf*U.boundaryField()[patchi]);
            area += gSum(magSf);
        }
    }
    if (area == 0)
    {
        FatalErrorInFunction
            << "the riser moves in the lab frame, but the mesh of "
            << U_.name() << " has no wall patch to take its velocity from"
            << exit(FatalError);
    }
    return sum/area;
}


Foam::vector Foam::carrierFlow::wallAcceleration() const
{
    return
        (wallMean(U_) - wallMean(U_.oldTime()))/mesh_.time().deltaTValue();
}


Foam::tmp<Foam::volVectorField>
Foam::carrierFlow::buildMaterialDerivative() const
{
    const tmp<volTensorField> tgradU(fvc::grad(U_));
    tmp<volVectorField> tDuDt;
    if (mesh_.moving())
    {
        // convect with the velocity relative to the moving cells, held as a
        // field of its own: the inner product of a temporary vector field
        // with a tensor field writes its result into the temporary's
        // storage, through pointers the loop declares not to alias
        // (OpenFOAM's List_ACCESS, __restrict__), and a product that mixes
        // the components then reads components it has overwritten (the
        // axial one took the disturbance's sideways convection
        // (u . grad) u_x in place of u_x: half the convection of a
        // particle's wake)
        const volVectorField Urel(U_ - meshVelocity());
        tDuDt = fvc::ddt(U_) + (Urel & tgradU());
    }
    else
    {
        tDuDt = fvc::ddt(U_) + (U_ & tgradU());
    }
    if (movingRiserLab())
    {
        // the carrier's acceleration relative to the riser: its change over
        // the step less its wall's (the riser's), which the particle's
        // Du/Dt takes at the particle's time instead (materialDerivative)
        tDuDt.ref() -=
            dimensionedVector("aWall", dimAcceleration, wallAcceleration());
    }
    return tDuDt;
}


Foam::tmp<Foam::volVectorField> Foam::carrierFlow::buildVelocityChange() const
{
    tmp<volVectorField> tchange(U_ - U_.oldTime());
    steadyStep_ = gMax(mag(tchange().primitiveField())()) == 0;
    if (movingRiserLab())
    {
        wall_.timeIndex = mesh_.time().timeIndex();
        wall_.end = wallMean(U_);
        wall_.start = wallMean(U_.oldTime());
    }
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
