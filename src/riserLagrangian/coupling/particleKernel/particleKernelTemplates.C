/*---------------------------------------------------------------------------*\
  riserFoam: particle transport in vibrating risers, on OpenFOAM
  License: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "particleKernel.H"
#include "fvMatrices.H"
#include "fvmSup.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class... Types>
void Foam::particleKernel::spreadFields
(
    const scalar b,
    Field<Types>&... densities
) const
{
    List<scalarField> components;
    const auto append = [&components](const auto& density)
    {
        using Type = typename std::decay_t<decltype(density)>::value_type;
        for (direction cmpt = 0; cmpt < pTraits<Type>::nComponents; ++cmpt)
        {
            components.append(scalarField(density.component(cmpt)));
        }
    };
    (append(densities), ...);
    diffuse(components, b);
    label next = 0;
    const auto take = [&components, &next](auto& density)
    {
        using Type = typename std::decay_t<decltype(density)>::value_type;
        for (direction cmpt = 0; cmpt < pTraits<Type>::nComponents; ++cmpt)
        {
            density.replace(cmpt, components[next++]);
        }
    };
    (take(densities), ...);
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
        spreadFields(bandwidth(dMax), density.field());
    }
}


template<class... Types>
void Foam::particleKernel::spreadAmount
(
    const scalar dMax,
    DimensionedField<Types, volMesh>&... amounts
) const
{
    if (spreads(dMax))
    {
        const scalarField& V = mesh_.V().field();
        ((amounts.field() /= V), ...);
        spreadFields(bandwidth(dMax), amounts.field()...);
        ((amounts.field() *= V), ...);
    }
}


template<class CloudType>
Foam::tmp<Foam::scalarField>
Foam::particleKernel::theta(const CloudType& cloud) const
{
    tmp<scalarField> ttheta(new scalarField(mesh_.nCells(), Zero));
    scalarField& theta = ttheta.ref();
    scalarField pointVolumes(mesh_.nPoints(), Zero);
    for (const auto& p : cloud)
    {
        shares_.deposit(p, p.nParticle()*p.volume(), theta, pointVolumes);
    }
    shares_.toCells(pointVolumes, theta);
    theta /= mesh_.V().field();
    return ttheta;
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
void Foam::particleKernel::checkOneCellDeposits(const CloudType& cloud) const
{
    if (type_ != kernelType::none)
    {
        return;
    }
    const scalarField& V = mesh_.V().field();
    for (const auto& p : cloud)
    {
        const scalar volume = p.nParticle()*p.volume();
        if (volume > V[p.cell()])
        {
            FatalIOErrorInFunction(dict_)
                << "entry 'type' = none: the particle " << p.origId()
                << " of processor " << p.origProc() << " (d = " << p.d()
                << " m, " << p.nParticle() << " in its parcel) at "
                << p.position() << " is " << volume << " m^3, more than its"
                << " cell " << p.cell() << " (" << V[p.cell()] << " m^3):"
                << " the one-cell deposit would put its whole volume and"
                << " reaction in that cell and drag the cell's carrier"
                << " alone (the forces then grow and change sign from step"
                << " to step). Spread them over a few diameters with" << nl
                << "    kernel { type diffusion; width 3; widthUnit diameters; }"
                << nl << exit(FatalIOError);
        }
    }
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
    // the deposit continuous in the particles' positions where the kernel
    // spreads it, the stock one (whole in the cell of the centre) otherwise
    if (spreads(dMax))
    {
        alpha.primitiveFieldRef() = theta(cloud);
    }
    else
    {
        alpha.primitiveFieldRef() = cloud.theta()().primitiveField();
    }
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
    // spread together: one pass of the kernel's solves for the four fields
    spreadAmount(dMax, uTrans, uCoeff);

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
