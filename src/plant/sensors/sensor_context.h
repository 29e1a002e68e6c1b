// What a sensor reads of the simulation when it updates, as the robot that carries it offers it:
// link poses and motion (the one kinematics query), gravity, the world's ray scene and its light.
// Sensor::update takes it, so the robot updates every kind of sensor by one call.
#pragma once

#include <string>
#include <vector>

#include <urdf_model/pose.h>

#include "bullet_plant/inertial_sensors.h"
#include "bullet_plant/sensors.h"
#include "rendering/frame_worker.h"
#include "rendering/gl_scene.h"
#include "rendering/ray_caster.h"

namespace bullet_plant
{
class SensorContext
{
public:
  virtual bool hasLink(const std::string& link) const = 0;
  virtual urdf::Pose linkPose(const std::string& link) const = 0;  // world
  virtual LinkMotion linkMotion(const std::string& link, const urdf::Pose& offset) const = 0;
  virtual urdf::Vector3 gravity() const = 0;
  // What lidars cast rays into: the world's ray scene where everything is now, without the robot's
  // own bodies (a lidar does not see its robot).
  virtual const RayScene& lidarScene() = 0;
  // What cameras render with: the world's GL scene where everything is now (the robot's own bodies
  // included: cameras see them, as Gazebo's do), or null where there is no OpenGL (cameras off).
  virtual GlScene* glScene() = 0;
  // Where camera frames render while the simulation goes on, or null: render them now.
  virtual FrameWorker* frameWorker() = 0;
  // Whether every camera frame due renders, the simulation waiting for a camera's previous frame
  // (World::setLockstep); else a frame due while its camera's previous one still renders is skipped.
  virtual bool lockstep() const = 0;
  virtual Lighting lighting() const = 0;
  // The touching points of `link`'s collisions named in `collisions` (SDF names), grouped by the
  // pair of collisions, as ContactSensor reports them.
  virtual std::vector<ContactState> contacts(const std::string& link, const std::vector<std::string>& collisions) const = 0;

protected:
  ~SensorContext() = default;
};

}  // namespace bullet_plant
