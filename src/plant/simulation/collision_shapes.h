// Where the plant's shapes become Bullet collision shapes: one switch over Shape::Kind for the world
// and the robots, one margin rule, and the URDF geometry each collision is read from.
#pragma once

#include <memory>
#include <string>

#include <btBulletCollisionCommon.h>
#include <urdf_model/link.h>

#include "bullet_plant/geometry.h"
#include "bullet_plant/log.h"
#include "description/mesh_loader.h"
#include "rendering/ray_caster.h"

namespace bullet_plant
{
// Bullet keeps a box's or cylinder's outer size and rounds its edges by the margin. Its 4 cm default
// is larger than this car's wheels; half a millimetre keeps contacts on the true surface. A sphere's
// margin is its radius and a plane has none: Bullet's own. A mesh on a moving body is its convex hull
// shrunk by the margin, so with the margin its outer surface is the mesh's (edges rounded by half a
// millimetre). A mesh on a static body is its exact triangles with the same margin, so what rests on
// it rests half a millimetre above them: with no margin every resting contact needs Bullet's
// penetration solver (EPA), which doubled the cost of a step of the car on a mesh floor.
constexpr btScalar kCollisionMargin = btScalar(0.0005);

// A convex piece of a moving body's mesh collides as its hull of at most this many vertices:
// contact cost grows with the vertices GJK walks.
constexpr int kMaxHullVertices = 100;

// Static bodies (world collisions, robots fixed in the world) take meshes as their triangles. Moving
// bodies take them as exactly as Gazebo's ODE collides a trimesh, at the cost of the cheapest Bullet
// shape that is exact: a convex mesh as its hull, a mesh of convex pieces (its triangles joined by
// shared corners: a track's wall segments, a pile of blocks) as a compound of their hulls, any other
// as its triangles (Bullet's GImpact, a BVH over them refitted as the body moves).
enum class Mobility { Static, Moving };

// The shape in its own frame (a cylinder and a capsule along its z axis; an ellipsoid by its exact
// support function). The caller owns it. Not for meshes (makeCollider loads them).
btCollisionShape* makeCollisionShape(const Shape& shape);

// A mesh as a static triangle mesh (Bullet's BVH over the loaded triangles, which the shape keeps
// alive, with the angles between its faces for correctInternalEdges) or as a moving body's shape
// (Mobility). A static mesh's shape is shared by every body of that mesh while any holds it: the worlds of
// one world file (a racing environment makes one at every reset, a vector environment N side by
// side) build its BVH and edge angles once (2 ms for the mesh race track's walls and floor) and
// collide through the same memory; Bullet only reads a triangle mesh's shape while it collides.
std::shared_ptr<btCollisionShape> makeMeshCollisionShape(const std::shared_ptr<const MeshData>& mesh,
                                                         Mobility mobility);

// Contacts with the static meshes of `object` (its shape, or a compound's children) at an edge
// between two faces take the faces' normals (Bullet's btInternalEdgeUtility). Without it a wheel
// rolling over a mesh floor meets the edges between its triangles with normals pointing sideways
// and down: bumps that are not in the floor. Nothing for an object with no static mesh.
void correctInternalEdges(btCollisionObject& object);

// A shape for Bullet and for the sensors' ray caster, at `pose` in its body (or the world).
struct Collider
{
  std::shared_ptr<btCollisionShape> shape;  // null where a mesh cannot be loaded: see reason
  RayPrimitive ray;
  std::shared_ptr<const MeshData> mesh;      // a mesh's triangles
  std::string reason;  // why the mesh could not be loaded ("cannot be read (...)", "has no triangles")
  std::string note;    // what a mesh became on a moving body (its hull, its pieces' hulls, GImpact), or ""
};
Collider makeCollider(const Shape& shape, Mobility mobility, const urdf::Pose& pose, const void* owner);

// The shape as Bullet's axis-aligned primitive where its pose in a body frame is one of its
// symmetries (no offset; for a box a rotation that permutes its axes, for a cylinder one that puts
// its axis on a body axis, for a sphere any, for a capsule as a cylinder, for an ellipsoid as a box):
// then the body's collider needs no compound, which costs every contact pair a tree walk and a
// transform per step. Null where a compound is needed.
btCollisionShape* makeAlignedCollisionShape(const Shape& shape, const btTransform& pose);

// A wheel-shaped mesh as the cylinder about `axis` that it fills: the vertices' farthest reach from
// the axis line (through the origin of the frame `mesh_pose` is given in) is the same, within 5 %, in
// 16 directions around it. Such a mesh rolls smoothly as that cylinder where its hull's facets would
// bump. False where the mesh is not wheel-shaped about that axis. `cylinder_pose`: in the same
// frame, its z along the axis.
bool fitWheelCylinder(const MeshData& mesh, const btTransform& mesh_pose, const btVector3& axis, Shape& cylinder,
                      btTransform& cylinder_pose);

// A URDF <collision>'s geometry as a Shape (a mesh's filename resolved with resolveUri, relative
// paths against the working directory as URDF comes as text). False, with a warning naming the link,
// where the geometry cannot be simulated (a mesh file not found, zero or negative size). An SDF
// capsule or ellipsoid (ShapeGeometry, robot_description.h) is its shape.
bool shapeFromUrdf(const urdf::Geometry& geometry, const std::string& link, const Log& log, Shape& shape);

}  // namespace bullet_plant
