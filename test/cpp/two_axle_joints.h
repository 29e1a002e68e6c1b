// Real joint handles behind the JointHandles interface, for the controller tests: the handles are
// the plant's own class; only the robot around them is left out (their state stays at rest).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "bullet_plant/hardware_interface.h"

namespace bullet_plant
{
// Joint handles in a list, as a robot's transmissions give them.
class JointList : public JointHandles
{
public:
  JointList& add(const std::string& name, JointType type, JointInterface iface, const JointLimits& limits)
  {
    joints_.emplace_back(name, type, iface, limits);
    return *this;
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

// The car's drive wheel and steering hinge limits.
inline JointLimits wheelLimits()
{
  JointLimits wheel;
  wheel.effort = 1.0;
  wheel.velocity = 125.0;
  return wheel;
}

inline JointLimits hingeLimits()
{
  JointLimits hinge = wheelLimits();
  hinge.has_position = true;
  hinge.lower = -0.6;
  hinge.upper = 0.6;
  hinge.velocity = 10.0;
  return hinge;
}

inline JointLimits mastLimits()
{
  JointLimits mast;
  mast.has_position = true;
  mast.upper = 0.5;
  mast.effort = 50.0;
  mast.velocity = 0.2;
  return mast;
}

// A robot's joints as the plant has them: two velocity wheels, two effort steering hinges and a
// position-controlled prismatic mast.
class TwoAxleJoints : public JointList
{
public:
  TwoAxleJoints()
  {
    add("left_wheel", JointType::Continuous, JointInterface::Velocity, wheelLimits());
    add("right_wheel", JointType::Continuous, JointInterface::Velocity, wheelLimits());
    add("left_hinge", JointType::Revolute, JointInterface::Effort, hingeLimits());
    add("right_hinge", JointType::Revolute, JointInterface::Effort, hingeLimits());
    add("mast", JointType::Prismatic, JointInterface::Position, mastLimits());
  }
};

}  // namespace bullet_plant
