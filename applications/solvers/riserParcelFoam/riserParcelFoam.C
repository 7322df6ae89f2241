/*---------------------------------------------------------------------------*\
  riserFoam: particle transport in vibrating risers, on OpenFOAM
  License: GPL-3.0-or-later

Application
    riserParcelFoam

Group
    riserFoam/solvers

Description
    Particles in the oscillating riser of Wei et al. (Phys. Fluids 35,
    113311, 2023): the analytic carrier of constant/riserProperties imposed
    on a riser mesh, and a colliding cloud evolved in it (one-way coupled).

    Each step, in the stock order: store the particles' global positions
    (on a dynamic mesh: for a change of topology), move the mesh
    (constant/dynamicMeshDict: solidBodyMotionFunction riserOscillation in
    the lab frame; no motion in the riser frame),
    impose the carrier u(x, t) on the cells and on every boundary face (the
    wall moves with the riser), keep U's old time (ddt(U) of the
    interpolated carrier), then evolve the cloud, so that stock cloud
    functions and function objects work.

    constant/riserProperties (riserModel, carrierFlow) sets the riser, the carrier
    evaluation (exact or interpolated) and the frame (lab: moving mesh and
    wall; riser: static mesh, Poiseuille carrier and the frame force).

    Checks at start: a restart's start time is complete (every file ends
    with OpenFOAM's closing divider and holds every file of the time
    written before it: a run killed while writing leaves files cut short or
    missing), else the run stops naming the incomplete time and the latest
    complete one to restart from (riserCommon/checkStartTime.H); the riser exists; its diameter and axis agree with the
    mesh (largest distance of a mesh point from the axis at t = 0 equal to
    D/2 within 0.1%); the frame agrees with the mesh motion (riser frame:
    static mesh; lab frame with a moving riser: a dynamic mesh).

    Which frame: on the flagship the lab frame's moving mesh costs some 25
    times more than the riser frame (benchmarks/README.md), for lifting
    distances that agree to first order in dt (tested). A rigid riser is best run in the
    riser frame; the lab frame (moving mesh and wall) is the general path
    for what moves otherwise.

Usage
    riserParcelFoam [-cloud name]

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "dynamicFvMesh.H"
#include "singlePhaseTransportModel.H"
#include "basicRiserCloud.H"
#include "carrierFlow.H"
#include "modelEntries.H"
#include "coreVector.H"
#include "foamVtkSeriesWriter.H"

#include "caseDictionaries.H"

#include <fstream>
#include <sstream>

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Particles in an oscillating riser: analytic carrier on a riser mesh"
        " (moving with the riser, or the riser's frame), colliding cloud"
    );
    argList::addOption
    (
        "cloud",
        "name",
        "cloud name (default kinematicCloud)"
    );

    #include "setRootCaseLists.H"
    #include "createTime.H"
    caseDictionaries::checkNumbers(runTime);
    #include "checkStartTime.H"
    #include "createDynamicFvMesh.H"
    #include "createFields.H"

    // * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

    Info<< "\nStarting time loop\n" << endl;

    while (runTime.loop())
    {
        Info<< "Time = " << runTime.timeName() << nl << endl;

        // (the cloud's autoMap after a change of topology, which only a
        // dynamic mesh makes: a static mesh skips this pass over the cloud)
        if (mesh.dynamic())
        {
            kinematicCloud.storeGlobalPositions();
        }

        mesh.update();

        #include "imposeCarrier.H"

        laminarTransport.correct();
        mu = laminarTransport.nu()*rhoInfValue;

        Info<< "Evolving " << kinematicCloud.name() << endl;
        kinematicCloud.evolve();
        #include "finishCloudStep.H"

        runTime.write();

        runTime.printExecutionTime(Info);
    }

    Info<< "End\n" << endl;

    return 0;
}


// ************************************************************************* //
