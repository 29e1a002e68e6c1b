#include "bullet_plant/geometry.h"

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

urdf::Pose inverse(const urdf::Pose& p)
{
  urdf::Pose out;
  out.rotation = p.rotation.GetInverse();
  urdf::Vector3 t = rotate(out.rotation, p.position);
  out.position = urdf::Vector3(-t.x, -t.y, -t.z);
  return out;
}

}  // namespace bullet_plant
