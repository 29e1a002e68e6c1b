// Ray casting for the sensors: analytic ray/box/cylinder/sphere/plane intersections against a
// snapshot of the scene, with angular culling for lidar fans (each shape only meets the rays whose
// azimuth falls within its bounding sphere), in double precision.
#pragma once

#include <vector>

#include "bullet_plant/geometry.h"
#include "physics/spatial.h"

namespace bullet_plant
{
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
  Rgba colour;                 // what cameras see

  static RayPrimitive fromShape(const Shape& s, const urdf::Pose& pose, const void* owner);
  // Distance along the unit ray (origin, dir) in the primitive's parent frame to the first surface
  // hit ahead of an origin outside the shape; +inf if none.
  double intersect(const double origin[3], const double dir[3]) const;
  // Outward unit normal at a point on the surface (parent frame).
  void normalAt(const double point[3], double out[3]) const;
};

struct RayHit
{
  double distance;               // +inf: nothing within range
  const RayPrimitive* primitive;
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

}  // namespace bullet_plant
