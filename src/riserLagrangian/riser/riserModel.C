/*---------------------------------------------------------------------------*\
  riserFoam: particle transport in vibrating risers, on OpenFOAM
  License: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "riserModel.H"
#include "checkedEntry.H"
#include "boundBox.H"
#include "cyclicPolyPatch.H"
#include "IOdictionary.H"
#include "unitConversion.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(riserModel, 0);
}

const Foam::scalar Foam::riserModel::maxDiameter = 10;
const Foam::scalar Foam::riserModel::maxSpeed = 100;
const Foam::scalar Foam::riserModel::maxAmplitude = 10;
const Foam::scalar Foam::riserModel::maxFrequency = 1000;
const Foam::scalar Foam::riserModel::maxAcceleration = 1e4;


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::riserModel::riserModel(const polyMesh& mesh)
:
    regIOobject
    (
        IOobject
        (
            typeName,
            mesh.time().constant(),
            mesh,
            IOobject::NO_READ,
            IOobject::NO_WRITE
        )
    ),
    mesh_(mesh),
    frame_(simulationFrame::lab),
    exactCarrier_(false),
    steady_(false),
    uniform_(true)
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
        dict_ = IOdictionary(io);
        lab_.reset(new riser::RiserFlow(read(dict_)));
        if (dict_.found("frame"))
        {
            frame_ = checkedEntry::choice<simulationFrame>
            (
                dict_, "frame",
                {{"lab", simulationFrame::lab}, {"riser", simulationFrame::riser}}
            );
        }
        if (dict_.found("carrier"))
        {
            exactCarrier_ = checkedEntry::choice<bool>
            (
                dict_, "carrier", {{"exact", true}, {"interpolated", false}}
            );
        }
        flow_.reset
        (
            frame_ == simulationFrame::lab
          ? new riser::RiserFlow(*lab_)
          : new riser::RiserFlow
            (
                lab_->diameter(), lab_->centreLineSpeed(),
                riser::SinusoidMotion::atRest()
            )
        );
        steady_ = flow_->motion().steady();
        uniform_ = lab_->motion().uniformAlongAxis();
        if (steady_)
        {
            last_.flow = flow_->motion().state(0, 0);
        }
    }

    // The section the mesh holds
    const boundBox bb(mesh_.points(), true);
    bool periodic = false;
    for (const polyPatch& patch : mesh_.boundaryMesh())
    {
        periodic = periodic || isA<cyclicPolyPatch>(patch);
    }
    section_ = sectionExtent
    {
        bb.min().z(), bb.max().z() - bb.min().z(), periodic,
        gSum(mesh_.cellVolumes())
    };
}


// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

const Foam::riserModel& Foam::riserModel::New(const polyMesh& mesh)
{
    if (!mesh.foundObject<riserModel>(typeName))
    {
        riserModel* ptr = new riserModel(mesh);
        ptr->store();
    }
    return mesh.lookupObject<riserModel>(typeName);
}


void Foam::riserModel::checkWallMotion
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


riser::RiserFlow Foam::riserModel::read(const dictionary& dict)
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

Foam::scalar Foam::riserModel::angularFrequency
(
    const dictionary& dict,
    const string& what
) const
{
    try
    {
        return motion().angularFrequency();
    }
    catch (const std::domain_error&)
    {
        FatalIOErrorInFunction(dict)
            << what << " needs the riser's frequency, but its motion ("
            << motion().type() << ", constant/riserProperties) has several"
            << exit(FatalIOError);
    }
    return 0;
}


void Foam::riserModel::requireRiser() const
{
    if (!lab_)
    {
        FatalErrorInFunction
            << "no riser: constant/riserProperties is missing (the riser's"
            << " diameter D, centre-line speed uCentre, motion A, f and"
            << " frame; see the user guide)" << exit(FatalError);
    }
}


// ************************************************************************* //
