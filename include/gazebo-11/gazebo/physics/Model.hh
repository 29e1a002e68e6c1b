// physics::Model as a model plugin reads and moves it: its name, world, pose and velocities (its
// canonical link's), its links and joints by name.
#pragma once

#include <map>
#include <memory>
#include <string>

#include <boost/enable_shared_from_this.hpp>
#include <boost/function.hpp>
#include <ignition/math/Pose3.hh>
#include <ignition/math/Vector3.hh>

#include "gazebo/common/CommonTypes.hh"
#include "gazebo/common/Event.hh"
#include "gazebo/common/Time.hh"
#include "gazebo/common/UpdateInfo.hh"
#include "gazebo/physics/Entity.hh"
#include "gazebo/physics/PhysicsTypes.hh"
#include "gazebo/util/system.hh"

namespace gazebo
{
namespace physics
{
class ModelBridge;

class GZ_PHYSICS_VISIBLE Model : public Entity, public boost::enable_shared_from_this<Model>
{
public:
  Model(std::shared_ptr<ModelBridge> bridge, WorldPtr world);
  std::string GetName() const override;
  std::string GetScopedName(bool prependWorldName = false) const override;
  WorldPtr GetWorld() const;
  ignition::math::Pose3d WorldPose() const override;
  ignition::math::Pose3d RelativePose() const override { return WorldPose(); }
  ignition::math::Vector3d WorldLinearVel() const override;
  ignition::math::Vector3d WorldAngularVel() const override;
  ignition::math::Vector3d RelativeLinearVel() const;
  ignition::math::Vector3d RelativeAngularVel() const;
  // The canonical link moves with this velocity from now on, its angular velocity kept (and the
  // other way about for SetAngularVel).
  void SetLinearVel(const ignition::math::Vector3d& velocity);
  void SetAngularVel(const ignition::math::Vector3d& velocity);
  // "canonical" (the default) is the canonical link; null for a link the model lacks.
  LinkPtr GetLink(const std::string& name = "canonical") const;
  LinkPtr GetChildLink(const std::string& name) const;
  const Link_V& GetLinks() const;
  // By its name or its scoped name (MODEL::JOINT); null, with one error naming it, for a joint the
  // model lacks or a fixed one.
  JointPtr GetJoint(const std::string& name);
  const Joint_V& GetJoints() const;
  unsigned int GetJointCount() const;
  // The model moved so that its canonical link is at `pose` (world), its joints as they are, at
  // rest (a static or kinematic model too); nothing for a model a joint holds to the world.
  void SetWorldPose(const ignition::math::Pose3d& pose, bool notify = true, bool publish = true);
  // The model moved so that the link (by name or handle) is at `pose` (world), as SetWorldPose.
  void SetLinkWorldPose(const ignition::math::Pose3d& pose, std::string link);
  void SetLinkWorldPose(const ignition::math::Pose3d& pose, const LinkPtr& link);
  // Its <static>: a static model with a plugin is a Model that forces and contacts never move but
  // SetWorldPose (and SetAnimation) does, as Gazebo's; a static model without one is scenery, which
  // World::ModelByName does not find.
  bool IsStatic() const;
  // The model's joint controller, made at the first call (its joints by scoped name).
  JointControllerPtr GetJointController();
  // Each joint named (by name or scoped name) put where its animation says, each step before the
  // physics, its animation's time moving on with the simulated time; an animation that does not loop
  // ends at its length, and `onComplete` runs once all have ended. Replaces the animations of the
  // joints it names.
  void SetJointAnimation(const std::map<std::string, common::NumericAnimationPtr>& anims,
                         boost::function<void()> onComplete = NULL);
  // The model moved each step (SetWorldPose) to the animation's pose taken from where the model is
  // now; `onComplete` runs when it reaches its length.
  void SetAnimation(const common::PoseAnimationPtr& anim);
  void SetAnimation(const common::PoseAnimationPtr& anim, boost::function<void()> onComplete);
  // The pose and joint animations stop where they are, their completions not called.
  void StopAnimation();

private:
  friend class World;  // which keeps one Model for each of the simulator's models
  // Its links' GetModel from now on (once a shared_ptr holds it: World::ModelByName).
  void adoptLinks();
  std::shared_ptr<ModelBridge> bridge_;
  WorldPtr world_;
  Link_V links_;
  mutable Joint_V joints_;
  JointControllerPtr joint_controller_;
  std::map<std::string, JointPtr> joints_by_name_;

  void UpdateJointAnimation(const common::UpdateInfo& info);
  void UpdateAnimation(const common::UpdateInfo& info);
  std::map<std::string, common::NumericAnimationPtr> joint_animations_;
  boost::function<void()> on_joint_animation_complete_;
  common::Time joint_animation_time_;  // the simulated time the joint animations were last moved to
  event::ConnectionPtr joint_animation_update_;
  common::PoseAnimationPtr animation_;
  boost::function<void()> on_animation_complete_;
  ignition::math::Pose3d animation_start_;
  common::Time animation_time_;
  event::ConnectionPtr animation_update_;
};
}  // namespace physics
}  // namespace gazebo
