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
    writeFrom       0.46;           // [s] rows from this time on, in
                                    // [0, endTime) (default:
                                    // all; with a fine deltaT, the inside of
                                    // a contact)
    integrator      adaptive;       // adaptive | paper
    adaptiveCoeffs
    {
        tolerance   1e-10;          // relative, in [1e-14, 1), default
                                    // 1e-10 (validation/riserParticle/
                                    // eightScenes.py)
        maxStep     5e-4;           // [s], >= 1e-10, default none (the
                                    // rows come from each step's
                                    // continuous extension and do not
                                    // shorten the steps)
    }
    paperCoeffs
    {
        flowStep    1e-4;           // [s], >= 1e-10, default 1e-3 D/u_cm
                                    // (the paper's)
        contactStep 1e-7;           // [s], >= 1e-10, default 1e-6 D/u_cm
        eps         1e-3;           // contact when the gap < eps d, [0, 1)
    }                               // (the contact's overlap starts at the
                                    // gap, or at zero if the flow step
                                    // ended inside the wall)
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
    firstPeriodsOnly, bothWallsEveryPeriod, other (doc/theory.md section 4); a
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
#include "sigFpe.H"
#include "riserParticleJobs.H"
#include "caseDictionaries.H"

#include <stdexcept>

using namespace Foam;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

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
    caseDictionaries::checkNumbers(runTime);

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
