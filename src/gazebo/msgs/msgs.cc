// Gazebo's conversions between its messages and ignition's types (gazebo/msgs/msgs.hh).
#include "gazebo/msgs/msgs.hh"

namespace gazebo
{
namespace msgs
{
Vector3d Convert(const ignition::math::Vector3d& v)
{
  Vector3d out;
  Set(&out, v);
  return out;
}

ignition::math::Vector3d ConvertIgn(const Vector3d& v) { return {v.x(), v.y(), v.z()}; }

void Set(Vector3d* out, const ignition::math::Vector3d& v)
{
  out->set_x(v.X());
  out->set_y(v.Y());
  out->set_z(v.Z());
}
}  // namespace msgs
}  // namespace gazebo
