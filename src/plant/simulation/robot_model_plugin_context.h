// What a robot's model plugins reach of their model (ModelPluginContext), as its own object: more
// than a sensor may (robot_sensor_context.h), since gazebo_plugins' model plugins drive joints, add
// forces and move the model as Gazebo's physics::Model lets them.
#pragma once

#include <cstdint>
#include <string>

#include "bullet_plant/model_plugin.h"
#include "bullet_plant/robot.h"

namespace bullet_plant
{
class RobotModelPluginContext final : public ModelPluginContext
{
public:
  explicit RobotModelPluginContext(Robot::Internals& robot) : robot_(robot) {}

  const std::string& modelName() const override;
  const RobotDescription& robotDescription() const override;
  const std::string& rootLink() const override;
  const std::string& spawnNamespace() const override;
  ModelJoint* modelJoint(const std::string& joint, const std::string& plugin) override;
  bool jointState(const std::string& joint, double& position, double& velocity) const override;
  LinkMotion linkMotion(const std::string& link) const override;
  void setModelVelocity(const urdf::Vector3& linear, const urdf::Vector3& angular) override;
  uint32_t noiseSeed(const ModelPluginDescription& plugin) const override;
  void addLinkWrench(const std::string& link, const urdf::Vector3& force, const urdf::Vector3& torque) override;
  void addedLinkWrench(const std::string& link, urdf::Vector3& force, urdf::Vector3& torque) const override;
  urdf::Vector3 bodyCentreOfMass(const std::string& link) const override;
  bool setJointPosition(const std::string& joint, double position) override;
  bool transmissionDrives(const std::string& joint) const override;
  void setLinkWorldPose(const std::string& link, const urdf::Pose& pose) override;
  void setPhysicsEnabled(bool enabled) override;
  bool physicsEnabled() const override;
  bool watchJointWrench(const std::string& joint) override;
  void jointWrench(const std::string& joint, urdf::Vector3& force, urdf::Vector3& torque) const override;
  urdf::Vector3 gravity() const override;
  double linkMass(const std::string& link) const override;
  double linkIxx(const std::string& link) const override;
  std::vector<LinkCollision> linkCollisions(const std::string& link) const override;
  bool setCollisionFriction(const std::string& link, const std::string& collision,
                            const CollisionFriction& friction) override;
  bool setLinkGravity(const std::string& link, bool gravity) override;
  bool lumpedInertia(const std::string& link, double& mass, urdf::Pose& com, urdf::Vector3& moments) const override;
  double stepSize() const override;
  const Param& params() const override;
  std::string pluginNamespace(const ModelPluginDescription& plugin) const override;
  std::string tfPrefix(const ModelPluginDescription& plugin) const override;
  GazeboHost& gazeboHost() override;
  Log& log() override;

private:
  Robot::Internals& robot_;
};

}  // namespace bullet_plant
