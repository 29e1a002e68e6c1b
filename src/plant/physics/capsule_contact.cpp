#include "physics/capsule_contact.h"

#include <BulletCollision/CollisionDispatch/btManifoldResult.h>
#include <BulletCollision/CollisionShapes/btCapsuleShape.h>

#include "physics/plane_pair.h"

namespace bullet_plant
{
namespace
{
class CapsulePlaneAlgorithm : public OwnManifoldPlaneAlgorithm
{
public:
  using OwnManifoldPlaneAlgorithm::OwnManifoldPlaneAlgorithm;

  void processCollision(const btCollisionObjectWrapper* body0, const btCollisionObjectWrapper* body1,
                        const btDispatcherInfo&, btManifoldResult* result) override
  {
    const btCollisionObjectWrapper* capsule_wrap = shapeOfPair(body0, body1, swapped_);
    const auto* capsule = static_cast<const btCapsuleShape*>(capsule_wrap->getCollisionShape());
    const btTransform& capsule_pose = capsule_wrap->getWorldTransform();
    const WorldPlane plane = WorldPlane::of(planeOfPair(body0, body1, swapped_));
    const btVector3& normal = plane.normal;
    const btVector3 axis = capsule_pose.getBasis().getColumn(capsule->getUpAxis());
    const btScalar radius = capsule->getRadius(), half = capsule->getHalfHeight();

    // Fresh points each step, each carrying the impulses of the last step's point at the same end,
    // so the solver starts warm.
    btScalar impulses[2][3] = {{0, 0, 0}, {0, 0, 0}};
    for (int k = 0; k < manifold_->getNumContacts() && k < 2; ++k)
    {
      const btManifoldPoint& old = manifold_->getContactPoint(k);
      btScalar* kept = impulses[end_of_point_[k]];
      kept[0] = old.m_appliedImpulse;
      kept[1] = old.m_appliedImpulseLateral1;
      kept[2] = old.m_appliedImpulseLateral2;
    }
    manifold_->clearManifold();
    result->setPersistentManifold(manifold_);
    for (int end = 0; end < 2; ++end)
    {
      const btVector3 lowest = capsule_pose.getOrigin() + axis * (end == 0 ? half : -half) - normal * radius;
      const btScalar distance = plane.height(lowest);
      if (distance > manifold_->getContactBreakingThreshold())
        continue;
      const int before = manifold_->getNumContacts();
      result->addContactPoint(normal, lowest - normal * distance, distance);
      if (manifold_->getNumContacts() == before + 1)
      {
        btManifoldPoint& point = manifold_->getContactPoint(before);
        point.m_appliedImpulse = impulses[end][0];
        point.m_appliedImpulseLateral1 = impulses[end][1];
        point.m_appliedImpulseLateral2 = impulses[end][2];
        end_of_point_[before] = end;
      }
    }
  }

private:
  int end_of_point_[2] = {0, 1};  // which end each of the manifold's points is at
};
}  // namespace

void registerCapsuleContact(btCollisionDispatcher& dispatcher)
{
  registerPlanePair<CapsulePlaneAlgorithm>(dispatcher, CAPSULE_SHAPE_PROXYTYPE);
}

}  // namespace bullet_plant
