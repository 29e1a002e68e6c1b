// Real joint handles behind the JointHandles interface, for the controller tests: the handles are
// the plant's own class; only the robot around them is left out (their state stays at rest).
#pragma once

#include <string>
#include <vector>

#include "bullet_plant/hardware_interface.h"

namespace bullet_plant
{
// A robot's joints as the plant has them: two velocity wheels, two effort steering hinges and a
// position-controlled prismatic mast.
class TwoAxleJoints : public JointHandles
{
public:
  TwoAxleJoints()
  {
    JointLimits wheel;
    wheel.effort = 1.0;
    wheel.velocity = 125.0;
    JointLimits hinge;
    hinge.has_position = true;
    hinge.lower = -0.6;
    hinge.upper = 0.6;
    hinge.effort = 1.0;
    hinge.velocity = 10.0;
    joints_.emplace_back("left_wheel", JointType::Continuous, JointInterface::Velocity, wheel);
    joints_.emplace_back("right_wheel", JointType::Continuous, JointInterface::Velocity, wheel);
    joints_.emplace_back("left_hinge", JointType::Revolute, JointInterface::Effort, hinge);
    joints_.emplace_back("right_hinge", JointType::Revolute, JointInterface::Effort, hinge);
    JointLimits mast;
    mast.has_position = true;
    mast.upper = 0.5;
    mast.effort = 50.0;
    mast.velocity = 0.2;
    joints_.emplace_back("mast", JointType::Prismatic, JointInterface::Position, mast);
  }
  JointHandle* handle(const std::string& joint) override
  {
    for (JointHandle& h : joints_)
      if (h.name() == joint)
        return &h;
    return nullptr;
  }
  std::vector<JointHandle>& handles() override { return joints_; }

private:
  std::vector<JointHandle> joints_;
};

}  // namespace bullet_plant
