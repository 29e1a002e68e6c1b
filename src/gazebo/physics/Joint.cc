// physics::Joint (gazebo/physics/Joint.hh): a model's joint over the simulator's JointBridge, or a
// joint made at run time, which has one from its WorldBridge while attached.
#include "gazebo/physics/Joint.hh"

#include <cmath>
#include <limits>

#include "gazebo/common/Console.hh"
#include "gazebo/physics/Link.hh"
#include "gazebo/physics/Model.hh"
#include "gazebo/physics/PlantBridge.hh"
#include "gazebo/physics/World.hh"

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

Joint::~Joint() = default;

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

bool Joint::bridged(const char* call) const
{
  if (bridge_)
    return true;
  if (!said_unattached_)  // once: a plugin asks every step
    gzerr << "Joint::" << call << " on joint [" << name_ << "], made at run time: it is not attached (Init or "
          << "Attach attaches it); it answers 0 and takes nothing until it is" << std::endl;
  said_unattached_ = true;
  return false;
}

double Joint::Position(unsigned int index) const
{
  return axisZero(index, "Position") && bridged("Position") ? bridge_->position() : 0.0;
}

double Joint::GetVelocity(unsigned int index) const
{
  return axisZero(index, "GetVelocity") && bridged("GetVelocity") ? bridge_->velocity() : 0.0;
}

void Joint::SetVelocity(unsigned int index, double velocity)
{
  if (axisZero(index, "SetVelocity") && bridged("SetVelocity"))
    bridge_->setVelocity(velocity);
}

void Joint::SetForce(unsigned int index, double effort)
{
  if (axisZero(index, "SetForce") && bridged("SetForce"))
    bridge_->setForce(effort);
}

double Joint::GetForce(unsigned int index)
{
  return axisZero(index, "GetForce") && bridge_ ? bridge_->appliedForce() : 0.0;
}

bool Joint::SetPosition(unsigned int index, double position, bool /*preserveWorldVelocity*/)
{
  return axisZero(index, "SetPosition") && bridged("SetPosition") && bridge_->setPosition(position);
}

double Joint::LowerLimit(unsigned int index) const { return axisZero(index, "LowerLimit") ? lower_ : 0.0; }

double Joint::UpperLimit(unsigned int index) const { return axisZero(index, "UpperLimit") ? upper_ : 0.0; }

void Joint::SetLowerLimit(unsigned int index, double limit)
{
  if (!axisZero(index, "SetLowerLimit"))
    return;
  if (bridge_)
    gzwarn << "Joint::SetLowerLimit on joint [" << name_ << "]: the plant keeps the limits "
           << (world_ ? "it was attached with until it is attached again" : "its model gives") << "; its lower "
           << "limit stays " << lower_ << std::endl;
  else
    lower_ = limit;
}

void Joint::SetUpperLimit(unsigned int index, double limit)
{
  if (!axisZero(index, "SetUpperLimit"))
    return;
  if (bridge_)
    gzwarn << "Joint::SetUpperLimit on joint [" << name_ << "]: the plant keeps the limits "
           << (world_ ? "it was attached with until it is attached again" : "its model gives") << "; its upper "
           << "limit stays " << upper_ << std::endl;
  else
    upper_ = limit;
}

double Joint::GetEffortLimit(unsigned int index)
{
  if (!axisZero(index, "GetEffortLimit"))
    return -1.0;
  const double limit = bridge_ ? bridge_->effortLimit() : effort_limit_;
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
  if ((key == "vel" || key == "fmax") && bridged("SetParam"))
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
  if (!axisZero(index, "GetForceTorque") || !bridged("GetForceTorque"))
    return wrench;
  bridge_->childWrench(wrench.body2Force, wrench.body2Torque);
  if (child_)
  {
    // The joint's push on the child, turned into the parent link's axes (the world's for a joint
    // to the world).
    const ignition::math::Quaterniond parent_rotation = parent_ ? parent_->WorldPose().Rot() : ignition::math::Quaterniond::Identity;
    const ignition::math::Quaterniond child_in_parent = parent_rotation.Inverse() * child_->WorldPose().Rot();
    wrench.body1Force = -child_in_parent.RotateVector(wrench.body2Force);
    wrench.body1Torque = -child_in_parent.RotateVector(wrench.body2Torque);
  }
  return wrench;
}

void Joint::SetProvideFeedback(bool enable)
{
  if (!enable || !bridged("SetProvideFeedback"))
    return;
  ignition::math::Vector3d force, torque;
  bridge_->childWrench(force, torque);  // the first call starts the watch
}

ignition::math::Pose3d Joint::InitialAnchorPose() const
{
  // a joint made at run time keeps the anchor it was loaded with
  return world_ || !bridge_ ? pose_ : bridge_->anchorPose();
}

void Joint::Load(LinkPtr parent, LinkPtr child, const ignition::math::Pose3d& pose)
{
  parent_ = std::move(parent);
  child_ = std::move(child);
  pose_ = pose;
}

LinkPtr Joint::linkNamed(const std::string& name) const
{
  const size_t scope = name.rfind("::");
  ModelPtr model = model_;
  if (scope != std::string::npos && model_ && model_->GetWorld())
    model = model_->GetWorld()->ModelByName(name.substr(0, scope));
  LinkPtr link = model ? model->GetLink(scope == std::string::npos ? name : name.substr(scope + 2)) : LinkPtr();
  if (!link)
    gzerr << "Joint [" << name_ << "]: no link [" << name << "]"
          << (model_ ? "" : " (the joint has no model: SetModel first)") << std::endl;
  return link;
}

namespace
{
// An SDF value of `element`'s child `name`, or `otherwise` (joint.sdf's default) where it has none.
template <class T>
T childValue(const sdf::ElementPtr& element, const std::string& name, const T& otherwise)
{
  return element && element->HasElement(name) ? element->Get<T>(name) : otherwise;
}
}  // namespace

void Joint::Load(sdf::ElementPtr sdf)
{
  if (!sdf)
  {
    gzerr << "Joint::Load on joint [" << name_ << "]: no <joint> element" << std::endl;
    return;
  }
  // What plugins hand over is their <plugin>'s copy of a <joint>, unchecked against joint.sdf: each
  // value is read where it is given, with joint.sdf's default where not.
  if (sdf->HasAttribute("name"))
    name_ = sdf->Get<std::string>("name");
  // The type is CreateJoint's, as Gazebo's joint classes are.
  if (sdf->HasAttribute("type") && sdf->Get<std::string>("type") != type_)
    gzwarn << "Joint::Load on joint [" << name_ << "]: made as a " << type_ << " joint, it stays one (its "
           << "<joint type> says " << sdf->Get<std::string>("type") << ")" << std::endl;
  pose_ = childValue(sdf, "pose", ignition::math::Pose3d::Zero);
  const std::string parent = childValue<std::string>(sdf, "parent", "world");
  parent_ = parent == "world" ? LinkPtr() : linkNamed(parent);
  child_ = linkNamed(childValue<std::string>(sdf, "child", ""));
  const sdf::ElementPtr axis = sdf->HasElement("axis") ? sdf->GetElement("axis") : sdf::ElementPtr();
  if (!axis)
    return;
  axis_ = childValue(axis, "xyz", ignition::math::Vector3d::UnitZ);
  // SDF 1.6: use_parent_model_frame; 1.7 on: <xyz expressed_in="__model__">.
  const sdf::ElementPtr xyz = axis->HasElement("xyz") ? axis->GetElement("xyz") : sdf::ElementPtr();
  axis_in_model_frame_ = childValue(axis, "use_parent_model_frame", false) ||
                         (xyz && xyz->HasAttribute("expressed_in") && xyz->Get<std::string>("expressed_in") == "__model__");
  const sdf::ElementPtr limit = axis->HasElement("limit") ? axis->GetElement("limit") : sdf::ElementPtr();
  // joint.sdf's defaults, -1e16 and 1e16 and an effort of -1, are none.
  const double lower = childValue(limit, "lower", -1e16), upper = childValue(limit, "upper", 1e16);
  lower_ = lower <= -1e16 ? -std::numeric_limits<double>::infinity() : lower;
  upper_ = upper >= 1e16 ? std::numeric_limits<double>::infinity() : upper;
  const double effort = childValue(limit, "effort", -1.0);
  effort_limit_ = effort < 0 ? std::numeric_limits<double>::infinity() : effort;
  damping_ = childValue(axis->HasElement("dynamics") ? axis->GetElement("dynamics") : sdf::ElementPtr(), "damping", 0.0);
}

void Joint::Init()
{
  if (!bridge_ && child_)
    Attach(parent_, child_);
}

void Joint::SetAxis(unsigned int index, const ignition::math::Vector3d& axis)
{
  if (!axisZero(index, "SetAxis"))
    return;
  if (bridge_)
    gzwarn << "Joint::SetAxis on joint [" << name_ << "]: the plant keeps the axis "
           << (world_ ? "it was attached with until it is attached again" : "its model gives") << std::endl;
  else
    axis_ = axis;
}

ignition::math::Vector3d Joint::LocalAxis(unsigned int index) const
{
  if (!axisZero(index, "LocalAxis"))
    return ignition::math::Vector3d::Zero;
  return world_ || !bridge_ ? axis_ : bridge_->localAxis();
}

ignition::math::Vector3d Joint::GlobalAxis(unsigned int index) const
{
  if (!axisZero(index, "GlobalAxis"))
    return ignition::math::Vector3d::Zero;
  if (bridge_)
    return bridge_->globalAxis();
  if (!child_)
  {
    gzerr << "Joint::GlobalAxis on joint [" << name_ << "]: no child link yet (Load names it)" << std::endl;
    return ignition::math::Vector3d::Zero;
  }
  // Not attached yet: the joint's frame turns with the child link; the model's frame with the model.
  const ignition::math::Quaterniond frame = axis_in_model_frame_ && model_ ? model_->WorldPose().Rot()
                                                                           : child_->WorldPose().Rot() * pose_.Rot();
  return frame.RotateVector(axis_).Normalized();
}

void Joint::Attach(LinkPtr parent, LinkPtr child)
{
  if (!world_)
  {
    gzerr << "Joint::Attach on joint [" << name_ << "] of a model: only a joint made by "
          << "PhysicsEngine::CreateJoint attaches" << std::endl;
    return;
  }
  if (!child)
  {
    gzerr << "Joint::Attach on joint [" << name_ << "]: no child link; nothing is attached" << std::endl;
    return;
  }
  if (bridge_ && parent == parent_ && child == child_)
    return;  // Init after Attach, as gazebo_ros_link_attacher does: already held
  Detach();
  parent_ = parent;
  child_ = child;
  const ModelPtr parent_model = parent ? parent->GetModel() : ModelPtr(), child_model = child->GetModel();
  if ((parent && !parent_model) || !child_model)
  {
    gzerr << "Joint::Attach on joint [" << name_ << "]: link [" << (child_model ? parent : child)->GetName()
          << "]'s model has left the world" << std::endl;
    return;
  }
  RunTimeJointSpec spec;
  spec.name = name_;
  spec.type = type_;
  if (parent)
  {
    spec.parent_model = parent_model->GetName();
    spec.parent_link = parent->GetName();
  }
  spec.child_model = child_model->GetName();
  spec.child_link = child->GetName();
  const ignition::math::Pose3d child_pose = child->WorldPose();
  spec.anchor = child_pose.Pos() + child_pose.Rot().RotateVector(pose_.Pos());
  spec.axis = GlobalAxis(0);
  spec.lower = lower_;
  spec.upper = upper_;
  spec.damping = damping_;
  spec.effort_limit = effort_limit_;
  bridge_ = world_->attach(spec);
}

void Joint::Detach()
{
  if (world_)
    bridge_.reset();
}

void Joint::SetModel(ModelPtr model) { model_ = std::move(model); }

ModelPtr Joint::GetModel() const { return model_; }

LinkPtr Joint::GetParent() const { return parent_; }

LinkPtr Joint::GetChild() const { return child_; }
}  // namespace physics
}  // namespace gazebo
