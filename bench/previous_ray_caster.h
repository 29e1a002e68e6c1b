// The sensors' ray casting before Embree (commit 4fd8362's src/plant/ray_caster.h, in namespace
// bullet_plant::previous), kept only so `make bench` can time it beside the Embree path in the same
// run. Ray casting for the sensors: analytic ray/box/cylinder/sphere/plane intersections and triangle
// meshes (each through its own bounding volume hierarchy) against a snapshot of the scene, with
// angular culling for lidar fans (each shape only meets the rays whose azimuth falls within its
// bounding sphere), in double precision.
#pragma once

#include <memory>
#include <vector>

#include "bullet_plant/geometry.h"
#include "mesh_loader.h"
#include "physics/spatial.h"

namespace bullet_plant
{
namespace previous
{
// A bounding volume hierarchy of axis-aligned boxes over a mesh's triangles (binary, split at the
// median centroid along the longest axis, up to four triangles a leaf), built once per loaded mesh
// and shared by all its copies.
class TriangleBvh
{
public:
  explicit TriangleBvh(std::shared_ptr<const MeshData> mesh);
  static std::shared_ptr<const TriangleBvh> of(const std::shared_ptr<const MeshData>& mesh);

  // Distance along the unit ray (mesh frame) to the nearest triangle (either side) ahead of the
  // origin, +inf if none; `triangle` is its index in the mesh.
  double intersect(const double origin[3], const double dir[3], int& triangle) const;
  // The triangle's unit normal, (v1 - v0) x (v2 - v0) normalised.
  void normal(int triangle, double out[3]) const;
  const MeshData& mesh() const { return *mesh_; }
  double boundRadius() const { return bound_radius_; }  // about the mesh frame's origin

private:
  struct Node
  {
    float lo[3], hi[3];
    int first = 0;  // leaf: first entry of triangles_; inner node: its second child (the first follows it)
    int count = 0;  // leaf: number of triangles; 0: inner node
  };
  struct Triangle
  {
    double v0[3], e1[3], e2[3];
    int index;  // in the mesh
  };
  int build(int first, int count, std::vector<float>& centroids);

  std::shared_ptr<const MeshData> mesh_;
  std::vector<Node> nodes_;
  std::vector<Triangle> triangles_;  // in leaf order
  double bound_radius_ = 0.0;
};

struct RayPrimitive
{
  Shape::Kind kind = Shape::Kind::Box;
  double half[3] = {0, 0, 0};  // box half extents
  double radius = 0.0;         // cylinder, sphere
  double half_length = 0.0;    // cylinder
  double normal[3] = {0, 0, 1};
  Frame frame;                 // shape frame in its parent's frame
  const void* owner = nullptr; // the robot it belongs to (null: the world)
  double bound_radius = 0.0;   // bounding sphere about the shape origin; infinite for planes
  std::shared_ptr<const TriangleBvh> mesh;  // mesh
  Rgba colour;                 // what cameras see (for a mesh: where its sub-mesh has no colour)

  // Not for meshes (fromMesh).
  static RayPrimitive fromShape(const Shape& s, const urdf::Pose& pose, const void* owner);
  static RayPrimitive fromMesh(const std::shared_ptr<const MeshData>& mesh, const urdf::Pose& pose, const void* owner);
  // Distance along the unit ray (origin, dir) in the primitive's parent frame to the first surface
  // hit ahead of an origin outside the shape; +inf if none. `triangle`: the mesh triangle hit.
  double intersect(const double origin[3], const double dir[3], int* triangle = nullptr) const;
  // Outward unit normal at a point on the surface (parent frame); for a mesh the normal of the
  // triangle hit, which may face either way.
  void normalAt(const double point[3], double out[3], int triangle = -1) const;
  // The colour at a triangle of a mesh (its sub-mesh's diffuse colour where the file gives one).
  const Rgba& colourAt(int triangle) const;
};

struct RayHit
{
  double distance;               // +inf: nothing within range
  const RayPrimitive* primitive;
  int triangle;                  // of a mesh primitive, else -1
};

class RayCaster
{
public:
  // primitives in the world frame; those owned by `exclude` are ignored.
  RayCaster(const std::vector<RayPrimitive>& primitives, const void* exclude);

  double cast(const double origin[3], const double dir[3], double max_range) const;
  RayHit castHit(const double origin[3], const double dir[3], double max_range) const;

  // A lidar: rays from origin in the sensor frame `sensor` (world), azimuth a_i = a0 + i*da for
  // i < n_azimuth, elevations e_j. Writes distances (+inf: nothing within max_range) row by row
  // (elevation major) into out.
  void castFan(const Frame& sensor, double a0, double da, int n_azimuth, const std::vector<double>& elevations,
               double max_range, std::vector<double>& out) const;

private:
  std::vector<const RayPrimitive*> primitives_;
};

}  // namespace previous
}  // namespace bullet_plant
