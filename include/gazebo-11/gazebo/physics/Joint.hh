// physics::Joint as a model plugin drives a movable joint: its position and velocity, and an
// effort, a velocity or a position set (axis 0; a joint of the plant has one axis).
#pragma once

#include <memory>
#include <string>

#include "gazebo/physics/PhysicsTypes.hh"
#include "gazebo/util/system.hh"

namespace gazebo
{
namespace physics
{
class JointBridge;

class GZ_PHYSICS_VISIBLE Joint
{
public:
  Joint(const std::string& name, std::unique_ptr<JointBridge> bridge);
  ~Joint();
  std::string GetName() const;
  // Axis 0; another axis is 0 with one error naming the joint.
  double Position(unsigned int index = 0) const;
  double GetVelocity(unsigned int index) const;
  // Joint::SetVelocity: the joint moving at `velocity` now (the rest of the model keeps its motion).
  void SetVelocity(unsigned int index, double velocity);
  // An effort (N m or N) added for the coming step.
  void SetForce(unsigned int index, double effort);
  bool SetPosition(unsigned int index, double position, bool preserveWorldVelocity = false);

private:
  bool axisZero(unsigned int index, const char* call) const;
  std::string name_;
  std::unique_ptr<JointBridge> bridge_;
};
}  // namespace physics
}  // namespace gazebo
