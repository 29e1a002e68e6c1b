// The plant side of gazebo_ros_control's joint layer (its DefaultRobotHWSim): the joint handles of
// one robot, writeSim (the handles' commands into the physics: limits, pid_gains loops, motors,
// e-stop, the joints' passive dynamics) before a step and readSim (the physics' state into the
// handles) after it.
#pragma once

#include <string>
#include <vector>

#include "bullet_plant/hardware_interface.h"
#include "bullet_plant/joint_layer.h"
#include "bullet_plant/log.h"
#include "physics/movable_joint.h"

class btMultiBody;

namespace bullet_plant
{
// The JointHandles controllers get: gazebo_ros_control registers the same handles with ros_control.
class JointLayer : public JointHandles
{
  // Says once per handle that its command exceeds `limit` (and is held to it).
  void sayBeyondLimit(size_t handle, double command, double limit, const char* what);

public:
  // A handle for a transmitted joint (joints[joint]); its pid_gains loop when gains are given.
  JointHandle& addHandle(const MovableJoint& joint, size_t joint_index, JointInterface iface);
  // Where a command beyond its joint's limits is said (once per joint).
  void setLog(const Log* log) { log_ = log; }
  bool drives(size_t joint_index) const;

  std::vector<JointHandle>& handles() override { return handles_; }
  JointHandle* handle(const std::string& joint) override;

  // gazebo_ros_control's e-stop: while on, efforts are 0, velocity commands 0 and position commands
  // the position the joint had when it came on.
  void setEStop(bool on);
  bool eStop() const { return e_stop_; }

  // `joints`: the robot's movable joints in URDF order, of the multibody `bullet`.
  void writeSim(std::vector<MovableJoint>& joints, btMultiBody& bullet, double dt);
  void readSim(const std::vector<MovableJoint>& joints, const btMultiBody& bullet, double dt);
  // A restored state invalidates what the pid_gains loops remember.
  void resetPids();

private:
  std::vector<JointHandle> handles_;   // transmission order
  std::vector<size_t> handle_joint_;   // handle i drives joints[handle_joint_[i]]
  std::vector<char> said_beyond_limit_;  // per handle
  const Log* log_ = nullptr;
  bool e_stop_ = false;
};

// The actuator's effort on a joint in the last step (what its handle and joint_states report).
double actuatorEffort(const MovableJoint& joint, double velocity, double dt);

}  // namespace bullet_plant
