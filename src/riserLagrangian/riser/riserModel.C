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
#include "riser/harmonicsMotion.hpp"
#include "riser/modesMotion.hpp"

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
const Foam::scalar Foam::riserModel::maxSlope = 0.05;
const Foam::scalar Foam::riserModel::maxModeNumber = 1000;


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
        if (!uniform_)
        {
            // the sheared riser's carrier and frame terms (riser::RiserFlow,
            // doc/theory.md section 2.2) are the mesh-free engine's; the
            // clouds' frame force, walls and interpolated carriers take
            // the riser as the same at every height
            FatalIOErrorInFunction(dict_)
                << "the riser's motion (type " << lab_->motion().type()
                << ") varies along its length: the clouds of riserParcelFoam"
                << " and riserCoupledFoam take the riser as the same at every"
                << " height; run this riser with the mesh-free engine"
                << " riserParticle, or give a motion the same at every height"
                << " (sinusoid, harmonics)" << nl << exit(FatalIOError);
        }
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


// * * * * * * * * * * * * * * * Reading the motion  * * * * * * * * * * * * //

namespace Foam
{
namespace
{

using rm = riserModel;

//- The sinusoid of the entries A, f or omega, phi0 of dict
riser::MotionPtr readSinusoid(const dictionary& dict)
{
    using checkedEntry::dimensionedInRange;
    using constant::mathematical::twoPi;

    const scalar A =
        dimensionedInRange
        (
            dict, "A", dimLength, 0, true, rm::maxAmplitude, true
        );

    const bool hasF = dict.found("f"), hasOmega = dict.found("omega");
    if (hasF == hasOmega)
    {
        FatalIOErrorInFunction(dict)
            << "give exactly one of the entries 'f' [Hz] and 'omega' [rad/s]"
            << exit(FatalIOError);
    }
    const scalar omega = hasF
      ? twoPi
       *dimensionedInRange
        (
            dict, "f", dimless/dimTime, 0, true, rm::maxFrequency, true
        )
      : dimensionedInRange
        (
            dict, "omega", dimless/dimTime, 0, true, twoPi*rm::maxFrequency, true
        );
    rm::checkWallMotion(dict, A, omega/twoPi);

    const scalar phi0 =
        checkedEntry::inRange(dict, "phi0", -twoPi, true, twoPi, true, 0);

    return riser::SinusoidMotion::make(A, omega, phi0);
}


//- The rows of the list entry key of dict (empty without it), each of N
//  finite numbers within [lo, hi]: a rowName (harmonic, mode) of the
//  form rowForm, its fields named by names (for the messages)
template<int N>
List<FixedList<scalar, N>> readRows
(
    const dictionary& dict,
    const word& key,
    const char* rowName,
    const char* rowForm,
    const char* const (&names)[N],
    const scalar (&lo)[N],
    const scalar (&hi)[N]
)
{
    if (!dict.found(key))
    {
        return List<FixedList<scalar, N>>();
    }
    // numbers only: nan and inf are words to the parser
    for (const token& t : dict.lookup(key))
    {
        if (!t.isNumber() && !t.isPunctuation())
        {
            FatalIOErrorInFunction(dict)
                << "entry '" << key << "': a list of " << rowForm
                << " of finite numbers, found " << t << nl
                << exit(FatalIOError);
        }
    }
    const List<FixedList<scalar, N>> rows =
        dict.get<List<FixedList<scalar, N>>>(key);
    forAll(rows, i)
    {
        for (label k = 0; k < N; ++k)
        {
            const scalar v = rows[i][k];
            if (!(std::isfinite(v) && v >= lo[k] && v <= hi[k]))
            {
                FatalIOErrorInFunction(dict)
                    << "entry '" << key << "' " << rowName << " " << i
                    << ": " << names[k] << " = " << v
                    << " outside the allowed range [" << lo[k] << ", "
                    << hi[k] << "]" << nl << exit(FatalIOError);
            }
        }
    }
    return rows;
}


//- The harmonics of the list entry key of dict (empty without it)
std::vector<riser::Harmonic> readHarmonicList
(
    const dictionary& dict,
    const word& key
)
{
    using constant::mathematical::twoPi;
    std::vector<riser::Harmonic> list;
    for
    (
        const FixedList<scalar, 3>& e
      : readRows<3>
        (
            dict, key, "harmonic",
            "(amplitude [m] frequency [Hz] phase [rad])",
            {"amplitude", "frequency", "phase"},
            {0, 0, -twoPi}, {rm::maxAmplitude, rm::maxFrequency, twoPi}
        )
    )
    {
        list.push_back(riser::Harmonic{e[0], twoPi*e[1], e[2]});
    }
    return list;
}


//- The modes of the list entry key of dict (empty without it)
std::vector<riser::Mode> readModeList(const dictionary& dict, const word& key)
{
    using constant::mathematical::twoPi;
    std::vector<riser::Mode> list;
    for
    (
        const FixedList<scalar, 4>& e
      : readRows<4>
        (
            dict, key, "mode",
            "(n amplitude [m] frequency [Hz] phase [rad])",
            {"n", "amplitude", "frequency", "phase"},
            {1, 0, 0, -twoPi},
            {rm::maxModeNumber, rm::maxAmplitude, rm::maxFrequency, twoPi}
        )
    )
    {
        if (e[0] != std::round(e[0]))
        {
            FatalIOErrorInFunction(dict)
                << "entry '" << key << "': mode number n = " << e[0]
                << " is not a whole number (n = 1, 2, ... "
                << rm::maxModeNumber << ")" << nl << exit(FatalIOError);
        }
        list.push_back
        (
            riser::Mode{static_cast<int>(e[0]), e[1], twoPi*e[2], e[3]}
        );
    }
    return list;
}


//- The modes of a motion dictionary (riserModel.H, Usage)
riser::MotionPtr readModes(const dictionary& m)
{
    checkedEntry::allowedKeys(m, {"type", "foot", "length", "wave", "x", "y"});
    const scalar foot = checkedEntry::inRange
    (
        m, "foot", -1e6, true, 1e6, true
    );
    const scalar length = checkedEntry::inRange
    (
        m, "length", 0, false, 1e6, true
    );
    const riser::ModesMotion::Wave wave =
        m.found("wave")
      ? checkedEntry::choice<riser::ModesMotion::Wave>
        (
            m, "wave",
            {
                {"standing", riser::ModesMotion::Wave::standing},
                {"travelling", riser::ModesMotion::Wave::travelling}
            }
        )
      : riser::ModesMotion::Wave::standing;
    const riser::MotionPtr motion = riser::ModesMotion::make
    (
        foot, length, wave, readModeList(m, "x"), readModeList(m, "y")
    );
    if (motion->maxSlope() > rm::maxSlope)
    {
        FatalIOErrorInFunction(m)
            << "the modes give the riser a slope of up to "
            << motion->maxSlope() << " (hypot of the sums of amplitude n pi"
            << " / length over x and over y); the sheared riser's cross-"
            << "sections and carrier neglect the slope (errors of order"
            << " slope^2), which is allowed up to " << rm::maxSlope
            << ": lower the amplitudes or the mode numbers"
            << nl << exit(FatalIOError);
    }
    return motion;
}


//- The riser's motion of a riserProperties dictionary (riserModel.H, Usage)
riser::MotionPtr readMotion(const dictionary& dict)
{
    if (!dict.found("motion"))
    {
        return readSinusoid(dict);
    }
    for (const char* key : {"A", "f", "omega", "phi0"})
    {
        if (dict.found(key))
        {
            FatalIOErrorInFunction(dict)
                << "entry '" << key << "' beside the dictionary 'motion':"
                << " give the riser's motion once, in 'motion' (or, for a"
                << " sinusoid, as the entries A, f or omega, phi0 alone)"
                << nl << exit(FatalIOError);
        }
    }
    const dictionary& m = dict.subDict("motion");
    enum class motionType { sinusoid, harmonics, modes };
    const motionType type = checkedEntry::choice<motionType>
    (
        m, "type",
        {
            {"sinusoid", motionType::sinusoid},
            {"harmonics", motionType::harmonics},
            {"modes", motionType::modes}
        }
    );
    if (type == motionType::sinusoid)
    {
        checkedEntry::allowedKeys(m, {"type", "A", "f", "omega", "phi0"});
        return readSinusoid(m);
    }

    riser::MotionPtr motion;
    if (type == motionType::harmonics)
    {
        checkedEntry::allowedKeys(m, {"type", "x", "y"});
        motion = riser::HarmonicsMotion::make
        (
            readHarmonicList(m, "x"), readHarmonicList(m, "y")
        );
    }
    else
    {
        motion = readModes(m);
    }
    if
    (
        motion->maxSpeed() > rm::maxSpeed
     || motion->maxAcceleration() > rm::maxAcceleration
    )
    {
        FatalIOErrorInFunction(m)
            << "the " << motion->type() << " give the wall a speed of up to "
            << motion->maxSpeed() << " m/s and an acceleration of up to "
            << motion->maxAcceleration() << " m/s^2 (hypot of the sums of"
            << " amplitude omega and amplitude omega^2 over x and over y);"
            << " a riser's are at most " << rm::maxSpeed << " m/s and "
            << rm::maxAcceleration << " m/s^2" << nl << exit(FatalIOError);
    }
    return motion;
}

} // End anonymous namespace
} // End namespace Foam


riser::RiserFlow Foam::riserModel::read(const dictionary& dict)
{
    using checkedEntry::dimensionedInRange;

    checkedEntry::allowedKeys
    (
        dict,
        {
            "D", "uCentre", "A", "f", "omega", "phi0", "frame", "carrier",
            "drive", "motion"
        }
    );
    const scalar D =
        dimensionedInRange(dict, "D", dimLength, 0, false, maxDiameter, true);
    const scalar uCentre =
        dimensionedInRange(dict, "uCentre", dimVelocity, 0, true, maxSpeed, true);

    return riser::RiserFlow(D, uCentre, readMotion(dict));
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
