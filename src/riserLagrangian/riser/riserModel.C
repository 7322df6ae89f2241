/*---------------------------------------------------------------------------*\
  riserFoam: particle transport in vibrating risers, on OpenFOAM
  License: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "riserModel.H"
#include "checkedEntry.H"
#include "boundBox.H"
#include "cyclicPolyPatch.H"
#include "IOdictionary.H"
#include "IFstream.H"
#include "unitConversion.H"
#include "riser/harmonicsMotion.hpp"
#include "riser/modesMotion.hpp"
#include "riser/tableMotion.hpp"
#include "carrier/tabulatedPipeProfile.hpp"
#include "carrier/turbulentPipeProfile.hpp"

#include <fstream>
#include <sstream>

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
const Foam::scalar Foam::riserModel::minTurbulentRe = 4000;


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
        dict_ = readProperties(mesh_.time())();
        lab_.reset(new riser::RiserFlow(read(dict_)));
        noteLaminarCarrier(dict_, *lab_);
        frame_ = checkedEntry::choiceOrDefault
        (
            dict_, "frame",
            {{"lab", simulationFrame::lab}, {"riser", simulationFrame::riser}},
            frame_
        );
        exactCarrier_ = checkedEntry::choiceOrDefault
        (
            dict_, "carrier", {{"exact", true}, {"interpolated", false}},
            exactCarrier_
        );
        flow_.reset
        (
            frame_ == simulationFrame::lab
          ? new riser::RiserFlow(*lab_)
          : new riser::RiserFlow
            (
                lab_->withMotion(riser::SinusoidMotion::atRest())
            )
        );
        steady_ = flow_->motion().steady();
        uniform_ = lab_->motion().uniformAlongAxis();
        if (!uniform_ && !exactCarrier_)
        {
            // the sheared riser's carrier (doc/theory.md section 2.6) is
            // the exact one's: an interpolated carrier has no slope terms
            FatalIOErrorInFunction(dict_)
                << "the riser's motion (type " << lab_->motion().type()
                << ") varies along its length: a cloud runs it with the exact"
                << " carrier only (carrier exact; in the riser's frame, or in"
                << " the lab on a mesh that deforms with it), or run it with"
                << " the mesh-free engine riserParticle"
                << nl << exit(FatalIOError);
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
    if (lab_ && !uniform_ && periodic)
    {
        // a particle's height in a periodic section is wrapped, and the
        // riser's motion differs at the section's two ends
        FatalIOErrorInFunction(dict_)
            << "the riser's motion (type " << lab_->motion().type()
            << ") varies along its length, and the mesh's section (z from "
            << bb.min().z() << " to " << bb.max().z() << " m) is periodic:"
            << " its ends are not the same riser. Give the mesh open ends"
            << " (riserMesh -ends wall, placed at the riser's heights)"
            << nl << exit(FatalIOError);
    }
    if (lab_)
    {
        const Time& time = mesh_.time();
        checkMotionDomain
        (
            dict_, lab_->motion(), bb.min().z(), bb.max().z(),
            time.startTime().value(), time.endTime().value(),
            "the mesh (its heights) and the run (startTime to endTime)"
        );
    }
}


// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::IOdictionary> Foam::riserModel::readProperties
(
    const Time& time
)
{
    autoPtr<IOdictionary> dict
    (
        new IOdictionary
        (
            IOobject
            (
                "riserProperties",
                time.constant(),
                time,
                IOobject::MUST_READ,
                IOobject::NO_WRITE,
                false
            )
        )
    );
    // a global file: in a parallel run the processors other than the master
    // receive its entries without its name
    dict->dictionary::name() = time.globalPath()/time.constant()/"riserProperties";
    return dict;
}


const Foam::riserModel& Foam::riserModel::New(const polyMesh& mesh)
{
    if (!mesh.foundObject<riserModel>(typeName))
    {
        riserModel* ptr = new riserModel(mesh);
        ptr->store();
    }
    return mesh.lookupObject<riserModel>(typeName);
}


void Foam::riserModel::checkMotionDomain
(
    const dictionary& dict,
    const riser::RiserMotion& motion,
    const scalar zMin,
    const scalar zMax,
    const scalar t0,
    const scalar t1,
    const string& what
)
{
    const riser::MotionDomain d = motion.domain();
    if (zMin < d.zMin || zMax > d.zMax || t0 < d.tMin || t1 > d.tMax)
    {
        FatalIOErrorInFunction(dict)
            << what.c_str() << " needs the riser's motion at heights [" << zMin
            << ", " << zMax << "] m and times [" << t0 << ", " << t1
            << "] s, beyond its " << motion.type() << " motion, known at"
            << " heights [" << d.zMin << ", " << d.zMax << "] m and times ["
            << d.tMin << ", " << d.tMax << "] s only" << nl
            << exit(FatalIOError);
    }
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


//- FatalIOError unless the list entry key of dict holds numbers only (nan
//  and inf are words to the parser): rows of the form rowForm
void requireNumbers(const dictionary& dict, const word& key, const char* rowForm)
{
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
}


//- A file named relative to the case of the riserProperties dict (the
//  folder holding constant/), or absolute; environment variables expanded
fileName caseFile(const dictionary& dict, fileName file)
{
    file.expand();
    return file.isAbsolute() ? file : dict.topDict().name().path().path()/file;
}


//- The rows of the list entry key of dict (empty without it), each of N
//  finite numbers within [lo, hi]: a rowName (harmonic, mode, row) of the
//  form rowForm, its fields named by names, the rows counted from first
//  (for the messages)
template<int N>
List<FixedList<scalar, N>> readRows
(
    const dictionary& dict,
    const word& key,
    const char* rowName,
    const char* rowForm,
    const char* const (&names)[N],
    const scalar (&lo)[N],
    const scalar (&hi)[N],
    const label first = 0
)
{
    if (!dict.found(key))
    {
        return List<FixedList<scalar, N>>();
    }
    requireNumbers(dict, key, rowForm);
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
                    << "entry '" << key << "' " << rowName << " " << i + first
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


//- The tabulated mode shapes of a motion dictionary: entry shapes, rows
//  (z phi_1 phi_2 ...) of finite numbers, as many in each
riser::ShapesPtr readShapes(const dictionary& m)
{
    requireNumbers(m, "shapes", "rows (z phi_1 phi_2 ...)");
    const List<scalarList> rows = m.get<List<scalarList>>("shapes");
    const label columns = rows.empty() ? 0 : rows[0].size();
    std::vector<double> heights;
    std::vector<std::vector<double>> phi(max(columns - 1, label(0)));
    forAll(rows, i)
    {
        if (columns < 2 || rows[i].size() != columns)
        {
            FatalIOErrorInFunction(m)
                << "entry 'shapes' row " << i + 1 << ": " << rows[i].size()
                << " numbers; every row holds a height and a value per shape"
                << " (z phi_1 phi_2 ...), "
                << (columns < 2 ? "two numbers or more" : "as many as the first row")
                << nl << exit(FatalIOError);
        }
        heights.push_back(rows[i][0]);
        for (label n = 1; n < columns; ++n)
        {
            phi[n - 1].push_back(rows[i][n]);
        }
    }
    try
    {
        return std::make_shared<const riser::ModeShapes>(heights, phi);
    }
    catch (const std::invalid_argument& e)
    {
        FatalIOErrorInFunction(m)
            << "entry 'shapes': " << e.what() << nl << exit(FatalIOError);
    }
    return nullptr;
}


//- The modes of a motion dictionary (riserModel.H, Usage)
riser::MotionPtr readModes(const dictionary& m)
{
    if (m.found("shapes"))
    {
        // the table's heights place the riser; its shapes stand
        checkedEntry::allowedKeys(m, {"type", "shapes", "x", "y"});
        try
        {
            return riser::ModesMotion::make
            (
                0, 1, riser::ModesMotion::Wave::standing,
                readModeList(m, "x"), readModeList(m, "y"), readShapes(m)
            );
        }
        catch (const std::invalid_argument& e)
        {
            FatalIOErrorInFunction(m)
                << "entries 'x', 'y': " << e.what() << nl << exit(FatalIOError);
        }
    }
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
        checkedEntry::choiceOrDefault
        (
            m, "wave",
            {
                {"standing", riser::ModesMotion::Wave::standing},
                {"travelling", riser::ModesMotion::Wave::travelling}
            },
            riser::ModesMotion::Wave::standing
        );
    const riser::MotionPtr motion = riser::ModesMotion::make
    (
        foot, length, wave, readModeList(m, "x"), readModeList(m, "y")
    );
    return motion;
}


//- A motion table's rows (t z x y), and where each stands in its source
struct tableRows
{
    //- The source as refusals name it: "entry 'file' (<path>)" or
    //  "entry 'rows'"
    std::string source;
    std::vector<FixedList<scalar, 4>> rows;
    //- Each row's place: "line N" of the file, or "row N" of the list
    std::vector<std::string> where;
    //- The place after the last row (for what the table lacks)
    std::string end;
};


//- The rows of a motion table file, as riser-dynamics codes write them:
//  four numbers a line, commas, semicolons, tabs or blanks between them,
//  '#' comments, one first line of column names
tableRows readTableFile(const dictionary& m)
{
    const fileName file(caseFile(m, m.get<fileName>("file")));
    std::ifstream in(file);
    if (!in)
    {
        FatalIOErrorInFunction(m)
            << "entry 'file': cannot read " << file << nl << exit(FatalIOError);
    }
    tableRows table;
    table.source = "entry 'file' (\"" + file + "\")";
    std::string text;
    label line = 0;
    bool header = false;
    while (std::getline(in, text))
    {
        ++line;
        text = text.substr(0, text.find('#'));
        for (char& c : text)
        {
            if (c == ',' || c == ';' || c == '\t' || c == '\r') c = ' ';
        }
        std::istringstream fields(text);
        std::vector<std::string> words;
        for (std::string w; fields >> w;) words.push_back(w);
        if (words.empty()) continue;
        FixedList<scalar, 4> v;
        bool numbers = words.size() == 4;
        for (std::size_t k = 0; numbers && k < 4; ++k)
        {
            char* end = nullptr;
            v[k] = std::strtod(words[k].c_str(), &end);
            numbers = end != words[k].c_str() && *end == '\0';
        }
        if (!numbers && table.rows.empty() && !header)
        {
            header = true;          // one line of column names allowed
            continue;
        }
        if (!numbers)
        {
            FatalIOErrorInFunction(m)
                << table.source.c_str() << " line " << line << ": a row of four"
                << " numbers 't z x y' expected, found '" << text.c_str() << "'"
                << nl << exit(FatalIOError);
        }
        table.rows.push_back(v);
        table.where.push_back("line " + std::to_string(line));
    }
    table.end = "line " + std::to_string(line);
    return table;
}


//- The rows of a motion table given as an OpenFOAM list in the dictionary
//  (rows ((t z x y) ...); written there or #include'd)
tableRows readTableList(const dictionary& m)
{
    tableRows table;
    table.source = "entry 'rows'";
    for (const FixedList<scalar, 4>& row : m.get<List<FixedList<scalar, 4>>>("rows"))
    {
        table.rows.push_back(row);
        table.where.push_back("row " + std::to_string(table.rows.size()));
    }
    table.end = "row " + std::to_string(table.rows.size());
    return table;
}


//- A motion table (rows t z x y, from a file or a list): time by time,
//  each time's heights in increasing order, the same at every time, the
//  times at a fixed interval; checked, then its sampling
riser::MotionPtr readTable(const dictionary& m)
{
    checkedEntry::allowedKeys(m, {"type", "file", "rows"});
    const tableRows table =
        checkedEntry::firstOfTwo
        (
            m, "a motion of type table takes its rows (t z x y)",
            "file", "a CSV file", "rows", "an OpenFOAM list"
        )
      ? readTableFile(m)
      : readTableList(m);
    const std::vector<FixedList<scalar, 4>>& rows = table.rows;
    auto refuse = [&](const std::string& where, const std::string& what)
    {
        FatalIOErrorInFunction(m)
            << table.source.c_str() << " " << where.c_str() << ": "
            << what.c_str() << nl << exit(FatalIOError);
    };
    for (std::size_t k = 0; k < rows.size(); ++k)
    {
        for (const scalar value : rows[k])
        {
            if (!std::isfinite(value))
            {
                refuse(table.where[k], "a value that is not a finite number");
            }
        }
    }
    // the heights: those of the first time, increasing
    std::vector<double> heights, times, x, y;
    for (std::size_t k = 0; k < rows.size() && rows[k][0] == rows[0][0]; ++k)
    {
        if (k > 0 && !(rows[k][1] > heights.back()))
        {
            refuse(table.where[k], "the heights at a time must increase");
        }
        heights.push_back(rows[k][1]);
    }
    const std::size_t M = heights.size();
    if (M < 2)
    {
        refuse(table.end, "at least two heights are needed at each time");
    }
    // every time: the same heights, in the same order, times increasing
    for (std::size_t k = 0; k < rows.size(); ++k)
    {
        const std::size_t i = k % M;
        if (i == 0)
        {
            if (!times.empty() && !(rows[k][0] > times.back()))
            {
                refuse(table.where[k], "the times must increase (rows time by time)");
            }
            times.push_back(rows[k][0]);
        }
        if (rows[k][0] != times.back() || rows[k][1] != heights[i])
        {
            refuse
            (
                table.where[k], "each time must hold the heights of the first"
                " time, in the same order (a gap or an extra row)"
            );
        }
        x.push_back(rows[k][2]);
        y.push_back(rows[k][3]);
    }
    if (rows.size() % M != 0)
    {
        refuse(table.end, "the last time lacks heights (a gap)");
    }
    if (times.size() < 6)
    {
        refuse(table.end, "at least six times are needed");
    }
    const scalar h = (times.back() - times.front())/(times.size() - 1);
    for (std::size_t j = 0; j < times.size(); ++j)
    {
        // the times as printed: to 1e-6 of the interval
        if (mag(times[j] - (times.front() + j*h)) > 1e-6*h)
        {
            FatalIOErrorInFunction(m)
                << table.source.c_str() << ": time " << times[j]
                << " is off the fixed interval " << h << " s of the table"
                << " (times at a fixed interval are needed)" << nl
                << exit(FatalIOError);
        }
    }
    try
    {
        const auto motion = std::make_shared<const riser::TableMotion>
        (
            heights, times.front(), h, label(times.size()), x, y
        );
        motion->checkSampling();
        return motion;
    }
    catch (const std::invalid_argument& e)
    {
        FatalIOErrorInFunction(m)
            << table.source.c_str() << ": " << e.what() << nl
            << exit(FatalIOError);
    }
    return nullptr;
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
    enum class motionType { sinusoid, harmonics, modes, table };
    const motionType type = checkedEntry::choice<motionType>
    (
        m, "type",
        {
            {"sinusoid", motionType::sinusoid},
            {"harmonics", motionType::harmonics},
            {"modes", motionType::modes},
            {"table", motionType::table}
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
    else if (type == motionType::modes)
    {
        motion = readModes(m);
    }
    else
    {
        motion = readTable(m);
    }
    if
    (
        motion->maxSpeed() > rm::maxSpeed
     || motion->maxAcceleration() > rm::maxAcceleration
    )
    {
        FatalIOErrorInFunction(m)
            << "the " << motion->type() << " motion gives the wall a speed of up to "
            << motion->maxSpeed() << " m/s and an acceleration of up to "
            << motion->maxAcceleration() << " m/s^2 (its bounds over every"
            << " height and time); a riser's are at most " << rm::maxSpeed << " m/s and "
            << rm::maxAcceleration << " m/s^2" << nl << exit(FatalIOError);
    }
    if (motion->maxSlope() > rm::maxSlope)
    {
        FatalIOErrorInFunction(m)
            << "the " << motion->type() << " motion gives the riser a slope of"
            << " up to " << motion->maxSlope() << "; the sheared riser's"
            << " cross-sections and carrier neglect the slope (errors of"
            << " order slope^2), which is allowed up to " << rm::maxSlope
            << ": lower the amplitudes or the mode numbers"
            << nl << exit(FatalIOError);
    }
    return motion;
}

//- The kinematic viscosity nu of constant/transportProperties, beside the
//  riserProperties of dict; without that file, -1, or with required
//  (what needs it) FatalIOError
scalar readViscosity(const dictionary& dict, const char* required = nullptr)
{
    const fileName file(caseFile(dict, "constant/transportProperties"));
    IFstream is(file);
    if (!is.good())
    {
        if (!required)
        {
            return -1;
        }
        FatalIOErrorInFunction(dict)
            << required << " needs the viscosity nu of " << file
            << ", which cannot be read" << nl << exit(FatalIOError);
    }
    const dictionary transport(is);
    return checkedEntry::dimensionedInRange
    (
        transport, "nu", dimViscosity, 0, false, 1, true
    );
}

//- The tabulated profile of riserProperties dict's entry profileFile, of a
//  pipe of radius R: rows (r w k nu_t), as riserCarrierProfile writes them
std::shared_ptr<const riser::TabulatedPipeProfile> readProfileFile
(
    const dictionary& dict,
    const scalar R
)
{
    checkedEntry::checkFound
    (
        dict, "profileFile", "the file of the samples (riserCarrierProfile's)"
    );
    const fileName file(caseFile(dict, dict.get<fileName>("profileFile")));
    IFstream is(file);
    if (!is.good())
    {
        FatalIOErrorInFunction(dict)
            << "entry 'profileFile': cannot read " << file << nl
            << exit(FatalIOError);
    }
    const dictionary samples(is);
    checkedEntry::allowedKeys(samples, {"FoamFile", "rows"});
    const List<FixedList<scalar, 4>> rows =
        readRows<4>
        (
            samples, "rows", "row", "(r [m] w [m/s] k [m^2/s^2] nu_t [m^2/s])",
            {"r", "w", "k", "nu_t"},
            {0, -rm::maxSpeed, 0, 0}, {R*(1 + 1e-6), rm::maxSpeed, 1e4, 1e2}, 1
        );
    std::vector<double> r, w, k, nut;
    for (const FixedList<scalar, 4>& row : rows)
    {
        r.push_back(row[0]);
        w.push_back(row[1]);
        k.push_back(row[2]);
        nut.push_back(row[3]);
    }
    try
    {
        return std::make_shared<const riser::TabulatedPipeProfile>(R, r, w, k, nut);
    }
    catch (const std::invalid_argument& e)
    {
        FatalIOErrorInFunction(samples)
            << "entry 'rows': " << e.what() << nl << exit(FatalIOError);
    }
    return nullptr;
}

} // End anonymous namespace
} // End namespace Foam


void Foam::riserModel::noteLaminarCarrier
(
    const dictionary& dict,
    const riser::RiserFlow& flow
)
{
    const scalar nu = flow.profile() ? -1 : readViscosity(dict);
    if (nu <= 0)
    {
        return;
    }
    // the bulk speed of Poiseuille flow is half its centre-line speed
    const scalar Re = 0.5*flow.centreLineSpeed()*flow.diameter()/nu;
    if (Re > 2300)
    {
        Info<< "riserProperties: the carrier is laminar Poiseuille flow at the"
            << " pipe Reynolds number " << Re << " (bulk speed uCentre/2), where"
            << " a pipe's flow is turbulent (above 2,300), "
            << (dict.found("profile") ? "as asked (profile laminar)"
                                      : "the paper's carrier (no profile given)")
            << "; profile turbulent gives the turbulent mean flow" << endl;
    }
}


riser::RiserFlow Foam::riserModel::read(const dictionary& dict)
{
    using checkedEntry::dimensionedInRange;

    checkedEntry::allowedKeys
    (
        dict,
        {
            "D", "uCentre", "A", "f", "omega", "phi0", "frame", "carrier",
            "drive", "motion", "profile", "uBulk", "roughness", "profileFile"
        }
    );
    const scalar D =
        dimensionedInRange(dict, "D", dimLength, 0, false, maxDiameter, true);
    enum class profileType { laminar, turbulent, tabulated };
    const profileType profile =
        checkedEntry::choiceOrDefault
        (
            dict, "profile",
            {
                {"laminar", profileType::laminar},
                {"turbulent", profileType::turbulent},
                {"tabulated", profileType::tabulated}
            },
            profileType::laminar
        );
    // each profile's own entries, and none of another's
    const std::pair<const char*, profileType> owners[] =
    {
        {"uCentre", profileType::laminar},
        {"uBulk", profileType::turbulent},
        {"roughness", profileType::turbulent},
        {"profileFile", profileType::tabulated}
    };
    const char* const takes[] =
    {
        "laminar (Poiseuille) profile takes its centre-line speed uCentre",
        "turbulent profile takes the bulk speed uBulk (its centre-line speed"
        " follows from it)",
        "tabulated profile takes its samples from profileFile (its speeds"
        " are the file's)"
    };
    for (const auto& owner : owners)
    {
        if (owner.second != profile && dict.found(owner.first))
        {
            FatalIOErrorInFunction(dict)
                << "entry '" << owner.first << "' with profile "
                << dict.getOrDefault<word>("profile", "laminar") << ": the "
                << takes[int(profile)] << nl << exit(FatalIOError);
        }
    }
    if (profile == profileType::laminar)
    {
        const scalar uCentre =
            dimensionedInRange(dict, "uCentre", dimVelocity, 0, true, maxSpeed, true);
        return riser::RiserFlow(D, uCentre, readMotion(dict));
    }
    if (profile == profileType::tabulated)
    {
        return riser::RiserFlow(D, readProfileFile(dict, 0.5*D), readMotion(dict));
    }
    const scalar uBulk =
        dimensionedInRange(dict, "uBulk", dimVelocity, 0, false, maxSpeed, true);
    const scalar roughness =
        dict.found("roughness")
      ? dimensionedInRange(dict, "roughness", dimLength, 0, true, D/2, false)
      : 0;
    const scalar nu = readViscosity(dict, "profile turbulent");
    const scalar Re = uBulk*D/nu;
    if (Re < minTurbulentRe || Re > 1e8)
    {
        FatalIOErrorInFunction(dict)
            << "profile turbulent: the pipe Reynolds number uBulk D/nu = " << Re
            << " (uBulk " << uBulk << " m/s, D " << D << " m, nu " << nu
            << " m^2/s) is outside the profile's range [" << minTurbulentRe
            << ", 1e8]; below, the flow is laminar or transitional: use"
            << " profile laminar" << nl << exit(FatalIOError);
    }
    return riser::RiserFlow
    (
        D,
        std::make_shared<const riser::TurbulentPipeProfile>(D, uBulk, nu, roughness),
        readMotion(dict)
    );
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
            << " frame; see doc/reference.md)" << exit(FatalError);
    }
}


// ************************************************************************* //
