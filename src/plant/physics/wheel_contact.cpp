#include "physics/wheel_contact.h"

#include <memory>

#include <BulletCollision/CollisionDispatch/btConvexPlaneCollisionAlgorithm.h>
#include <BulletCollision/CollisionDispatch/btManifoldResult.h>
#include <BulletCollision/CollisionDispatch/btCollisionConfiguration.h>
#include <BulletCollision/CollisionShapes/btCylinderShape.h>
#include <BulletCollision/CollisionShapes/btTriangleShape.h>

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

// The lowest line of a lying cylinder's tread towards a face of normal `normal`: the radius away from
// the axis, straight towards the face in the wheel's plane; its middle.
btVector3 lowestTreadPoint(const btCylinderShape& cylinder, const btTransform& pose, const btVector3& axis,
                           const btVector3& normal)
{
  btVector3 down = -(normal - axis * axis.dot(normal));
  down.normalize();
  const int up = cylinder.getUpAxis();
  return pose.getOrigin() + down * cylinder.getHalfExtentsWithMargin()[(up + 1) % 3];
}

// How far a point may be off a triangle's plane and still be on it (a neighbouring face of a flat
// floor, which carries the wheel where this one does not).
constexpr btScalar kCoplanar = btScalar(0.001);

// A cylinder lying on a triangle of a mesh (a wheel on a mesh floor, static or a moving link's): one
// point in the middle of the tread, along the face's normal, as on a plane. Bullet's cylinder-triangle
// test (GJK, then EPA) gave a wheel rolling on a large triangle points at the triangle's far corner
// with sideways normals (a 12 x 6 m floor's: a crash in the middle of the lane), and normals up to
// 90 degrees off within the face. The general test stays for a cylinder that is not lying on the
// face (standing, tilted, behind it) or that touches the triangle off its face (at an edge that is
// not a flat neighbour's). The points go into the mesh's manifold, which the mesh's algorithm owns.
class WheelTriangleAlgorithm : public btCollisionAlgorithm
{
public:
  WheelTriangleAlgorithm(const btCollisionAlgorithmConstructionInfo& ci, const btCollisionObjectWrapper* body0,
                         const btCollisionObjectWrapper* body1, bool swapped)
    : btCollisionAlgorithm(ci), swapped_(swapped)
  {
    // The general test: the collision configuration's own algorithm for the pair.
    btCollisionConfiguration* configuration =
        static_cast<btCollisionDispatcher*>(ci.m_dispatcher1)->getCollisionConfiguration();
    btCollisionAlgorithmConstructionInfo general_ci = ci;
    general_ = configuration
                   ->getCollisionAlgorithmCreateFunc(body0->getCollisionShape()->getShapeType(),
                                                     body1->getCollisionShape()->getShapeType())
                   ->CreateCollisionAlgorithm(general_ci, body0, body1);
  }
  ~WheelTriangleAlgorithm() override
  {
    general_->~btCollisionAlgorithm();
    m_dispatcher->freeCollisionAlgorithm(general_);
  }

  void processCollision(const btCollisionObjectWrapper* body0, const btCollisionObjectWrapper* body1,
                        const btDispatcherInfo& info, btManifoldResult* result) override
  {
    const btCollisionObjectWrapper* cylinder_wrap = swapped_ ? body1 : body0;
    const btCollisionObjectWrapper* triangle_wrap = swapped_ ? body0 : body1;
    const auto* cylinder = static_cast<const btCylinderShape*>(cylinder_wrap->getCollisionShape());
    const auto* triangle = static_cast<const btTriangleShape*>(triangle_wrap->getCollisionShape());
    const btTransform& cylinder_pose = cylinder_wrap->getWorldTransform();
    const btTransform& triangle_pose = triangle_wrap->getWorldTransform();
    btVector3 normal;
    triangle->calcNormal(normal);  // its front, by its winding
    normal = triangle_pose.getBasis() * normal;
    const btVector3 corner = triangle_pose * triangle->m_vertices1[0];
    const btVector3 axis = cylinder_pose.getBasis().getColumn(cylinder->getUpAxis());
    if (normal.fuzzyZero() || btFabs(axis.dot(normal)) > kLyingCosine || normal.dot(cylinder_pose.getOrigin() - corner) < 0)
    {
      general_->processCollision(body0, body1, info, result);
      return;
    }
    const btVector3 lowest = lowestTreadPoint(*cylinder, cylinder_pose, axis, normal);
    const btScalar distance = normal.dot(lowest - corner);
    if (distance > result->getPersistentManifold()->getContactBreakingThreshold())
      return;
    const btVector3 on_face = lowest - normal * distance;
    if (!overFace(*triangle, triangle_pose.invXform(on_face)))
    {
      if (btFabs(distance) > kCoplanar)
        general_->processCollision(body0, body1, info, result);
      return;
    }
    // Bullet's convention: the normal on the pair's second body, the point on it.
    if (swapped_)
      result->addContactPoint(-normal, lowest, distance);
    else
      result->addContactPoint(normal, on_face, distance);
  }

  btScalar calculateTimeOfImpact(btCollisionObject*, btCollisionObject*, const btDispatcherInfo&,
                                 btManifoldResult*) override
  {
    return btScalar(1);
  }
  void getAllContactManifolds(btManifoldArray& manifolds) override { general_->getAllContactManifolds(manifolds); }

private:
  // Whether `p` (in the triangle's frame, in its plane) lies on the triangle, its edges included.
  static bool overFace(const btTriangleShape& triangle, const btVector3& p)
  {
    const btVector3* v = triangle.m_vertices1;
    const btVector3 normal = (v[1] - v[0]).cross(v[2] - v[0]);
    for (int i = 0; i < 3; ++i)
      if ((p - v[i]).dot(normal.cross(v[(i + 1) % 3] - v[i])) < 0)
        return false;
    return true;
  }

  bool swapped_;
  btCollisionAlgorithm* general_ = nullptr;
};

template <class Algorithm>
struct SwappableCreateFunc : public btCollisionAlgorithmCreateFunc
{
  btCollisionAlgorithm* CreateCollisionAlgorithm(btCollisionAlgorithmConstructionInfo& ci,
                                                 const btCollisionObjectWrapper* body0,
                                                 const btCollisionObjectWrapper* body1) override
  {
    void* memory = ci.m_dispatcher1->allocateCollisionAlgorithm(sizeof(Algorithm));
    return new (memory) Algorithm(ci, body0, body1, m_swapped);
  }
};
}  // namespace

void registerWheelContact(btCollisionDispatcher& dispatcher)
{
  registerPlanePair<WheelPlaneAlgorithm>(dispatcher, CYLINDER_SHAPE_PROXYTYPE);
  // A wheel on a mesh's triangles (a static mesh's, a moving link's GImpact).
  static SwappableCreateFunc<WheelTriangleAlgorithm> cylinder_triangle, triangle_cylinder;
  triangle_cylinder.m_swapped = true;
  dispatcher.registerCollisionCreateFunc(CYLINDER_SHAPE_PROXYTYPE, TRIANGLE_SHAPE_PROXYTYPE, &cylinder_triangle);
  dispatcher.registerCollisionCreateFunc(TRIANGLE_SHAPE_PROXYTYPE, CYLINDER_SHAPE_PROXYTYPE, &triangle_cylinder);
}

}  // namespace bullet_plant
