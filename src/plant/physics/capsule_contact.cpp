#include "physics/capsule_contact.h"

#include <BulletCollision/BroadphaseCollision/btCollisionAlgorithm.h>
#include <BulletCollision/CollisionDispatch/btCollisionObjectWrapper.h>
#include <BulletCollision/CollisionDispatch/btCollisionCreateFunc.h>
#include <BulletCollision/CollisionDispatch/btManifoldResult.h>
#include <BulletCollision/CollisionShapes/btCapsuleShape.h>
#include <BulletCollision/CollisionShapes/btStaticPlaneShape.h>
#include <BulletCollision/NarrowPhaseCollision/btPersistentManifold.h>

namespace bullet_plant
{
namespace
{
class CapsulePlaneAlgorithm : public btCollisionAlgorithm
{
public:
  CapsulePlaneAlgorithm(const btCollisionAlgorithmConstructionInfo& ci, const btCollisionObjectWrapper* body0,
                        const btCollisionObjectWrapper* body1, bool swapped)
    : btCollisionAlgorithm(ci), swapped_(swapped)
  {
    const btCollisionObjectWrapper* capsule = swapped ? body1 : body0;
    const btCollisionObjectWrapper* plane = swapped ? body0 : body1;
    manifold_ = m_dispatcher->getNewManifold(capsule->getCollisionObject(), plane->getCollisionObject());
  }

  ~CapsulePlaneAlgorithm() override { m_dispatcher->releaseManifold(manifold_); }

  void processCollision(const btCollisionObjectWrapper* body0, const btCollisionObjectWrapper* body1,
                        const btDispatcherInfo&, btManifoldResult* result) override
  {
    const btCollisionObjectWrapper* capsule_wrap = swapped_ ? body1 : body0;
    const btCollisionObjectWrapper* plane_wrap = swapped_ ? body0 : body1;
    const auto* capsule = static_cast<const btCapsuleShape*>(capsule_wrap->getCollisionShape());
    const auto* plane = static_cast<const btStaticPlaneShape*>(plane_wrap->getCollisionShape());
    const btTransform& capsule_pose = capsule_wrap->getWorldTransform();
    const btTransform& plane_pose = plane_wrap->getWorldTransform();
    const btVector3 normal = plane_pose.getBasis() * plane->getPlaneNormal();
    const btVector3 on_plane = plane_pose * (plane->getPlaneNormal() * plane->getPlaneConstant());
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
      const btScalar distance = normal.dot(lowest - on_plane);
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

  btScalar calculateTimeOfImpact(btCollisionObject*, btCollisionObject*, const btDispatcherInfo&,
                                 btManifoldResult*) override
  {
    return btScalar(1);
  }

  void getAllContactManifolds(btManifoldArray& manifolds) override
  {
    if (manifold_)
      manifolds.push_back(manifold_);
  }

  struct CreateFunc : public btCollisionAlgorithmCreateFunc
  {
    btCollisionAlgorithm* CreateCollisionAlgorithm(btCollisionAlgorithmConstructionInfo& ci,
                                                   const btCollisionObjectWrapper* body0,
                                                   const btCollisionObjectWrapper* body1) override
    {
      void* memory = ci.m_dispatcher1->allocateCollisionAlgorithm(sizeof(CapsulePlaneAlgorithm));
      return new (memory) CapsulePlaneAlgorithm(ci, body0, body1, m_swapped);
    }
  };

private:
  bool swapped_;
  btPersistentManifold* manifold_ = nullptr;
  int end_of_point_[2] = {0, 1};  // which end each of the manifold's points is at
};
}  // namespace

void registerCapsuleContact(btCollisionDispatcher& dispatcher)
{
  static CapsulePlaneAlgorithm::CreateFunc capsule_plane, plane_capsule;
  plane_capsule.m_swapped = true;
  dispatcher.registerCollisionCreateFunc(CAPSULE_SHAPE_PROXYTYPE, STATIC_PLANE_PROXYTYPE, &capsule_plane);
  dispatcher.registerCollisionCreateFunc(STATIC_PLANE_PROXYTYPE, CAPSULE_SHAPE_PROXYTYPE, &plane_capsule);
}

}  // namespace bullet_plant
