// physics::JointWrench as Joint::GetForceTorque gives it: what the joint passes between its two
// links over the last step (body2: on the child, in the child link's frame, the torque about the
// joint's origin; body1: the same wrench's reaction on the parent, in the parent link's axes).
#pragma once

#include <ignition/math/Vector3.hh>

namespace gazebo
{
namespace physics
{
class JointWrench
{
public:
  ignition::math::Vector3d body1Force, body2Force, body1Torque, body2Torque;
};
}  // namespace physics
}  // namespace gazebo
