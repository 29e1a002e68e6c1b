// physics::Joint (gazebo/physics/Joint.hh): a model's joint over the simulator's JointBridge, or a
// joint made at run time over its WorldBridge.
#include "gazebo/physics/Joint.hh"

#include "gazebo/common/Console.hh"
#include "gazebo/physics/Link.hh"
#include "gazebo/physics/Model.hh"
#include "gazebo/physics/PlantBridge.hh"

namespace gazebo
{
namespace physics
{
Joint::Joint(const std::string& name, std::unique_ptr<JointBridge> bridge, const std::string& model_name)
  : name_(name), model_name_(model_name), bridge_(std::move(bridge))
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
