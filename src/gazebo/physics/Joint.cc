// physics::Joint (gazebo/physics/Joint.hh), over the simulator's JointBridge.
#include "gazebo/physics/Joint.hh"

#include "gazebo/common/Console.hh"
#include "gazebo/physics/PlantBridge.hh"

namespace gazebo
{
namespace physics
{
Joint::Joint(const std::string& name, std::unique_ptr<JointBridge> bridge) : name_(name), bridge_(std::move(bridge)) {}

Joint::~Joint() = default;

std::string Joint::GetName() const { return name_; }

bool Joint::axisZero(unsigned int index, const char* call) const
{
  if (index == 0)
    return true;
  gzerr << "Joint::" << call << "(" << index << ") on joint [" << name_
        << "]: the joint has one axis, 0" << std::endl;
  return false;
}

double Joint::Position(unsigned int index) const { return axisZero(index, "Position") ? bridge_->position() : 0.0; }

double Joint::GetVelocity(unsigned int index) const
{
  return axisZero(index, "GetVelocity") ? bridge_->velocity() : 0.0;
}

void Joint::SetVelocity(unsigned int index, double velocity)
{
  if (axisZero(index, "SetVelocity"))
    bridge_->setVelocity(velocity);
}

void Joint::SetForce(unsigned int index, double effort)
{
  if (axisZero(index, "SetForce"))
    bridge_->setForce(effort);
}

bool Joint::SetPosition(unsigned int index, double position, bool /*preserveWorldVelocity*/)
{
  return axisZero(index, "SetPosition") && bridge_->setPosition(position);
}
}  // namespace physics
}  // namespace gazebo
