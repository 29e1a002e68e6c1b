// What a robot's sensors read of the simulation (SensorContext), as its own object: a sensor is
// handed this and nothing else, so it cannot reach what only model plugins may (drive joints, add
// forces, move the model; RobotModelPluginContext).
#pragma once

#include <string>
#include <vector>

#include "bullet_plant/robot.h"
#include "sensors/sensor_context.h"

namespace bullet_plant
{
class RobotSensorContext final : public SensorContext
{
public:
  explicit RobotSensorContext(Robot::Internals& robot) : robot_(robot) {}

  bool hasLink(const std::string& link) const override;
  urdf::Pose linkPose(const std::string& link) const override;
  LinkMotion linkMotion(const std::string& link, const urdf::Pose& offset) const override;
  urdf::Vector3 gravity() const override;
  const RayScene& lidarScene() override;
  GlScene* glScene() override;
  FrameWorker* frameWorker() override;
  bool lockstep() const override;
  Lighting lighting() const override;
  std::vector<ContactState> contacts(const std::string& link, const std::vector<std::string>& collisions) const override;

private:
  Robot::Internals& robot_;
};

}  // namespace bullet_plant
