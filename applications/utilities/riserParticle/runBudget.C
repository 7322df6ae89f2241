/*---------------------------------------------------------------------------*\
  riserFoam: particle transport in vibrating risers, on OpenFOAM
  License: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "riserParticleJobs.H"
#include "OFstream.H"
#include "addedMass/addedMass.hpp"

#include <chrono>
#include <functional>
#include <vector>

using namespace Foam;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace
{

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
        out.rows.push_back(s.riser.motion().toRiserFrame(p.x, t));
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

} // End anonymous namespace


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

// The force budget of the case's first release: each force's RMS and
// largest magnitude over the rows relative to the buoyant weight, and what
// dropping it changes (lifting distance and relative trajectory at the end
// of the run, in D) and saves (CPU time). Every force of the core's list but
// the buoyant weight; the wall contact is never dropped (the particle would
// leave the pipe).
void Foam::runBudget
(
    const Time& runTime,
    const riserScene& scene,
    const integratorChoice& integ
)
{
    using riser::Force;
    const riserRelease& r = scene.releases.first();
    const scalar D = scene.riser.diameter();
    struct tally { scalar sum2 = 0, max = 0; };
    std::vector<Force> budgeted;
    for (const Force k : riser::allForces)
    {
        if (k != Force::gravity) budgeted.push_back(k);
    }
    std::vector<tally> t(riser::nForces);
    label n = 0;
    scalar weight = 0, impulse = 0, peak = 0;
    const budgetRun full = runForBudget
    (
        scene, scene.forces, r, integ,
        [&](double time, const riser::ParticleState& p, const riser::RiserParticleLaw& law)
        {
            riser::ForceReport f = law.forces(time, p);
            // the added mass as C_A m_f (Du/Dt - dv/dt)
            if (scene.forces[Force::addedMass])
            {
                f[Force::addedMass] = riser::addedMassForce
                (
                    scene.forces.CA, law.fluidMass(),
                    scene.riser.materialDerivative(p.x, time) - law.acceleration(time, p)
                );
            }
            for (const Force k : budgeted)
            {
                const scalar m = f[k].norm();
                t[int(k)].sum2 += m*m;
                t[int(k)].max = max(t[int(k)].max, m);
            }
            weight = mag(law.mass() - law.fluidMass())*mag(scene.g);
            ++n;
        },
        [&](const riser::ContactRecord& c, const riser::RiserParticleLaw& law)
        {
            // contacts last microseconds, between rows: the wall force's
            // time mean from the normal impulses, its peak from the
            // largest overlap (the elastic part, k_n delta^(3/2))
            impulse += law.inertia()*(c.impactSpeed + c.reboundSpeed);
            peak = max
            (
                peak,
                law.contactLaw().normalStiffness(law.body())*std::pow(c.maxOverlap, 1.5)
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
    tally& contact = t[int(Force::contact)];
    contact.sum2 = n*sqr(impulse/max(duration, SMALL));   // reported as its mean
    contact.max = peak;

    OFstream os(outputDir(runTime)/"budget.dat");
    os.precision(6);
    os  << "# riserParticle force budget, particle 0, integrator " << integ.name
        << ", to t = " << scene.endTime << " s; buoyant weight " << weight << " N" << nl
        << "# riserContact: the time mean of its normal force from the"
        << " impulses, and its elastic peak k_n delta_max^(3/2)" << nl
        << "# force rms/W max/W dropped:liftChange/D dropped:largestTrajectoryChange/D"
        << " dropped:cpu/full (full model: " << fullCpu << " s, lift "
        << (full.rows.back().z() - full.rows.front().z())/D << " D)" << nl;
    Info<< "force budget (particle 0; W = buoyant weight " << weight << " N):" << nl;
    for (const Force k : budgeted)
    {
        const word name = riser::forceName(k);
        const scalar rms = std::sqrt(t[int(k)].sum2/max(n, 1))/weight;
        os  << name << ' ' << rms << ' ' << t[int(k)].max/weight;
        Info<< "    " << name << ": rms " << rms << " W, max " << t[int(k)].max/weight << " W";
        if (k != Force::contact && scene.forces[k])
        {
            riser::ForceSelection dropped = scene.forces;
            dropped[k] = false;
            const budgetRun d = runForBudget(scene, dropped, r, integ);
            if (d.failed || d.rows.size() != full.rows.size())
            {
                os  << " failed failed " << d.cpu/fullCpu << nl;
                Info<< "; dropped: the integration failed" << nl;
                continue;
            }
            scalar worst = 0;
            for (std::size_t i = 0; i < d.rows.size(); ++i)
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
            // not selected, or the contact
            os  << " - - -" << nl;
            Info<< nl;
        }
    }
    Info<< "wrote " << outputDir(runTime)/"budget.dat" << endl;
}


// ************************************************************************* //
