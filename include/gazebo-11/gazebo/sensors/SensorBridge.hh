// The simulator's side of the sensor classes: the one simulation of a sensor that its
// sensors::Sensor object reads and drives (its rate, whether it measures). The Bullet plant
// implements it over its own sensors (src/plant/gazebo_host/sensor_host.cpp); a plugin never uses it.
#pragma once

#include <vector>

#include <ignition/math/Pose3.hh>
#include <ignition/math/Quaternion.hh>
#include <ignition/math/Vector3.hh>

#include "gazebo/common/Time.hh"
#include "gazebo/msgs/MessageTypes.hh"

namespace gazebo
{
namespace sensors
{
class SensorBridge
{
public:
  virtual ~SensorBridge() = default;
  // Whether the simulation measures (Sensor::IsActive, handed over each step).
  virtual void setActive(bool active) = 0;
  // Sensor::SetUpdateRate (0: every step).
  virtual void setUpdateRate(double hz) = 0;
  // The sensor's pose in the world now.
  virtual ignition::math::Pose3d worldPose() const = 0;
  // The simulated time of the latest measurement.
  virtual common::Time measurementTime() const = 0;
};

class RayBridge : public SensorBridge
{
public:
  // The latest scan's ranges, row (vertical sample) after row, as the simulation measured them
  // (its noise applied): +inf where nothing is within the range, -inf for a hit nearer than its
  // minimum; empty before the first scan.
  virtual const std::vector<float>& ranges() const = 0;
  // The sensor's pose in the world the latest scan was cast from.
  virtual ignition::math::Pose3d scanOrigin() const = 0;
};

class SonarBridge : public SensorBridge
{
public:
  // The nearest thing in the sonar's cone (or sphere) in its latest measurement: true, with its
  // distance from the sensor's origin (m) and where it is in the sensor's frame; false where
  // nothing is.
  virtual bool nearest(double& range, ignition::math::Vector3d& point) const = 0;
};

class CameraBridge : public SensorBridge
{
public:
  // The latest frame in its <image><format>'s bytes (width x height pixels of the format's bytes,
  // row after row, as Gazebo's camera gives them); null before the first.
  virtual const unsigned char* image() = 0;
  // Whether a barrel distortion's black border is cropped away, from the next frame on.
  virtual void setDistortionCrop(bool crop) = 0;
};

// A <sensor type="multicamera">: the simulator's camera of each of its <camera> elements, in their
// order; its activity and rate are all of theirs, its pose the <sensor>'s.
class MultiCameraBridge : public SensorBridge
{
public:
  virtual unsigned int cameraCount() const = 0;
  virtual CameraBridge& camera(unsigned int index) = 0;
};

class DepthCameraBridge : public CameraBridge
{
public:
  // The latest frame's depths (metres along the optical axis, NaN where nothing is seen) and its
  // points (x, y, z in the optical frame, NaN where nothing is seen, and the pixel's colour packed
  // r << 16 | g << 8 | b in a float's bits); null before the first.
  virtual const float* depths() = 0;
  virtual const float* rgbPoints() = 0;
};

class ContactBridge : public SensorBridge
{
public:
  // The latest measurement's contacts, one msgs::Contact for each pair of its collision
  // (collision1) and another touching it (collision2), both MODEL::LINK::COLLISION; its `time` and
  // `world` are left to the sensor.
  virtual void contacts(google::protobuf::RepeatedPtrField<msgs::Contact>& out) const = 0;
};

class ImuBridge : public SensorBridge
{
public:
  // The latest measurement: the IMU frame's orientation in the world, its angular velocity and its
  // linear acceleration (the reaction to gravity included: +9.8 up at rest) in its own frame.
  virtual ignition::math::Quaterniond orientation() const = 0;
  virtual ignition::math::Vector3d angularVelocity() const = 0;
  virtual ignition::math::Vector3d linearAcceleration() const = 0;
};
}  // namespace sensors
}  // namespace gazebo
