/*---------------------------------------------------------------------------*\
  riserFoam: particle transport in vibrating risers, on OpenFOAM
  License: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "pointShares.H"
#include "syncTools.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::pointShares::pointShares(const fvMesh& mesh)
:
    mesh_(mesh),
    pointCellsVolume_(),
    volumeTimeIndex_(-1)
{}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

const Foam::scalarField& Foam::pointShares::pointCellsVolume() const
{
    if (outdated(mesh_, volumeTimeIndex_))
    {
        const labelListList& pointCells = mesh_.pointCells();
        const scalarField& V = mesh_.V().field();
        pointCellsVolume_.setSize(mesh_.nPoints());
        forAll(pointCells, pointi)
        {
            scalar sum = 0;
            for (const label celli : pointCells[pointi])
            {
                sum += V[celli];
            }
            pointCellsVolume_[pointi] = sum;
        }
        syncTools::syncPointList
        (
            mesh_,
            pointCellsVolume_,
            plusEqOp<scalar>(),
            scalar(0)
        );
        volumeTimeIndex_ = mesh_.time().timeIndex();
    }
    return pointCellsVolume_;
}


// ************************************************************************* //
