/*---------------------------------------------------------------------------*\
  riserFoam: particle transport in vibrating risers, on OpenFOAM
  License: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "pointShares.H"
#include "syncTools.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class Type>
void Foam::pointShares::toCells
(
    Field<Type>& pointAmounts,
    Field<Type>& cellAmounts
) const
{
    const scalarField& pointVolume = pointCellsVolume();
    syncTools::syncPointList
    (
        mesh_,
        pointAmounts,
        plusEqOp<Type>(),
        pTraits<Type>::zero
    );
    const labelListList& pointCells = mesh_.pointCells();
    const scalarField& V = mesh_.V().field();
    forAll(pointCells, pointi)
    {
        if (pointAmounts[pointi] != pTraits<Type>::zero)
        {
            const Type perVolume = pointAmounts[pointi]/pointVolume[pointi];
            for (const label celli : pointCells[pointi])
            {
                cellAmounts[celli] += perVolume*V[celli];
            }
        }
    }
}


// ************************************************************************* //
