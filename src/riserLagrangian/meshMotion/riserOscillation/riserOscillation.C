/*---------------------------------------------------------------------------*\
  riserFoam: particle transport in vibrating risers, on OpenFOAM
  License: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "riserOscillation.H"
#include "riserModel.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace solidBodyMotionFunctions
{
    defineTypeNameAndDebug(riserOscillation, 0);
    addToRunTimeSelectionTable
    (
        solidBodyMotionFunction,
        riserOscillation,
        dictionary
    );
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::solidBodyMotionFunctions::riserOscillation::riserOscillation
(
    const dictionary& SBMFCoeffs,
    const Time& runTime
)
:
    solidBodyMotionFunction(SBMFCoeffs, runTime)
{
    read(SBMFCoeffs);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::septernion
Foam::solidBodyMotionFunctions::riserOscillation::transformation() const
{
    // the riser's motion is the same at every height (read): asked at z = 0
    const scalar t = time_.value();
    const vector displacement =
        fromCore(motion_->axis(0, t) - motion_->axis(0, 0));
    return septernion(-displacement)*quaternion(1);
}


bool Foam::solidBodyMotionFunctions::riserOscillation::read
(
    const dictionary& SBMFCoeffs
)
{
    solidBodyMotionFunction::read(SBMFCoeffs);
    const autoPtr<IOdictionary> riserProperties(riserModel::readProperties(time_));
    const dictionary& riserDict = riserProperties();
    motion_ = riserModel::read(riserDict).motionPtr();
    if (!motion_->uniformAlongAxis())
    {
        FatalIOErrorInFunction(riserDict)
            << "riserOscillation moves the mesh rigidly: it needs a riser"
            << " whose motion is the same at every height, not of type "
            << motion_->type() << ": deform the mesh with the riser instead"
            << " (motionSolver riserDeformation;)" << exit(FatalIOError);
    }
    return true;
}


// ************************************************************************* //
