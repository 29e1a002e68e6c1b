// Joint wrench watching: Joint::GetForceTorque(0) as gazebo_ros_ft_sensor reads it
// (ModelPluginContext::watchJointWrench). Bullet's multibody has no joint reaction to read, so the
// wrench a joint transmitted is found from its child's subtree: momenta and added forces before
// the step, Newton and Euler after it. Its own unit because it brackets the physics step (the only
// work that does) and costs nothing for a robot that watches no joint.
#pragma once

#include <string>
#include <vector>

#include <btBulletDynamicsCommon.h>
#include "bullet_plant/robot_description.h"

#include "simulation/robot_multibody.h"

namespace bullet_plant
{
class JointWrenchWatches
{
public:
  // Watch a movable joint from now on (once; again is a no-op); false for a joint the robot lacks
  // or a fixed one.
  bool watch(const RobotMultibody& multibody, const RobotDescription& robot, const std::string& joint);
  // The last step's wrench of a watched joint as Gazebo's JointWrench body2 has it: what the child
  // passed to the joint (the joint's push on the child, negated), in the child link's frame, the
  // torque about its origin; zero for one not watched.
  void wrench(const std::string& joint, urdf::Vector3& force, urdf::Vector3& torque) const;
  bool empty() const { return watches_.empty(); }

  // Around the physics step: the watched joints' subtrees before it, their wrenches after it
  // (dt the step, gravity the world's, dispatcher the world's contacts of the step).
  void beforeStep(const RobotMultibody& multibody);
  void afterStep(const RobotMultibody& multibody, const std::string& robot, btScalar dt, const btVector3& gravity,
                 btDispatcher& dispatcher);

private:
  // A watched joint: the child's subtree, its momenta and added forces before the step, the wrench
  // after it.
  struct Watch
  {
    std::string joint, child_link;
    // whose axes the wrench is in: the child link's (below an SDF joint's frame link, the link it holds)
    std::string axes_link;
    std::vector<int> bodies;                  // the child's body and every body below it
    std::vector<btVector3> momentum, angular_momentum, force_added, torque_added;  // per body, before
    urdf::Vector3 force, torque;              // the last step's, in the child link frame
  };
  std::vector<Watch> watches_;
};

}  // namespace bullet_plant
