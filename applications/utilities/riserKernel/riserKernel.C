/*---------------------------------------------------------------------------*\
  riserFoam: particle transport in vibrating risers, on OpenFOAM
  License: GPL-3.0-or-later

Application
    riserKernel

Group
    riserFoam/utilities

Description
    Spreads point deposits over the coarse-particle kernel (particleKernel)
    on a case's mesh and writes what it did: particle volumes deposited in
    the cells holding the points (per unit volume, as theta) and vector
    amounts (momentum, as UTrans) deposited per cell, both spread with the
    kernel of system/riserKernelDict.

    On a moving mesh (constant/dynamicMeshDict) the mesh is first moved
    from the start time to endTime, step by step, and the deposits are
    spread on the moved mesh.

    With -cloud name, the deposits are instead those of a two-way coupled
    stock colliding cloud (basicKinematicCollidingCloud of
    constant/<name>Properties, in the carrier U of the start time, rho and
    nu of constant/transportProperties) after one step of it, and the
    kernel is the cloud's ('kernel' in its properties): the utility calls
    what a coupled solver calls, particleKernel::alphac and
    particleKernel::SU (alphaMin 0), and prints their sums beside the stock
    cloud's (theta, SU): sum (1 - alpha_c) V against sum theta V, the
    largest of each; the momentum source's explicit part sum(source) and
    implicit part sum(diag).

    Prints the bandwidth, the largest cell size, the mesh's cross-section
    and, for each field, its sum over the cells (sum of theta V; sum of the
    amounts) before and after spreading; writes
    postProcessing/riserKernel/cells.dat (per processor in parallel): one
    row per cell, its centre, volume, theta and the vector amount after
    spreading.

Usage
    system/riserKernelDict:
    \verbatim
    kernel      { type diffusion; width 3; widthUnit diameters; pseudoSteps 4; }
    diameter    0.01;       // largest particle diameter [m], (0, 10]
    deposits                // (position volume [m^3]), volume > 0
    (
        ((0 0 0.05) 5.2e-7)
    );
    sources                 // (position amount), e.g. momentum [kg m/s]
    (
        ((0.01 0 0.05) (1 -2 3))
    );
    \endverbatim
    The kernel sub-dictionary is that of particleKernel. Unknown entries
    are refused; a point outside the mesh is an error.

    riserKernel -cloud kinematicCloud: no riserKernelDict; the cloud's
    properties hold the kernel.

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "dynamicFvMesh.H"
#include "particleKernel.H"
#include "checkedEntry.H"
#include "OFstream.H"
#include "Tuple2.H"
#include "basicKinematicCollidingCloud.H"
#include "singlePhaseTransportModel.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

//- The cell holding p on this processor, -1 if another's (a point on a
//  processor boundary belongs to the lowest-numbered processor holding
//  it: deposited once); FatalIOError naming the entry if no processor
//  holds it
label holdingCell
(
    const fvMesh& mesh,
    const dictionary& dict,
    const word& key,
    const point& p
)
{
    const label celli = mesh.findCell(p);
    const label owner = returnReduce
    (
        celli >= 0 ? Pstream::myProcNo() : Pstream::nProcs(),
        minOp<label>()
    );
    if (owner == Pstream::nProcs())
    {
        FatalIOErrorInFunction(dict)
            << "entry '" << key << "': the point " << p
            << " is outside the mesh" << nl << exit(FatalIOError);
    }
    return owner == Pstream::myProcNo() ? celli : -1;
}


//- One step of the coupled cloud, its deposits spread with the cloud's
//  kernel: alpha_c and the momentum source beside the stock cloud's
void spreadCloud(const fvMesh& mesh, Time& runTime, const word& cloudName)
{
    #include "readGravitationalAcceleration.H"
    volVectorField U
    (
        IOobject("U", runTime.timeName(), mesh, IOobject::MUST_READ),
        mesh
    );
    const surfaceScalarField phi
    (
        IOobject("phi", runTime.timeName(), mesh),
        fvc::flux(U)
    );
    singlePhaseTransportModel transport(U, phi);
    const dimensionedScalar rhoInf("rhoInf", dimDensity, transport);
    const volScalarField rho
    (
        IOobject("rho", runTime.timeName(), mesh),
        mesh,
        rhoInf
    );
    const volScalarField mu
    (
        IOobject("mu", runTime.timeName(), mesh),
        transport.nu()*rhoInf
    );

    basicKinematicCollidingCloud cloud(cloudName, rho, U, mu, g);
    particleKernel kernel(mesh, cloud.particleProperties().subDict("kernel"));
    ++runTime;
    cloud.evolve();

    const scalarField& V = mesh.V().field();
    const scalarField theta(cloud.theta()().primitiveField());
    const scalarField spreadTheta(1 - kernel.alphac(cloud, 0)().primitiveField());
    const fvVectorMatrix stock(cloud.SU(U));
    const fvVectorMatrix spread(kernel.SU(cloud, U));
    Info<< "parcels " << cloud.size() << " largestDiameter "
        << kernel.largestDiameter(cloud) << nl
        << "solids stock " << gSum(theta*V) << " spread "
        << gSum(spreadTheta*V) << nl
        << "largestTheta stock " << gMax(theta) << " spread "
        << gMax(spreadTheta) << nl
        << "explicit stock " << gSum(stock.source())
        << " spread " << gSum(spread.source()) << nl
        << "implicit stock " << gSum(stock.diag())
        << " spread " << gSum(spread.diag()) << nl;
}

} // End anonymous namespace


int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Spread point deposits over the coarse-particle kernel"
    );
    argList::addOption
    (
        "cloud",
        "name",
        "spread the deposits of one step of this two-way coupled colliding"
        " cloud with its kernel"
    );

    #include "setRootCase.H"
    #include "createTime.H"
    #include "createDynamicFvMesh.H"

    while (mesh.dynamic() && runTime.run())
    {
        ++runTime;
        mesh.update();
    }

    Info().precision(17);
    if (args.found("cloud"))
    {
        spreadCloud(mesh, runTime, args.get<word>("cloud"));
        Info<< "End" << nl << endl;
        return 0;
    }

    const IOdictionary dict
    (
        IOobject
        (
            "riserKernelDict",
            runTime.system(),
            mesh,
            IOobject::MUST_READ,
            IOobject::NO_WRITE
        )
    );
    checkedEntry::allowedKeys(dict, {"kernel", "diameter", "deposits", "sources"});
    particleKernel kernel(mesh, dict.subDict("kernel"));
    const scalar d = checkedEntry::inRange(dict, "diameter", 0, false, 10, true);

    volScalarField::Internal theta
    (
        IOobject("theta", runTime.timeName(), mesh),
        mesh,
        dimensionedScalar(dimless, Zero)
    );
    for (const auto& deposit : dict.get<List<Tuple2<point, scalar>>>("deposits"))
    {
        const label celli = holdingCell(mesh, dict, "deposits", deposit.first());
        if (!(deposit.second() > 0))
        {
            FatalIOErrorInFunction(dict)
                << "entry 'deposits': the volume " << deposit.second()
                << " is not > 0" << nl << exit(FatalIOError);
        }
        if (celli >= 0)
        {
            theta[celli] += deposit.second()/mesh.V()[celli];
        }
    }
    volVectorField::Internal amount
    (
        IOobject("amount", runTime.timeName(), mesh),
        mesh,
        dimensionedVector(dimless, Zero)
    );
    for (const auto& source : dict.get<List<Tuple2<point, vector>>>("sources"))
    {
        const label celli = holdingCell(mesh, dict, "sources", source.first());
        if (celli >= 0)
        {
            amount[celli] += source.second();
        }
    }

    const scalar thetaBefore = gSum(theta.field()*mesh.V().field());
    const vector amountBefore = gSum(amount.field());
    kernel.spreadDensity(theta, d);
    kernel.spreadAmount(d, amount);
    const scalar thetaAfter = gSum(theta.field()*mesh.V().field());
    const vector amountAfter = gSum(amount.field());

    if (kernel.type() == particleKernel::kernelType::diffusion)
    {
        Info<< "bandwidth " << kernel.bandwidth(d) << nl;
    }
    Info<< "largestCellSize " << kernel.largestCellSize() << nl
        << "crossSection " << kernel.crossSection() << nl
        << "deposits before " << thetaBefore << " after " << thetaAfter << nl
        << "sources before " << amountBefore << " after " << amountAfter << nl;

    const fileName dir
    (
        (Pstream::parRun() ? runTime.path() : runTime.globalPath())
       /"postProcessing"/"riserKernel"
    );
    mkDir(dir);
    OFstream out(dir/"cells.dat");
    out.precision(17);
    out << "# x y z V theta ax ay az" << nl;
    forAll(theta, celli)
    {
        const point& c = mesh.C()[celli];
        const vector& a = amount[celli];
        out << c.x() << ' ' << c.y() << ' ' << c.z() << ' '
            << mesh.V()[celli] << ' ' << theta[celli] << ' '
            << a.x() << ' ' << a.y() << ' ' << a.z() << nl;
    }

    Info<< "End" << nl << endl;
    return 0;
}


// ************************************************************************* //
