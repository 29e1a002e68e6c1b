// A movable URDF joint's kind and limits, as the physics, the joint handles and the controllers
// all read them (the robot builder fills them from the URDF's <joint> and <limit>).
#pragma once

namespace bullet_plant
{
enum class JointType { Revolute, Continuous, Prismatic };

struct JointLimits
{
  bool has_position = false;   // revolute and prismatic with lower < upper
  double lower = 0.0, upper = 0.0;
  double effort = 0.0;         // N m or N; infinite when the URDF gives no <limit>
  double velocity = 0.0;       // rad/s or m/s; infinite when the URDF gives none
};

}  // namespace bullet_plant
