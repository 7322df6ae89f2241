/*---------------------------------------------------------------------------*\
  riserFoam: particle transport in vibrating risers, on OpenFOAM
  License: GPL-3.0-or-later

Application
    riserParticle

Group
    riserFoam/utilities

Description
    The mesh-free engine: runs a riser case directory - the dictionaries
    riserParcelFoam reads (riserScene.H) - without a mesh, particle by
    particle, in the lab frame, calling the core laws directly
    (riser::RiserParticleLaw), and writes the table riserParticleTable
    writes, to postProcessing/riserParticle/particles.dat (the same columns;
    riserFrame's column is zero, the lab frame needing none), and the
    contacts to postProcessing/riserParticle/contacts.dat.

    Integrator (system/riserParticleDict, optional; -integrator overrides):
    \verbatim
    writeFrom       0.46;           // [s] rows from this time on (default:
                                    // all; with a fine deltaT, the inside of
                                    // a contact)
    integrator      adaptive;       // adaptive | paper
    adaptiveCoeffs
    {
        tolerance   1e-6;           // relative, in (0, 1)
        maxStep     5e-4;           // [s], default none (rows bound the steps)
    }
    paperCoeffs
    {
        flowStep    1e-4;           // [s], default 1e-3 D/u_cm (the paper's)
        contactStep 1e-7;           // [s], default 1e-6 D/u_cm
        eps         1e-3;           // contact when the gap < eps d
        contactStart detection;     // detection | geometric: the contact's
                                    // overlap starts at zero (or the gap)
                                    // or at the flow step's penetration
    }
    \endverbatim

    Sweeps (-sweep): the case's first release over a grid of riser
    amplitudes and frequencies, in parallel over the cores, one row per case
    in postProcessing/riserParticle/sweep.dat, in grid order (deterministic).
    system/riserSweepDict:
    \verbatim
    A           (0.05 0.1 0.15);    // [m], each >= 0
    f           (0.5 1 3);          // [Hz], each > 0
    periods     20;                 // riser periods per case, > 0
    liftTime    10;                 // [s] lifting distance after this time
                                    // (0 or absent: after the periods)
    \endverbatim
    The release is taken relative to the riser (position from the axis,
    velocity relative to the riser's), so that each case starts as the
    case's particle does in its own riser. Columns: A f status lift
    maxRelativeLateralSpeed meanVerticalSpeed contactsPerPeriodLeft
    contactsPerPeriodRight regime, regime one of noContact, onceFirstPeriod,
    firstPeriodsOnly, bothWallsEveryPeriod, other (MODEL.md section 4); a
    case that fails says so in its status and the others go on.

    Force budget (-budget): the case's first release run with every force,
    then once with each of drag, lift, added mass and fluid stress dropped;
    postProcessing/riserParticle/budget.dat has, per force, its RMS and
    largest magnitude over the rows relative to the buoyant weight W (the
    added mass as C_A m_f (Du/Dt - dv/dt); the wall contact's too, which is
    never dropped), and with it dropped the change of the lifting distance
    at endTime and the largest change of the relative trajectory (in D),
    and the CPU time against the full model's.

Usage
    riserParticle [-integrator adaptive|paper] [-sweep | -budget]

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "OFstream.H"
#include "sigFpe.H"
#include "riserScene.H"

#include <atomic>
#include <functional>
#include <vector>
#include <chrono>
#include <memory>
#include <stdexcept>
#include <thread>

using namespace Foam;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace
{

//- One of the two integrators, as chosen
struct integratorChoice
{
    word name;
    std::unique_ptr<riser::AdaptiveScheme> adaptive;
    std::unique_ptr<riser::PaperScheme> paper;
    //- The table's rows start here (a fine deltaT over a short window)
    scalar writeFrom = -GREAT;

    riser::IntegratorStats run
    (
        const riser::RiserParticleLaw& law, double t0, const riser::ParticleState& s,
        double tEnd, double every, const riser::Observer& obs
    ) const
    {
        return adaptive
            ? adaptive->run(law, t0, s, tEnd, every, obs)
            : paper->run(law, t0, s, tEnd, every, obs);
    }
};


integratorChoice readIntegrator(const Time& runTime, const argList& args, const riserScene& s)
{
    using namespace checkedEntry;
    dictionary dict;
    IOobject io
    (
        "riserParticleDict", runTime.system(), runTime,
        IOobject::MUST_READ, IOobject::NO_WRITE, false
    );
    if (io.typeHeaderOk<IOdictionary>(true))
    {
        dict = IOdictionary(io);
    }
    integratorChoice c;
    if (dict.found("writeFrom"))
    {
        c.writeFrom = checkedEntry::nonNegative(dict, "writeFrom");
    }
    c.name = args.getOrDefault<word>
    (
        "integrator", dict.lookupOrDefault<word>("integrator", "adaptive")
    );
    const scalar unit = s.riser.diameter()/max(s.riser.centreLineSpeed(), SMALL);
    if (c.name == "adaptive")
    {
        const dictionary& coeffs = dict.subOrEmptyDict("adaptiveCoeffs");
        const scalar tol =
            coeffs.found("tolerance") ? inRange(coeffs, "tolerance", 0, false, 1, false) : 1e-6;
        const scalar maxStep =
            coeffs.found("maxStep") ? positive(coeffs, "maxStep") : VGREAT;
        c.adaptive.reset(new riser::AdaptiveScheme(tol, maxStep));
    }
    else if (c.name == "paper")
    {
        const dictionary& coeffs = dict.subOrEmptyDict("paperCoeffs");
        const scalar flow =
            coeffs.found("flowStep") ? positive(coeffs, "flowStep") : 1e-3*unit;
        const scalar contact =
            coeffs.found("contactStep") ? positive(coeffs, "contactStep") : 1e-6*unit;
        const scalar eps = coeffs.found("eps") ? nonNegative(coeffs, "eps") : 1e-3;
        const word start = coeffs.lookupOrDefault<word>("contactStart", "detection");
        if (start != "detection" && start != "geometric")
        {
            FatalIOErrorInFunction(coeffs)
                << "contactStart '" << start << "' is not one of: detection geometric"
                << exit(FatalIOError);
        }
        c.paper.reset
        (
            new riser::PaperScheme
            (
                flow, contact, eps,
                start == "detection"
              ? riser::ContactStart::detection : riser::ContactStart::geometric
            )
        );
    }
    else
    {
        FatalIOErrorInFunction(dict)
            << "integrator '" << c.name << "' is not one of: adaptive paper"
            << exit(FatalIOError);
    }
    return c;
}


riser::ParticleState initialState(const riserRelease& r)
{
    riser::ParticleState s;
    s.x = toCore(r.x0);
    s.v = toCore(r.U0);
    return s;
}


//- One table row (the columns of riserParticleTable)
void writeRow
(
    OFstream& os, const riserScene& scene, const riser::RiserParticleLaw& law,
    label id, scalar z0, double t, const riser::ParticleState& s
)
{
    const riser::ForceReport f = law.forces(t, s);
    const scalar xc = scene.riser.axisPosition(t), Ur = scene.riser.riserVelocity(t);
    os  << t << " 0 " << id << ' '
        << s.x.x() << ' ' << s.x.y() << ' ' << s.x.z() << ' '
        << s.v.x() << ' ' << s.v.y() << ' ' << s.v.z() << ' '
        << s.x.x() - xc << ' ' << s.x.y() << ' '
        << s.v.x() - Ur << ' ' << s.v.y() << ' ' << s.v.z() << ' '
        << s.x.z() - z0 << ' '
        << f.contact.x() << ' ' << f.contact.y() << ' ' << f.contact.z() << ' '
        << max(f.overlap, 0.0) << ' ' << s.spring.norm();
    for (const word& name : scene.forceNames)
    {
        const riser::Vector F =
            name == "wallCorrectedDrag" ? f.drag
          : name == "riserSaffmanMeiLift" ? f.lift
          : name == "riserAddedMass" ? f.addedMass
          : name == "riserFluidStress" ? f.fluidStress
          : name == "gravity" ? f.gravity
          : riser::Vector::Zero().eval();
        os  << ' ' << F.x() << ' ' << F.y() << ' ' << F.z();
    }
    os  << nl;
}


//- Run every release of the case and write its table and contacts
void runCase(const Time& runTime, const riserScene& scene, const integratorChoice& integ)
{
    const fileName dir = runTime.globalPath()/"postProcessing"/"riserParticle";
    mkDir(dir);
    OFstream table(dir/"particles.dat");
    table.precision(12);
    table
        << "# riserParticle (mesh-free, lab frame, integrator " << integ.name
        << "), SI units; relative: to the riser axis and velocity" << nl
        << "# t origProc origId x y z Ux Uy Uz xr yr Urx Ury Urz lift"
        << " Fc_x Fc_y Fc_z deltaN deltaT";
    for (const word& n : scene.forceNames)
    {
        table << " F_" << n << "_x F_" << n << "_y F_" << n << "_z";
    }
    table << nl;
    OFstream contacts(dir/"contacts.dat");
    contacts.precision(12);
    contacts
        << "# riserParticle contacts: origId start end side(+1: x > x_c)"
        << " maxOverlap impactSpeed reboundSpeed" << nl;

    label finished = 0, lost = 0, failed = 0;
    forAll(scene.releases, i)
    {
        const riserRelease& r = scene.releases[i];
        const riser::RiserParticleLaw law = scene.law(r);
        const riser::ParticleState s0 = initialState(r);
        bool outside = false;
        riser::Observer obs;
        double writing = 0;     // the time spent writing rows, not integrating
        obs.row = [&](double t, const riser::ParticleState& s)
        {
            const auto start = std::chrono::steady_clock::now();
            if (law.axisDistance(s.x, t) > scene.riser.radius())
            {
                outside = true;
            }
            if (t >= integ.writeFrom)
            {
                writeRow(table, scene, law, i, r.x0.z(), t, s);
            }
            writing += std::chrono::duration<double>
                (std::chrono::steady_clock::now() - start).count();
        };
        obs.contact = [&](const riser::ContactRecord& c)
        {
            contacts
                << i << ' ' << c.start << ' ' << c.end << ' ' << c.side << ' '
                << c.maxOverlap << ' ' << c.impactSpeed << ' ' << c.reboundSpeed << nl;
        };
        const auto start = std::chrono::steady_clock::now();
        riser::IntegratorStats st;
        try
        {
            st = integ.run(law, r.t0, s0, scene.endTime, scene.deltaT, obs);
        }
        catch (const riser::IntegrationFailure& e)
        {
            ++failed;
            WarningInFunction
                << "particle " << i << " failed: " << e.what() << "; its rows"
                << " stop there (integrator " << integ.name << ": a smaller"
                << " step or tolerance is needed for this scene)" << endl;
            continue;
        }
        const double cpu = std::chrono::duration<double>
            (std::chrono::steady_clock::now() - start).count();
        Info<< "particle " << i << ": " << st.steps << " steps (" << st.rejected
            << " rejected, " << st.contactSteps << " in contact), "
            << st.forceEvaluations << " force evaluations, " << cpu << " s ("
            << cpu - writing << " s integrating, " << writing << " s writing rows)"
            << endl;
        if (outside)
        {
            ++lost;
            WarningInFunction
                << "particle " << i << " was outside the pipe at a row" << endl;
        }
        else
        {
            ++finished;
        }
    }
    Info<< "particles: " << scene.releases.size() << " released, " << finished
        << " inside the pipe to the end, " << lost << " outside, " << failed
        << " failed" << nl
        << "wrote " << dir/"particles.dat" << " and " << dir/"contacts.dat" << endl;
    if (failed)
    {
        FatalErrorInFunction
            << failed << " of " << scene.releases.size() << " particle(s) failed"
            << " (see the warnings above)" << exit(FatalError);
    }
}


//- The sweep's summary of one case
struct sweepRow
{
    scalar A = 0, f = 0;
    std::string status = "ok";
    scalar lift = 0, maxLateral = 0, meanVertical = 0, leftPerPeriod = 0, rightPerPeriod = 0;
    std::string regime;
};


List<scalar> readSweepList(const dictionary& dict, const word& key, bool zeroAllowed)
{
    const List<scalar> values = dict.get<List<scalar>>(key);
    if (values.empty())
    {
        FatalIOErrorInFunction(dict)
            << "sweep list '" << key << "' is empty" << exit(FatalIOError);
    }
    forAll(values, i)
    {
        if (!(zeroAllowed ? values[i] >= 0 : values[i] > 0) || !std::isfinite(values[i]))
        {
            FatalIOErrorInFunction(dict)
                << "sweep list '" << key << "' entry " << i << " = " << values[i]
                << " outside the allowed range " << (zeroAllowed ? "[0" : "(0")
                << ", inf)" << exit(FatalIOError);
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
        s.riser = riser::RiserFlow
        (
            base.diameter(), base.centreLineSpeed(), A, 2*constant::mathematical::pi*f,
            base.phase()
        );
        // the release relative to the case's own riser, placed in this one
        riserRelease r = scene.releases.first();
        r.x0.x() += s.riser.axisPosition(r.t0) - base.axisPosition(r.t0);
        r.U0.x() += s.riser.riserVelocity(r.t0) - base.riserVelocity(r.t0);

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
            if (law.axisDistance(p.x, t) > s.riser.radius())
            {
                throw std::runtime_error("particle outside the pipe");
            }
            row.maxLateral = max(row.maxLateral, mag(p.v.x() - s.riser.riserVelocity(t)));
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


void runSweep(const Time& runTime, const riserScene& scene, const integratorChoice& integ)
{
    using namespace checkedEntry;
    const IOdictionary dict(readCaseDict(runTime, "riserSweepDict", runTime.system()));
    const List<scalar> As = readSweepList(dict, "A", true);
    const List<scalar> fs = readSweepList(dict, "f", false);
    const label periods = label(inRange(dict, "periods", 1, true, 1e6, true));
    const scalar liftTime = dict.found("liftTime") ? nonNegative(dict, "liftTime") : 0;
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

    const fileName dir = runTime.globalPath()/"postProcessing"/"riserParticle";
    mkDir(dir);
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

//- A run's relative trajectory (x - x_c, y, z) at the rows, and its time
struct budgetRun
{
    std::vector<riser::Vector> rows;
    double cpu = 0;
    bool failed = false;
};


budgetRun runForBudget
(
    const riserScene& scene, const riser::ForceSelection& forces,
    const riserRelease& r, const integratorChoice& integ,
    const std::function<void(double, const riser::ParticleState&,
                             const riser::RiserParticleLaw&)>& look = {},
    const std::function<void(const riser::ContactRecord&,
                             const riser::RiserParticleLaw&)>& touch = {}
)
{
    riserScene s = scene;
    s.forces = forces;
    const riser::RiserParticleLaw law = s.law(r);
    budgetRun out;
    riser::Observer obs;
    obs.row = [&](double t, const riser::ParticleState& p)
    {
        out.rows.push_back(p.x - riser::Vector(s.riser.axisPosition(t), 0, 0));
        if (look) look(t, p, law);
    };
    obs.contact = [&](const riser::ContactRecord& c)
    {
        if (touch) touch(c, law);
    };
    const auto start = std::chrono::steady_clock::now();
    try
    {
        integ.run(law, r.t0, initialState(r), scene.endTime, scene.deltaT, obs);
    }
    catch (const riser::IntegrationFailure&)
    {
        out.failed = true;
    }
    out.cpu = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return out;
}


//- The force budget of the case's first release: each force's RMS and
//  largest magnitude over the rows relative to the buoyant weight, and what
//  dropping it changes (lifting distance and relative trajectory at the end
//  of the run, in D) and saves (CPU time)
void runBudget(const Time& runTime, const riserScene& scene, const integratorChoice& integ)
{
    const riserRelease& r = scene.releases.first();
    const scalar D = scene.riser.diameter();
    struct tally { scalar sum2 = 0, max = 0; };
    // drag, lift, added mass (C_A m_f (Du/Dt - dv/dt)), fluid stress, contact
    const wordList names
    ({
        "wallCorrectedDrag", "riserSaffmanMeiLift", "riserAddedMass", "riserFluidStress",
        "riserWallContact"
    });
    List<tally> t(names.size());
    label n = 0;
    scalar weight = 0, impulse = 0, peak = 0;
    const budgetRun full = runForBudget
    (
        scene, scene.forces, r, integ,
        [&](double time, const riser::ParticleState& p, const riser::RiserParticleLaw& law)
        {
            const riser::ForceReport f = law.forces(time, p);
            const riser::Vector a = law.acceleration(time, p);
            const riser::Vector am =
                scene.forces.addedMass
              ? riser::Vector
                (
                    scene.forces.CA*law.fluidMass()
                   *(scene.riser.materialDerivative(p.x, time) - a)
                )
              : riser::Vector::Zero().eval();
            const scalar m[] =
                {f.drag.norm(), f.lift.norm(), am.norm(), f.fluidStress.norm(), f.contact.norm()};
            forAll(t, k)
            {
                t[k].sum2 += m[k]*m[k];
                t[k].max = max(t[k].max, m[k]);
            }
            weight = mag(law.mass() - law.fluidMass())*mag(scene.g);
            ++n;
        },
        [&](const riser::ContactRecord& c, const riser::RiserParticleLaw& law)
        {
            // contacts last microseconds, between rows: the wall force's
            // time mean from the normal impulses, its peak from the
            // largest overlap (the elastic part, k_n delta^(3/2))
            impulse += law.mass()*(c.impactSpeed + c.reboundSpeed);
            const riser::ContactBody body{law.radius(), law.mass()};
            peak = max
            (
                peak,
                law.contactLaw().normalStiffness(body)*std::pow(c.maxOverlap, 1.5)
            );
        }
    );
    if (full.failed || full.rows.empty())
    {
        FatalErrorInFunction
            << "the full model failed for particle 0: no budget" << exit(FatalError);
    }
    // the full model's time without the tallies
    const double fullCpu = runForBudget(scene, scene.forces, r, integ).cpu;
    const scalar duration = scene.endTime - r.t0;
    t[4].sum2 = n*sqr(impulse/max(duration, SMALL));   // reported as its mean
    t[4].max = peak;

    const fileName dir = runTime.globalPath()/"postProcessing"/"riserParticle";
    mkDir(dir);
    OFstream os(dir/"budget.dat");
    os.precision(6);
    os  << "# riserParticle force budget, particle 0, integrator " << integ.name
        << ", to t = " << scene.endTime << " s; buoyant weight " << weight << " N" << nl
        << "# riserWallContact: the time mean of its normal force from the"
        << " impulses, and its elastic peak k_n delta_max^(3/2)" << nl
        << "# force rms/W max/W dropped:liftChange/D dropped:largestTrajectoryChange/D"
        << " dropped:cpu/full (full model: " << fullCpu << " s, lift "
        << (full.rows.back().z() - full.rows.front().z())/D << " D)" << nl;
    Info<< "force budget (particle 0; W = buoyant weight " << weight << " N):" << nl;
    forAll(names, k)
    {
        riser::ForceSelection dropped = scene.forces;
        bool* flag =
            k == 0 ? &dropped.drag : k == 1 ? &dropped.lift : k == 2 ? &dropped.addedMass
          : k == 3 ? &dropped.fluidStress : nullptr;
        os  << names[k] << ' ' << std::sqrt(t[k].sum2/max(n, 1))/weight << ' '
            << t[k].max/weight;
        Info<< "    " << names[k] << ": rms " << std::sqrt(t[k].sum2/max(n, 1))/weight
            << " W, max " << t[k].max/weight << " W";
        if (flag && *flag)
        {
            *flag = false;
            const budgetRun d = runForBudget(scene, dropped, r, integ);
            if (d.failed || d.rows.size() != full.rows.size())
            {
                os  << " failed failed " << d.cpu/fullCpu << nl;
                Info<< "; dropped: the integration failed" << nl;
                continue;
            }
            scalar worst = 0;
            forAll(d.rows, i)
            {
                worst = max(worst, scalar((d.rows[i] - full.rows[i]).norm()));
            }
            const scalar lift =
                ((d.rows.back().z() - d.rows.front().z())
               - (full.rows.back().z() - full.rows.front().z()))/D;
            os  << ' ' << lift << ' ' << worst/D << ' ' << d.cpu/fullCpu << nl;
            Info<< "; dropped: lift changes by " << lift << " D, trajectory by up to "
                << worst/D << " D, CPU x " << d.cpu/fullCpu << nl;
        }
        else
        {
            // not selected, or the contact (the particle would leave the pipe)
            os  << " - - -" << nl;
            Info<< nl;
        }
    }
    Info<< "wrote " << dir/"budget.dat" << endl;
}

} // End anonymous namespace


int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Mesh-free engine: the riser case's particles with the core laws,"
        " no mesh"
    );
    argList::noParallel();
    argList::addOption("integrator", "name", "adaptive | paper (overrides system/riserParticleDict)");
    argList::addBoolOption("sweep", "run the (A, f) grid of system/riserSweepDict");
    argList::addBoolOption
    (
        "budget",
        "force budget of the first particle: each force against the buoyant"
        " weight, and what dropping it changes"
    );

    #include "setRootCase.H"
    #include "createTime.H"

    const riserScene scene = readScene(runTime);
    const integratorChoice integ = readIntegrator(runTime, args, scene);
    Info<< "riserParticle: " << scene.releases.size() << " particle(s), integrator "
        << integ.name << ", to t = " << scene.endTime << " s" << nl << endl;

    // the integrators check their states themselves and report a step too
    // large for the scene as riser::IntegrationFailure (a sweep case in its
    // row), which a floating-point trap would pre-empt
    sigFpe::unset();

    try
    {
        if (args.found("sweep"))
        {
            runSweep(runTime, scene, integ);
        }
        else if (args.found("budget"))
        {
            runBudget(runTime, scene, integ);
        }
        else
        {
            runCase(runTime, scene, integ);
        }
    }
    catch (const std::invalid_argument& e)
    {
        FatalErrorInFunction << e.what() << exit(FatalError);
    }

    Info<< "End" << endl;
    return 0;
}

// ************************************************************************* //
