// physics::JointWrench as Joint::GetForceTorque gives it, with Gazebo 11's signs: what passed
// through the joint over the last step. body2: what the child passed to the joint (the joint's
// push on the child, negated), in the child link's frame, the torque about the joint's origin;
// body1: the joint's push on the child, in the parent link's axes. A joint holding a 2 kg load up
// reads body2Force (0, 0, -19.6) N and body1Force (0, 0, 19.6) N (Gazebo's joint_force_torque test).
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
