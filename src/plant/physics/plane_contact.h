// A convex shape against a plane: Bullet's multipoint algorithm (a box landing flat meets the ground
// in its four corners at once, not the deepest one alone), asked nothing while the shape's box is
// clear of the plane. Bullet runs its perturbed queries whenever the manifold holds fewer than three
// points, touching or not: for a convex hull (a car body's mesh) each is a support-vertex search over
// the hull, and a car whose body never touches the ground paid 8.7 % of its step for them.
#pragma once

#include <BulletCollision/CollisionDispatch/btCollisionDispatcher.h>

namespace bullet_plant
{
// Registers the plane contact for every convex shape type but the cylinder (the wheel contact's,
// which registerWheelContact puts after it), both orders.
void registerPlaneContact(btCollisionDispatcher& dispatcher);

}  // namespace bullet_plant
