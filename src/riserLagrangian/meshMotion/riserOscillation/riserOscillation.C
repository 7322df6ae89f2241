/*---------------------------------------------------------------------------*\
  riserFoam: particle transport in vibrating risers, on OpenFOAM
  License: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "riserOscillation.H"
#include "riserModel.H"
#include "IOdictionary.H"
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
    const scalar t = time_.value();
    const vector displacement
    (
        motion_->axisPosition(t) - motion_->axisPosition(0), 0, 0
    );
    return septernion(-displacement)*quaternion(1);
}


bool Foam::solidBodyMotionFunctions::riserOscillation::read
(
    const dictionary& SBMFCoeffs
)
{
    solidBodyMotionFunction::read(SBMFCoeffs);
    const IOdictionary riserDict
    (
        IOobject
        (
            "riserProperties",
            time_.constant(),
            time_,
            IOobject::MUST_READ,
            IOobject::NO_WRITE,
            false
        )
    );
    motion_.reset(new riser::RiserMotion(riserModel::read(riserDict).motion()));
    return true;
}


// ************************************************************************* //
