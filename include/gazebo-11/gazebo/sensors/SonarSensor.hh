// sensors::SonarSensor: a <sensor type="sonar"> as Gazebo 11's: the nearest thing within its cone
// (apex at the sensor's origin, opening along its -z axis, <radius> wide at <max> - <min> along it)
// or, with <geometry>sphere</geometry>, within <max> - <min> all round; <max> where nothing is, after
// five measurements without anything (Gazebo's hysteresis). Each measurement a msgs::SonarStamped
// on Topic() and to ConnectUpdate's subscribers. Its measurements are the simulator's (SonarBridge);
// what differs from Gazebo's: docs/gazebo_api.md.
#pragma once

#include <functional>
#include <mutex>
#include <string>

#include "gazebo/common/Event.hh"
#include "gazebo/msgs/MessageTypes.hh"
#include "gazebo/sensors/Sensor.hh"
#include "gazebo/transport/TransportTypes.hh"

namespace gazebo
{
namespace sensors
{
class GZ_SENSORS_VISIBLE SonarSensor : public Sensor
{
public:
  SonarSensor();
  ~SonarSensor() override;
  // Its <sonar> (Gazebo's errors for a negative minimum or radius, a minimum above the maximum: it
  // then measures nothing), its topic advertised.
  void Load(const std::string& _worldName) override;
  using Sensor::Load;
  // Its first message: the maximum range.
  void Init() override;
  void Fini() override;
  // ~/MODEL/LINK/SENSOR/sonar
  std::string Topic() const override;
  double RangeMin() const;
  double RangeMax() const;
  double Radius() const;
  // "cone" or "sphere"
  std::string Geometry() const;
  // The latest measurement's (m).
  double Range();
  // Set active, or its topic has a subscriber.
  bool IsActive() const override;
  event::ConnectionPtr ConnectUpdate(std::function<void(msgs::SonarStamped)> _subscriber);

protected:
  bool UpdateImpl(const bool _force) override;

private:
  mutable std::mutex mutex_;
  double range_min_ = 0.0, range_max_ = 0.0, radius_ = 0.0;
  bool loaded_ = false;
  int empty_count_ = 0;  // measurements in a row with nothing in the cone
  msgs::SonarStamped message_;
  transport::PublisherPtr pub_;
  event::EventT<void(msgs::SonarStamped)> update_;
};
}  // namespace sensors
}  // namespace gazebo
