/*---------------------------------------------------------------------------*\
  riserFoam: particle transport in vibrating risers, on OpenFOAM
  License: GPL-3.0-or-later

Description
    Registers the riser cloud function objects for the stock colliding cloud
    basicKinematicCollidingCloud.

\*---------------------------------------------------------------------------*/

#include "basicKinematicCollidingCloud.H"
#include "ParticleForceFields.H"
#include "RiserParticleTable.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

makeCloudFunctionObjectType(ParticleForceFields, basicKinematicCollidingCloud);
makeCloudFunctionObjectType(RiserParticleTable, basicKinematicCollidingCloud);

// ************************************************************************* //
