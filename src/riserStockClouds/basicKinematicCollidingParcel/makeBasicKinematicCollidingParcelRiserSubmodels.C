/*---------------------------------------------------------------------------*\
  riserFoam: particle transport in vibrating risers, on OpenFOAM
  License: GPL-3.0-or-later

Description
    Registers the riser forces, the riser injection models and the riser
    collision submodels for the
    stock colliding cloud basicKinematicCollidingCloud, so that
    icoUncoupledKinematicParcelFoam, icoUncoupledKinematicParcelDyMFoam,
    DPMFoam and DPMDyMFoam find them after
    libs ("libriserStockClouds.so"); in system/controlDict.

\*---------------------------------------------------------------------------*/

#include "basicKinematicCollidingCloud.H"
#include "makeRiserSubmodels.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

makeRiserForces(basicKinematicCollidingCloud);
makeRiserInjectionModels(basicKinematicCollidingCloud);
makeRiserDispersionModels(basicKinematicCollidingCloud);
makeRiserCloudOnlyRefusals(basicKinematicCollidingCloud);
makeRiserCollisionSubmodels(basicKinematicCollidingCloud);

// ************************************************************************* //
