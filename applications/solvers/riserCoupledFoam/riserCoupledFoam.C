/*---------------------------------------------------------------------------*\
  riserFoam: particle transport in vibrating risers, on OpenFOAM
  License: GPL-3.0-or-later

Application
    riserCoupledFoam

Group
    riserFoam/solvers

Description
    Particles in a riser whose carrier is computed and feels them (two-way
    coupled, unresolved CFD-DEM): the incompressible volume-averaged
    equations of the carrier (Anderson & Jackson 1967) solved by PIMPLE on
    the riser mesh, with the riser cloud of riserParcelFoam
    (basicRiserCloud: the riser forces, wall and pair contact, the Basset
    history) evolved in it.

    The carrier, of volume fraction alpha_c and velocity u (per unit mass,
    p the kinematic pressure):
        ddt(alpha_c) + div(alpha_c u) = 0,
        ddt(alpha_c u) + div(alpha_c u u) - div(alpha_c R_eff)
            = -grad p + G e_z + b_r + f_p / rho,
    where R_eff is the stress of the turbulence model of
    constant/turbulenceProperties (laminar, RAS or LES, OpenFOAM's own,
    alpha_c weighted), G e_z the drive of a periodic riser (a uniform
    pressure gradient, riserDrive), f_p the particles' reaction per unit
    volume, -sum_p F_p/V over the forces the cloud couples (drag, lift,
    added mass, history and fluid stress: particleCoupling.H; each
    particle's volume and force spread over the cells near it by the
    cloud's coarse-particle kernel, or kept in its cell), and b_r what
    the pressure leaves of the riser's acceleration a_r. p is the pressure
    less its hydrostatic part (the particles feel it through their buoyant
    weight, force gravity) and less -a_r.x, which takes a uniform a_r
    whole: in the riser frame the carrier's fictitious force -alpha_c a_r
    leaves b_r = (1 - alpha_c) a_r, nothing without particles; in the lab
    frame (the mesh and the wall moving) b_r = a_r, the change of the
    mesh's velocity over the step, (x_c(t) - 2 x_c(t - dt) + x_c(t - 2 dt))
    / dt^2, given to the cells (the moving wall's flux is the wall's). The
    particles' reaction is that of their whole fluid forces: with the parts
    of the added mass and the history force that their inertia takes
    (-C_A m_f dv/dt, HistoryParcel), without which the added mass's
    reaction, -C_A m_f Du/Dt, would depend on the frame.

    Each step: store the particles' global positions and move the mesh (lab
    frame: constant/dynamicMeshDict, solidBodyMotionFunction
    riserOscillation; the carrier's flux, relative to the mesh, kept
    through the rigid move); take alpha_c from the particles as they stand
    at the step's start and the reaction of the forces of their last step
    (the previous flow step's); the PIMPLE loop: the momentum predictor
    with the reaction's implicit part in the matrix; pressure corrections in
    which the reaction's explicit part, the drive and b_r act through the
    face fluxes (as the pressure gradient does, so that a pressure gradient
    balances a uniform force exactly), each followed by the drive's
    adjustment to the target bulk velocity (by the momentum matrix's own
    response to a uniform axial acceleration, riserDrive); the face flux's
    correction for the time derivative (OpenFOAM's ddtCorr of the Euler
    scheme) weighted by the carrier's flux relative to the mesh in either
    frame (OpenFOAM's moving-mesh form weighs it by the absolute flux,
    which in the lab frame holds the riser's velocity); the turbulence
    model's correction; then evolve the cloud in the carrier of the step:
    its velocity at the step's end, and its change over the step, which the
    fluid stress and the added mass take through the carrier's material
    derivative (carrierFlow: fvc::ddt(U), plus the convective part relative
    to the moving mesh). In the lab frame the carrier moves with its wall,
    at the mesh's velocity over the step, and carrierFlow gives the
    particles the carrier relative to the wall and the riser's velocity
    and acceleration at their time instead, as the riser frame does.
    Moving the particles before the carrier would give
    them the carrier of the step before with no change over their step: in
    the lab frame they would not feel the riser's acceleration through the
    fluid, nor in either frame the local change of an unsteady carrier.

    Checks at start, shared with riserParcelFoam (riserCommon): a
    restart's start time is complete (checkStartTime.H); the riser agrees
    with the mesh and the frame with its motion (checkRiser.H); the cloud's
    density, frame force and injectors (checkCloud.H). And, of this
    solver: riserProperties' 'carrier' is interpolated (the computed
    carrier is the mesh's); a periodic riser (cyclic ends) has a 'drive', a
    riser with other ends none; the cloud's alphaMax and its 'kernel'
    sub-dictionary are given (particleCoupling.H); the turbulence model's
    fields are in the start time (else refused naming the model's entry
    and the missing file). A cloud with
    coupled false is a one-way run on the computed carrier: allowed, and
    said in the log; its carrier does not see the particles (alpha_c = 1,
    no reaction; a drag with a voidage function is refused).

Usage
    riserCoupledFoam [-cloud name]

    constant/riserProperties (riserModel; carrier interpolated, the
    default, is the only value allowed here):
    \verbatim
    D           0.1;            // riser diameter [m], (0, 10]
    uCentre     1;              // centre-line speed [m/s], [0, 100]
    A           0.1;            // amplitude [m], [0, 10]
    f           3;              // frequency [Hz], [0, 1000] (or omega)
    phi0        0;              // phase [rad], [-2 pi, 2 pi]
    frame       riser;          // lab | riser, default lab
    drive                       // periodic riser only (riserDrive)
    {
        bulkVelocity    0.5;    // target bulk velocity [m/s], [0, 100],
                                // default uCentre/2
        relaxation      1;      // (0, 1], default 1
        // optional, both or neither: a pulsation U_p sin(2 pi f_p t) of
        // the target (the Womersley flow of a pulsating pump)
        pulseAmplitude  0.1;    // U_p [m/s], (0, 100]
        pulseFrequency  1;      // f_p [Hz], (0, 1e3]
    }
    \endverbatim

    constant/<cloud>Properties: the riser cloud's dictionary (as for
    riserParcelFoam), with in its solution dictionary coupled true for a
    two-way run and the semi-implicit source scheme for U
    (sourceTerms { schemes { U semiImplicit 1; } }; explicit, or a
    coefficient other than 1, which relaxes the reaction, is refused),
    and in
    constantProperties
    \verbatim
    alphaMax    0.6;            // largest solids volume fraction of a cell,
                                // (0, 0.74]: alpha_c >= 1 - alphaMax
    \endverbatim
    The bound 0.74 is the densest packing of equal spheres, pi/(3 sqrt 2);
    random packings stop near 0.64. The floor on alpha_c keeps the
    carrier's equations defined where the particles, counted whole in the
    cell of their centre, would fill a cell. And, required, the
    coarse-particle kernel (particleKernel.H lists its entries):
    \verbatim
    kernel { type none; }       // each particle's volume and force in the
                                // cell of its centre (d much below a cell)
    kernel                      // or spread (d comparable to a cell or more)
    {
        type        diffusion;
        width       3;          // bandwidth, a few diameters
        widthUnit   diameters;  // of the largest particle so far | metres
    }
    \endverbatim

    constant/transportProperties: transportModel Newtonian; nu (0, 1] m^2/s;
    rhoInf (0, 1e5] kg/m^3. constant/turbulenceProperties: simulationType
    laminar | RAS | LES with the models OpenFOAM builds for DPMFoam's
    carrier (laminar Stokes; RAS kEpsilon, realizableKE, kOmegaSST; LES
    Smagorinsky, kEqn), their fields in the start time (k, omega, nut with
    wall functions, ...).

    system/fvSolution: solvers for p, pFinal, U (and UFinal, the turbulence
    fields) and PIMPLE { nOuterCorrectors; nCorrectors;
    nNonOrthogonalCorrectors; momentumPredictor; pRefCell; pRefValue; }
    (the periodic riser's pressure needs a reference).

    Fields: U [m/s] (riserWall: noSlip in the riser frame, movingWallVelocity
    in the lab frame), p [m^2/s^2] (riserWall: fixedFluxPressure, which
    gives the wall the pressure gradient that balances the forces through
    the fluxes), and the turbulence model's (and system/fvSchemes wallDist
    for the models that need the wall distance); written
    besides: phi, alphac (the one of the step that wrote the time: of the
    particles at the step's start, read back by a continuation as its
    first step's old time), particleForce (the particles' explicit reaction
    over rho [m/s^2]), particleReaction (the whole reaction over rho, the
    explicit part and the implicit part on the step's final U [m/s^2]: its
    integral times rho is the force the carrier took from the particles in
    the step), the cloud (with its sources UTrans and UCoeff, the
    reaction of a continuation's first step), and <time>/uniform/riserDrive (the
    drive's dp/dz). The drive's time series is
    postProcessing/riserDrive/<start time>/drive.dat (t, dpdz [Pa/m], Ub).

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "dynamicFvMesh.H"
#include "singlePhaseTransportModel.H"
#include "PhaseIncompressibleTurbulenceModel.H"
#include "pimpleControl.H"
#include "basicRiserCloud.H"
#include "carrierFlow.H"
#include "riserDrive.H"
#include "modelEntries.H"
#include "coreVector.H"
#include "foamVtkSeriesWriter.H"
#include "particleCoupling.H"

#include "caseDictionaries.H"

#include <fstream>
#include <sstream>

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Particles in a riser with a computed, two-way coupled carrier"
        " (volume-averaged incompressible flow, PIMPLE), periodic riser"
        " driven at its bulk velocity, riser or lab frame"
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

    // The riser's acceleration, which the pressure takes: p is the
    // pressure less its part -a_r.x (and less the hydrostatic part). In
    // the riser frame a_r is the frame's (riserModel); in the lab frame
    // the change of the moving mesh's velocity over the step,
    // (x_c(t) - 2 x_c(t - dt) + x_c(t - 2 dt))/dt^2 (and y_c's), so that
    // the carrier keeps the wall's discrete velocity; the riser's motion
    // is the same at every height (createFields), asked at the section's
    // lowest z
    dimensionedVector aRiser("aRiser", dimAcceleration, Zero);
    const bool riserFrame =
        theRiser.frame() == riserModel::simulationFrame::riser;
    auto riserAcceleration = [&]()
    {
        const riser::RiserMotion& motion = theRiser.motion();
        const scalar t = runTime.value();
        const scalar z = theRiser.section().z0;
        if (motion.maxSpeed() == 0)
        {
            return vector::zero;
        }
        if (riserFrame)
        {
            return theRiser.frameAcceleration(z, t);
        }
        const scalar dt = runTime.deltaTValue();
        return fromCore
        (
            (
                motion.axis(z, t) - 2*motion.axis(z, t - dt)
              + motion.axis(z, t - 2*dt)
            )/sqr(dt)
        );
    };

    // The forces that act through the face fluxes, as the pressure
    // gradient does, times 1/A: the particles' explicit reaction, the drive
    // (a uniform pressure gradient) and what p leaves of the riser's
    // acceleration: in the riser frame the fictitious force -alpha_c a_r
    // on the carrier's mass less the -a_r that p takes, (1 - alpha_c) a_r,
    // nothing without particles; in the lab frame the a_r that p does not
    // give
    auto forceFlux = [&]
    (
        const volScalarField& rAU,
        const surfaceScalarField& rAUf
    )
    {
        tmp<surfaceScalarField> tflux(fvc::flux(rAU*particleForce));
        if (drive.valid())
        {
            tflux.ref() += rAUf*(drive->acceleration() & mesh.Sf());
        }
        if (mag(aRiser.value()) > 0)
        {
            if (riserFrame)
            {
                tflux.ref() += rAUf*(1 - alphacf)*(aRiser & mesh.Sf());
            }
            else
            {
                tflux.ref() += rAUf*(aRiser & mesh.Sf());
            }
        }
        return tflux;
    };

    // The face flux's correction for the carrier's time derivative (the
    // time part of the Rhie-Chow interpolation, fvc::ddtCorr of the Euler
    // scheme): (phi_0 - S_f . (U_0)_f)/dt, phi_0 the old flux (on a moving
    // mesh the face velocity's, S_f . Uf_0), weighted as OpenFOAM weighs it,
    // 1 - min(|phi_0 - S_f . (U_0)_f|/|phi_0|, 1) and 0 at the walls, but
    // with phi_0 the carrier's flux relative to the mesh in either frame.
    // The difference phi_0 - S_f . (U_0)_f is the same in both frames (the
    // riser's uniform velocity cancels); OpenFOAM's moving-mesh form
    // weighs it by the absolute flux, which in the lab frame holds the
    // riser's velocity, so that where the particles disturb the carrier
    // (two-way) the lab frame corrected the flux more than the riser frame,
    // whatever the step
    auto ddtFluxCorrection = [&]()
    {
        const surfaceScalarField phi0
        (
            Uf.valid()
          ? surfaceScalarField(mesh.Sf() & Uf().oldTime())
          : phi.oldTime()
        );
        const surfaceScalarField phiCorr
        (
            phi0 - fvc::dotInterpolate(mesh.Sf(), U.oldTime())
        );
        tmp<fv::ddtScheme<vector>> scheme
        (
            fv::ddtScheme<vector>::New
            (
                mesh,
                mesh.ddtScheme("ddt(" + U.name() + ')')
            )
        );
        return tmp<surfaceScalarField>
        (
            scheme.ref().fvcDdtPhiCoeff(U.oldTime(), phi.oldTime(), phiCorr)
           *phiCorr/runTime.deltaT()
        );
    };

    turbulence->validate();

    // * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

    Info<< "\nStarting time loop\n" << endl;

    while (runTime.loop())
    {
        Info<< "Time = " << runTime.timeName() << nl << endl;

        if (mesh.dynamic())
        {
            kinematicCloud.storeGlobalPositions();
        }

        // (phi, relative to the mesh, stays: the riser's mesh moves
        // rigidly, its cells and the wall's flux, zero, unchanged)
        mesh.update();
        if (!phiRelative && mesh.moving())
        {
            fvc::makeRelative(phi, U);
            phiRelative = true;
        }

        #include "CourantNo.H"

        laminarTransport.correct();
        mu = laminarTransport.nu()*rhoInfValue;

        aRiser.value() = riserAcceleration();

        // What the carrier takes from the particles as they stand at the
        // step's start (particleCoupling.H): their volume fraction, and
        // the reaction of the forces of their last step
        coupling.volumeFraction(alphac);
        if (gMin(alphac.oldTime().primitiveField()) == 1)
        {
            // the carrier held no particles before: those filled in since
            // (riserFill) do not displace it through the continuity
            // equation, which in a periodic section would have no solution
            alphac.oldTime() == alphac;
        }
        alphacf = fvc::interpolate(alphac);
        alphaPhi = alphacf*phi;
        const tmp<fvVectorMatrix> tparticleReaction
        (
            coupling.reaction(U, particleForce)
        );
        const fvVectorMatrix& particleReaction = tparticleReaction();

        while (pimple.loop())
        {
            #include "UEqn.H"

            while (pimple.correct())
            {
                #include "pEqn.H"
            }

            alphaPhi = alphacf*phi;

            if (pimple.turbCorr())
            {
                turbulence->correct();
            }
        }

        particleCoupling::wholeReaction
        (
            particleReaction, particleForce, U, reactionField
        );

        // The particles' step in the carrier of the step: its velocity at
        // the step's end and its change over the step, fvc::ddt(U), which
        // the fluid stress and the added mass take (carrierFlow's Du/Dt),
        // in either frame
        Info<< "Evolving " << kinematicCloud.name() << endl;
        kinematicCloud.evolve();
        #include "finishCloudStep.H"

        if (drive.valid())
        {
            drive->writeRow();
        }

        runTime.write();

        runTime.printExecutionTime(Info);
    }

    Info<< "End\n" << endl;

    return 0;
}


// ************************************************************************* //
