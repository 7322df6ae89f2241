/*---------------------------------------------------------------------------*\
  riserFoam: particle transport in vibrating risers, on OpenFOAM
  License: GPL-3.0-or-later

Description
    Registers the riser wall contact for the stock colliding cloud
    basicKinematicCollidingCloud (collisionModel riserWallContact;).

\*---------------------------------------------------------------------------*/

#include "basicKinematicCollidingCloud.H"
#include "RiserWallContact.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

makeCollisionModelType(RiserWallContact, basicKinematicCollidingCloud);

// ************************************************************************* //
