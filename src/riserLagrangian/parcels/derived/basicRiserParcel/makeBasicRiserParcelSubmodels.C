/*---------------------------------------------------------------------------*\
  riserFoam: particle transport in vibrating risers, on OpenFOAM
  License: GPL-3.0-or-later

Description
    Registers, for the riser cloud basicRiserCloud, the stock kinematic
    submodels (so that a riser case can use any of them), the riser
    submodels, and the Basset force and the cloud function
    riserTransportStatistics, which need the history parcels.

\*---------------------------------------------------------------------------*/

#include "basicRiserCloud.H"

#include "makeParcelCloudFunctionObjects.H"
#include "makeParcelForces.H"
#include "makeParcelDispersionModels.H"
#include "makeParcelInjectionModels.H"
#include "makeParcelCollisionModels.H"
#include "makeParcelPatchInteractionModels.H"
#include "makeParcelStochasticCollisionModels.H"
#include "makeParcelSurfaceFilmModels.H"

#include "makeRiserSubmodels.H"
#include "RiserBassetForce.H"
#include "RiserTransportStatistics.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

makeParcelCloudFunctionObjects(basicRiserCloud);

makeParcelForces(basicRiserCloud);
makeParcelDispersionModels(basicRiserCloud);
makeParcelInjectionModels(basicRiserCloud);
// the collision models live on the colliding cloud below the riser layer
namespace Foam
{
    typedef basicRiserCloud::collidingCloudType basicRiserCollidingCloud;
}
makeParcelCollisionModels(basicRiserCollidingCloud);
makeParcelPatchInteractionModels(basicRiserCloud);
makeParcelStochasticCollisionModels(basicRiserCloud);
makeParcelSurfaceFilmModels(basicRiserCloud);

makeRiserForces(basicRiserCloud);
makeRiserInjectionModels(basicRiserCloud);
makeRiserDispersionModels(basicRiserCloud);
makeRiserCollisionSubmodels(basicRiserCloud);
makeParticleForceModelType(RiserBassetForce, basicRiserCloud);
makeCloudFunctionObjectType(RiserTransportStatistics, basicRiserCloud);

// ************************************************************************* //
