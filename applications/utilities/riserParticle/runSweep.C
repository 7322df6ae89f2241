/*---------------------------------------------------------------------------*\
  riserFoam: particle transport in vibrating risers, on OpenFOAM
  License: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "riserParticleJobs.H"
#include "OFstream.H"
#include "mathematicalConstants.H"

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <thread>
#include <vector>

using namespace Foam;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace
{

//- The sweep's summary of one case
struct sweepRow
{
    scalar A = 0, f = 0;
    std::string status = "ok";
    scalar lift = 0, maxLateral = 0, meanVertical = 0, leftPerPeriod = 0, rightPerPeriod = 0;
    std::string regime;
};


List<scalar> readSweepList
(
    const dictionary& dict, const word& key, bool zeroAllowed, scalar hi
)
{
    const List<scalar> values = dict.get<List<scalar>>(key);
    if (values.empty())
    {
        FatalIOErrorInFunction(dict)
            << "sweep list '" << key << "' is empty" << exit(FatalIOError);
    }
    forAll(values, i)
    {
        if
        (
            !(zeroAllowed ? values[i] >= 0 : values[i] > 0)
         || !(values[i] <= hi)
        )
        {
            FatalIOErrorInFunction(dict)
                << "sweep list '" << key << "' entry " << i << " = " << values[i]
                << " outside the allowed range " << (zeroAllowed ? "[0" : "(0")
                << ", " << hi << "]" << exit(FatalIOError);
        }
    }
    return values;
}


sweepRow sweepCase
(
    const riserScene& scene, const integratorChoice& integ, scalar A, scalar f,
    label periods, scalar liftTime
)
{
    sweepRow row;
    row.A = A;
    row.f = f;
    try
    {
        const riser::RiserFlow& base = scene.riser;
        riserScene s = scene;
        s.riser = base.withMotion
        (
            riser::SinusoidMotion::make
            (
                A, 2*constant::mathematical::pi*f,
                static_cast<const riser::SinusoidMotion&>(base.motion()).phase()
            )
        );
        // the release relative to the case's own riser, placed in this one
        riserRelease r = scene.releases.first();
        r.x0 = fromCore
        (
            s.riser.motion().toLabFrame(base.motion().toRiserFrame(toCore(r.x0), r.t0), r.t0)
        );
        r.U0 = fromCore
        (
            s.riser.motion().labVelocity
            (
                toCore(r.x0),
                base.motion().relativeVelocity(toCore(scene.releases.first().x0), toCore(r.U0), r.t0),
                r.t0
            )
        );

        const riser::RiserParticleLaw law = s.law(r);
        const scalar T = 1/f;
        const scalar liftAfter = liftTime > 0 ? liftTime : periods*T;
        const scalar duration = max(periods*T, liftAfter);
        // rows: about 50 per period, on a grid through liftAfter (where the
        // lifting distance is read); the lateral speed's peaks right after
        // contacts come from the contacts themselves
        const scalar every = liftAfter/std::ceil(liftAfter/min(T/50, duration/50));
        List<label> left(label(std::ceil(duration/T)) + 1, 0), right(left.size(), 0);
        scalar liftAt = -1;
        scalar zStart = r.x0.z(), zEnd = zStart, tEnd = r.t0;
        riser::Observer obs;
        obs.row = [&](double t, const riser::ParticleState& p)
        {
            if (law.wall().distance(p.x, t) < 0)
            {
                throw std::runtime_error("particle outside the pipe");
            }
            row.maxLateral =
                max(row.maxLateral, mag(s.riser.motion().relativeVelocity(p.x, p.v, t).x()));
            if (liftAt < 0 && t - r.t0 >= liftAfter*(1 - 1e-12))
            {
                liftAt = t;
                row.lift = p.x.z() - zStart;
            }
            zEnd = p.x.z();
            tEnd = t;
        };
        obs.contact = [&](const riser::ContactRecord& c)
        {
            row.maxLateral = max(row.maxLateral, max(mag(c.impactSpeed), mag(c.reboundSpeed)));
            const label k = min(label((c.start - r.t0)/T), left.size() - 1);
            (c.side > 0 ? right : left)[k]++;
        };
        integ.run(law, r.t0, initialState(r), r.t0 + duration, every, obs);
        if (liftAt < 0)
        {
            throw std::runtime_error("no row at liftTime");
        }
        row.meanVertical = (zEnd - zStart)/max(tEnd - r.t0, SMALL);
        label nLeft = 0, nRight = 0, total = 0, inFirst = 0;
        bool laterContacts = false, bothEvery = true;
        for (label k = 0; k < periods; ++k)
        {
            nLeft += left[k];
            nRight += right[k];
            total += left[k] + right[k];
            if (k == 0) inFirst = left[k] + right[k];
            if (k >= periods/2)
            {
                laterContacts = laterContacts || left[k] + right[k] > 0;
                bothEvery = bothEvery && left[k] > 0 && right[k] > 0;
            }
        }
        row.leftPerPeriod = scalar(nLeft)/periods;
        row.rightPerPeriod = scalar(nRight)/periods;
        row.regime =
            total == 0 ? "noContact"
          : total == 1 && inFirst == 1 ? "onceFirstPeriod"
          : !laterContacts ? "firstPeriodsOnly"
          : bothEvery ? "bothWallsEveryPeriod"
          : "other";
    }
    catch (const std::exception& e)
    {
        row.status = std::string("failed(") + e.what() + ")";
        for (char& ch : row.status) if (ch == ' ') ch = '_';
        row.regime = "none";
    }
    return row;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

void Foam::runSweep
(
    const Time& runTime,
    const riserScene& scene,
    const integratorChoice& integ
)
{
    using namespace checkedEntry;
    const IOdictionary dict(readCaseDict(runTime, "riserSweepDict", runTime.system()));
    allowedKeys(dict, {"A", "f", "periods", "liftTime"});
    if (!dynamic_cast<const riser::SinusoidMotion*>(&scene.riser.motion()))
    {
        FatalIOErrorInFunction(dict)
            << "the sweep varies a sinusoid riser's A and f, but the riser's"
            << " motion (constant/riserProperties) is of type "
            << scene.riser.motion().type() << exit(FatalIOError);
    }
    const List<scalar> As = readSweepList(dict, "A", true, riserModel::maxAmplitude);
    const List<scalar> fs = readSweepList(dict, "f", false, riserModel::maxFrequency);
    for (const scalar A : As)
    {
        for (const scalar f : fs)
        {
            riserModel::checkWallMotion(dict, A, f);
        }
    }
    const label periods = count(dict, "periods", 1, 10000);
    // the lift read after the longest case's periods would lengthen them all
    const scalar liftTime = inRange(dict, "liftTime", 0, true, periods/min(fs), true, 0);
    if (scene.releases.empty())
    {
        FatalErrorInFunction << "the case releases no particle" << exit(FatalError);
    }

    const label n = As.size()*fs.size();
    List<sweepRow> rows(n);
    std::atomic<label> next(0);
    const unsigned nThreads = std::max(1u, std::thread::hardware_concurrency());
    const auto start = std::chrono::steady_clock::now();
    std::vector<std::thread> workers;
    for (unsigned w = 0; w < nThreads; ++w)
    {
        workers.emplace_back([&]()
        {
            for (label i = next++; i < n; i = next++)
            {
                rows[i] = sweepCase
                (
                    scene, integ, As[i/fs.size()], fs[i % fs.size()], periods, liftTime
                );
            }
        });
    }
    for (auto& w : workers) w.join();
    const double wall = std::chrono::duration<double>
        (std::chrono::steady_clock::now() - start).count();

    const fileName dir = outputDir(runTime);
    OFstream os(dir/"sweep.dat");
    os.precision(10);
    os  << "# riserParticle sweep (integrator " << integ.name << ", " << periods
        << " periods per case, lift after " << liftTime << " s), SI units" << nl
        << "# A f status lift maxRelativeLateralSpeed meanVerticalSpeed"
        << " contactsPerPeriodLeft contactsPerPeriodRight regime" << nl;
    label failed = 0;
    for (const sweepRow& r : rows)
    {
        os  << r.A << ' ' << r.f << ' ' << r.status.c_str() << ' ' << r.lift << ' '
            << r.maxLateral << ' ' << r.meanVertical << ' ' << r.leftPerPeriod << ' '
            << r.rightPerPeriod << ' ' << r.regime.c_str() << nl;
        if (r.status != "ok") ++failed;
    }
    Info<< "sweep: " << n << " cases (" << failed << " failed) on " << nThreads
        << " threads in " << wall << " s; wrote " << dir/"sweep.dat" << endl;
}


// ************************************************************************* //
