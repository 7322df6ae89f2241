/*---------------------------------------------------------------------------*\
  riserFoam: particle transport in vibrating risers, on OpenFOAM
  License: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "particleKernel.H"
#include "fvMatrices.H"
#include "fvmSup.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class Type>
void Foam::particleKernel::spreadField
(
    Field<Type>& density,
    const scalar b
) const
{
    List<scalarField> components(pTraits<Type>::nComponents);
    forAll(components, cmpt)
    {
        components[cmpt] = density.component(cmpt);
    }
    diffuse(components, b);
    forAll(components, cmpt)
    {
        density.replace(cmpt, components[cmpt]);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class Type>
void Foam::particleKernel::spreadDensity
(
    DimensionedField<Type, volMesh>& density,
    const scalar dMax
) const
{
    if (spreads(dMax))
    {
        spreadField(density.field(), bandwidth(dMax));
    }
}


template<class Type>
void Foam::particleKernel::spreadAmount
(
    DimensionedField<Type, volMesh>& amount,
    const scalar dMax
) const
{
    if (spreads(dMax))
    {
        Field<Type>& f = amount.field();
        f /= mesh_.V().field();
        spreadField(f, bandwidth(dMax));
        f *= mesh_.V().field();
    }
}


template<class CloudType>
Foam::scalar Foam::particleKernel::largestDiameter(const CloudType& cloud)
{
    scalar d = 0;
    for (const auto& p : cloud)
    {
        d = max(d, p.d());
    }
    largestDiameter_ = max(largestDiameter_, returnReduce(d, maxOp<scalar>()));
    return largestDiameter_;
}


template<class CloudType>
Foam::tmp<Foam::volScalarField> Foam::particleKernel::alphac
(
    const CloudType& cloud,
    const scalar alphaMin
)
{
    const scalar dMax = largestDiameter(cloud);
    tmp<volScalarField> talphac(workField(cloud.name() + ":alphac"));
    volScalarField& alpha = talphac.ref();
    alpha.primitiveFieldRef() = cloud.theta()().primitiveField();
    spreadDensity(alpha.ref(), dMax);
    alpha.primitiveFieldRef() = max(1 - alpha.primitiveField(), alphaMin);
    alpha.correctBoundaryConditions();
    return talphac;
}


template<class CloudType>
Foam::tmp<Foam::fvVectorMatrix> Foam::particleKernel::SU
(
    const CloudType& cloud,
    volVectorField& U
)
{
    const scalar dMax = largestDiameter(cloud);
    tmp<fvVectorMatrix> tsource(new fvVectorMatrix(U, dimForce));
    if (!cloud.solution().coupled())
    {
        return tsource;
    }
    volVectorField::Internal uTrans("particleKernel:UTrans", cloud.UTrans());
    volScalarField::Internal uCoeff("particleKernel:UCoeff", cloud.UCoeff());
    if (spreads(dMax))
    {
        // the four fields in one pass of the kernel's solves, as densities
        const scalarField& V = mesh_.V().field();
        List<scalarField> densities(vector::nComponents + 1);
        for (direction cmpt = 0; cmpt < vector::nComponents; ++cmpt)
        {
            densities[cmpt] = uTrans.field().component(cmpt)/V;
        }
        densities[vector::nComponents] = uCoeff.field()/V;
        diffuse(densities, bandwidth(dMax));
        for (direction cmpt = 0; cmpt < vector::nComponents; ++cmpt)
        {
            uTrans.field().replace(cmpt, densities[cmpt]*V);
        }
        uCoeff.field() = densities[vector::nComponents]*V;
    }

    // per unit volume and time; the implicit part on the new U, its
    // explicit counterpart on the current U: at convergence the source is
    // the spread UTrans/(V dt) alone
    const volScalarField::Internal Vdt(mesh_.V()*mesh_.time().deltaT());
    fvVectorMatrix& source = tsource.ref();
    source += uTrans/Vdt;
    if (cloud.solution().semiImplicit("U"))
    {
        source += uCoeff/Vdt*U();
        source -= fvm::Sp(uCoeff/Vdt, U);
    }
    return tsource;
}


// ************************************************************************* //
