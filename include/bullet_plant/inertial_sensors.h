// Sensors that read the motion of a link rather than cast rays: the IMU of gazebo_ros_imu_sensor
// (inside <sensor type="imu">) and of the model plugin gazebo_ros_imu, and the ground-truth
// odometry of gazebo_ros_p3d. Each plugin's parameters, defaults and frame rule:
// docs/interfaces.md section 11.
#pragma once

#include <cstdint>
#include <string>

#include <urdf_model/pose.h>

#include "bullet_plant/sensors.h"

namespace bullet_plant
{
// A link's motion at one instant, in the world frame.
struct LinkMotion
{
  urdf::Pose pose;              // of the sensor frame
  urdf::Vector3 velocity;       // of the sensor frame's origin
  urdf::Vector3 angular_velocity;
};

// sensor_msgs/Imu's fields; the covariances' diagonals are all `variance` (gaussianNoise^2).
struct ImuReading
{
  int64_t stamp_ns = 0;
  urdf::Rotation orientation;
  urdf::Vector3 angular_velocity;     // rad/s, IMU frame
  urdf::Vector3 linear_acceleration;  // m/s^2, IMU frame, the reaction to gravity included (+9.8 up at rest)
  double variance = 0.0;
};

class Imu : public Sensor
{
public:
  Imu(const SensorDescription& d, uint32_t noise_seed);
  bool update(SensorContext& context, int64_t time_ns) override;
  bool modelPlugin() const { return description_.model_plugin; }
  // A sensor plugin file of the user's own reads it through Gazebo's ImuSensor (upstream's
  // gazebo_ros_imu_sensor built from source, say): it measures as Gazebo's sensor does, in the
  // world's orientation, at its <update_rate>, and leaves gaussianNoise, rpyOffset and updateRateHZ
  // to that plugin, which applies them itself.
  bool readByGazeboSensor() const { return !description_.library.empty(); }
  // The IMU's orientation at spawn, which gazebo_ros_imu_sensor reports its orientation relative to
  // where <initialOrientationAsReference> is true (Gazebo's ImuSensor's own reference; deprecated
  // upstream); by default it reports the world orientation, as REP 145 and gazebo_ros_pkgs 2.9 do
  // (so do gazebo_ros_imu and an IMU read by Gazebo's ImuSensor, which applies its reference itself).
  void setReference(const urdf::Rotation& spawn_orientation)
  {
    if (initial_orientation_as_reference_)
      reference_ = spawn_orientation.GetInverse();
  }
  // An update: the accelerometer differentiates the velocity since the previous sample (none
  // before the first one after a pause in sampling: then only gravity's reaction).
  void sample(const LinkMotion& motion, const urdf::Vector3& gravity, int64_t time_ns);
  bool hasReading() const { return samples_ > 0; }
  const ImuReading& latest() const { return reading_; }

private:
  double noise();
  bool initial_orientation_as_reference_ = false;
  urdf::Rotation reference_, offset_;
  double stddev_ = 0.0;
  ImuReading reading_;
  uint64_t samples_ = 0;
  int64_t last_sample_ns_ = -1;
  urdf::Vector3 last_velocity_;
};

// nav_msgs/Odometry of gazebo_ros_p3d: the pose and world-frame twist of bodyName, relative to
// the link frameName unless that is world or map.
struct GroundTruthReading
{
  int64_t stamp_ns = 0;
  urdf::Pose pose;
  urdf::Vector3 linear, angular;
  double variance = 0.0;
};

class GroundTruthOdometry : public Sensor
{
public:
  GroundTruthOdometry(const SensorDescription& d, uint32_t noise_seed);
  bool update(SensorContext& context, int64_t time_ns) override;
  // The link poses are relative to; empty for the world.
  std::string referenceLink() const;
  void sample(const LinkMotion& body, const LinkMotion* reference, int64_t time_ns);
  bool hasReading() const { return samples_ > 0; }
  const GroundTruthReading& latest() const { return reading_; }

private:
  urdf::Pose offset_;
  double stddev_ = 0.0;
  GroundTruthReading reading_;
  uint64_t samples_ = 0;
};

}  // namespace bullet_plant
