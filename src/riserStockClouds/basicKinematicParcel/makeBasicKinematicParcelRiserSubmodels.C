/*---------------------------------------------------------------------------*\
  riserFoam: particle transport in vibrating risers, on OpenFOAM
  License: GPL-3.0-or-later

Description
    Registers the riser forces and the riser injection models for the stock kinematic cloud
    basicKinematicCloud, so that uncoupledKinematicParcelFoam and
    uncoupledKinematicParcelDyMFoam find them after
    libs ("libriserStockClouds.so"); in system/controlDict. The cloud does
    not collide: riserContact and riserParticleTable are not available
    for it (makeRiserSubmodels.H).

\*---------------------------------------------------------------------------*/

#include "basicKinematicCloud.H"
#include "makeRiserSubmodels.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

makeRiserForces(basicKinematicCloud);
makeRiserInjectionModels(basicKinematicCloud);
makeRiserDispersionModels(basicKinematicCloud);
makeRiserCloudOnlyRefusals(basicKinematicCloud);

// ************************************************************************* //
