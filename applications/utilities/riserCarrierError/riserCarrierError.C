/*---------------------------------------------------------------------------*\
  riserFoam: particle transport in vibrating risers, on OpenFOAM
  License: GPL-3.0-or-later

Application
    riserCarrierError

Group
    riserFoam/utilities

Description
    How far the interpolated carrier is from the exact one on a riser mesh:
    imposes the analytic oscillating-riser flow of constant/riserProperties
    on the cells at t - dt, with the mesh centred on the riser axis, and at
    t, after translating the mesh with the axis (as a mesh moving with the
    riser does), builds the
    interpolated carrier of carrierFlow (cellPoint interpolation of U, of
    curl U and of Du/Dt = ddt(U) + ((U - U_mesh) . grad) U) and compares u,
    curl u and Du/Dt at random points inside the pipe (at least one
    particle radius from the wall) with the exact values.

    Errors are scaled by u_cm (velocity), 2 u_cm / R (vorticity, its value
    at the wall) and A omega^2 (material derivative, the riser's largest
    acceleration). Prints the RMS and largest scaled error of each and
    appends one line to postProcessing/riserCarrierError/errors.dat.

Usage
    riserCarrierError [-time t] [-deltaT dt] [-samples N] [-particleDiameter d]

    -time             evaluation time [s] (default: an eighth of a period
                      before the end of the first period, 7/8 T)
    -deltaT           step between the two field levels [s] (default 1e-5)
    -samples          number of random points (default 4000)
    -particleDiameter d [m]: sample at least d/2 from the wall (default 0.01)

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "carrierFlow.H"
#include "coreVector.H"
#include "interpolationCellPoint.H"
#include "Random.H"
#include "riserFoamVersion.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Error of the interpolated riser carrier against the exact one"
    );
    argList::noParallel();
    argList::addOption("time", "t", "evaluation time [s]");
    argList::addOption("deltaT", "dt", "step between the field levels [s]");
    argList::addOption("samples", "N", "number of random points");
    argList::addOption("particleDiameter", "d", "sample at least d/2 from the wall");

    #include "setRootCase.H"
    #include "createTime.H"
    #include "createMesh.H"

    volVectorField U
    (
        IOobject("U", runTime.timeName(), mesh, IOobject::NO_READ, IOobject::NO_WRITE),
        mesh,
        dimensionedVector(dimVelocity, Zero)
    );
    carrierFlow carrier(U, true);
    const riserModel& theRiser = riserModel::New(mesh);
    const riser::RiserFlow& flow = theRiser.flow();
    const riser::RiserMotion& motion = flow.motion();
    const scalar R = flow.radius();
    if (!motion.uniformAlongAxis())
    {
        FatalErrorInFunction
            << "the mesh moves rigidly here: the riser's motion must be the"
            << " same at every height, not of type " << motion.type()
            << exit(FatalError);
    }
    // the riser's kinematics, the same at every height, asked at the mesh's
    // lowest z
    const scalar z0 = theRiser.section().z0;
    auto period = [&]()
    {
        const scalar omega =
            theRiser.angularFrequency(theRiser.dict(), "the default -time");
        return omega > 0 ? constant::mathematical::twoPi/omega : 1;
    };

    const scalar t =
        args.found("time") ? args.get<scalar>("time") : 0.875*period();
    const scalar dt = args.getOrDefault<scalar>("deltaT", 1e-5);
    const label nSamples = args.getOrDefault<label>("samples", 4000);
    const scalar d = args.getOrDefault<scalar>("particleDiameter", 0.01);
    if (!(dt > 0) || nSamples < 1 || !(d >= 0 && d < 2*R))
    {
        FatalErrorInFunction
            << "need deltaT > 0, samples >= 1 and 0 <= particleDiameter < D"
            << exit(FatalError);
    }

    // The mesh is centred on the axis at t - dt: mesh coordinates are lab
    // coordinates shifted by (x_c, y_c)(t - dt) (a constant shift changes
    // nothing), so that only the step's own small translation moves the
    // mesh.
    const vector shift = fromCore(motion.axis(z0, t - dt));
    auto lab = [shift](const point& x)
    {
        return toCore(x + shift);
    };
    const pointField points0(mesh.points());

    auto imposeFlow = [&](const scalar time)
    {
        vectorField& Ui = U.primitiveFieldRef();
        forAll(Ui, celli)
        {
            const point& c = mesh.C()[celli];
            Ui[celli] = fromCore(flow.velocity(lab(c), time));
        }
        forAll(U.boundaryField(), patchi)
        {
            fvPatchVectorField& Up = U.boundaryFieldRef()[patchi];
            const vectorField& Cf = mesh.C().boundaryField()[patchi];
            forAll(Up, facei)
            {
                const point& c = Cf[facei];
                Up[facei] = fromCore(flow.velocity(lab(c), time));
            }
        }
    };

    runTime.setTime(t - dt, 1);
    runTime.setDeltaT(dt);
    imposeFlow(t - dt);
    U.oldTime();
    runTime.setTime(t, 2);
    const vector axisNow = fromCore(motion.axis(z0, t)) - shift;
    mesh.movePoints(points0 + axisNow);
    imposeFlow(t);

    dictionary schemes;
    schemes.add("U", "cellPoint");
    carrier.cacheVorticity(true, schemes);
    carrier.cacheMaterialDerivative(true, schemes);
    interpolationCellPoint<vector> Uinterp(U);

    const scalar uScale = max(flow.centreLineSpeed(), SMALL);
    const scalar curlScale = 2*uScale/R;
    const scalar aScale = max(motion.maxAcceleration(), SMALL);
    const boundBox bb(mesh.points());

    Random rnd(1234);
    label n = 0;
    scalar sumU = 0, sumCurl = 0, sumA = 0, maxU = 0, maxCurl = 0, maxA = 0;
    for (label i = 0; i < 100*nSamples && n < nSamples; ++i)
    {
        const scalar r = (R - 0.5*d)*Foam::sqrt(rnd.sample01<scalar>());
        const scalar theta = constant::mathematical::twoPi*rnd.sample01<scalar>();
        const scalar z = bb.min().z() + bb.span().z()*(0.1 + 0.8*rnd.sample01<scalar>());
        const point x = axisNow + vector(r*Foam::cos(theta), r*Foam::sin(theta), z);
        const label celli = mesh.findCell(x);
        if (celli < 0) continue;
        const riser::Vector xc = lab(x);

        const scalar eU =
            mag(Uinterp.interpolate(x, celli) - fromCore(flow.velocity(xc, t)))/uScale;
        const scalar eCurl =
            mag(carrier.vorticityAt(x, celli) - fromCore(flow.vorticity(xc, t)))/curlScale;
        const scalar eA =
            mag(carrier.materialDerivativeAt(x, celli)
              - fromCore(flow.materialDerivative(xc, t)))/aScale;
        sumU += sqr(eU); sumCurl += sqr(eCurl); sumA += sqr(eA);
        maxU = max(maxU, eU); maxCurl = max(maxCurl, eCurl); maxA = max(maxA, eA);
        ++n;
    }
    if (n == 0)
    {
        FatalErrorInFunction << "no sample point inside the mesh" << exit(FatalError);
    }
    const scalar rmsU = Foam::sqrt(sumU/n);
    const scalar rmsCurl = Foam::sqrt(sumCurl/n);
    const scalar rmsA = Foam::sqrt(sumA/n);

    Info<< nl << "Carrier interpolation error at t = " << t << " s, " << n
        << " points, " << mesh.nCells() << " cells (scaled RMS, max):" << nl
        << "    velocity              " << rmsU << "  " << maxU << nl
        << "    vorticity             " << rmsCurl << "  " << maxCurl << nl
        << "    material derivative   " << rmsA << "  " << maxA << nl << endl;

    const fileName dir = runTime.globalPath()/"postProcessing"/"riserCarrierError";
    mkDir(dir);
    const bool fresh = !isFile(dir/"errors.dat");
    appendOFstream os(dir/"errors.dat");
    if (fresh)
    {
        os  << "# cells cellSize rmsVelocity maxVelocity rmsVorticity maxVorticity"
            << " rmsMaterialDerivative maxMaterialDerivative" << nl;
    }
    os  << mesh.nCells() << ' ' << Foam::cbrt(gSum(mesh.V())/mesh.nCells()) << ' '
        << rmsU << ' ' << maxU << ' ' << rmsCurl << ' ' << maxCurl << ' '
        << rmsA << ' ' << maxA << nl;

    Info<< "End" << nl << endl;
    return 0;
}


// ************************************************************************* //
