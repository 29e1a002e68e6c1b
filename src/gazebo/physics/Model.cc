// physics::Model (gazebo/physics/Model.hh), over the simulator's ModelBridge.
#include "gazebo/physics/Model.hh"

#include "gazebo/common/Animation.hh"
#include "gazebo/common/Console.hh"
#include "gazebo/common/Events.hh"
#include "gazebo/common/KeyFrame.hh"
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
  AddType(MODEL);
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

bool Model::IsStatic() const { return bridge_->isStatic(); }

unsigned int Model::GetJointCount() const { return static_cast<unsigned int>(GetJoints().size()); }

JointControllerPtr Model::GetJointController()
{
  if (!joint_controller_)
    joint_controller_.reset(new JointController(shared_from_this()));
  return joint_controller_;
}
void Model::SetJointAnimation(const std::map<std::string, common::NumericAnimationPtr>& anims,
                              boost::function<void()> onComplete)
{
  for (const auto& anim : anims)
    if (anim.second)
      joint_animations_[anim.first] = anim.second;
  on_joint_animation_complete_ = onComplete;
  joint_animation_time_ = world_ ? world_->SimTime() : common::Time();
  if (!joint_animation_update_ && !joint_animations_.empty())
    // Gazebo's world moves its models' joint animations in the model's update, after the world update
    // begin callbacks and the model's joint controller, before the physics
    joint_animation_update_ = event::Events::ConnectBeforePhysicsUpdate(
        [this](const common::UpdateInfo& info) { UpdateJointAnimation(info); });
}

void Model::UpdateJointAnimation(const common::UpdateInfo& info)
{
  common::NumericKeyFrame frame(0);
  std::map<std::string, double> positions;
  for (auto anim = joint_animations_.begin(); anim != joint_animations_.end();)
  {
    anim->second->AddTime((info.simTime - joint_animation_time_).Double());
    if (anim->second->GetTime() < anim->second->GetLength())
    {
      anim->second->GetInterpolatedKeyFrame(frame);
      positions[anim->first] = frame.GetValue();
      ++anim;
    }
    else
      anim = joint_animations_.erase(anim);
  }
  joint_animation_time_ = info.simTime;
  if (!positions.empty())
  {
    GetJointController()->SetJointPositions(positions);
    return;
  }
  joint_animation_update_.reset();  // all ended: the model's updates stop moving its joints
  boost::function<void()> complete;
  complete.swap(on_joint_animation_complete_);
  if (complete)
    complete();
}

void Model::SetAnimation(const common::PoseAnimationPtr& anim) { SetAnimation(anim, NULL); }

void Model::SetAnimation(const common::PoseAnimationPtr& anim, boost::function<void()> onComplete)
{
  animation_start_ = WorldPose();
  animation_time_ = world_ ? world_->SimTime() : common::Time();
  animation_ = anim;
  on_animation_complete_ = onComplete;
  animation_update_.reset();
  if (animation_)
    animation_update_ = event::Events::ConnectWorldUpdateBegin(
        [this](const common::UpdateInfo& info) { UpdateAnimation(info); });
}

void Model::UpdateAnimation(const common::UpdateInfo& info)
{
  common::PoseKeyFrame frame(0);
  animation_->AddTime((info.simTime - animation_time_).Double());
  animation_->GetInterpolatedKeyFrame(frame);
  // the key frame's pose taken in the frame of the pose the model started from
  SetWorldPose(ignition::math::Pose3d(frame.Translation(), frame.Rotation()) + animation_start_);
  animation_time_ = info.simTime;
  if (animation_->GetTime() < animation_->GetLength())
    return;
  animation_update_.reset();
  animation_.reset();
  boost::function<void()> complete;
  complete.swap(on_animation_complete_);
  if (complete)
    complete();
}

void Model::StopAnimation()
{
  animation_update_.reset();
  animation_.reset();
  on_animation_complete_.clear();
  joint_animation_update_.reset();
  joint_animations_.clear();
  on_joint_animation_complete_.clear();
}
}  // namespace physics
}  // namespace gazebo
