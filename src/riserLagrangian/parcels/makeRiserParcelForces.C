/*---------------------------------------------------------------------------*\
  riserFoam: particle transport in vibrating risers, on OpenFOAM
  License: GPL-3.0-or-later

Description
    Registers the riser particle forces for the stock colliding cloud
    basicKinematicCollidingCloud, so that icoUncoupledKinematicParcelFoam,
    icoUncoupledKinematicParcelDyMFoam and DPMFoam find them after
    libs ("libriserLagrangian.so"); in system/controlDict.

\*---------------------------------------------------------------------------*/

#include "basicKinematicCollidingCloud.H"
#include "WallCorrectedDragForce.H"
#include "RiserSaffmanMeiLiftForce.H"
#include "RiserAddedMassForce.H"
#include "RiserFluidStressForce.H"
#include "RiserFrameForce.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

makeParticleForceModelType(WallCorrectedDragForce, basicKinematicCollidingCloud);
makeParticleForceModelType(RiserSaffmanMeiLiftForce, basicKinematicCollidingCloud);
makeParticleForceModelType(RiserAddedMassForce, basicKinematicCollidingCloud);
makeParticleForceModelType(RiserFluidStressForce, basicKinematicCollidingCloud);
makeParticleForceModelType(RiserFrameForce, basicKinematicCollidingCloud);

// ************************************************************************* //
