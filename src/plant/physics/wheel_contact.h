// Contact of a cylinder lying on a plane (a wheel on the ground) as ONE point in the middle of the
// tread. Bullet's general convex-plane test returns one edge of the tread or the other from step to
// step, and the manifold keeps both: twice the contact rows, with the force jumping between the
// edges. A cylinder that is not lying on the plane (standing on a cap, tilted) keeps Bullet's
// general test with several points.
#pragma once

#include <BulletCollision/CollisionDispatch/btCollisionDispatcher.h>

namespace bullet_plant
{
// Registers the wheel contact for cylinder/plane and cylinder/mesh pairs (a static mesh, a moving
// one's GImpact) with a dispatcher, both orders; after GImpact's own registration.
void registerWheelContact(btCollisionDispatcher& dispatcher);

}  // namespace bullet_plant
