// Contact of a capsule with a plane as ODE's capsule-plane test gives it (dCollideCapsulePlane): the
// lowest point of each end's sphere within reach of the plane, two points for a capsule lying down,
// one for one standing or tilted. Bullet's general convex-plane test returns one end of a lying
// capsule or the other, and its perturbed queries add points off the contact line, which made a
// rolling capsule gain speed (0.07 m/s a second at 0.67 m/s for a 0.4 m capsule).
#pragma once

#include <BulletCollision/CollisionDispatch/btCollisionDispatcher.h>

namespace bullet_plant
{
// Registers the capsule contact for capsule/plane pairs with a dispatcher (both orders).
void registerCapsuleContact(btCollisionDispatcher& dispatcher);

}  // namespace bullet_plant
