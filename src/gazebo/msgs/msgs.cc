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

Quaternion Convert(const ignition::math::Quaterniond& q)
{
  Quaternion out;
  Set(&out, q);
  return out;
}

Pose Convert(const ignition::math::Pose3d& p)
{
  Pose out;
  Set(&out, p);
  return out;
}

ignition::math::Vector3d ConvertIgn(const Vector3d& v) { return {v.x(), v.y(), v.z()}; }

ignition::math::Quaterniond ConvertIgn(const Quaternion& q) { return {q.w(), q.x(), q.y(), q.z()}; }

ignition::math::Pose3d ConvertIgn(const Pose& p) { return {ConvertIgn(p.position()), ConvertIgn(p.orientation())}; }

void Set(Vector3d* out, const ignition::math::Vector3d& v)
{
  out->set_x(v.X());
  out->set_y(v.Y());
  out->set_z(v.Z());
}

void Set(Quaternion* out, const ignition::math::Quaterniond& q)
{
  out->set_x(q.X());
  out->set_y(q.Y());
  out->set_z(q.Z());
  out->set_w(q.W());
}

void Set(Pose* out, const ignition::math::Pose3d& p)
{
  Set(out->mutable_position(), p.Pos());
  Set(out->mutable_orientation(), p.Rot());
}
Time Convert(const common::Time& t)
{
  Time out;
  Set(&out, t);
  return out;
}

common::Time Convert(const Time& t) { return common::Time(t.sec(), t.nsec()); }

void Set(Time* out, const common::Time& t)
{
  out->set_sec(t.sec);
  out->set_nsec(t.nsec);
}
}  // namespace msgs
}  // namespace gazebo
