// Ray casting for the sensors through Embree (Intel's CPU ray tracer): one Embree scene per world.
// The world's static shapes form one shape set, each robot body another; every set is built once
// into its own Embree scene and placed in the top-level scene as an instance, so a sensor update
// only moves instances (rtcSetGeometryTransform) and commits the top level, never rebuilding a
// link's geometry. Boxes, planes and meshes are triangles (a box's and a plane's faces are exactly
// planar, so triangles are exact and take Embree's fast path); spheres and cylinders are user
// geometry intersected analytically in double precision (tessellating them would move a curved
// surface by up to its chord error). Camera rays go in packets of 16, tiles in parallel on a small
// thread pool; every pixel is computed alone, so frames do not depend on the number of threads.
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
  double half[3] = {0, 0, 0};  // box half extents
  double radius = 0.0;         // cylinder, sphere
  double half_length = 0.0;    // cylinder
  double normal[3] = {0, 0, 1};
  Frame frame;                 // shape frame in its parent's frame
  const void* owner = nullptr; // the robot it belongs to (null: the world)
  unsigned seen_by = kSeenByAll;
  std::shared_ptr<const MeshData> mesh;  // mesh
  Rgba colour;                 // what cameras see (for a mesh: where its sub-mesh has no colour or texture)

  // Not for meshes (fromMesh).
  static RayPrimitive fromShape(const Shape& s, const urdf::Pose& pose, const void* owner);
  static RayPrimitive fromMesh(const std::shared_ptr<const MeshData>& mesh, const urdf::Pose& pose, const void* owner);
  // The colour cameras see at a hit: a mesh triangle's texture at its (u, v) barycentric point,
  // else its sub-mesh's diffuse colour, else the primitive's own colour.
  Rgba surfaceColour(int triangle, float u, float v) const;
};

struct SurfaceLook;  // what cameras see on a shape (ray_caster.cpp)

struct RayHit
{
  double distance = 0;           // +inf: nothing within range
  const RayPrimitive* primitive = nullptr;
  int triangle = -1;             // of a mesh primitive, else -1
  float u = 0, v = 0;            // barycentric point on the triangle
  double normal[3] = {0, 0, 0};  // unit surface normal in the world, facing the ray
};

// How cameras light what they see: one directional light, lambert shading over an ambient term,
// the background colour where nothing is hit.
struct Lighting
{
  double towards_light[3] = {0.5, -0.1, 0.9};  // unit
  double ambient = 0.35;
  float background[3] = {0.70f, 0.80f, 0.95f};
  static Lighting of(const urdf::Vector3& light_direction, double ambient, const Rgba& background);
};

// The rays of a pinhole camera (one through each pixel centre) and what they give.
struct PinholeRays
{
  int width = 0, height = 0;
  double fx = 0, fy = 0, cx = 0, cy = 0;
  double near = 0, far = 100;  // clip distances along the optical axis
  // Gaussian noise added to each colour value before rounding: kNoiseTableSize samples of it (null:
  // none), picked by a hash of the frame's seed, the pixel and the channel, so that a frame does
  // not depend on the order or the threads its pixels are computed in.
  static constexpr int kNoiseTableSize = 1 << 16;
  const float* noise = nullptr;
  uint64_t noise_seed = 0;
  // Whether the frame's depths are wanted (a colour camera's are not): a renderer may skip them.
  bool depth = true;
};
// A pixel's lit colour (0..1 per channel) into its three bytes: the rays' noise added (the sample
// their seed and the pixel pick), clamped, rounded half up.
void writePixelColour(const PinholeRays& rays, size_t pixel, const float rgb[3], uint8_t* rgb8);
// The same noise added to a colour already rounded to bytes (the GL renderer's), rounded again.
void addPixelNoise(const PinholeRays& rays, size_t pixel, uint8_t* rgb8);

struct PinholeImage
{
  std::vector<uint8_t> rgb8;  // lit colour per pixel (plus noise), rounded to 0..255, background where nothing is hit
  std::vector<float> depth;   // along the optical axis, +inf where nothing is hit within the clip range
};

// Distance along the unit ray (o, d), in the shape's frame (a cylinder along z), to a sphere's or a
// cylinder's surface; +inf if it misses or starts inside.
double intersectSphere(const double o[3], const double d[3], double radius);
double intersectCylinder(const double o[3], const double d[3], double radius, double half_length);

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
  // until the next commit (a lidar does not see its own robot), or null.
  void commit(const void* hidden);

  // One ray (unit dir) from `near` to `far` against what `seen_by` sees.
  RayHit castHit(const double origin[3], const double dir[3], double near, double far, unsigned seen_by) const;
  double cast(const double origin[3], const double dir[3], double far, unsigned seen_by) const;
  // Rays from the sensor frame's origin along `directions` (unit, in the sensor frame, x y z each):
  // distances (+inf: nothing in [near, far]) in the same order.
  void castRays(const Frame& sensor, const std::vector<double>& directions, double near, double far,
                unsigned seen_by, std::vector<double>& out) const;
  // A camera at `pose` (x forward, y left, z up; the optical frame is z forward, x right, y down).
  void castPinhole(const Frame& pose, const PinholeRays& rays, const Lighting& lighting, PinholeImage& out) const;

  // The instruction set this scene's kernels use, and why not the one asked for if it is not.
  const EmbreeIsa& isa() const { return isa_; }

private:
  struct ShapeSet;
  struct Instance
  {
    std::shared_ptr<ShapeSet> set;
    const void* owner = nullptr;
    unsigned geometry_id = RTC_INVALID_GEOMETRY_ID;
    Frame pose;
    float rotation[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};  // pose.R, row major, for shading
  };
  // A camera's lambert shading of its hits, on one thread (RayScene::castPinhole).
  class CameraShading
  {
  public:
    CameraShading(const RayScene& scene, const Lighting& lighting);
    // The lit colour of a packet lane's hit (the lane hit something). Inline: once per camera ray
    // (defined in ray_caster.cpp, its only user).
    inline Rgba litColour(const RTCRayHit16& rh, int lane);

  private:
    // The light on either face of the triangle whose geometric normal (in its instance) is ng.
    void lightFaces(const float ng[3]);

    const RayScene& scene_;
    const float light_[3];
    const float ambient_;
    // What the previous lane hit: lanes on the same shape skip the lookups, lanes on the same
    // triangle (the same Embree normal) the normal's transform and the light.
    unsigned instance_id_ = RTC_INVALID_GEOMETRY_ID, geometry_id_ = RTC_INVALID_GEOMETRY_ID;
    const Instance* instance_ = nullptr;
    const RayPrimitive* primitive_ = nullptr;
    const SurfaceLook* look_ = nullptr;
    float ng_[3] = {std::numeric_limits<float>::quiet_NaN(), 0, 0};
    float normal_[3] = {0, 0, 0};  // in the world
    float lit_[2] = {0, 0};        // on the face towards the ray, on the back face
  };
  void attach(Instance& instance);
  // The primitive, triangle and world normal (facing the ray) of an Embree hit.
  void resolve(const RTCRayHit& hit, RayHit& out) const;

  const EmbreeIsa isa_;
  const RTCDevice device_;
  RTCScene top_ = nullptr;
  std::vector<Instance> instances_;  // [0]: the world's static shapes; the rest robots' bodies (null set: removed)
  std::vector<int> instance_of_geometry_;  // top-level geometry id -> index in instances_
  const void* hidden_ = nullptr;  // as the last commit hid it
  bool changed_ = true;                       // since the last commit: the top level needs one
};

}  // namespace bullet_plant
