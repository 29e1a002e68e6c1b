// physics::Model's, Link's and Joint's side in the plant (gazebo/physics/PlantBridge.hh), over a
// model's plugin context (ModelPluginContext): one for each model of the world, shared by its
// model plugins and the world plugins that look it up. When the model leaves the world (delete_model)
// the bridge is released: the handles plugins still hold answer nothing and change nothing.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <gazebo/physics/PlantBridge.hh>
#include <gazebo/physics/ode/ODESurfaceParams.hh>

#include "bullet_plant/model_plugin.h"

namespace bullet_plant
{
// The plant's vectors and poses in Gazebo's API's ignition types.
inline ignition::math::Vector3d toIgnition(const urdf::Vector3& v) { return {v.x, v.y, v.z}; }
inline ignition::math::Pose3d toIgnition(const urdf::Pose& p)
{
  return {p.position.x, p.position.y, p.position.z, p.rotation.w, p.rotation.x, p.rotation.y, p.rotation.z};
}

// The model a bridge reaches while it is in the world: null once it left.
struct ModelReach
{
  ModelPluginContext* context = nullptr;
  std::string label;  // how messages name it: "model 'NAME'"
};

class ContextModel final : public gazebo::physics::ModelBridge
{
public:
  explicit ContextModel(ModelPluginContext& context);
  // The model left the world.
  void release() { reach_->context = nullptr; }

  std::string name() const override { return name_; }
  std::string canonicalLink() const override;
  std::vector<std::string> linkNames() const override;
  std::vector<std::string> jointNames() const override;
  ignition::math::Pose3d linkPose(const std::string& link) const override;
  ignition::math::Vector3d linkLinearVel(const std::string& link) const override;
  ignition::math::Vector3d linkAngularVel(const std::string& link) const override;
  void setVelocity(const ignition::math::Vector3d& linear, const ignition::math::Vector3d& angular) override;
  void addLinkWrench(const std::string& link, const ignition::math::Vector3d& force,
                     const ignition::math::Vector3d& torque) override;
  void addedLinkWrench(const std::string& link, ignition::math::Vector3d& force,
                       ignition::math::Vector3d& torque) const override;
  ignition::math::Vector3d bodyCentreOfMass(const std::string& link) const override;
  gazebo::physics::LinkInertia linkInertia(const std::string& link) const override;
  bool isStatic() const override;
  bool linkGravity(const std::string& link) const override;
  void setLinkGravity(const std::string& link, bool gravity) override;
  std::vector<std::string> linkJoints(const std::string& link, bool parent_side) const override;
  void setLinkWorldPose(const std::string& link, const ignition::math::Pose3d& pose) override;
  std::unique_ptr<gazebo::physics::JointBridge> joint(const std::string& name) override;
  std::vector<gazebo::physics::CollisionSpec> linkCollisions(const std::string& link) const override;
  gazebo::physics::SurfaceParamsPtr collisionSurface(const std::string& link, const std::string& collision) override;
  // What plugins changed of the surfaces handed out (friction coefficients, slips), to the solver
  // before the step: called once the world update's events have run.
  void pushSurfaces();

private:
  // The context while the model is in the world; null (and one error) after.
  ModelPluginContext* reach(const char* call) const;
  std::shared_ptr<ModelReach> reach_;
  // The surfaces plugins hold, by (link, collision), and what the solver last took of each.
  struct HandedSurface
  {
    boost::shared_ptr<gazebo::physics::ODESurfaceParams> surface;
    CollisionFriction pushed;
  };
  std::map<std::pair<std::string, std::string>, HandedSurface> surfaces_;
  std::string name_;
  mutable bool said_gone_ = false;
  bool said_bad_surface_ = false;
};
}  // namespace bullet_plant
