// physics::Model (gazebo/physics/Model.hh), over the simulator's ModelBridge.
#include "gazebo/physics/Model.hh"

#include "gazebo/common/Console.hh"
#include "gazebo/physics/Joint.hh"
#include "gazebo/physics/JointController.hh"
#include "gazebo/physics/Link.hh"
#include "gazebo/physics/PlantBridge.hh"
#include "gazebo/physics/World.hh"

namespace gazebo
{
namespace physics
{
Model::Model(std::shared_ptr<ModelBridge> bridge, WorldPtr world) : bridge_(std::move(bridge)), world_(std::move(world))
{
  const std::string canonical = bridge_->canonicalLink();
  links_.push_back(LinkPtr(new Link(canonical, bridge_)));  // the canonical link first, as Gazebo's
  for (const std::string& link : bridge_->linkNames())
    if (link != canonical)
      links_.push_back(LinkPtr(new Link(link, bridge_)));
}

void Model::adoptLinks()
{
  for (const LinkPtr& link : links_)
    link->model_ = shared_from_this();
}

std::string Model::GetName() const { return bridge_->name(); }

std::string Model::GetScopedName(bool prependWorldName) const
{
  return prependWorldName && world_ ? world_->Name() + "::" + GetName() : GetName();
}

WorldPtr Model::GetWorld() const { return world_; }

ignition::math::Pose3d Model::WorldPose() const { return links_.front()->WorldPose(); }

ignition::math::Vector3d Model::WorldLinearVel() const { return links_.front()->WorldLinearVel(); }

ignition::math::Vector3d Model::WorldAngularVel() const { return links_.front()->WorldAngularVel(); }

ignition::math::Vector3d Model::RelativeLinearVel() const { return links_.front()->RelativeLinearVel(); }

ignition::math::Vector3d Model::RelativeAngularVel() const { return links_.front()->RelativeAngularVel(); }

void Model::SetLinearVel(const ignition::math::Vector3d& velocity) { bridge_->setVelocity(velocity, WorldAngularVel()); }

void Model::SetAngularVel(const ignition::math::Vector3d& velocity) { bridge_->setVelocity(WorldLinearVel(), velocity); }

LinkPtr Model::GetLink(const std::string& name) const
{
  if (name == "canonical")
    return links_.front();
  const std::string prefix = GetName() + "::";
  const std::string bare = name.compare(0, prefix.size(), prefix) == 0 ? name.substr(prefix.size()) : name;
  for (const LinkPtr& link : links_)
    if (link->GetName() == bare)
      return link;
  return LinkPtr();
}

LinkPtr Model::GetChildLink(const std::string& name) const { return GetLink(name); }

const Link_V& Model::GetLinks() const { return links_; }

JointPtr Model::GetJoint(const std::string& name)
{
  const std::string prefix = GetName() + "::";
  const std::string bare = name.compare(0, prefix.size(), prefix) == 0 ? name.substr(prefix.size()) : name;
  auto known = joints_by_name_.find(bare);
  if (known != joints_by_name_.end())
    return known->second;
  std::unique_ptr<JointBridge> bridge = bridge_->joint(bare);
  if (!bridge)
  {
    gzerr << "Model [" << GetName() << "] has no movable joint [" << name << "]" << std::endl;
    return JointPtr();
  }
  const std::string parent = bridge->parentLink(), child = bridge->childLink();
  JointPtr joint(new Joint(bare, std::move(bridge), GetName(), GetLink(parent), GetLink(child)));
  joints_by_name_[bare] = joint;
  return joint;
}

const Joint_V& Model::GetJoints() const
{
  joints_.clear();
  for (const std::string& name : bridge_->jointNames())
  {
    JointPtr joint = const_cast<Model*>(this)->GetJoint(name);
    if (joint)
      joints_.push_back(joint);
  }
  return joints_;
}
void Model::SetWorldPose(const ignition::math::Pose3d& pose, bool /*notify*/, bool /*publish*/)
{
  bridge_->setLinkWorldPose(bridge_->canonicalLink(), pose);
}

void Model::SetLinkWorldPose(const ignition::math::Pose3d& pose, std::string link)
{
  const LinkPtr found = GetLink(link);
  if (!found)
  {
    gzerr << "Model::SetLinkWorldPose: model [" << GetName() << "] has no link [" << link << "]" << std::endl;
    return;
  }
  SetLinkWorldPose(pose, found);
}

void Model::SetLinkWorldPose(const ignition::math::Pose3d& pose, const LinkPtr& link)
{
  if (link)
    bridge_->setLinkWorldPose(link->GetName(), pose);
}

bool Model::IsStatic() const { return false; }

unsigned int Model::GetJointCount() const { return static_cast<unsigned int>(GetJoints().size()); }

JointControllerPtr Model::GetJointController()
{
  if (!joint_controller_)
    joint_controller_.reset(new JointController(shared_from_this()));
  return joint_controller_;
}
}  // namespace physics
}  // namespace gazebo
