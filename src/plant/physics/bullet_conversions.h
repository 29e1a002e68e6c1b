// The one place urdfdom's types (what the descriptions give: urdf::Vector3, urdf::Pose) and Bullet's
// (what the physics steps: btVector3, btTransform) meet. The plant's own spatial vocabulary and its
// conversions from urdf are physics/spatial.h.
#pragma once

#include <LinearMath/btTransform.h>
#include <urdf_model/pose.h>

namespace bullet_plant
{
inline btVector3 toBullet(const urdf::Vector3& v) { return btVector3(btScalar(v.x), btScalar(v.y), btScalar(v.z)); }
inline urdf::Vector3 fromBullet(const btVector3& v) { return urdf::Vector3(v.x(), v.y(), v.z()); }
// A rotation of (near) zero length becomes the identity; any other is normalised.
btTransform toBullet(const urdf::Pose& p);
urdf::Pose fromBullet(const btTransform& t);

}  // namespace bullet_plant
