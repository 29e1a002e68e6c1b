#include "physics/bullet_conversions.h"

namespace bullet_plant
{
btTransform toBullet(const urdf::Pose& p)
{
  btQuaternion q(btScalar(p.rotation.x), btScalar(p.rotation.y), btScalar(p.rotation.z), btScalar(p.rotation.w));
  if (q.length2() < btScalar(1e-12))
    q = btQuaternion::getIdentity();
  q.normalize();
  return btTransform(q, toBullet(p.position));
}

urdf::Pose fromBullet(const btTransform& t)
{
  urdf::Pose p;
  btQuaternion q = t.getRotation();
  p.rotation = urdf::Rotation(q.x(), q.y(), q.z(), q.w());
  p.position = fromBullet(t.getOrigin());
  return p;
}

}  // namespace bullet_plant
