// gazebo_ros_range: a ray sensor's shortest ray as sensor_msgs/Range on <topicName> (default
// "/range"), frame tf::resolve(tf_prefix, <frameName>) (default "/world"), with <radiation>
// (ultrasound unless "infrared"), <fov> (0.05), min/max range from the sensor's <ray><range>, and
// <gaussianNoise> added to a range short of the maximum, the sum held to it; at most <updateRate>
// (0: every scan). Upstream's rules (docs/interfaces.md section 11).
#include <cmath>
#include <limits>

#include <sensor_msgs/Range.h>

#include "bullet_plant/rate_gate.h"
#include "msg_conversions.h"
#include "ros_names.h"
#include "sensor_plugin.h"

namespace bullet_plant
{
class GazeboRosRange : public SensorPlugin
{
public:
  void Load(Sensor& sensor) override
  {
    lidar_ = &sensorAs<Lidar>(sensor, "gazebo_ros_range");
    const SensorDescription& d = sensor.description();
    ros::NodeHandle nh = nodeHandle(sensor);
    std::string prefix;
    nh.getParam("tf_prefix", prefix);  // its own namespace only, no search
    range_.header.frame_id = pluginFrameId(d, prefix);
    range_.radiation_type = d.pluginParam("radiation", "ultrasound") == "ultrasound" ? sensor_msgs::Range::ULTRASOUND
                                                                                    : sensor_msgs::Range::INFRARED;
    range_.field_of_view = float(d.pluginNumber("fov", 0.05));
    range_.min_range = float(d.range_min);
    range_.max_range = float(d.range_max);
    gaussian_noise_ = d.pluginNumber("gaussianNoise", 0.0);
    publish_gate_.setPeriodNs(periodNsOfRate(d.pluginNumber("updateRate", 0.0)));
    range_pub_ = CountedPublisher::advertise<sensor_msgs::Range>(
        nh, requireValidRosName(pluginTopic(d), "sensor '" + sensor.name() + "' topicName"), 1);
  }

  bool subscribed() const override { return range_pub_.subscribed(); }

  void OnUpdate() override
  {
    if (!takeUpdate(*lidar_))
      return;
    const LaserScan& scan = lidar_->latest();
    if (!publish_gate_.due(scan.stamp_ns))
      return;
    range_.header.stamp = rosTime(scan.stamp_ns);
    // Gazebo's rays report their full length where they hit nothing: the maximum range.
    float shortest = std::numeric_limits<float>::max();
    for (float r : scan.ranges)
      shortest = std::min(shortest, std::isfinite(r) ? r : range_.max_range);
    if (shortest < range_.max_range)
      shortest = float(std::min(shortest + gaussian_kernel_(0.0, gaussian_noise_), double(range_.max_range)));
    range_.range = shortest;
    outbox().publish(range_pub_.publisher(), range_);
  }

private:
  Lidar* lidar_ = nullptr;
  sensor_msgs::Range range_;
  double gaussian_noise_ = 0.0;
  RateGate publish_gate_;  // updateRate
  GaussianKernel gaussian_kernel_;
  CountedPublisher range_pub_;
};

GAZEBO_ROS_SENSOR_PLUGIN(GazeboRosRange, "libgazebo_ros_range.so");

}  // namespace bullet_plant
