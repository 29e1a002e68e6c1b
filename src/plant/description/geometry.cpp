#include "bullet_plant/geometry.h"

#include <algorithm>

namespace bullet_plant
{
// urdf::Vector3's operators are not const-correct, so the arithmetic is spelled out here.

urdf::Pose poseFromXyzRpy(double x, double y, double z, double roll, double pitch, double yaw)
{
  urdf::Pose p;
  p.position = urdf::Vector3(x, y, z);
  p.rotation.setFromRPY(roll, pitch, yaw);
  return p;
}

urdf::Vector3 rotate(const urdf::Rotation& q, const urdf::Vector3& v)
{
  // v + 2 w (u x v) + 2 u x (u x v), with u the vector part of q
  double ux = q.x, uy = q.y, uz = q.z, w = q.w;
  double cx = uy * v.z - uz * v.y, cy = uz * v.x - ux * v.z, cz = ux * v.y - uy * v.x;
  double dx = uy * cz - uz * cy, dy = uz * cx - ux * cz, dz = ux * cy - uy * cx;
  return urdf::Vector3(v.x + 2 * (w * cx + dx), v.y + 2 * (w * cy + dy), v.z + 2 * (w * cz + dz));
}

urdf::Pose compose(const urdf::Pose& a, const urdf::Pose& b)
{
  urdf::Pose out;
  out.rotation = a.rotation * b.rotation;
  out.rotation.normalize();
  urdf::Vector3 t = rotate(a.rotation, b.position);
  out.position = urdf::Vector3(a.position.x + t.x, a.position.y + t.y, a.position.z + t.z);
  return out;
}

namespace
{
bool same(const Rgba& a, const Rgba& b) { return a.r == b.r && a.g == b.g && a.b == b.b && a.a == b.a; }
}  // namespace

bool Material::operator==(const Material& o) const
{
  return same(ambient, o.ambient) && same(diffuse, o.diffuse) && same(specular, o.specular) &&
         same(emissive, o.emissive) && shininess == o.shininess;
}

Material Material::ofColour(const Rgba& colour)
{
  Material m;
  m.ambient = m.diffuse = colour;
  m.ambient.a = 1.0f;
  return m;
}

Material Material::gazeboWhite()
{
  // gazebo.material: `ambient 1 1 1 1` in its first pass, `diffuse 1 1 1 1` and `specular .1 .1 .1
  // 128` in the second, which draws over the first (OGRE's default ambient is white too).
  Material m;
  m.specular = {0.1f, 0.1f, 0.1f, 1.0f};
  m.shininess = 128;
  return m;
}

bool VisualMaterial::operator==(const VisualMaterial& o) const
{
  return has_replace == o.has_replace && has_ambient == o.has_ambient && has_diffuse == o.has_diffuse &&
         has_specular == o.has_specular && has_emissive == o.has_emissive && replace == o.replace &&
         same(ambient, o.ambient) && same(diffuse, o.diffuse) && same(specular, o.specular) &&
         same(emissive, o.emissive) && shininess == o.shininess && transparency == o.transparency;
}

Material VisualMaterial::resolve(const Material& own, bool& keep_texture) const
{
  Material m = own;
  keep_texture = true;
  if (has_replace || has_ambient || has_diffuse || has_specular)
  {
    m = has_replace ? replace : Material();
    keep_texture = false;
  }
  if (has_ambient)
    m.ambient = ambient;
  if (has_diffuse)
    m.diffuse = diffuse;
  if (has_specular)
  {
    m.specular = specular;
    m.shininess = shininess;
  }
  if (has_emissive)
    m.emissive = emissive;
  if (transparency >= 0)
    m.diffuse.a = float(1.0 - std::min(1.0, transparency));
  return m;
}

VisualMaterial VisualMaterial::colour(const Rgba& colour)
{
  VisualMaterial v;
  v.has_replace = true;
  v.replace = Material::ofColour(colour);
  return v;
}

urdf::Pose inverse(const urdf::Pose& p)
{
  urdf::Pose out;
  out.rotation = p.rotation.GetInverse();
  urdf::Vector3 t = rotate(out.rotation, p.position);
  out.position = urdf::Vector3(-t.x, -t.y, -t.z);
  return out;
}

}  // namespace bullet_plant
