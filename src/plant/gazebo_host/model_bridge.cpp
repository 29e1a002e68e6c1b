#include "gazebo_host/model_bridge.h"

#include <cmath>
#include <limits>

#include <gazebo/common/Console.hh>

#include "bullet_plant/log.h"

namespace bullet_plant
{
namespace
{
ignition::math::Vector3d toIgnition(const urdf::Vector3& v) { return {v.x, v.y, v.z}; }

urdf::Vector3 toUrdf(const ignition::math::Vector3d& v) { return urdf::Vector3(v.X(), v.Y(), v.Z()); }

bool finite(const ignition::math::Vector3d& v) { return std::isfinite(v.X()) && std::isfinite(v.Y()) && std::isfinite(v.Z()); }

class ContextJoint final : public gazebo::physics::JointBridge
{
public:
  ContextJoint(std::shared_ptr<ModelReach> reach, std::string name) : reach_(std::move(reach)), name_(std::move(name)) {}

  double position() const override
  {
    double position = 0.0, velocity = 0.0;
    if (reach_->context)
      reach_->context->jointState(name_, position, velocity);
    return position;
  }
  double velocity() const override
  {
    double position = 0.0, velocity = 0.0;
    if (reach_->context)
      reach_->context->jointState(name_, position, velocity);
    return velocity;
  }
  bool setVelocity(double velocity) override
  {
    ModelJoint* joint = driven();
    if (joint)
      joint->setPosition(joint->position(), velocity);  // Gazebo's SetVelocity: the rate now, no motor
    return joint != nullptr;
  }
  bool setForce(double effort) override
  {
    ModelJoint* joint = driven();
    if (joint)
      joint->setForce(effort);
    return joint != nullptr;
  }
  double appliedForce() const override
  {
    // a joint no SetForce (or motor) has reached yet had none: asking is not driving it
    return reach_->context && joint_ ? joint_->appliedForce() : 0.0;
  }
  bool setPosition(double position) override
  {
    ModelJoint* joint = driven();
    if (joint)
      joint->setPosition(position, 0.0);
    return joint != nullptr;
  }
  double lowerLimit() const override { return limit(false); }
  double upperLimit() const override { return limit(true); }
  double effortLimit() const override
  {
    const auto joint = urdfJoint();
    return joint && joint->limits && joint->limits->effort > 0 ? joint->limits->effort
                                                               : std::numeric_limits<double>::infinity();
  }
  double velocityLimit() const override
  {
    const auto joint = urdfJoint();
    return joint && joint->limits && joint->limits->velocity > 0 ? joint->limits->velocity
                                                                 : std::numeric_limits<double>::infinity();
  }
  std::string parentLink() const override
  {
    const auto joint = urdfJoint();
    return joint ? joint->parent_link_name : "";
  }
  ignition::math::Vector3d localAxis() const override
  {
    const auto joint = urdfJoint();
    return joint ? ignition::math::Vector3d(joint->axis.x, joint->axis.y, joint->axis.z) : ignition::math::Vector3d::Zero;
  }
  ignition::math::Vector3d globalAxis() const override
  {
    // URDF's joint frame is the child link's frame: the axis turns with the child.
    const auto joint = urdfJoint();
    if (!joint || !reach_->context)
      return ignition::math::Vector3d::Zero;
    const urdf::Rotation child = reach_->context->linkMotion(joint->child_link_name).pose.rotation;
    const urdf::Vector3 axis = child * joint->axis;
    return ignition::math::Vector3d(axis.x, axis.y, axis.z);
  }
  std::string childLink() const override
  {
    const auto joint = urdfJoint();
    return joint ? joint->child_link_name : "";
  }
  bool setMotorVelocity(double velocity) override
  {
    ModelJoint* joint = driven();
    if (joint)
      joint->setVelocity(velocity);
    return joint != nullptr;
  }
  bool setMotorMaxForce(double force) override
  {
    ModelJoint* joint = driven();
    if (joint)
      joint->setMaxForce(force);
    return joint != nullptr;
  }
  void childWrench(ignition::math::Vector3d& force, ignition::math::Vector3d& torque) override
  {
    force = torque = ignition::math::Vector3d::Zero;
    if (!reach_->context)
      return;
    if (!watched_)
      watched_ = reach_->context->watchJointWrench(name_);
    urdf::Vector3 f, t;
    reach_->context->jointWrench(name_, f, t);
    force = toIgnition(f);
    torque = toIgnition(t);
  }

private:
  // The joint taken for driving at the first call that drives it (the context says once why it
  // cannot be: a transmission drives it); null once the model left the world.
  ModelJoint* driven()
  {
    if (!reach_->context)
      return nullptr;
    if (!asked_)
    {
      joint_ = reach_->context->modelJoint(name_, reach_->label);
      asked_ = true;
    }
    return joint_;
  }
  urdf::JointConstSharedPtr urdfJoint() const
  {
    return reach_->context ? reach_->context->robotDescription().model->getJoint(name_) : nullptr;
  }
  double limit(bool upper) const
  {
    const double none = upper ? std::numeric_limits<double>::infinity() : -std::numeric_limits<double>::infinity();
    const auto joint = urdfJoint();
    if (!joint || !joint->limits || joint->type == urdf::Joint::CONTINUOUS)
      return none;
    return upper ? joint->limits->upper : joint->limits->lower;
  }

  std::shared_ptr<ModelReach> reach_;
  std::string name_;
  ModelJoint* joint_ = nullptr;
  bool asked_ = false;
  bool watched_ = false;
};
}  // namespace

ContextModel::ContextModel(ModelPluginContext& context)
  : reach_(std::make_shared<ModelReach>(ModelReach{&context, "model '" + context.modelName() + "'"})),
    name_(context.modelName())
{
}

ModelPluginContext* ContextModel::reach(const char* call) const
{
  if (!reach_->context && !said_gone_)
  {
    said_gone_ = true;  // on Gazebo's console: the model's own log left with it
    gzerr << "Model [" << name_ << "]: " << call << " after the model was deleted; it does nothing" << std::endl;
  }
  return reach_->context;
}

std::string ContextModel::canonicalLink() const
{
  ModelPluginContext* context = reach("GetLink");
  return context ? context->rootLink() : "";
}

std::vector<std::string> ContextModel::linkNames() const
{
  std::vector<std::string> names;
  if (ModelPluginContext* context = reach("GetLinks"))
    for (const auto& link : context->robotDescription().model->links_)
      if (!context->robotDescription().frame_links.count(link.first))
        names.push_back(link.first);
  return names;
}

std::vector<std::string> ContextModel::jointNames() const
{
  std::vector<std::string> names;
  double position, velocity;
  if (ModelPluginContext* context = reach("GetJoints"))
    for (const auto& joint : context->robotDescription().model->joints_)
      if (context->jointState(joint.first, position, velocity))
        names.push_back(joint.first);
  return names;
}

ignition::math::Pose3d ContextModel::linkPose(const std::string& link) const
{
  ModelPluginContext* context = reach("WorldPose");
  if (!context)
    return ignition::math::Pose3d::Zero;
  const urdf::Pose pose = context->linkMotion(link).pose;
  return {pose.position.x, pose.position.y, pose.position.z, pose.rotation.w, pose.rotation.x, pose.rotation.y,
          pose.rotation.z};
}

ignition::math::Vector3d ContextModel::linkLinearVel(const std::string& link) const
{
  ModelPluginContext* context = reach("WorldLinearVel");
  return context ? toIgnition(context->linkMotion(link).velocity) : ignition::math::Vector3d::Zero;
}

ignition::math::Vector3d ContextModel::linkAngularVel(const std::string& link) const
{
  ModelPluginContext* context = reach("WorldAngularVel");
  return context ? toIgnition(context->linkMotion(link).angular_velocity) : ignition::math::Vector3d::Zero;
}

void ContextModel::setVelocity(const ignition::math::Vector3d& linear, const ignition::math::Vector3d& angular)
{
  ModelPluginContext* context = reach("SetLinearVel");
  if (!context)
    return;
  if (finite(linear) && finite(angular))
    context->setModelVelocity(toUrdf(linear), toUrdf(angular));
  else
    context->log().warn(reach_->label + ": a non-finite model velocity is ignored");
}

void ContextModel::addLinkWrench(const std::string& link, const ignition::math::Vector3d& force,
                                 const ignition::math::Vector3d& torque)
{
  ModelPluginContext* context = reach("AddForce");
  if (!context)
    return;
  if (finite(force) && finite(torque))
    context->addLinkWrench(link, toUrdf(force), toUrdf(torque));
  else
    context->log().warn(reach_->label + ": a non-finite force or torque on link '" + link + "' is ignored");
}

void ContextModel::addedLinkWrench(const std::string& link, ignition::math::Vector3d& force,
                                   ignition::math::Vector3d& torque) const
{
  urdf::Vector3 f, t;
  if (ModelPluginContext* context = reach("WorldForce"))
    context->addedLinkWrench(link, f, t);
  force = toIgnition(f);
  torque = toIgnition(t);
}

ignition::math::Vector3d ContextModel::bodyCentreOfMass(const std::string& link) const
{
  ModelPluginContext* context = reach("WorldCoGPose");
  return context ? toIgnition(context->bodyCentreOfMass(link)) : ignition::math::Vector3d::Zero;
}

gazebo::physics::LinkInertia ContextModel::linkInertia(const std::string& link) const
{
  gazebo::physics::LinkInertia inertia;
  ModelPluginContext* context = reach("GetInertial");
  if (!context)
    return inertia;
  const urdf::LinkConstSharedPtr l = context->robotDescription().model->getLink(link);
  if (!l || !l->inertial)
    return inertia;
  const urdf::Inertial& i = *l->inertial;
  inertia.mass = i.mass;
  inertia.pose = {i.origin.position.x, i.origin.position.y, i.origin.position.z, i.origin.rotation.w,
                  i.origin.rotation.x, i.origin.rotation.y, i.origin.rotation.z};
  inertia.ixx = i.ixx;
  inertia.iyy = i.iyy;
  inertia.izz = i.izz;
  inertia.ixy = i.ixy;
  inertia.ixz = i.ixz;
  inertia.iyz = i.iyz;
  return inertia;
}

bool ContextModel::linkGravity(const std::string& link) const
{
  ModelPluginContext* context = reach("GetGravityMode");
  if (!context)
    return true;
  const auto& physics = context->robotDescription().link_physics;
  auto found = physics.find(link);
  return found == physics.end() || found->second.gravity;
}

std::vector<std::string> ContextModel::linkJoints(const std::string& link, bool parent_side) const
{
  std::vector<std::string> names;
  double position, velocity;
  if (ModelPluginContext* context = reach(parent_side ? "GetParentJoints" : "GetChildJoints"))
    for (const auto& joint : context->robotDescription().model->joints_)
      if ((parent_side ? joint.second->child_link_name : joint.second->parent_link_name) == link &&
          context->jointState(joint.first, position, velocity))
        names.push_back(joint.first);
  return names;
}

void ContextModel::setLinkWorldPose(const std::string& link, const ignition::math::Pose3d& pose)
{
  ModelPluginContext* context = reach("SetWorldPose");
  if (!context)
    return;
  const ignition::math::Quaterniond& q = pose.Rot();
  if (!finite(pose.Pos()) || !std::isfinite(q.W() + q.X() + q.Y() + q.Z()))
  {
    context->log().warn(reach_->label + ": a non-finite pose is ignored");
    return;
  }
  urdf::Pose p;
  p.position = toUrdf(pose.Pos());
  p.rotation = urdf::Rotation(q.X(), q.Y(), q.Z(), q.W());
  context->setLinkWorldPose(link, p);
}

std::unique_ptr<gazebo::physics::JointBridge> ContextModel::joint(const std::string& name)
{
  double position, velocity;
  ModelPluginContext* context = reach("GetJoint");
  if (!context || !context->jointState(name, position, velocity))
    return nullptr;
  return std::make_unique<ContextJoint>(reach_, name);
}
}  // namespace bullet_plant
