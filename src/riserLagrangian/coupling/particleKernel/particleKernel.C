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
#include "PstreamCombineReduceOps.H"
#include "cpuTimeCxx.H"
#include "riserFoamVersion.H"

#include <Eigen/Core>

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
            dict, {"type", "width", "widthUnit", "pseudoSteps", "tolerance"}
        );
    }
    return type;
}

//- Sum each entry of a list of per-processor partial sums over the
//  processors (one reduction for all)
void combineSums(scalarField& sums)
{
    riserCompatibility::listCombineAll(sums, plusEqOp<scalar>());
}


//- The reciprocal pivots 1/d_i of the incomplete Cholesky factorisation
//  without fill-in, L D^-1 L^T with L's strict lower part the matrix's, of
//  the symmetric matrix A (DIC): d_i = a_ii - sum over the faces f = (j, i),
//  j < i, of a_f^2/d_j
scalarField dicReciprocal(const lduMatrix& A)
{
    scalarField d(A.diag());
    const labelUList& lower = A.lduAddr().lowerAddr();
    const labelUList& upper = A.lduAddr().upperAddr();
    const scalarField& a = A.upper();
    forAll(a, f)
    {
        d[upper[f]] -= sqr(a[f])/d[lower[f]];
    }
    return 1/d;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * The pseudo-step * * * * * * * * * * * * * * //

//- A pseudo-step's matrix A = V - dtau laplacian (Gauss linear
//  uncorrected), its coupled patches' diagonal share included (cyclic,
//  processor) as OpenFOAM's segregated solve sets it, with what the
//  solves need of it: the DIC factor, the sweeps' face factors, the
//  coupled patches and the cells next to them. Built for one bandwidth;
//  particleKernel keeps it while the mesh stands still
class Foam::particleKernelPseudoStep
{
    //- A zero field whose patch fields the interfaces refer to
    tmp<volScalarField> work_;

    //- The matrix as assembled (its boundary coefficients)
    tmp<fvScalarMatrix> eq_;

    static tmp<fvScalarMatrix> assemble
    (
        volScalarField& work,
        const scalar dtau
    )
    {
        const fvMesh& mesh = work.mesh();
        IStringStream schemeSpec("Gauss linear uncorrected");
        tmp<fv::laplacianScheme<scalar, scalar>> laplacian
        (
            fv::laplacianScheme<scalar, scalar>::New(mesh, schemeSpec)
        );
        const surfaceScalarField dtauf
        (
            IOobject
            (
                "particleKernel:dtau",
                mesh.time().timeName(),
                mesh,
                IOobject::NO_READ,
                IOobject::NO_WRITE,
                false
            ),
            mesh,
            dimensionedScalar("dtau", dimArea, dtau)
        );
        return
            fvm::Sp(dimensionedScalar("one", dimless, 1), work)
          - laplacian->fvmLaplacian(dtauf, work);
    }

    //- The matrix with its diagonal D
    static lduMatrix withDiagonal(const fvScalarMatrix& eq)
    {
        lduMatrix A(eq);
        A.diag() = eq.D();
        return A;
    }

public:

    //- The bandwidth and the time index it was built for
    const scalar b;
    const label timeIndex;

    //- A, its diagonal D (internal and coupled coefficients)
    const lduMatrix A;
    const lduInterfaceFieldPtrsList interfaces;

    //- The DIC factor's reciprocal pivots
    const scalarField rD;

    //- The sweeps' face factors: rD of the face's upper cell times its
    //  coefficient (the forward sweep), of its lower cell (the backward)
    scalarField forward, backward;

    //- The cells next to the coupled patches
    labelList couplingCells;

    particleKernelPseudoStep
    (
        tmp<volScalarField> work,
        const scalar dtau,
        const scalar b,
        const label timeIndex
    )
    :
        work_(work),
        eq_(assemble(work_.ref(), dtau)),
        b(b),
        timeIndex(timeIndex),
        A(withDiagonal(eq_())),
        interfaces(work_().boundaryField().scalarInterfaces()),
        rD(dicReciprocal(A)),
        forward(A.upper().size()),
        backward(A.upper().size())
    {
        const labelUList& lower = A.lduAddr().lowerAddr();
        const labelUList& upper = A.lduAddr().upperAddr();
        forAll(forward, f)
        {
            forward[f] = rD[upper[f]]*A.upper()[f];
            backward[f] = rD[lower[f]]*A.upper()[f];
        }
        labelHashSet cells;
        forAll(interfaces, patchi)
        {
            if (interfaces.set(patchi))
            {
                cells.insert(A.lduAddr().patchAddr(patchi));
            }
        }
        couplingCells = cells.sortedToc();
    }

    //- The coupled patches' coefficients
    const FieldField<Field, scalar>& bouCoeffs() const
    {
        return eq_().boundaryCoeffs();
    }
};


// * * * * * * * * * * * * * * * The solves  * * * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;


//- One cell's entries of K interleaved fields, as a small fixed-size
//  array: its arithmetic is one SIMD instruction for two fields where the
//  compiler's vector width allows
template<label K>
using Lanes = Eigen::Array<scalar, K, 1>;

template<label K>
inline Eigen::Map<Lanes<K>> lanes(scalar* p)
{
    return Eigen::Map<Lanes<K>>(p);
}

template<label K>
inline Eigen::Map<const Lanes<K>> lanes(const scalar* p)
{
    return Eigen::Map<const Lanes<K>>(p);
}


//- Preconditioned conjugate gradients for K fields at once on one
//  symmetric matrix A (the kernel's pseudo-step), the DIC preconditioner:
//  the fields interleaved (entry K*cell + k), so that each face's
//  addressing and coefficient are read once for the K fields and their
//  values share cache lines; each field has its own step lengths and
//  stops on its own residual. Each iteration makes four passes over the
//  cells and three over the faces (the product and the two sweeps of the
//  preconditioner)
template<label K>
class lockstepPCG
{
    const particleKernelPseudoStep& step_;
    const lduMatrix& A_;
    const scalarField& rD_;
    const label n_;

    //- Work fields, interleaved: solution, residual, preconditioned
    //  residual, direction, A times direction
    scalarField x_, r_, w_, p_, q_;

    //- One field's values and its interface contribution (the coupled
    //  patches' updates take one scalar field at a time), set at the
    //  coupling cells
    solveScalarField one_, oneResult_;

    //- Sum each field's entry of per-processor partial sums over the
    //  processors
    static Lanes<K> reduced(const Lanes<K>& sums)
    {
        scalarField all(K);
        for (label k = 0; k < K; ++k)
        {
            all[k] = sums(k);
        }
        combineSums(all);
        Lanes<K> out;
        for (label k = 0; k < K; ++k)
        {
            out(k) = all[k];
        }
        return out;
    }

    //- y += (the off-diagonal part of A, the coupled patches included) v,
    //  interleaved
    void addOffDiagonal(scalarField& y, const scalarField& v)
    {
        const scalar* const __restrict__ a = A_.upper().begin();
        const label* const __restrict__ lower = A_.lduAddr().lowerAddr().begin();
        const label* const __restrict__ upper = A_.lduAddr().upperAddr().begin();
        const scalar* const vp = v.begin();
        scalar* const yp = y.begin();
        const label nFaces = A_.upper().size();
        for (label f = 0; f < nFaces; ++f)
        {
            const label l = K*lower[f];
            const label u = K*upper[f];
            lanes<K>(yp + u) += a[f]*lanes<K>(vp + l);
            lanes<K>(yp + l) += a[f]*lanes<K>(vp + u);
        }
        // the coupled patches read and write their cells only
        for (label k = 0; k < K; ++k)
        {
            for (const label i : step_.couplingCells)
            {
                one_[i] = vp[K*i + k];
                oneResult_[i] = 0;
            }
            addCoupledProduct
            (
                A_, step_.bouCoeffs(), step_.interfaces, one_, oneResult_
            );
            for (const label i : step_.couplingCells)
            {
                yp[K*i + k] += oneResult_[i];
            }
        }
    }

    //- The sweeps of w = M^-1 r, M = (D + L) D^-1 (D + L^T) the DIC
    //  factorisation (rD = 1/d), given w = rD r: forward and backward
    //  over the faces
    void sweep()
    {
        const label* const __restrict__ lower = A_.lduAddr().lowerAddr().begin();
        const label* const __restrict__ upper = A_.lduAddr().upperAddr().begin();
        const scalar* const __restrict__ fw = step_.forward.begin();
        const scalar* const __restrict__ bw = step_.backward.begin();
        scalar* const w = w_.begin();
        const label nFaces = step_.forward.size();
        for (label f = 0; f < nFaces; ++f)
        {
            lanes<K>(w + K*upper[f]) -= fw[f]*lanes<K>(w + K*lower[f]);
        }
        for (label f = nFaces - 1; f >= 0; --f)
        {
            lanes<K>(w + K*lower[f]) -= bw[f]*lanes<K>(w + K*upper[f]);
        }
    }

    //- Per field, the sum over the cells and processors of u v
    Lanes<K> dot(const scalarField& u, const scalarField& v) const
    {
        Lanes<K> sums(Lanes<K>::Zero());
        for (label i = 0; i < n_; ++i)
        {
            sums += lanes<K>(u.begin() + K*i)*lanes<K>(v.begin() + K*i);
        }
        return reduced(sums);
    }

public:

    explicit lockstepPCG(const particleKernelPseudoStep& step)
    :
        step_(step),
        A_(step.A),
        rD_(step.rD),
        n_(rD_.size()),
        x_(K*n_),
        r_(K*n_),
        w_(K*n_),
        p_(K*n_),
        q_(K*n_),
        one_(n_, Zero),
        oneResult_(n_, Zero)
    {}

    //- Solve A x = V x0 for the K fields fields[first .. first + K - 1]
    //  in place, from x0 (the previous pseudo-step), to residuals of at
    //  most stop[k] in the 1-norm; returns the iterations of each field
    FixedList<label, K> solve
    (
        List<scalarField>& fields,
        const label first,
        const scalarField& V,
        const FixedList<scalar, K>& stop
    )
    {
        const scalar* const __restrict__ d = A_.diag().begin();
        const scalar* const __restrict__ rd = rD_.begin();
        scalar* const __restrict__ x = x_.begin();
        scalar* const __restrict__ r = r_.begin();
        scalar* const __restrict__ w = w_.begin();
        scalar* const __restrict__ p = p_.begin();
        scalar* const __restrict__ q = q_.begin();

        for (label k = 0; k < K; ++k)
        {
            const scalarField& f = fields[first + k];
            for (label i = 0; i < n_; ++i)
            {
                x[K*i + k] = f[i];
            }
        }
        // r = V x0 - A x0, its 1-norm, and w = rD r ahead of the sweeps
        for (label i = 0; i < n_; ++i)
        {
            lanes<K>(q + K*i) = d[i]*lanes<K>(x + K*i);
        }
        addOffDiagonal(q_, x_);
        Lanes<K> res(Lanes<K>::Zero());
        for (label i = 0; i < n_; ++i)
        {
            lanes<K>(r + K*i) = V[i]*lanes<K>(x + K*i) - lanes<K>(q + K*i);
            res += lanes<K>(r + K*i).abs();
            lanes<K>(w + K*i) = rd[i]*lanes<K>(r + K*i);
        }
        res = reduced(res);

        FixedList<label, K> iterations(label(0));
        FixedList<bool, K> active;
        Lanes<K> rho(Lanes<K>::Zero());
        for (label k = 0; k < K; ++k)
        {
            active[k] = res(k) > stop[k];
        }
        p_ = Zero;
        for (label iter = 0; active.found(true); ++iter)
        {
            if (iter == maxIterations)
            {
                FixedList<scalar, K> reached;
                for (label k = 0; k < K; ++k)
                {
                    reached[k] = res(k);
                }
                WarningInFunction
                    << "stopped after " << iter << " iterations at"
                    << " residuals " << reached << " (to reach " << stop
                    << "): the sum of each spread field is restored"
                    << " afterwards" << endl;
                break;
            }
            sweep();
            const Lanes<K> rw = dot(r_, w_);
            Lanes<K> beta(Lanes<K>::Zero());
            for (label k = 0; k < K; ++k)
            {
                beta(k) = iter > 0 && active[k] ? rw(k)/rho(k) : 0;
                rho(k) = rw(k);
            }
            // p = w + beta p, and q = A p: its diagonal part, then the rest
            for (label i = 0; i < n_; ++i)
            {
                lanes<K>(p + K*i) =
                    lanes<K>(w + K*i) + beta*lanes<K>(p + K*i);
                lanes<K>(q + K*i) = d[i]*lanes<K>(p + K*i);
            }
            addOffDiagonal(q_, p_);
            const Lanes<K> pq = dot(p_, q_);
            Lanes<K> alpha(Lanes<K>::Zero());
            for (label k = 0; k < K; ++k)
            {
                if (active[k] && pq(k) > 0)
                {
                    alpha(k) = rho(k)/pq(k);
                    ++iterations[k];
                }
            }
            // the update, the residual's 1-norm, and w = rD r for the next
            // iteration's sweeps
            res = Lanes<K>::Zero();
            for (label i = 0; i < n_; ++i)
            {
                lanes<K>(x + K*i) += alpha*lanes<K>(p + K*i);
                lanes<K>(r + K*i) -= alpha*lanes<K>(q + K*i);
                res += lanes<K>(r + K*i).abs();
                lanes<K>(w + K*i) = rd[i]*lanes<K>(r + K*i);
            }
            res = reduced(res);
            for (label k = 0; k < K; ++k)
            {
                active[k] = active[k] && pq(k) > 0 && res(k) > stop[k];
            }
        }
        for (label k = 0; k < K; ++k)
        {
            scalarField& f = fields[first + k];
            for (label i = 0; i < n_; ++i)
            {
                f[i] = x[K*i + k];
            }
        }
        return iterations;
    }

    //- A solve stops (with a warning) after so many iterations
    static constexpr label maxIterations = 1000;
};


//- The pseudo-steps of the fields fields[first .. first + K - 1]
//  (debug: each step's iterations printed)
template<label K>
void pseudoSteps
(
    List<scalarField>& fields,
    const label first,
    const label nSteps,
    const scalarField& V,
    const scalarField& stop,
    const particleKernelPseudoStep& pseudoStep,
    const bool report
)
{
    lockstepPCG<K> solver(pseudoStep);
    FixedList<scalar, K> stopK;
    for (label k = 0; k < K; ++k)
    {
        stopK[k] = stop[first + k];
    }
    for (label step = 0; step < nSteps; ++step)
    {
        const FixedList<label, K> iterations =
            solver.solve(fields, first, V, stopK);
        if (report)
        {
            Info<< "particleKernel: pseudo-step " << step
                << ", iterations of the " << K << " fields:";
            for (const label n : iterations)
            {
                Info<< ' ' << n;
            }
            Info<< endl;
        }
    }
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
    tolerance_
    (
        type_ == kernelType::diffusion
      ? checkedEntry::inRange(dict, "tolerance", 1e-15, true, 1e-3, true, 1e-4)
      : 0
    ),
    largestDiameter_(0),
    sizesTimeIndex_(-1),
    largestCellSize_(0),
    crossSection_(0),
    shares_(mesh)
{
    if (type_ == kernelType::diffusion && unit_ == widthUnit::metres)
    {
        // checked now: the width does not depend on the particles
        bandwidth(0);
    }
}


// * * * * * * * * * * * * * * * * Destructor  * * * * * * * * * * * * * * * //

Foam::particleKernel::~particleKernel()
{}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

bool Foam::particleKernel::outdated(const label builtAt) const
{
    return pointShares::outdated(mesh_, builtAt);
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
    // the mesh's sizes
    if (outdated(sizesTimeIndex_))
    {
        largestCellSize_ = largestCellSize();
        crossSection_ = crossSection();
        sizesTimeIndex_ = mesh_.time().timeIndex();
    }
    const scalar h = largestCellSize_;
    const scalar D = crossSection_;
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
    const cpuTimeCxx timer;
    const scalar dtau = sqr(b)/4/pseudoSteps_;
    const scalarField& V = mesh_.V().field();

    // the pseudo-step, built again for another bandwidth
    if (!pseudoStep_ || pseudoStep_->b != b || outdated(pseudoStep_->timeIndex))
    {
        pseudoStep_.reset
        (
            new particleKernelPseudoStep
            (
                workField("spread"), dtau, b, mesh_.time().timeIndex()
            )
        );
    }
    const particleKernelPseudoStep& pseudoStep = *pseudoStep_;

    const label nFields = densities.size();
    scalarField total0(nFields), stop(nFields), lowest(nFields);
    forAll(densities, k)
    {
        total0[k] = sum(V*densities[k]);
        stop[k] = tolerance_*sum(V*mag(densities[k]));
        lowest[k] = min(densities[k]);
    }
    combineSums(total0);
    combineSums(stop);
    riserCompatibility::listCombineAll(lowest, minEqOp<scalar>());

    // the fields in groups of up to four, each group's solves in lock-step
    for (label first = 0; first < nFields; first += 4)
    {
        switch (min(label(4), nFields - first))
        {
            case 1:
                pseudoSteps<1>
                (
                    densities, first, pseudoSteps_, V, stop, pseudoStep,
                    debug
                );
                break;
            case 2:
                pseudoSteps<2>
                (
                    densities, first, pseudoSteps_, V, stop, pseudoStep,
                    debug
                );
                break;
            case 3:
                pseudoSteps<3>
                (
                    densities, first, pseudoSteps_, V, stop, pseudoStep,
                    debug
                );
                break;
            default:
                pseudoSteps<4>
                (
                    densities, first, pseudoSteps_, V, stop, pseudoStep,
                    debug
                );
                break;
        }
    }

    // The sums kept exactly: a field deposited non-negative stays so (the
    // exact solution does; the iterate's round-off and tolerance
    // undershoots are cut), then the defect of sum(phi V), of the order of
    // the tolerance, goes back in proportion to |phi|, where the field is
    scalarField total(nFields), weight(nFields);
    forAll(densities, k)
    {
        scalarField& phi = densities[k];
        if (lowest[k] >= 0)
        {
            phi = max(phi, scalar(0));
        }
        total[k] = sum(V*phi);
        weight[k] = sum(V*mag(phi));
    }
    combineSums(total);
    combineSums(weight);
    forAll(densities, k)
    {
        if (weight[k] > 0)
        {
            densities[k] += ((total0[k] - total[k])/weight[k])*mag(densities[k]);
        }
    }
    if (debug)
    {
        Info<< "particleKernel: " << nFields << " field(s) spread in "
            << timer.elapsedCpuTime() << " s of CPU time" << endl;
    }
}


// ************************************************************************* //
