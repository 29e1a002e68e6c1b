#include "physics/wheel_contact.h"

#include <memory>

#include <BulletCollision/CollisionDispatch/btConvexPlaneCollisionAlgorithm.h>
#include <BulletCollision/CollisionDispatch/btManifoldResult.h>
#include <BulletCollision/CollisionShapes/btCylinderShape.h>

#include "physics/plane_pair.h"

namespace bullet_plant
{
namespace
{
// Above this |cos| between the cylinder's axis and the plane normal the cylinder is not lying down.
constexpr btScalar kLyingCosine = btScalar(0.2);

class WheelPlaneAlgorithm : public OwnManifoldPlaneAlgorithm
{
public:
  WheelPlaneAlgorithm(const btCollisionAlgorithmConstructionInfo& ci, const btCollisionObjectWrapper* body0,
                      const btCollisionObjectWrapper* body1, bool swapped)
    : OwnManifoldPlaneAlgorithm(ci, body0, body1, swapped),
      general_(new btConvexPlaneCollisionAlgorithm(manifold_, ci, body0, body1, swapped, 3, 3))
  {
  }

  void processCollision(const btCollisionObjectWrapper* body0, const btCollisionObjectWrapper* body1,
                        const btDispatcherInfo& info, btManifoldResult* result) override
  {
    const btCollisionObjectWrapper* cylinder_wrap = shapeOfPair(body0, body1, swapped_);
    const auto* cylinder = static_cast<const btCylinderShape*>(cylinder_wrap->getCollisionShape());
    const btTransform& cylinder_pose = cylinder_wrap->getWorldTransform();
    const WorldPlane plane = WorldPlane::of(planeOfPair(body0, body1, swapped_));
    const btVector3& normal = plane.normal;
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
    const btScalar distance = plane.height(lowest);

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

private:
  std::unique_ptr<btConvexPlaneCollisionAlgorithm> general_;
};
}  // namespace

void registerWheelContact(btCollisionDispatcher& dispatcher)
{
  registerPlanePair<WheelPlaneAlgorithm>(dispatcher, CYLINDER_SHAPE_PROXYTYPE);
}

}  // namespace bullet_plant
