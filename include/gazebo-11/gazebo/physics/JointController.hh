// physics::JointController as Gazebo 11's model has one (Model::GetJointController): forces, and
// position and velocity PID loops, on the model's joints by their scoped names (MODEL::JOINT), applied
// before each step's physics as efforts (Joint::SetForce).
#pragma once

#include <map>
#include <string>

#include <boost/weak_ptr.hpp>

#include "gazebo/common/Event.hh"
#include "gazebo/common/PID.hh"
#include "gazebo/common/Time.hh"
#include "gazebo/physics/PhysicsTypes.hh"
#include "gazebo/util/system.hh"

namespace gazebo
{
namespace common
{
class UpdateInfo;
}
namespace physics
{
class GZ_PHYSICS_VISIBLE JointController
{
public:
  // The model's movable joints, added; its updates run while it lives.
  explicit JointController(ModelPtr model);
  virtual ~JointController();
  void AddJoint(JointPtr joint);
  // One update: each joint's force, then its position loop's and its velocity loop's commands, added
  // as efforts for the coming step (dt: the simulated time since the last update).
  void Update();
  // The loops start again and the targets go.
  void Reset();
  bool SetForce(const std::string& joint, double force);
  void SetPositionPID(const std::string& joint, const common::PID& pid);
  bool SetPositionTarget(const std::string& joint, double target);
  void SetVelocityPID(const std::string& joint, const common::PID& pid);
  bool SetVelocityTarget(const std::string& joint, double target);
  // The joint put at the position now (Joint::SetPosition), by its scoped name; a warning naming it
  // for a joint the controller lacks.
  void SetJointPosition(const std::string& name, double position, int index = 0);
  void SetJointPosition(JointPtr joint, double position, int index = 0);
  // Each of the controller's joints whose name or scoped name the map has, put there.
  void SetJointPositions(const std::map<std::string, double>& positions);
  std::map<std::string, JointPtr> GetJoints() const;
  std::map<std::string, double> GetForces() const;
  std::map<std::string, double> GetPositions() const;
  std::map<std::string, double> GetVelocities() const;
  std::map<std::string, common::PID> GetPositionPIDs() const;
  std::map<std::string, common::PID> GetVelocityPIDs() const;

private:
  bool known(const std::string& joint, const char* call) const;
  boost::weak_ptr<Model> model_;
  std::map<std::string, JointPtr> joints_;
  std::map<std::string, double> forces_, positions_, velocities_;
  std::map<std::string, common::PID> position_pids_, velocity_pids_;
  common::Time last_update_;
  event::ConnectionPtr update_, reset_;
};
}  // namespace physics
}  // namespace gazebo
