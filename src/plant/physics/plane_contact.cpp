#include "physics/plane_contact.h"

#include <BulletCollision/BroadphaseCollision/btBroadphaseProxy.h>
#include <BulletCollision/CollisionDispatch/btConvexPlaneCollisionAlgorithm.h>

#include "physics/plane_pair.h"

namespace bullet_plant
{
namespace
{
// Bullet's multipoint option (setPlaneConvexMultipointIterations): three perturbed queries while
// the manifold holds fewer than three points.
constexpr int kPerturbations = 3, kPointsBeforePerturbing = 3;

class PlaneContactAlgorithm : public btConvexPlaneCollisionAlgorithm
{
public:
  PlaneContactAlgorithm(const btCollisionAlgorithmConstructionInfo& ci, const btCollisionObjectWrapper* body0,
                        const btCollisionObjectWrapper* body1, bool swapped)
    : btConvexPlaneCollisionAlgorithm(nullptr, ci, body0, body1, swapped, kPerturbations, kPointsBeforePerturbing),
      swapped_(swapped)
  {
  }

  void processCollision(const btCollisionObjectWrapper* body0, const btCollisionObjectWrapper* body1,
                        const btDispatcherInfo& info, btManifoldResult* result) override
  {
    btManifoldArray manifolds;
    getAllContactManifolds(manifolds);
    // With points, Bullet's pass also drops those gone stale; without, a shape whose box is farther
    // from the plane than the manifold's threshold, plus the most a perturbed query tilts it down
    // (its angle is the breaking threshold over the shape's radius), gives none in any query.
    if (manifolds.size() == 1 && manifolds[0]->getNumContacts() == 0 &&
        clearance(shapeOfPair(body0, body1, swapped_), planeOfPair(body0, body1, swapped_)) >
            manifolds[0]->getContactBreakingThreshold() + gContactBreakingThreshold)
      return;
    btConvexPlaneCollisionAlgorithm::processCollision(body0, body1, info, result);
  }

private:
  // How far the convex shape's world box lies above the plane (negative: it reaches below).
  static btScalar clearance(const btCollisionObjectWrapper* convex, const btCollisionObjectWrapper* plane_wrap)
  {
    btVector3 low, high;
    convex->getCollisionShape()->getAabb(convex->getWorldTransform(), low, high);
    const WorldPlane plane = WorldPlane::of(plane_wrap);
    const btVector3 centre = (low + high) * btScalar(0.5), half = (high - low) * btScalar(0.5);
    return plane.height(centre) - plane.normal.absolute().dot(half);
  }

  bool swapped_;
};
}  // namespace

void registerPlaneContact(btCollisionDispatcher& dispatcher)
{
  for (int type = 0; type < CONCAVE_SHAPES_START_HERE; ++type)
    if (btBroadphaseProxy::isConvex(type) && type != CYLINDER_SHAPE_PROXYTYPE)
      registerPlanePair<PlaneContactAlgorithm>(dispatcher, type);
}

}  // namespace bullet_plant
