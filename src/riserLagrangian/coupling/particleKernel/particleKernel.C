/*---------------------------------------------------------------------------*\
  riserFoam: particle transport in vibrating risers, on OpenFOAM
  License: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "particleKernel.H"
#include "checkedEntry.H"
#include "fvMatrices.H"
#include "fvmSup.H"
#include "laplacianScheme.H"
#include "zeroGradientFvPatchFields.H"
#include "IStringStream.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(particleKernel, 0);
}


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

particleKernel::kernelType readType(const dictionary& dict)
{
    const auto type = checkedEntry::choice<particleKernel::kernelType>
    (
        dict, "type",
        {{"diffusion", particleKernel::kernelType::diffusion},
         {"none", particleKernel::kernelType::none}}
    );
    if (type == particleKernel::kernelType::none)
    {
        // the one-cell deposit: an entry of the diffusion kernel would
        // look as if it acted
        checkedEntry::allowedKeys(dict, {"type"});
    }
    else
    {
        checkedEntry::allowedKeys
        (
            dict, {"type", "width", "widthUnit", "pseudoSteps"}
        );
    }
    return type;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::particleKernel::particleKernel
(
    const fvMesh& mesh,
    const dictionary& dict
)
:
    mesh_(mesh),
    dict_(dict),
    type_(readType(dict)),
    width_
    (
        type_ == kernelType::diffusion
      ? checkedEntry::inRange(dict, "width", 0, false, VGREAT, false)
      : 0
    ),
    unit_
    (
        type_ == kernelType::diffusion
      ? checkedEntry::choice<widthUnit>
        (
            dict, "widthUnit",
            {{"diameters", widthUnit::diameters},
             {"metres", widthUnit::metres}}
        )
      : widthUnit::metres
    ),
    pseudoSteps_
    (
        type_ == kernelType::diffusion
      ? checkedEntry::count(dict, "pseudoSteps", 1, 100, 4)
      : 0
    ),
    largestDiameter_(0)
{
    if (type_ == kernelType::diffusion && unit_ == widthUnit::metres)
    {
        // checked now: the width does not depend on the particles
        bandwidth(0);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::particleKernel::largestCellSize() const
{
    // each cell's bounding box from the points of its faces
    const pointField& points = mesh_.points();
    const label nCells = mesh_.nCells();
    vectorField lo(nCells, vector::uniform(VGREAT));
    vectorField hi(nCells, vector::uniform(-VGREAT));
    const labelList& own = mesh_.faceOwner();
    const labelList& nei = mesh_.faceNeighbour();
    forAll(mesh_.faces(), facei)
    {
        for (const label pointi : mesh_.faces()[facei])
        {
            const point& p = points[pointi];
            lo[own[facei]] = min(lo[own[facei]], p);
            hi[own[facei]] = max(hi[own[facei]], p);
            if (facei < mesh_.nInternalFaces())
            {
                lo[nei[facei]] = min(lo[nei[facei]], p);
                hi[nei[facei]] = max(hi[nei[facei]], p);
            }
        }
    }
    scalar h = 0;
    forAll(lo, celli)
    {
        h = max(h, cmptMax(hi[celli] - lo[celli]));
    }
    return returnReduce(h, maxOp<scalar>());
}


Foam::scalar Foam::particleKernel::crossSection() const
{
    const boundBox bb(mesh_.points(), true);
    const vector span = bb.span();
    return min(span.x(), span.y());
}


Foam::scalar Foam::particleKernel::bandwidth(const scalar dMax) const
{
    if (type_ != kernelType::diffusion)
    {
        FatalErrorInFunction
            << "the kernel of type none has no bandwidth" << exit(FatalError);
    }
    const scalar h = largestCellSize();
    const scalar D = crossSection();
    if (unit_ == widthUnit::metres)
    {
        checkedEntry::checkRange(dict_, "width", width_, h, true, D, true);
        return width_;
    }
    if (!(dMax > 0))
    {
        FatalErrorInFunction
            << "a kernel width in particle diameters needs a particle"
            << " diameter; given " << dMax << exit(FatalError);
    }
    const scalar b = width_*dMax;
    if (!(b >= h && b <= D))
    {
        FatalIOErrorInFunction(dict_)
            << "entry 'width' = " << width_ << " diameters is a bandwidth of "
            << b << " m for the largest particle diameter " << dMax
            << " m; allowed: [" << h/dMax << ", " << D/dMax
            << "] diameters, from the largest cell size " << h
            << " m to the mesh's cross-section " << D << " m" << nl
            << exit(FatalIOError);
    }
    return b;
}


Foam::tmp<Foam::volScalarField>
Foam::particleKernel::workField(const word& name) const
{
    wordList types(mesh_.boundary().size());
    forAll(types, patchi)
    {
        const word& patchType = mesh_.boundaryMesh()[patchi].type();
        types[patchi] =
            polyPatch::constraintType(patchType)
          ? patchType
          : zeroGradientFvPatchScalarField::typeName;
    }
    return tmp<volScalarField>::New
    (
        IOobject
        (
            "particleKernel:" + name,
            mesh_.time().timeName(),
            mesh_,
            IOobject::NO_READ,
            IOobject::NO_WRITE,
            false
        ),
        mesh_,
        dimensionedScalar(dimless, Zero),
        types
    );
}


void Foam::particleKernel::diffuse
(
    List<scalarField>& densities,
    const scalar b
) const
{
    const scalar dtau = sqr(b)/4/pseudoSteps_;

    // the field the matrix solves for; each density in turn
    tmp<volScalarField> twork(workField("spread"));
    volScalarField& phi = twork.ref();

    // the two-point Laplacian (no explicit non-orthogonal part: an
    // M-matrix, non-negative deposits stay non-negative), whatever the
    // case's fvSchemes say
    IStringStream schemeSpec("Gauss linear uncorrected");
    tmp<fv::laplacianScheme<scalar, scalar>> laplacian
    (
        fv::laplacianScheme<scalar, scalar>::New(mesh_, schemeSpec)
    );
    const surfaceScalarField dtauf
    (
        IOobject
        (
            "particleKernel:dtau",
            mesh_.time().timeName(),
            mesh_,
            IOobject::NO_READ,
            IOobject::NO_WRITE,
            false
        ),
        mesh_,
        dimensionedScalar("dtau", dimArea, dtau)
    );

    // V phi - dtau laplacian(phi) = V phi_old: the matrix is the same for
    // every step and density (the solver leaves it unchanged), only the
    // source changes
    fvScalarMatrix eq
    (
        fvm::Sp(dimensionedScalar("one", dimless, 1), phi)
      - laplacian->fvmLaplacian(dtauf, phi)
    );

    dictionary controls;
    controls.add("solver", "PCG");
    controls.add("preconditioner", "DIC");
    controls.add("tolerance", 1e-14);
    controls.add("relTol", 0);
    controls.add("maxIter", 1000);

    // the pseudo-steps' solver lines are not the flow's: kept out of the log
    const int printing = solverPerformance::debug;
    solverPerformance::debug = 0;
    for (scalarField& density : densities)
    {
        phi.primitiveFieldRef() = density;
        phi.correctBoundaryConditions();
        for (label step = 0; step < pseudoSteps_; ++step)
        {
            eq.source() = mesh_.V().field()*phi.primitiveField();
            const solverPerformance perf = eq.solve(controls);
            if (debug)
            {
                Info<< "particleKernel: pseudo-step " << step << ", "
                    << perf.nIterations() << " iterations, residual "
                    << perf.initialResidual() << " -> "
                    << perf.finalResidual() << endl;
            }
            if (!perf.converged() && perf.finalResidual() > 1e-10)
            {
                WarningInFunction
                    << "pseudo-step " << step << " left the residual "
                    << perf.finalResidual() << " after "
                    << perf.nIterations() << " iterations: the sum of the"
                    << " spread field is kept to about that" << endl;
            }
        }
        density = phi.primitiveField();
    }
    solverPerformance::debug = printing;
}


// ************************************************************************* //
