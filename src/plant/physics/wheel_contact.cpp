#include "physics/wheel_contact.h"

#include <array>
#include <memory>
#include <vector>

#include <BulletCollision/CollisionDispatch/btConvexPlaneCollisionAlgorithm.h>
#include <BulletCollision/CollisionDispatch/btManifoldResult.h>
#include <BulletCollision/CollisionDispatch/btCollisionConfiguration.h>
#include <BulletCollision/CollisionShapes/btCylinderShape.h>
#include <BulletCollision/CollisionShapes/btConcaveShape.h>
#include <BulletCollision/CollisionShapes/btTriangleCallback.h>
#include <BulletCollision/Gimpact/btGImpactCollisionAlgorithm.h>

#include "physics/plane_pair.h"

namespace bullet_plant
{
namespace
{
// Above this |cos| between the cylinder's axis and the plane normal the cylinder is not lying down.
constexpr btScalar kLyingCosine = btScalar(0.2);

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

// The wheel's one point of a step in its own manifold, `distance` off the surface along `normal` at
// `on_surface` (the manifold's second body's), carrying the previous step's point's impulses so the
// solver starts warm; none beyond the manifold's breaking threshold.
void placeTreadPoint(btPersistentManifold* manifold, btManifoldResult* result, const btVector3& normal,
                     const btVector3& on_surface, btScalar distance)
{
  btScalar impulse = 0, lateral1 = 0, lateral2 = 0;
  if (manifold->getNumContacts() > 0)
  {
    const btManifoldPoint& old = manifold->getContactPoint(0);
    impulse = old.m_appliedImpulse;
    lateral1 = old.m_appliedImpulseLateral1;
    lateral2 = old.m_appliedImpulseLateral2;
  }
  manifold->clearManifold();
  result->setPersistentManifold(manifold);
  if (distance > manifold->getContactBreakingThreshold())
    return;
  result->addContactPoint(normal, on_surface, distance);
  if (manifold->getNumContacts() > 0)
  {
    btManifoldPoint& point = manifold->getContactPoint(0);
    point.m_appliedImpulse = impulse;
    point.m_appliedImpulseLateral1 = lateral1;
    point.m_appliedImpulseLateral2 = lateral2;
  }
}

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
    // The middle of the tread's lowest line is the contact point.
    const btVector3 lowest = lowestTreadPoint(*cylinder, cylinder_pose, axis, normal);
    placeTreadPoint(manifold_, result, normal, lowest - normal * plane.height(lowest), plane.height(lowest));
  }

private:
  std::unique_ptr<btConvexPlaneCollisionAlgorithm> general_;
};

// How far a triangle's corner may be off a face's plane, and its normal off the face's, and still be
// part of one flat patch with it (a flat floor's neighbouring triangles).
constexpr btScalar kCoplanar = btScalar(0.001);      // m
constexpr btScalar kParallel = btScalar(0.99999);    // cosine

// Where a lying wheel touches a flat patch of a mesh: the face under its tread, in the world.
struct FlatPatchContact
{
  btVector3 normal, on_face;
  btScalar distance = 0;
};

// The mesh's triangles near the wheel (in the mesh's frame), collected.
struct NearTriangles : btTriangleCallback
{
  std::vector<std::array<btVector3, 3>> triangles;
  void processTriangle(btVector3* t, int, int) override { triangles.push_back({{t[0], t[1], t[2]}}); }
};

// Whether `p` (in a triangle's plane) lies on the triangle, its edges included.
bool overTriangle(const std::array<btVector3, 3>& v, const btVector3& p)
{
  const btVector3 normal = (v[1] - v[0]).cross(v[2] - v[0]);
  for (int i = 0; i < 3; ++i)
    if ((p - v[i]).dot(normal.cross(v[(i + 1) % 3] - v[i])) < 0)
      return false;
  return true;
}

// Whether the cylinder lies on one flat patch of the mesh: every triangle within `reach` of its box is
// in one plane, its front towards the cylinder's axis, which lies along it, and the middle of the
// tread's lowest line is over one of them. Then `contact` says where.
bool lyingOnFlatPatch(const btCylinderShape& cylinder, const btTransform& cylinder_pose, const btConcaveShape& mesh,
                      const btTransform& mesh_pose, btScalar reach, FlatPatchContact& contact)
{
  const btTransform in_mesh = mesh_pose.inverse() * cylinder_pose;
  btVector3 low, high;
  cylinder.getAabb(in_mesh, low, high);
  const btVector3 grow(reach, reach, reach);
  NearTriangles near;
  mesh.processAllTriangles(&near, low - grow, high + grow);
  if (near.triangles.empty())
    return false;
  const btVector3 axis = in_mesh.getBasis().getColumn(cylinder.getUpAxis());
  const btScalar margin = mesh.getMargin();
  const std::array<btVector3, 3>* under = nullptr;
  btVector3 normal, lowest;
  for (const auto& t : near.triangles)
  {
    btVector3 n = (t[1] - t[0]).cross(t[2] - t[0]);
    if (n.fuzzyZero())
      continue;
    n.normalize();
    if (btFabs(axis.dot(n)) > kLyingCosine || n.dot(in_mesh.getOrigin() - t[0]) < 0)
      return false;  // standing or tilted on it, or behind it
    const btVector3 tread = lowestTreadPoint(cylinder, in_mesh, axis, n);
    if (overTriangle(t, tread - n * n.dot(tread - t[0])))
    {
      under = &t;
      normal = n;
      lowest = tread;
      break;
    }
  }
  if (!under)
    return false;
  for (const auto& t : near.triangles)
  {
    const btVector3 n = (t[1] - t[0]).cross(t[2] - t[0]);
    if (n.fuzzyZero())
      continue;
    if (n.normalized().dot(normal) < kParallel)
      return false;
    for (const btVector3& corner : t)
      if (btFabs(normal.dot(corner - (*under)[0])) > kCoplanar)
        return false;
  }
  // To the face's surface, its margin out (collision_shapes.h: a mesh's half millimetre).
  const btScalar distance = normal.dot(lowest - (*under)[0]) - margin;
  contact.normal = mesh_pose.getBasis() * normal;
  contact.on_face = mesh_pose * (lowest - normal * distance);
  contact.distance = distance;
  return true;
}

// A cylinder lying on a flat patch of a mesh (a wheel on a mesh floor, static or a moving link's) as
// ONE point in the middle of the tread, along the face's normal, as on a plane (WheelPlaneAlgorithm).
// Bullet's cylinder-triangle test (GJK, then EPA) gave a wheel rolling on a large triangle points at
// the triangle's far corner with sideways normals (a 12 x 6 m floor's: a crash in the middle of the
// lane), and normals up to 90 degrees off within the face. Anywhere else (a wheel at a mesh's edge,
// against a wall of the same mesh, tilted, standing) the mesh's general algorithm (Bullet's
// convex-concave, GImpact) collides it, each into its own manifold: the one not used is emptied.
class WheelMeshAlgorithm : public btCollisionAlgorithm
{
public:
  WheelMeshAlgorithm(const btCollisionAlgorithmConstructionInfo& ci, const btCollisionObjectWrapper* body0,
                     const btCollisionObjectWrapper* body1, bool swapped, btCollisionAlgorithmCreateFunc& general)
    : btCollisionAlgorithm(ci), swapped_(swapped)
  {
    manifold_ = m_dispatcher->getNewManifold((swapped ? body1 : body0)->getCollisionObject(),
                                             (swapped ? body0 : body1)->getCollisionObject());
    btCollisionAlgorithmConstructionInfo general_ci = ci;
    general_ci.m_manifold = nullptr;  // it makes its own
    general_ = general.CreateCollisionAlgorithm(general_ci, body0, body1);
  }
  ~WheelMeshAlgorithm() override
  {
    general_->~btCollisionAlgorithm();
    m_dispatcher->freeCollisionAlgorithm(general_);
    m_dispatcher->releaseManifold(manifold_);
  }

  void processCollision(const btCollisionObjectWrapper* body0, const btCollisionObjectWrapper* body1,
                        const btDispatcherInfo& info, btManifoldResult* result) override
  {
    const btCollisionObjectWrapper* cylinder_wrap = swapped_ ? body1 : body0;
    const btCollisionObjectWrapper* mesh_wrap = swapped_ ? body0 : body1;
    const auto* cylinder = static_cast<const btCylinderShape*>(cylinder_wrap->getCollisionShape());
    const auto* mesh = static_cast<const btConcaveShape*>(mesh_wrap->getCollisionShape());
    FlatPatchContact contact;
    if (!lyingOnFlatPatch(*cylinder, cylinder_wrap->getWorldTransform(), *mesh, mesh_wrap->getWorldTransform(),
                          manifold_->getContactBreakingThreshold(), contact))
    {
      manifold_->clearManifold();
      general_->processCollision(body0, body1, info, result);
      return;
    }
    manifolds_.resize(0);
    general_->getAllContactManifolds(manifolds_);
    for (int m = 0; m < manifolds_.size(); ++m)
      manifolds_[m]->clearManifold();
    placeTreadPoint(manifold_, result, contact.normal, contact.on_face, contact.distance);  // the mesh is B
  }

  btScalar calculateTimeOfImpact(btCollisionObject*, btCollisionObject*, const btDispatcherInfo&,
                                 btManifoldResult*) override
  {
    return btScalar(1);
  }
  void getAllContactManifolds(btManifoldArray& manifolds) override
  {
    manifolds.push_back(manifold_);
    general_->getAllContactManifolds(manifolds);
  }

private:
  bool swapped_;
  btPersistentManifold* manifold_ = nullptr;
  btCollisionAlgorithm* general_ = nullptr;
  btManifoldArray manifolds_;  // the general algorithm's, emptied while the wheel lies on a flat patch
};

// The wheel's algorithm for a cylinder and a mesh of `mesh_type`, in the order `swapped` says.
// General: a static mesh's, the collision configuration's own (Bullet's convex-concave); a moving
// mesh's, GImpact's (registered on the dispatcher, not in the configuration).
struct WheelMeshCreateFunc : public btCollisionAlgorithmCreateFunc
{
  int mesh_type = TRIANGLE_MESH_SHAPE_PROXYTYPE;
  btCollisionAlgorithm* CreateCollisionAlgorithm(btCollisionAlgorithmConstructionInfo& ci,
                                                 const btCollisionObjectWrapper* body0,
                                                 const btCollisionObjectWrapper* body1) override
  {
    static btGImpactCollisionAlgorithm::CreateFunc gimpact;
    btCollisionAlgorithmCreateFunc* general =
        mesh_type == GIMPACT_SHAPE_PROXYTYPE
            ? &gimpact
            : static_cast<btCollisionDispatcher*>(ci.m_dispatcher1)
                  ->getCollisionConfiguration()
                  ->getCollisionAlgorithmCreateFunc(body0->getCollisionShape()->getShapeType(),
                                                    body1->getCollisionShape()->getShapeType());
    void* memory = ci.m_dispatcher1->allocateCollisionAlgorithm(sizeof(WheelMeshAlgorithm));
    return new (memory) WheelMeshAlgorithm(ci, body0, body1, m_swapped, *general);
  }
};
}  // namespace

void registerWheelContact(btCollisionDispatcher& dispatcher)
{
  registerPlanePair<WheelPlaneAlgorithm>(dispatcher, CYLINDER_SHAPE_PROXYTYPE);
  // A wheel on a mesh: a static one (Bullet's BVH) and a moving one (GImpact, which the world
  // registers first).
  static WheelMeshCreateFunc on_static[2], on_moving[2];
  for (int order = 0; order < 2; ++order)
  {
    on_static[order].m_swapped = on_moving[order].m_swapped = order == 1;
    on_moving[order].mesh_type = GIMPACT_SHAPE_PROXYTYPE;
  }
  dispatcher.registerCollisionCreateFunc(CYLINDER_SHAPE_PROXYTYPE, TRIANGLE_MESH_SHAPE_PROXYTYPE, &on_static[0]);
  dispatcher.registerCollisionCreateFunc(TRIANGLE_MESH_SHAPE_PROXYTYPE, CYLINDER_SHAPE_PROXYTYPE, &on_static[1]);
  dispatcher.registerCollisionCreateFunc(CYLINDER_SHAPE_PROXYTYPE, GIMPACT_SHAPE_PROXYTYPE, &on_moving[0]);
  dispatcher.registerCollisionCreateFunc(GIMPACT_SHAPE_PROXYTYPE, CYLINDER_SHAPE_PROXYTYPE, &on_moving[1]);
}

}  // namespace bullet_plant
