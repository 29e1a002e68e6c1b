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

// A shape's own dimensions, each by its name (the keys of the viewer's scene and of
// World.static_collisions alike): a box's "size" (full lengths); a cylinder's and a capsule's "length"
// and "radius"; a sphere's "radius"; an ellipsoid's "radii"; a plane's "normal". A mesh has none here
// (its file and scale are its own). put(name, value) takes a double or three of them.
template <class Put>
void putShapeDimensions(const Shape& s, Put&& put)
{
  switch (s.kind)
  {
    case Shape::Kind::Box: put("size", s.box_size); break;
    case Shape::Kind::Cylinder:
    case Shape::Kind::Capsule: put("length", s.length); [[fallthrough]];
    case Shape::Kind::Sphere: put("radius", s.radius); break;
    case Shape::Kind::Ellipsoid: put("radii", s.radii); break;
    case Shape::Kind::Plane: put("normal", std::array<double, 3>{{s.normal.x, s.normal.y, s.normal.z}}); break;
    case Shape::Kind::Mesh: break;
  }
}

struct Rgba
{
  float r = 0.7f, g = 0.7f, b = 0.7f, a = 1.0f;
};

// What a surface is made of, as Gazebo's renderer (OGRE, per-pixel lighting) lights it: emissive
// plus the scene's ambient times `ambient`, plus each light's diffuse times `diffuse` times n . l (a
// texture modulating these), plus each light's specular times `specular` times (n . h)^shininess
// where shininess > 0 and `specular` is not black (OGRE has no specular term otherwise). The
// diffuse alpha is the surface's opacity. The defaults are an OGRE pass's own: what a visual whose
// <material> gives some colours has for the others.
struct Material
{
  Rgba ambient{1, 1, 1, 1}, diffuse{1, 1, 1, 1}, specular{0, 0, 0, 1}, emissive{0, 0, 0, 1};
  double shininess = 0.0;
  bool operator==(const Material& o) const;
  bool operator!=(const Material& o) const { return !(*this == o); }
  bool transparent() const { return diffuse.a < 1.0f; }
  bool hasSpecular() const { return shininess > 0 && (specular.r > 0 || specular.g > 0 || specular.b > 0); }
  // One colour as both ambient and diffuse, no specular: a URDF <material><color> (the plant's rule
  // for robots' colours; see docs/sdf.md).
  static Material ofColour(const Rgba& colour);
  // What Gazebo draws a visual without <material> with (a mesh's sub-mesh without a material of
  // its own too): gazebo.material's Gazebo/White, ambient and diffuse white, specular 0.1 at 128.
  static Material gazeboWhite();
};

// A visual's material as its description gives it, applied to each of its surfaces (a mesh's
// sub-meshes, each with the material its file gives, or gazeboWhite) as Gazebo's Visual::Load does:
// `replace` (a known Gazebo/* <script>, or a URDF colour) replaces the surface's material and
// texture; else an <ambient>, <diffuse> or <specular> replaces them with a fresh OGRE pass (Material's
// defaults, no texture: Visual::SetAmbient, SetDiffuse and SetSpecular make one); then each colour
// given overrides, <specular> bringing <shininess> with it (0 without one, so no specular); an
// <emissive> alone keeps the surface's own material and texture. <transparency> (or else the
// <diffuse> alpha) is every surface's opacity.
struct VisualMaterial
{
  bool has_replace = false, has_ambient = false, has_diffuse = false, has_specular = false, has_emissive = false;
  Material replace;
  Rgba ambient, diffuse, specular, emissive;
  double shininess = 0.0;
  double transparency = -1.0;  // <visual><transparency>; < 0: not given
  bool operator==(const VisualMaterial& o) const;
  // The material of a surface whose own is `own`, and whether its own texture stays on it.
  Material resolve(const Material& own, bool& keep_texture) const;
  // One colour as ambient and diffuse (Material::ofColour), in place of every surface's own.
  static VisualMaterial colour(const Rgba& colour);
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
