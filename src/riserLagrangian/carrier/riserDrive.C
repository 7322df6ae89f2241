/*---------------------------------------------------------------------------*\
  riserFoam: particle transport in vibrating risers, on OpenFOAM
  License: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "riserDrive.H"
#include "checkedEntry.H"
#include "cloudOutputFile.H"
#include "fvMatrices.H"
#include "mathematicalConstants.H"

#include <cmath>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::scalar Foam::riserDrive::maxBulkVelocity = 100;


namespace
{
    // The folder of the time series a run starting at time continues: the
    // latest one whose time is not after the start, else the start's own
    Foam::fileName seriesFolder(const Foam::Time& time)
    {
        using namespace Foam;
        const fileName root = time.globalPath()/"postProcessing"/"riserDrive";
        const scalar start = time.startTime().value();
        const scalar tol = 0.5*time.deltaTValue();
        word folder = time.timeName(start);
        scalar latest = -VGREAT;
        for (const fileName& d : readDir(root, fileName::DIRECTORY))
        {
            scalar t;
            if (readScalar(d, t) && t <= start + tol && t > latest)
            {
                latest = t;
                folder = d;
            }
        }
        return root/folder;
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::riserDrive::riserDrive
(
    const fvMesh& mesh,
    const dictionary& driveDict,
    const scalar uCentre,
    const scalar rho
)
:
    mesh_(mesh),
    rho_(rho),
    target_
    (
        checkedEntry::inRange
        (
            driveDict, "bulkVelocity", 0, true, maxBulkVelocity, true,
            0.5*uCentre
        )
    ),
    relaxation_
    (
        checkedEntry::inRange(driveDict, "relaxation", 0, false, 1, true, 1)
    ),
    pulseAmplitude_
    (
        checkedEntry::inRange
        (
            driveDict, "pulseAmplitude", 0, true, maxBulkVelocity, true, 0
        )
    ),
    pulseFrequency_
    (
        checkedEntry::inRange(driveDict, "pulseFrequency", 0, false, 1e3, true, 0)
    ),
    dpdz_
    (
        IOobject
        (
            "riserDrive",
            mesh.time().timeName(),
            "uniform",
            mesh,
            IOobject::READ_IF_PRESENT,
            IOobject::AUTO_WRITE
        ),
        dimensionedScalar(dimPressure/dimLength, Zero)
    ),
    lastBulk_(0)
{
    checkedEntry::allowedKeys
    (
        driveDict,
        {"bulkVelocity", "relaxation", "pulseAmplitude", "pulseFrequency"}
    );
    if ((pulseAmplitude_ > 0) != (pulseFrequency_ > 0))
    {
        FatalIOErrorInFunction(driveDict)
            << "entry '"
            << (pulseAmplitude_ > 0 ? "pulseAmplitude" : "pulseFrequency")
            << "' without '"
            << (pulseAmplitude_ > 0 ? "pulseFrequency" : "pulseAmplitude")
            << "': a pulsation needs both, pulseAmplitude in (0, "
            << maxBulkVelocity << "] m/s and pulseFrequency in (0, 1e3] Hz"
            << nl << exit(FatalIOError);
    }

    Info<< "Riser drive: bulk velocity " << target_ << " m/s"
        << (driveDict.found("bulkVelocity") ? "" : " (uCentre/2)")
        << pulseText().c_str()
        << ", relaxation " << relaxation_ << ", dp/dz = " << dpdz_.value()
        << " Pa/m at the start" << endl;

    if (Pstream::master())
    {
        const fileName dir = seriesFolder(mesh.time());
        mkDir(dir);
        const fileName file = dir/"drive.dat";
        fileNameList sources;
        if (isFile(file))
        {
            sources.append(file);
        }
        table_ = continuedTable
        (
            file,
            sources,
            "# riserDrive: the uniform pressure gradient driving the carrier"
            " at the bulk velocity " + std::string(Foam::name(target_))
          + pulseText() + " m/s\n"
            "# t [s], dpdz [Pa/m], Ub [m/s] (before the step's last"
            " adjustment)\n"
            "# t dpdz Ub\n",
            0,
            mesh.time()
        );
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::dimensionedVector Foam::riserDrive::acceleration() const
{
    return dimensionedVector
    (
        "riserDrive",
        dimAcceleration,
        vector(0, 0, -dpdz_.value()/rho_)
    );
}


Foam::scalar Foam::riserDrive::bulkVelocity
(
    const volScalarField& alphac,
    const volVectorField& U
) const
{
    const scalarField& V = mesh_.V();
    scalar flow = 0, volume = 0;
    forAll(V, celli)
    {
        flow += alphac[celli]*U[celli].z()*V[celli];
        volume += V[celli];
    }
    reduce(flow, sumOp<scalar>());
    reduce(volume, sumOp<scalar>());
    return flow/volume;
}


Foam::tmp<Foam::scalarField> Foam::riserDrive::response
(
    const fvVectorMatrix& UEqn,
    const volVectorField& U,
    const dictionary& solverControls
) const
{
    // The axial component's matrix: the coefficients and the patches'
    // implicit parts (the response is zero on walls: no boundary source)
    lduMatrix A(UEqn);
    scalarField& diag = A.diag();
    forAll(U.boundaryField(), patchi)
    {
        const labelUList& cells = mesh_.boundary()[patchi].faceCells();
        const vectorField& coeffs = UEqn.internalCoeffs()[patchi];
        forAll(cells, i)
        {
            diag[cells[i]] += coeffs[i].z();
        }
    }

    FieldField<Field, scalar> boundaryCoeffs(UEqn.boundaryCoeffs().component(vector::Z));
    FieldField<Field, scalar> internalCoeffs(UEqn.internalCoeffs().component(vector::Z));

    // a unit acceleration in every cell
    const scalarField source(mesh_.V());
    tmp<scalarField> ts(new scalarField(source.size(), Zero));
    lduMatrix::solver::New
    (
        "riserDriveResponse",
        A,
        boundaryCoeffs,
        internalCoeffs,
        U.boundaryField().scalarInterfaces(),
        solverControls
    )->solve(ts.ref(), source, vector::Z);
    return ts;
}


std::string Foam::riserDrive::pulseText() const
{
    if (pulseAmplitude_ == 0)
    {
        return std::string();
    }
    return
        " + " + std::string(Foam::name(pulseAmplitude_)) + " sin(2 pi "
      + std::string(Foam::name(pulseFrequency_)) + " t)";
}


Foam::scalar Foam::riserDrive::target() const
{
    if (pulseAmplitude_ == 0)
    {
        return target_;
    }
    const scalar t = mesh_.time().value();
    return target_ + pulseAmplitude_*std::sin(constant::mathematical::twoPi*pulseFrequency_*t);
}


void Foam::riserDrive::correct
(
    const volScalarField& alphac,
    const fvVectorMatrix& UEqn,
    volVectorField& U,
    const dictionary& solverControls
)
{
    lastBulk_ = bulkVelocity(alphac, U);

    const scalarField s(response(UEqn, U, solverControls));
    const scalarField& V = mesh_.V();
    scalar gain = 0, volume = 0;
    forAll(V, celli)
    {
        gain += alphac[celli]*s[celli]*V[celli];
        volume += V[celli];
    }
    reduce(gain, sumOp<scalar>());
    reduce(volume, sumOp<scalar>());

    // the acceleration that moves the bulk velocity to the target
    const scalar dG = relaxation_*(target() - lastBulk_)*volume/gain;

    vectorField& Ui = U.primitiveFieldRef();
    forAll(Ui, celli)
    {
        Ui[celli].z() += s[celli]*dG;
    }
    U.correctBoundaryConditions();

    dpdz_.value() -= rho_*dG;
}


void Foam::riserDrive::writeRow()
{
    Info<< "Riser drive: dp/dz = " << dpdz_.value() << " Pa/m, bulk velocity "
        << lastBulk_ << " m/s (target " << target() << ")" << endl;
    if (table_.valid())
    {
        table_() << mesh_.time().value() << ' ' << dpdz_.value() << ' '
            << lastBulk_ << nl;
        table_().flush();
    }
}


// ************************************************************************* //
