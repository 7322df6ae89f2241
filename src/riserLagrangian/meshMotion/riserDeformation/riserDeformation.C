/*---------------------------------------------------------------------------*\
  riserFoam: particle transport in vibrating risers, on OpenFOAM
  License: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "riserDeformation.H"
#include "riserModel.H"
#include "coreVector.H"
#include "boundBox.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(riserDeformation, 0);
    addToRunTimeSelectionTable(motionSolver, riserDeformation, dictionary);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::riserDeformation::riserDeformation
(
    const polyMesh& mesh,
    const IOdictionary& dict
)
:
    points0MotionSolver(mesh, dict, typeName)
{
    const autoPtr<IOdictionary> riserProperties(riserModel::readProperties(mesh.time()));
    const dictionary& riserDict = riserProperties();
    motion_ = riserModel::read(riserDict).motionPtr();
    // curPoints asks for the axis at t = 0 and at the run's times
    const boundBox bb(points0_, true);
    riserModel::checkMotionDomain
    (
        riserDict, *motion_, bb.min().z(), bb.max().z(),
        min(scalar(0), mesh.time().startTime().value()),
        mesh.time().endTime().value(),
        "the deforming mesh (its heights, from t = 0 to endTime)"
    );
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::tmp<Foam::pointField> Foam::riserDeformation::curPoints() const
{
    const scalar t = mesh().time().value();
    tmp<pointField> tpoints(new pointField(points0_));
    pointField& points = tpoints.ref();
    forAll(points, i)
    {
        const scalar z = points0_[i].z();
        const vector d = fromCore(motion_->axis(z, t) - motion_->axis(z, 0));
        points[i].x() += d.x();
        points[i].y() += d.y();
    }
    return tpoints;
}


// ************************************************************************* //
