/*---------------------------------------------------------------------------*\
  riserFoam: particle transport in vibrating risers, on OpenFOAM
  License: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "riserParticleJobs.H"
#include "OFstream.H"
#include "output/particleTable.hpp"

#include <chrono>

using namespace Foam;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace
{

//- One table row (the columns of the particle table's schema)
void writeRow
(
    OFstream& os, const riserScene& scene, const riser::RiserParticleLaw& law,
    label id, scalar z0, double t, const riser::ParticleState& s
)
{
    const riser::ForceReport f = law.forces(t, s);
    riser::ParticleTableRow row(t, 0, id, s.x, s.v, scene.riser.motion());
    row.lift = s.x.z() - z0;
    row.contactForce = f[riser::Force::contact];
    row.deltaN = max(f.overlap, 0.0);
    row.deltaT = s.spring.norm();
    for (const word& name : scene.forceNames)
    {
        riser::Force force;
        row.forces.push_back
        (
            riser::forceNamed(name, force) ? f[force] : riser::Vector::Zero().eval()
        );
    }
    riser::writeParticleTableRow(os, row);
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

//- Run every release of the case and write its table and contacts
void Foam::runCase
(
    const Time& runTime,
    const riserScene& scene,
    const integratorChoice& integ
)
{
    const fileName dir = outputDir(runTime);
    OFstream table(dir/"particles.dat");
    table.precision(12);
    table
        << riser::particleTableHeader
           (
               "riserParticle (mesh-free, lab frame, integrator " + integ.name
             + "), SI units; relative: to the riser axis and velocity",
               {scene.forceNames.begin(), scene.forceNames.end()}
           ).c_str();
    OFstream contacts(dir/"contacts.dat");
    contacts.precision(12);
    contacts
        << "# riserParticle contacts: origId start end side(+1: x > x_c)"
        << " maxOverlap impactSpeed reboundSpeed" << nl;

    label finished = 0, lost = 0, failed = 0, leftTable = 0;
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
            if (law.wall().distance(s.x, t) < 0)
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
        catch (const std::out_of_range& e)
        {
            // a tabulated riser's motion ends at its top (and last time)
            ++leftTable;
            Info<< "particle " << i << " left the riser motion table: "
                << e.what() << "; its rows stop at the last before" << endl;
            continue;
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
        << " failed";
    if (leftTable)
    {
        Info<< ", " << leftTable << " left the riser motion table";
    }
    Info<< nl
        << "wrote " << dir/"particles.dat" << " and " << dir/"contacts.dat" << endl;
    if (failed)
    {
        FatalErrorInFunction
            << failed << " of " << scene.releases.size() << " particle(s) failed"
            << " (see the warnings above)" << exit(FatalError);
    }
}


// ************************************************************************* //
