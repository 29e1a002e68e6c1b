// Collision shapes the plant knows (URDF and SDF share them) and the poses it works with.
#pragma once

#include <array>
#include <cmath>
#include <string>

#include <urdf_model/pose.h>

namespace bullet_plant
{
struct Shape
{
  // Capsule and Ellipsoid: SDF 1.8's (sdformat 11), which the plant reads in every version.
  enum class Kind { Box, Cylinder, Sphere, Plane, Mesh, Capsule, Ellipsoid };
  Kind kind = Kind::Box;
  std::array<double, 3> box_size{{0, 0, 0}};  // full lengths x y z
  double radius = 0.0;                          // cylinder, sphere, capsule
  double length = 0.0;                          // cylinder, and a capsule's cylindrical part, along its z axis
  std::array<double, 3> radii{{0, 0, 0}};      // ellipsoid, along its x y z axes
  urdf::Vector3 normal{0, 0, 1};                // plane, through the shape origin
  std::string mesh_uri;                         // mesh: as written in the URDF/SDF (for messages)
  std::string mesh_file;                        // mesh: the file it resolved to (resolveUri)
  urdf::Vector3 scale{1, 1, 1};                 // mesh: <scale>
};

struct Rgba
{
  float r = 0.7f, g = 0.7f, b = 0.7f, a = 1.0f;
};

// x y z roll pitch yaw (URDF/SDF convention: fixed axes, R = Rz(yaw) Ry(pitch) Rx(roll)).
urdf::Pose poseFromXyzRpy(double x, double y, double z, double roll, double pitch, double yaw);
urdf::Pose compose(const urdf::Pose& a, const urdf::Pose& b);  // a * b
urdf::Pose inverse(const urdf::Pose& p);
urdf::Vector3 rotate(const urdf::Rotation& q, const urdf::Vector3& v);
// The yaw of q about z (roll-pitch-yaw's, as ignition::math::Quaternion::Yaw() and tf's getYaw give it).
inline double yawOf(const urdf::Rotation& q) { return std::atan2(2 * (q.w * q.z + q.x * q.y), 1 - 2 * (q.y * q.y + q.z * q.z)); }
// A pose in the plane, the yaw about z (as the drives' odometry has it).
inline urdf::Pose planarPose(double x, double y, double heading)
{
  urdf::Pose pose;
  pose.position = urdf::Vector3(x, y, 0.0);
  pose.rotation.setFromRPY(0.0, 0.0, heading);
  return pose;
}
// urdf::Vector3 has + but neither - nor a scalar product.
inline urdf::Vector3 sub(const urdf::Vector3& a, const urdf::Vector3& b) { return urdf::Vector3(a.x - b.x, a.y - b.y, a.z - b.z); }
inline urdf::Vector3 scaled(const urdf::Vector3& a, double s) { return urdf::Vector3(a.x * s, a.y * s, a.z * s); }

}  // namespace bullet_plant
