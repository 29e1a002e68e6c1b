// physics::Joint (gazebo/physics/Joint.hh): a model's joint over the simulator's JointBridge, or a
// joint made at run time over its WorldBridge.
#include "gazebo/physics/Joint.hh"

#include <cmath>

#include "gazebo/common/Console.hh"
#include "gazebo/physics/Link.hh"
#include "gazebo/physics/Model.hh"
#include "gazebo/physics/PlantBridge.hh"

namespace gazebo
{
namespace physics
{
Joint::Joint(const std::string& name, std::unique_ptr<JointBridge> bridge, const std::string& model_name, LinkPtr parent,
             LinkPtr child)
  : name_(name), model_name_(model_name), bridge_(std::move(bridge)), parent_(std::move(parent)), child_(std::move(child))
{
  lower_ = bridge_->lowerLimit();
  upper_ = bridge_->upperLimit();
}

Joint::Joint(const std::string& type, ModelPtr model, std::shared_ptr<WorldBridge> world)
  : type_(type), world_(std::move(world)), model_(std::move(model))
{
}

Joint::~Joint()
{
  if (world_ && attachment_ >= 0)
    world_->detach(attachment_);
}

std::string Joint::GetName() const { return name_; }

std::string Joint::GetScopedName(bool prependWorldName) const
{
  const std::string model = model_ ? model_->GetScopedName(prependWorldName) : model_name_;
  return model.empty() ? name_ : model + "::" + name_;
}

void Joint::SetName(const std::string& name) { name_ = name; }

bool Joint::axisZero(unsigned int index, const char* call) const
{
  if (index == 0)
    return true;
  gzerr << "Joint::" << call << "(" << index << ") on joint [" << name_
        << "]: the joint has one axis, 0" << std::endl;
  return false;
}

bool Joint::modelJoint(const char* call) const
{
  if (bridge_)
    return true;
  gzerr << "Joint::" << call << " on joint [" << name_ << "], made at run time: it holds its links fixed "
        << "and has no position to read or drive" << std::endl;
  return false;
}

double Joint::Position(unsigned int index) const
{
  return axisZero(index, "Position") && modelJoint("Position") ? bridge_->position() : 0.0;
}

double Joint::GetVelocity(unsigned int index) const
{
  return axisZero(index, "GetVelocity") && modelJoint("GetVelocity") ? bridge_->velocity() : 0.0;
}

void Joint::SetVelocity(unsigned int index, double velocity)
{
  if (axisZero(index, "SetVelocity") && modelJoint("SetVelocity"))
    bridge_->setVelocity(velocity);
}

void Joint::SetForce(unsigned int index, double effort)
{
  if (axisZero(index, "SetForce") && modelJoint("SetForce"))
    bridge_->setForce(effort);
}

double Joint::GetForce(unsigned int index)
{
  return axisZero(index, "GetForce") && bridge_ ? bridge_->appliedForce() : 0.0;
}

bool Joint::SetPosition(unsigned int index, double position, bool /*preserveWorldVelocity*/)
{
  return axisZero(index, "SetPosition") && modelJoint("SetPosition") && bridge_->setPosition(position);
}

double Joint::LowerLimit(unsigned int index) const { return axisZero(index, "LowerLimit") ? lower_ : 0.0; }

double Joint::UpperLimit(unsigned int index) const { return axisZero(index, "UpperLimit") ? upper_ : 0.0; }

void Joint::SetLowerLimit(unsigned int index, double limit)
{
  if (!axisZero(index, "SetLowerLimit"))
    return;
  if (bridge_)
    gzwarn << "Joint::SetLowerLimit on joint [" << name_ << "]: the plant keeps the limits its model gives; "
           << "its lower limit stays " << lower_ << std::endl;
  else
    lower_ = limit;
}

void Joint::SetUpperLimit(unsigned int index, double limit)
{
  if (!axisZero(index, "SetUpperLimit"))
    return;
  if (bridge_)
    gzwarn << "Joint::SetUpperLimit on joint [" << name_ << "]: the plant keeps the limits its model gives; "
           << "its upper limit stays " << upper_ << std::endl;
  else
    upper_ = limit;
}

double Joint::GetEffortLimit(unsigned int index)
{
  if (!axisZero(index, "GetEffortLimit") || !bridge_)
    return -1.0;
  const double limit = bridge_->effortLimit();
  return std::isfinite(limit) ? limit : -1.0;
}

double Joint::GetVelocityLimit(unsigned int index)
{
  if (!axisZero(index, "GetVelocityLimit") || !bridge_)
    return -1.0;
  const double limit = bridge_->velocityLimit();
  return std::isfinite(limit) ? limit : -1.0;
}

namespace
{
// A number from what plugins pass SetParam: double, float, int, unsigned or bool, as Gazebo casts.
bool number(const boost::any& value, double& out)
{
  if (const double* d = boost::any_cast<double>(&value))
    out = *d;
  else if (const float* f = boost::any_cast<float>(&value))
    out = *f;
  else if (const int* i = boost::any_cast<int>(&value))
    out = *i;
  else if (const unsigned int* u = boost::any_cast<unsigned int>(&value))
    out = *u;
  else if (const bool* b = boost::any_cast<bool>(&value))
    out = *b ? 1.0 : 0.0;
  else
    return false;
  return true;
}
}  // namespace

bool Joint::SetParam(const std::string& key, unsigned int index, const boost::any& value)
{
  double v = 0.0;
  if (!axisZero(index, "SetParam"))
    return false;
  if (!number(value, v) || !std::isfinite(v))
  {
    gzerr << "Joint::SetParam(\"" << key << "\") on joint [" << name_ << "]: not a finite number" << std::endl;
    return false;
  }
  if ((key == "vel" || key == "fmax") && modelJoint("SetParam"))
  {
    const bool set = key == "vel" ? bridge_->setMotorVelocity(v) : bridge_->setMotorMaxForce(v);
    if (set)
      (key == "vel" ? motor_velocity_ : motor_max_force_) = v;
    return set;
  }
  gzwarn << "Joint::SetParam(\"" << key << "\") on joint [" << name_ << "]: not simulated by the plant "
         << "(\"vel\" and \"fmax\" are; the limits and friction are the model's)" << std::endl;
  return false;
}

double Joint::GetParam(const std::string& key, unsigned int index)
{
  if (!axisZero(index, "GetParam"))
    return 0.0;
  // drives ask for "fmax" every step (gazebo_ros_diff_drive): the cheapest test first
  if (key.size() == 4 && key == "fmax")
    return motor_max_force_;
  if (key.size() == 3 && key == "vel")
    return motor_velocity_;
  if (key == "hi_stop")
    return UpperLimit(0);
  if (key == "lo_stop")
    return LowerLimit(0);
  gzerr << "Joint::GetParam(\"" << key << "\") on joint [" << name_ << "]: not a parameter the plant keeps"
        << std::endl;
  return 0.0;
}

JointWrench Joint::GetForceTorque(unsigned int index)
{
  JointWrench wrench;
  if (!axisZero(index, "GetForceTorque") || !modelJoint("GetForceTorque"))
    return wrench;
  bridge_->childWrench(wrench.body2Force, wrench.body2Torque);
  if (parent_ && child_)
  {
    // The reaction on the parent, turned into the parent link's axes.
    const ignition::math::Quaterniond child_in_parent = parent_->WorldPose().Rot().Inverse() * child_->WorldPose().Rot();
    wrench.body1Force = -child_in_parent.RotateVector(wrench.body2Force);
    wrench.body1Torque = -child_in_parent.RotateVector(wrench.body2Torque);
  }
  return wrench;
}

void Joint::Load(LinkPtr parent, LinkPtr child, const ignition::math::Pose3d& /*pose*/)
{
  parent_ = std::move(parent);
  child_ = std::move(child);
}

void Joint::Init()
{
  if (!bridge_ && parent_ && child_)
    Attach(parent_, child_);
}

void Joint::Attach(LinkPtr parent, LinkPtr child)
{
  if (!world_)
  {
    gzerr << "Joint::Attach on joint [" << name_ << "] of a model: only a joint made by "
          << "PhysicsEngine::CreateJoint attaches" << std::endl;
    return;
  }
  if (!parent || !child)
  {
    gzerr << "Joint::Attach on joint [" << name_ << "]: both links are needed (a link to the world is not "
          << "supported by the plant)" << std::endl;
    return;
  }
  if (attachment_ >= 0 && parent == parent_ && child == child_)
    return;  // Init after Attach, as gazebo_ros_link_attacher does: already held
  Detach();
  parent_ = parent;
  child_ = child;
  if (type_ != "fixed" && !warned_type_ && !(lower_ == 0.0 && upper_ == 0.0))
  {
    gzwarn << "Joint [" << name_ << "] of type " << type_ << " made at run time: the plant holds its links "
           << "fixed to each other, as a " << type_ << " joint with both limits 0" << std::endl;
    warned_type_ = true;
  }
  const ModelPtr parent_model = parent->GetModel(), child_model = child->GetModel();
  if (!parent_model || !child_model)
  {
    gzerr << "Joint::Attach on joint [" << name_ << "]: link [" << (parent_model ? child : parent)->GetName()
          << "]'s model has left the world" << std::endl;
    return;
  }
  attachment_ = world_->attach(parent_model->GetName(), parent->GetName(), child_model->GetName(), child->GetName());
}

void Joint::Detach()
{
  if (world_ && attachment_ >= 0)
    world_->detach(attachment_);
  attachment_ = -1;
}

void Joint::SetModel(ModelPtr model) { model_ = std::move(model); }

ModelPtr Joint::GetModel() const { return model_; }

LinkPtr Joint::GetParent() const { return parent_; }

LinkPtr Joint::GetChild() const { return child_; }
}  // namespace physics
}  // namespace gazebo
