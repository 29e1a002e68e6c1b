#include "bullet_plant/joint_layer.h"

#include <cmath>

namespace bullet_plant
{
const char* interfaceName(JointInterface iface)
{
  switch (iface)
  {
    case JointInterface::Effort: return "hardware_interface::EffortJointInterface";
    case JointInterface::Velocity: return "hardware_interface::VelocityJointInterface";
    case JointInterface::Position: return "hardware_interface::PositionJointInterface";
  }
  return "";
}

bool JointHandle::setCommand(double value)
{
  if (!std::isfinite(value))
  {
    ++rejected_;
    return false;
  }
  command_ = value;
  has_law_ = false;
  return true;
}

void JointHandle::setEffortLaw(const EffortLaw& law)
{
  for (double v : {law.feedforward, law.stiffness, law.position_target, law.damping, law.velocity_target})
    if (!std::isfinite(v))
    {
      ++rejected_;
      return;
    }
  law_ = law;
  has_law_ = true;
}

}  // namespace bullet_plant
