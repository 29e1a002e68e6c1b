// physics::JointController (gazebo/physics/JointController.hh).
#include "gazebo/physics/JointController.hh"

#include "gazebo/common/Console.hh"
#include "gazebo/common/Events.hh"
#include "gazebo/physics/Joint.hh"
#include "gazebo/physics/Model.hh"
#include "gazebo/physics/World.hh"

namespace gazebo
{
namespace physics
{
JointController::JointController(ModelPtr model) : model_(model)
{
  for (const JointPtr& joint : model->GetJoints())
    AddJoint(joint);
  if (model->GetWorld())
    last_update_ = model->GetWorld()->SimTime();
  // Gazebo's world updates its models' controllers after the world update begin callbacks (where
  // plugins set their targets) and before the physics.
  update_ = event::Events::ConnectBeforePhysicsUpdate([this](const common::UpdateInfo&) { Update(); });
  reset_ = event::Events::ConnectWorldReset([this]() { Reset(); });  // the model's reset, as Gazebo's
}

JointController::~JointController() = default;

void JointController::AddJoint(JointPtr joint)
{
  joints_[joint->GetScopedName()] = joint;
}

bool JointController::known(const std::string& joint, const char* call) const
{
  if (joints_.count(joint))
    return true;
  gzerr << "JointController::" << call << ": no joint [" << joint << "] (the scoped name, MODEL::JOINT)"
        << std::endl;
  return false;
}

void JointController::Update()
{
  const ModelPtr model = model_.lock();
  if (!model || !model->GetWorld())
    return;
  const common::Time now = model->GetWorld()->SimTime();
  const common::Time dt = now - last_update_;
  last_update_ = now;
  for (const auto& force : forces_)
    joints_[force.first]->SetForce(0, force.second);
  forces_.clear();  // a force is for one update, as Gazebo's
  if (dt <= common::Time::Zero)
    return;
  for (auto& pid : position_pids_)
    if (positions_.count(pid.first))
    {
      const JointPtr& joint = joints_[pid.first];
      joint->SetForce(0, pid.second.Update(joint->Position(0) - positions_[pid.first], dt));
    }
  for (auto& pid : velocity_pids_)
    if (velocities_.count(pid.first))
    {
      const JointPtr& joint = joints_[pid.first];
      joint->SetForce(0, pid.second.Update(joint->GetVelocity(0) - velocities_[pid.first], dt));
    }
}

void JointController::Reset()
{
  for (auto& pid : position_pids_)
    pid.second.Reset();
  for (auto& pid : velocity_pids_)
    pid.second.Reset();
  positions_.clear();
  velocities_.clear();
  forces_.clear();
}

bool JointController::SetForce(const std::string& joint, double force)
{
  if (!known(joint, "SetForce"))
    return false;
  forces_[joint] = force;
  return true;
}

void JointController::SetPositionPID(const std::string& joint, const common::PID& pid)
{
  if (known(joint, "SetPositionPID"))
    position_pids_[joint] = pid;
}

bool JointController::SetPositionTarget(const std::string& joint, double target)
{
  if (!known(joint, "SetPositionTarget"))
    return false;
  positions_[joint] = target;
  return true;
}

void JointController::SetVelocityPID(const std::string& joint, const common::PID& pid)
{
  if (known(joint, "SetVelocityPID"))
    velocity_pids_[joint] = pid;
}

bool JointController::SetVelocityTarget(const std::string& joint, double target)
{
  if (!known(joint, "SetVelocityTarget"))
    return false;
  velocities_[joint] = target;
  return true;
}

void JointController::SetJointPosition(const std::string& name, double position, int index)
{
  auto joint = joints_.find(name);
  if (joint != joints_.end())
    SetJointPosition(joint->second, position, index);
  else
    gzwarn << "SetJointPosition [" << name << "] not found\n";
}

void JointController::SetJointPosition(JointPtr joint, double position, int index)
{
  if (joint && index >= 0)
    joint->SetPosition(static_cast<unsigned int>(index), position);
}

void JointController::SetJointPositions(const std::map<std::string, double>& positions)
{
  for (const auto& joint : joints_)
  {
    auto position = positions.find(joint.second->GetName());
    if (position == positions.end())
      position = positions.find(joint.second->GetScopedName());
    if (position != positions.end())
      SetJointPosition(joint.second, position->second);
  }
}

std::map<std::string, JointPtr> JointController::GetJoints() const { return joints_; }
std::map<std::string, double> JointController::GetForces() const { return forces_; }
std::map<std::string, double> JointController::GetPositions() const { return positions_; }
std::map<std::string, double> JointController::GetVelocities() const { return velocities_; }
std::map<std::string, common::PID> JointController::GetPositionPIDs() const { return position_pids_; }
std::map<std::string, common::PID> JointController::GetVelocityPIDs() const { return velocity_pids_; }
}  // namespace physics
}  // namespace gazebo
