// physics::Link (gazebo/physics/Link.hh), over its model's ModelBridge.
#include "gazebo/physics/Link.hh"

#include "gazebo/physics/Model.hh"
#include "gazebo/physics/PlantBridge.hh"

namespace gazebo
{
namespace physics
{
Link::Link(const std::string& name, std::shared_ptr<ModelBridge> bridge) : name_(name), bridge_(std::move(bridge)) {}

std::string Link::GetName() const { return name_; }

std::string Link::GetScopedName(bool prependWorldName) const
{
  const ModelPtr model = model_.lock();
  return (model ? model->GetScopedName(prependWorldName) : bridge_->name()) + "::" + name_;
}

ModelPtr Link::GetModel() const { return model_.lock(); }

ignition::math::Pose3d Link::WorldPose() const { return bridge_->linkPose(name_); }

ignition::math::Vector3d Link::WorldLinearVel() const { return bridge_->linkLinearVel(name_); }

ignition::math::Vector3d Link::WorldAngularVel() const { return bridge_->linkAngularVel(name_); }

ignition::math::Vector3d Link::RelativeLinearVel() const { return WorldPose().Rot().RotateVectorReverse(WorldLinearVel()); }

ignition::math::Vector3d Link::RelativeAngularVel() const
{
  return WorldPose().Rot().RotateVectorReverse(WorldAngularVel());
}

void Link::AddForce(const ignition::math::Vector3d& force) { bridge_->addLinkWrench(name_, force, ignition::math::Vector3d::Zero); }

void Link::AddTorque(const ignition::math::Vector3d& torque) { bridge_->addLinkWrench(name_, ignition::math::Vector3d::Zero, torque); }

void Link::AddRelativeForce(const ignition::math::Vector3d& force) { AddForce(WorldPose().Rot().RotateVector(force)); }

void Link::AddRelativeTorque(const ignition::math::Vector3d& torque) { AddTorque(WorldPose().Rot().RotateVector(torque)); }
}  // namespace physics
}  // namespace gazebo
