// sensors::SonarSensor (gazebo/sensors/SonarSensor.hh).
#include "gazebo/sensors/SonarSensor.hh"

#include <boost/algorithm/string/replace.hpp>

#include "gazebo/common/Console.hh"
#include "gazebo/msgs/msgs.hh"
#include "gazebo/physics/World.hh"
#include "gazebo/transport/Node.hh"
#include "gazebo/transport/Publisher.hh"

namespace gazebo
{
namespace sensors
{
SonarSensor::SonarSensor() : Sensor(OTHER) {}

SonarSensor::~SonarSensor() = default;

std::string SonarSensor::Topic() const
{
  std::string topic = "~/" + ParentName() + "/" + Name() + "/sonar";
  boost::replace_all(topic, "::", "/");
  return topic;
}

void SonarSensor::Load(const std::string& _worldName)
{
  // (sensor.sdf gives it, with its defaults, where the <sensor> has none)
  const sdf::ElementPtr sonar = sdf->GetElement("sonar");
  range_min_ = sonar->Get<double>("min");
  range_max_ = sonar->Get<double>("max");
  radius_ = sonar->Get<double>("radius");
  std::string geometry = sonar->HasElement("geometry") ? sonar->Get<std::string>("geometry") : "cone";
  if (radius_ < 0 && geometry == "cone")
  {
    gzerr << "Sonar cone radius must be > 0. Current value is [" << radius_ << "]\n";
    return;
  }
  if (range_min_ < 0)
  {
    gzerr << "Min sonar range must be >= 0. Current value is[" << range_min_ << "]\n";
    return;
  }
  if (range_min_ > range_max_)
  {
    gzerr << "Min sonar range of [" << range_min_ << "] must be less than" << "the max sonar range of["
          << range_max_ << "]\n";
    return;
  }
  if (geometry != "sphere" && geometry != "cone")
  {
    gzerr << "Invalid sonar collision shape [" << geometry << "]. Defaults to cone.\n";
    geometry = "cone";
  }
  Sensor::Load(_worldName);
  if (!world)
    return;
  loaded_ = true;
  pub_ = node->Advertise<msgs::SonarStamped>(Topic());
  std::lock_guard<std::mutex> lock(mutex_);
  msgs::Sonar& message = *message_.mutable_sonar();
  message.set_geometry(geometry);
  message.set_range_min(range_min_);
  message.set_range_max(range_max_);
  message.set_radius(radius_);
  message.set_range(0);
  msgs::Set(message.mutable_world_pose(), bridge ? bridge->worldPose() : pose);
}

void SonarSensor::Init()
{
  Sensor::Init();
  if (!loaded_)
    return;
  msgs::SonarStamped message;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    message_.mutable_sonar()->set_frame(ParentName());
    msgs::Set(message_.mutable_time(), world->SimTime());
    message_.mutable_sonar()->set_range(range_max_);
    message = message_;
  }
  if (pub_)
    pub_->Publish(message);
}

void SonarSensor::Fini()
{
  pub_.reset();
  Sensor::Fini();
}

double SonarSensor::RangeMin() const { return range_min_; }

double SonarSensor::RangeMax() const { return range_max_; }

double SonarSensor::Radius() const { return radius_; }

std::string SonarSensor::Geometry() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  return message_.sonar().geometry();
}

double SonarSensor::Range()
{
  std::lock_guard<std::mutex> lock(mutex_);
  return message_.sonar().range();
}

bool SonarSensor::UpdateImpl(const bool /*_force*/)
{
  const auto* sonar = dynamic_cast<const SonarBridge*>(bridge.get());
  if (!loaded_ || !sonar)
    return false;
  double nearest = 0.0;
  ignition::math::Vector3d point;
  const bool seen = sonar->nearest(nearest, point);
  msgs::SonarStamped message;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    lastMeasurementTime = sonar->measurementTime();
    msgs::Set(message_.mutable_time(), lastMeasurementTime);
    msgs::Set(message_.mutable_sonar()->mutable_world_pose(), sonar->worldPose());
    msgs::Sonar& measured = *message_.mutable_sonar();
    // Gazebo's five-measurement hysteresis: the range goes back to the maximum where something is
    // seen (the nearer then wins) or after six measurements without anything, and stays meanwhile
    if (seen || empty_count_ > 5)
    {
      measured.set_range(range_max_);
      empty_count_ = 0;
    }
    else
      ++empty_count_;
    if (seen && nearest < measured.range())
    {
      measured.set_range(nearest);
      msgs::Set(measured.mutable_contact(), point);
    }
    message = message_;
  }
  update_(message);
  if (pub_)
    pub_->Publish(message);
  return true;
}

bool SonarSensor::IsActive() const { return Sensor::IsActive() || (pub_ && pub_->HasConnections()); }

event::ConnectionPtr SonarSensor::ConnectUpdate(std::function<void(msgs::SonarStamped)> _subscriber)
{
  return update_.Connect(_subscriber);
}
}  // namespace sensors
}  // namespace gazebo
