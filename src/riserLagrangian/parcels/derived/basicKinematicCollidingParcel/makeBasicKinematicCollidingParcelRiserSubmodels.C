/*---------------------------------------------------------------------------*\
  riserFoam: particle transport in vibrating risers, on OpenFOAM
  License: GPL-3.0-or-later

Description
    Registers the riser submodels for the stock colliding cloud
    basicKinematicCollidingCloud, so that icoUncoupledKinematicParcelFoam,
    icoUncoupledKinematicParcelDyMFoam and DPMFoam find them after
    libs ("libriserLagrangian.so"); in system/controlDict.

\*---------------------------------------------------------------------------*/

#include "basicKinematicCollidingCloud.H"
#include "makeRiserSubmodels.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

makeRiserSubmodels(basicKinematicCollidingCloud);

// ************************************************************************* //
