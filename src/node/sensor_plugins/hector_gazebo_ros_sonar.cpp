// hector_gazebo_plugins' gazebo_ros_sonar: a ray sensor's shortest ray as sensor_msgs/Range
// (ULTRASOUND) on <topicName> (default "sonar", in <robotNamespace>), frame <frameId> as given
// (default "/sonar_link"), field of view the smaller of the horizontal and vertical spans of the
// rays, min/max range from the sensor's <ray><range>. Published by hector's UpdateTimer
// (<updateRate>, default 10 Hz, or <updatePeriod>; <updateOffset>) with the sensor's latest scan; a
// range short of the maximum goes through hector's error model (offset, drift, driftFrequency,
// gaussianNoise, scaleError, no prefix) and is held within [min, max]. Upstream's rules
// (docs/interfaces.md section 11).
#include <cmath>
#include <limits>
#include <random>

#include <sensor_msgs/Range.h>

#include "bullet_plant/hector_sensor_model.h"
#include "msg_conversions.h"
#include "ros_names.h"
#include "sensor_plugin.h"

namespace bullet_plant
{
class HectorGazeboRosSonar : public SensorPlugin
{
public:
  void Load(Sensor& sensor) override
  {
    lidar_ = &sensorAs<Lidar>(sensor, "hector_gazebo_ros_sonar");
    const SensorDescription& d = sensor.description();
    const ModelPluginDescription block = d.pluginBlock();
    range_.header.frame_id = pluginFrameId(d, "");
    range_.radiation_type = sensor_msgs::Range::ULTRASOUND;
    range_.field_of_view = float(std::min(std::fabs(d.horizontal_max_angle - d.horizontal_min_angle),
                                          std::fabs(d.vertical_max_angle - d.vertical_min_angle)));
    range_.min_range = float(d.range_min);
    range_.max_range = float(d.range_max);
    sensor_model_.load(block, "");
    update_timer_.load(block, 10.0, stepSize());
    rng_.seed(sensor.noiseSeed());
    sensor_model_.reset(rng_);
    range_pub_ = CountedPublisher::advertise<sensor_msgs::Range>(
        nodeHandle(sensor), requireValidRosName(pluginTopic(d), "sensor '" + sensor.name() + "' topicName"), 1);
  }

  bool subscribed() const override { return range_pub_.subscribed(); }

  void OnUpdate() override
  {
    const int64_t now = simTimeNs();
    if (update_timer_.wentBack(now))  // a world reset: Reset() as upstream's
    {
      update_timer_.reset();
      sensor_model_.reset(rng_);
    }
    if (!update_timer_.due(now) || lidar_->updates() == 0)
      return;
    const double dt = update_timer_.update(now);
    range_.header.stamp = rosTime(now);
    // Gazebo's rays report their full length where they hit nothing; nearer than <min> they see nothing.
    float shortest = std::numeric_limits<float>::max();
    for (float r : lidar_->latest().ranges)
      shortest = std::min(shortest, std::isfinite(r) ? r : r > 0 ? range_.max_range : range_.min_range);
    if (shortest < range_.max_range)
      shortest = float(std::max(double(range_.min_range),
                                std::min(sensor_model_(double(shortest), dt, rng_), double(range_.max_range))));
    range_.range = shortest;
    outbox().publish(range_pub_.publisher(), range_);
  }

private:
  Lidar* lidar_ = nullptr;
  sensor_msgs::Range range_;
  HectorSensorModel sensor_model_;
  HectorUpdateTimer update_timer_;
  std::mt19937 rng_;
  CountedPublisher range_pub_;
};

GAZEBO_ROS_SENSOR_PLUGIN(HectorGazeboRosSonar, "libhector_gazebo_ros_sonar.so");

}  // namespace bullet_plant
