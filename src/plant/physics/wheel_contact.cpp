#include "physics/wheel_contact.h"

#include <memory>

#include <BulletCollision/CollisionDispatch/btCollisionObjectWrapper.h>
#include <BulletCollision/CollisionDispatch/btConvexPlaneCollisionAlgorithm.h>
#include <BulletCollision/CollisionDispatch/btManifoldResult.h>
#include <BulletCollision/CollisionShapes/btCylinderShape.h>
#include <BulletCollision/CollisionShapes/btStaticPlaneShape.h>

namespace bullet_plant
{
namespace
{
// Above this |cos| between the cylinder's axis and the plane normal the cylinder is not lying down.
constexpr btScalar kLyingCosine = btScalar(0.2);

class WheelPlaneAlgorithm : public btCollisionAlgorithm
{
public:
  WheelPlaneAlgorithm(const btCollisionAlgorithmConstructionInfo& ci, const btCollisionObjectWrapper* body0,
                      const btCollisionObjectWrapper* body1, bool swapped)
    : btCollisionAlgorithm(ci), swapped_(swapped)
  {
    const btCollisionObjectWrapper* cylinder = swapped ? body1 : body0;
    const btCollisionObjectWrapper* plane = swapped ? body0 : body1;
    manifold_ = m_dispatcher->getNewManifold(cylinder->getCollisionObject(), plane->getCollisionObject());
    general_.reset(new btConvexPlaneCollisionAlgorithm(manifold_, ci, body0, body1, swapped, 3, 3));
  }

  ~WheelPlaneAlgorithm() override
  {
    general_.reset();
    m_dispatcher->releaseManifold(manifold_);
  }

  void processCollision(const btCollisionObjectWrapper* body0, const btCollisionObjectWrapper* body1,
                        const btDispatcherInfo& info, btManifoldResult* result) override
  {
    const btCollisionObjectWrapper* cylinder_wrap = swapped_ ? body1 : body0;
    const btCollisionObjectWrapper* plane_wrap = swapped_ ? body0 : body1;
    const auto* cylinder = static_cast<const btCylinderShape*>(cylinder_wrap->getCollisionShape());
    const auto* plane = static_cast<const btStaticPlaneShape*>(plane_wrap->getCollisionShape());
    const btTransform& cylinder_pose = cylinder_wrap->getWorldTransform();
    const btTransform& plane_pose = plane_wrap->getWorldTransform();

    const btVector3 normal = plane_pose.getBasis() * plane->getPlaneNormal();
    const btVector3 on_plane = plane_pose * (plane->getPlaneNormal() * plane->getPlaneConstant());
    const int up = cylinder->getUpAxis();
    const btVector3 axis = cylinder_pose.getBasis().getColumn(up);
    if (btFabs(axis.dot(normal)) > kLyingCosine)
    {
      general_->processCollision(body0, body1, info, result);
      return;
    }
    // The lowest line of the tread is the radius away from the axis, straight down in the wheel's
    // plane; its middle is the contact point.
    btVector3 down = -(normal - axis * axis.dot(normal));
    down.normalize();
    const btScalar radius = cylinder->getHalfExtentsWithMargin()[(up + 1) % 3];
    const btVector3 lowest = cylinder_pose.getOrigin() + down * radius;
    const btScalar distance = normal.dot(lowest - on_plane);

    // One fresh point per step, carrying the previous point's impulses so the solver starts warm.
    btScalar impulse = 0, lateral1 = 0, lateral2 = 0;
    if (manifold_->getNumContacts() > 0)
    {
      const btManifoldPoint& old = manifold_->getContactPoint(0);
      impulse = old.m_appliedImpulse;
      lateral1 = old.m_appliedImpulseLateral1;
      lateral2 = old.m_appliedImpulseLateral2;
    }
    manifold_->clearManifold();
    result->setPersistentManifold(manifold_);
    if (distance > manifold_->getContactBreakingThreshold())
      return;
    result->addContactPoint(normal, lowest - normal * distance, distance);
    if (manifold_->getNumContacts() > 0)
    {
      btManifoldPoint& point = manifold_->getContactPoint(0);
      point.m_appliedImpulse = impulse;
      point.m_appliedImpulseLateral1 = lateral1;
      point.m_appliedImpulseLateral2 = lateral2;
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
      void* memory = ci.m_dispatcher1->allocateCollisionAlgorithm(sizeof(WheelPlaneAlgorithm));
      return new (memory) WheelPlaneAlgorithm(ci, body0, body1, m_swapped);
    }
  };

private:
  bool swapped_;
  btPersistentManifold* manifold_ = nullptr;
  std::unique_ptr<btConvexPlaneCollisionAlgorithm> general_;
};
}  // namespace

void registerWheelContact(btCollisionDispatcher& dispatcher)
{
  static WheelPlaneAlgorithm::CreateFunc cylinder_plane, plane_cylinder;
  plane_cylinder.m_swapped = true;
  dispatcher.registerCollisionCreateFunc(CYLINDER_SHAPE_PROXYTYPE, STATIC_PLANE_PROXYTYPE, &cylinder_plane);
  dispatcher.registerCollisionCreateFunc(STATIC_PLANE_PROXYTYPE, CYLINDER_SHAPE_PROXYTYPE, &plane_cylinder);
}

}  // namespace bullet_plant
