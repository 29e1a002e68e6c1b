// What the plant's own collision algorithms for a convex shape against a static plane share
// (wheel_contact, capsule_contact, plane_contact): the plane in world coordinates, the shape and the
// plane told apart in whichever order Bullet's dispatcher hands them, an algorithm that owns its
// pair's manifold, and the registration for both orders.
#pragma once

#include <BulletCollision/BroadphaseCollision/btCollisionAlgorithm.h>
#include <BulletCollision/CollisionDispatch/btCollisionCreateFunc.h>
#include <BulletCollision/CollisionDispatch/btCollisionDispatcher.h>
#include <BulletCollision/CollisionDispatch/btCollisionObjectWrapper.h>
#include <BulletCollision/CollisionShapes/btStaticPlaneShape.h>
#include <BulletCollision/NarrowPhaseCollision/btPersistentManifold.h>

namespace bullet_plant
{
// A static plane's normal and one of its points, in the world.
struct WorldPlane
{
  btVector3 normal, point;

  static WorldPlane of(const btCollisionObjectWrapper* plane_wrap)
  {
    const auto* plane = static_cast<const btStaticPlaneShape*>(plane_wrap->getCollisionShape());
    const btTransform& pose = plane_wrap->getWorldTransform();
    return {pose.getBasis() * plane->getPlaneNormal(), pose * (plane->getPlaneNormal() * plane->getPlaneConstant())};
  }
  // Signed height of `p` above the plane.
  btScalar height(const btVector3& p) const { return normal.dot(p - point); }
};

// The convex shape of a pair and its plane: body0 is the shape unless the pair came swapped.
inline const btCollisionObjectWrapper* shapeOfPair(const btCollisionObjectWrapper* body0,
                                                   const btCollisionObjectWrapper* body1, bool swapped)
{
  return swapped ? body1 : body0;
}
inline const btCollisionObjectWrapper* planeOfPair(const btCollisionObjectWrapper* body0,
                                                   const btCollisionObjectWrapper* body1, bool swapped)
{
  return swapped ? body0 : body1;
}

// An algorithm that writes its own points into a manifold of its own, as Bullet's do.
class OwnManifoldPlaneAlgorithm : public btCollisionAlgorithm
{
public:
  OwnManifoldPlaneAlgorithm(const btCollisionAlgorithmConstructionInfo& ci, const btCollisionObjectWrapper* body0,
                            const btCollisionObjectWrapper* body1, bool swapped)
    : btCollisionAlgorithm(ci), swapped_(swapped)
  {
    manifold_ = m_dispatcher->getNewManifold(shapeOfPair(body0, body1, swapped)->getCollisionObject(),
                                             planeOfPair(body0, body1, swapped)->getCollisionObject());
  }
  ~OwnManifoldPlaneAlgorithm() override { m_dispatcher->releaseManifold(manifold_); }

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

protected:
  bool swapped_;
  btPersistentManifold* manifold_ = nullptr;
};

// Bullet's factory for an Algorithm(ci, body0, body1, swapped).
template <class Algorithm>
struct PlanePairCreateFunc : public btCollisionAlgorithmCreateFunc
{
  btCollisionAlgorithm* CreateCollisionAlgorithm(btCollisionAlgorithmConstructionInfo& ci,
                                                 const btCollisionObjectWrapper* body0,
                                                 const btCollisionObjectWrapper* body1) override
  {
    void* memory = ci.m_dispatcher1->allocateCollisionAlgorithm(sizeof(Algorithm));
    return new (memory) Algorithm(ci, body0, body1, m_swapped);
  }
};

// Algorithm for the pairs of `shape_type` and a static plane, in both orders.
template <class Algorithm>
void registerPlanePair(btCollisionDispatcher& dispatcher, int shape_type)
{
  static PlanePairCreateFunc<Algorithm> shape_plane, plane_shape;
  plane_shape.m_swapped = true;
  dispatcher.registerCollisionCreateFunc(shape_type, STATIC_PLANE_PROXYTYPE, &shape_plane);
  dispatcher.registerCollisionCreateFunc(STATIC_PLANE_PROXYTYPE, shape_type, &plane_shape);
}

}  // namespace bullet_plant
