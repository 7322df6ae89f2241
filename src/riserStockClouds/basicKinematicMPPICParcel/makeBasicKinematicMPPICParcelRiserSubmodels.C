/*---------------------------------------------------------------------------*\
  riserFoam: particle transport in vibrating risers, on OpenFOAM
  License: GPL-3.0-or-later

Description
    Registers the riser forces and the riser injection models for the stock MPPIC cloud
    basicKinematicMPPICCloud, so that MPPICFoam and MPPICDyMFoam find them
    after libs ("libriserStockClouds.so"); in system/controlDict. The cloud
    does not collide: riserContact and riserParticleTable are not
    available for it (makeRiserSubmodels.H).

\*---------------------------------------------------------------------------*/

#include "basicKinematicMPPICCloud.H"
#include "makeRiserSubmodels.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

makeRiserForces(basicKinematicMPPICCloud);
makeRiserInjectionModels(basicKinematicMPPICCloud);
makeRiserDispersionModels(basicKinematicMPPICCloud);
makeRiserCloudOnlyRefusals(basicKinematicMPPICCloud);

// ************************************************************************* //
