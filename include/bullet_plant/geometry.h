// Collision shapes the plant knows (URDF and SDF share them) and the poses it works with.
#pragma once

#include <array>
#include <string>

#include <urdf_model/pose.h>

namespace bullet_plant
{
struct Shape
{
  enum class Kind { Box, Cylinder, Sphere, Plane, Mesh };
  Kind kind = Kind::Box;
  std::array<double, 3> box_size{{0, 0, 0}};  // full lengths x y z
  double radius = 0.0;                          // cylinder, sphere
  double length = 0.0;                          // cylinder, along its z axis
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
// urdf::Vector3 has + but neither - nor a scalar product.
inline urdf::Vector3 sub(const urdf::Vector3& a, const urdf::Vector3& b) { return urdf::Vector3(a.x - b.x, a.y - b.y, a.z - b.z); }
inline urdf::Vector3 scaled(const urdf::Vector3& a, double s) { return urdf::Vector3(a.x * s, a.y * s, a.z * s); }

}  // namespace bullet_plant
