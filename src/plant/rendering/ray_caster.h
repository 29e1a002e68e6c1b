// Ray casting for the sensors through Embree (Intel's CPU ray tracer): one Embree scene per world.
// The world's static shapes form one shape set, each robot body another; every set is built once
// into its own Embree scene and placed in the top-level scene as an instance, so a sensor update
// only moves instances (rtcSetGeometryTransform) and commits the top level, never rebuilding a
// link's geometry. Boxes are quads, planes and meshes triangles (their faces are exactly planar, so
// quads and triangles are exact and take Embree's fast path; a box's six quads cast 1.25x the rays a
// second of its twelve triangles, the race track's lidar on one core); spheres, cylinders, capsules and
// ellipsoids are user geometry intersected analytically in double precision (tessellating them
// would move a curved surface by up to its chord error). The world's planes are a shape set of their own, built with
// Embree's robust traversal: in the fast one, rays that run exactly along the edge two of a plane's
// triangles share slipped through (14 of 20,001 in a test), and out of the other static shapes' BVH
// a 2 km plane no longer spoils its boxes (the car's lidar on the race track: 16 against 13.9 M rays
// a second). Rays go in packets of 16, in parallel on TBB's threads (ray_threads.h);
// every ray is computed alone, so scans do not depend on the number of threads. Lidars cast rays;
// cameras rasterize the same primitives with OpenGL (gl_scene.h).
#pragma once

#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include <embree3/rtcore.h>

#include "bullet_plant/geometry.h"
#include "bullet_plant/ray_kernels.h"
#include "description/mesh_loader.h"
#include "physics/spatial.h"
#include "rendering/ray_threads.h"  // setRayThreads, rayThreads

namespace bullet_plant
{
// Who sees a shape: cameras see visuals, lidars collisions (Gazebo's cameras and gpu_ray lidars
// render the visual geometry; its ray lidars hit the collision geometry). These are Embree ray
// masks.
enum SeenBy : unsigned
{
  kSeenByCameras = 1u,
  kSeenByLidars = 2u,
  kSeenByAll = 3u,
};

struct RayPrimitive
{
  Shape::Kind kind = Shape::Kind::Box;
  double half[3] = {0, 0, 0};  // box half extents; an ellipsoid's radii
  double radius = 0.0;         // cylinder, sphere, capsule
  double half_length = 0.0;    // cylinder, capsule (half its cylindrical part)
  double normal[3] = {0, 0, 1};
  Frame frame;                 // shape frame in its parent's frame
  const void* owner = nullptr; // the robot it belongs to (null: the world)
  unsigned seen_by = kSeenByAll;
  std::shared_ptr<const MeshData> mesh;  // mesh
  // What cameras see: the visual's material, applied to each surface's own (VisualMaterial::resolve;
  // a primitive's own and a sub-mesh's without a material of its file are Material::gazeboWhite).
  VisualMaterial material;

  // Not for meshes (fromMesh).
  static RayPrimitive fromShape(const Shape& s, const urdf::Pose& pose, const void* owner);
  static RayPrimitive fromMesh(const std::shared_ptr<const MeshData>& mesh, const urdf::Pose& pose, const void* owner);
  // The material cameras see on a mesh's triangle (or the primitive's, triangle < 0), and whether
  // its sub-mesh's texture shows there.
  Material surfaceMaterial(int triangle, bool& textured) const;
  // The colour under the light at a hit: the triangle's texture at its (u, v) barycentric point
  // where it shows, else its material's diffuse colour.
  Rgba surfaceColour(int triangle, float u, float v) const;
};

struct RayHit
{
  double distance = 0;           // +inf: nothing within range
  const RayPrimitive* primitive = nullptr;
  int triangle = -1;             // of a mesh primitive, else -1
  float u = 0, v = 0;            // barycentric point on the triangle
  double normal[3] = {0, 0, 0};  // unit surface normal in the world, facing the ray
};

// Distance along the unit ray (o, d), in the shape's frame (a cylinder along z), to a sphere's or a
// cylinder's surface; +inf if it misses or starts inside.
double intersectSphere(const double o[3], const double d[3], double radius);
double intersectCylinder(const double o[3], const double d[3], double radius, double half_length);
// A capsule along z (half_length: half its cylindrical part) and an ellipsoid (radii x y z), the same way.
double intersectCapsule(const double o[3], const double d[3], double radius, double half_length);
double intersectEllipsoid(const double o[3], const double d[3], const double radii[3]);

// A plane (through the origin, unit `normal`) as the sensors see it: a square of 2 km a side in
// tiles of 100 m, triangles (x y z per vertex, three indices each), far beyond any sensor's range.
void planeTriangles(const double normal[3], std::vector<float>& vertices, std::vector<int>& indices);

// A lidar's ray directions in its frame: azimuth a_i = a0 + i*da for i < n_azimuth, elevations e_j
// (up towards +z, Gazebo's convention), row by row (elevation major).
std::vector<double> fanDirections(double a0, double da, int n_azimuth, const std::vector<double>& elevations);


class RayScene
{
public:
  explicit RayScene(const std::vector<RayPrimitive>& world_shapes);
  ~RayScene();
  RayScene(const RayScene&) = delete;
  RayScene& operator=(const RayScene&) = delete;

  // A robot body's shapes in the body frame, built once; returns its handle for setPose.
  int addBody(const void* owner, std::vector<RayPrimitive> shapes);
  // Takes out every body of `owner` (at the next commit).
  void removeOwner(const void* owner);
  bool hasOwner(const void* owner) const;
  void setPose(int body, const Frame& world_from_body);
  // Makes the bodies added or removed and the poses set so far take effect (the top level is
  // rebuilt only when something changed). `hidden`: a robot whose shapes every ray passes through
  // until the next commit (a lidar does not see its own robot), or null. Hiding another robot
  // rebuilds nothing: each robot's instances carry an Embree mask bit of their own (kRobotMaskBits
  // robots; those beyond share one bit, and hiding one of them masks its instances out, a rebuild).
  void commit(const void* hidden);
  static constexpr int kRobotMaskBits = 29;

  // One ray (unit dir) from `near` to `far` against what `seen_by` sees.
  RayHit castHit(const double origin[3], const double dir[3], double near, double far, unsigned seen_by) const;
  double cast(const double origin[3], const double dir[3], double far, unsigned seen_by) const;
  // Rays from the sensor frame's origin along `directions` (unit, in the sensor frame, x y z each):
  // distances (+inf: nothing in [near, far]) in the same order.
  void castRays(const Frame& sensor, const std::vector<double>& directions, double near, double far,
                unsigned seen_by, std::vector<double>& out) const;

  // The instruction set this scene's kernels use, and why not the one asked for if it is not.
  const EmbreeIsa& isa() const { return isa_; }

  // How many sets of a world's static shapes this process has built; scenes of the same shapes
  // share one (staticSet), and the newest kUnheldStaticSets that no scene holds are kept.
  static size_t staticSetsBuilt();
  static constexpr size_t kUnheldStaticSets = 4;

private:
  struct ShapeSet;
  struct Instance
  {
    std::shared_ptr<ShapeSet> set;
    const void* owner = nullptr;
    unsigned geometry_id = RTC_INVALID_GEOMETRY_ID;
    unsigned mask = kSeenByAll;  // Embree's instance mask while shown: a robot's, its robot's bit
    Frame pose;
  };
  // The mask bit of `owner`'s instances (0: no body of it here): its own, the first no robot's
  // instance holds when its first body comes (freeRobotBit), or the one the robots beyond
  // kRobotMaskBits share.
  unsigned robotBit(const void* owner) const;
  unsigned freeRobotBit() const;
  // A world's static shapes as one set, shared by every scene of the same shapes while any holds
  // it: the worlds of one world file (a racing environment makes one at every reset, a vector
  // environment N side by side) build its BVH once (RTC_BUILD_QUALITY_HIGH: milliseconds on a race
  // track) and cast their rays through the same memory. A built scene is only read, which Embree
  // allows from any number of threads.
  static std::shared_ptr<ShapeSet> staticSet(RTCDevice device, const std::vector<RayPrimitive>& shapes, bool robust);
  void attach(Instance& instance);
  // A new instance of `instance`'s set at its pose in `level`; its geometry id there.
  unsigned attachInstance(RTCScene level, const Instance& instance) const;
  // The primitive, triangle and world normal (facing the ray) of an Embree hit.
  void resolve(const RTCRayHit& hit, RayHit& out) const;

  const EmbreeIsa isa_;
  const RTCDevice device_;
  RTCScene top_ = nullptr;
  RTCScene statics_top_ = nullptr;  // instances_[0] and [1] alone, committed once
  RTCScene cast_scene_ = nullptr;   // the level rays are cast into, as the last commit chose
  // [0]: the world's static shapes but planes, [1] its planes (robust traversal); the rest robots'
  // bodies (null set: removed)
  std::vector<Instance> instances_;
  std::vector<int> instance_of_geometry_;  // top-level geometry id -> index in instances_
  unsigned rays_see_robots_ = ~0u;  // the robots' bits of every ray's mask: all but the hidden one's
  const void* masked_out_ = nullptr;  // the robot of the shared bit whose instances the last commit masked out
  bool changed_ = true;                       // since the last commit: the top level needs one
};

}  // namespace bullet_plant
