// gazebo_ros_block_laser: a multi-row ray sensor's scan as sensor_msgs/PointCloud (one unnamed
// channel: intensity) on <topicName> (default "/world"), frame tf::resolve(tf_prefix, <frameName>)
// (default "/world"), every scan of the sensor while subscribed. Upstream's rules, quirks included
// (docs/interfaces.md section 11):
// - rows from the lowest up, each from the first azimuth; a ray that hits nothing reads its full
//   length, max; a range below min is -inf and above max +inf (REP 117, gazebo_ros_pkgs 2.9.2's
//   clipping fix: before it, ranges were held to max - min); a point sits at the mean angle of the
//   ray pair its range is interpolated between, so with <resolution> 1 point k carries ray k's
//   range half a step towards ray k + 1 (the last row and column at their ray's own angle);
// - <gaussianNoise> is added to x, y and z of a point short of max, and to every intensity
//   (Gazebo's retro values: 0 here);
// - <updateRate> and <hokuyoMinIntensity> are read and not used, as upstream.
// A single row or column (upstream divides by zero there: NaN points) sits at its min angle.
#include <algorithm>
#include <cmath>
#include <limits>

#include <geometry_msgs/Point32.h>
#include <sensor_msgs/PointCloud.h>

#include "msg_conversions.h"
#include "ros_names.h"
#include "sensor_plugin.h"

namespace bullet_plant
{
class GazeboRosBlockLaser : public SensorPlugin
{
public:
  void Load(Sensor& sensor) override
  {
    lidar_ = &sensorAs<Lidar>(sensor, "gazebo_ros_block_laser");
    const SensorDescription& d = sensor.description();
    ros::NodeHandle nh = nodeHandle(sensor);
    std::string prefix;
    nh.getParam("tf_prefix", prefix);  // its own namespace only, no search
    cloud_.header.frame_id = pluginFrameId(d, prefix);
    gaussian_noise_ = d.pluginNumber("gaussianNoise", 0.0);
    cloud_pub_ = advertiseUnlessEmpty<sensor_msgs::PointCloud>(nh, sensor, pluginTopic(d), 1);
  }

  bool subscribed() const override { return cloud_pub_.subscribed(); }

  void OnUpdate() override
  {
    if (!takeUpdate(*lidar_))
      return;
    const LaserScan& scan = lidar_->latest();
    const SensorDescription& d = lidar_->description();
    const int columns = d.horizontal_samples, rows = scan.vertical_samples;
    const double range_min = scan.range_min, range_max = scan.range_max;
    cloud_.header.stamp = rosTime(scan.stamp_ns);
    cloud_.points.resize(size_t(columns) * rows);
    cloud_.channels.resize(1);
    std::vector<float>& intensities = cloud_.channels[0].values;
    intensities.resize(cloud_.points.size());
    size_t k = 0;
    for (int row = 0; row < rows; ++row)
    {
      const double pitch = pairAngle(row, rows, d.vertical_min_angle, d.vertical_max_angle);
      for (int column = 0; column < columns; ++column, ++k)
      {
        const double yaw = pairAngle(column, columns, d.horizontal_min_angle, d.horizontal_max_angle);
        const float ray = scan.ranges[size_t(column) + size_t(row) * columns];
        // Gazebo's ray reads its full length where it hits nothing.
        double r = std::isfinite(ray) ? double(ray) : ray > 0 ? range_max : -kInfinity;
        if (r < range_min)
          r = -kInfinity;
        else if (r > range_max)
          r = kInfinity;
        geometry_msgs::Point32& point = cloud_.points[k];
        point.x = float(r * std::cos(pitch) * std::cos(yaw));
        point.y = float(r * std::cos(pitch) * std::sin(yaw));
        point.z = float(r * std::sin(pitch));
        if (std::fabs(range_max - r) > 1e-6)  // upstream's EPSILON_DIFF
        {
          point.x += float(gaussian_kernel_(0.0, gaussian_noise_));
          point.y += float(gaussian_kernel_(0.0, gaussian_noise_));
          point.z += float(gaussian_kernel_(0.0, gaussian_noise_));
        }
        intensities[k] = float(0.0 + gaussian_kernel_(0.0, gaussian_noise_));
      }
    }
    outbox().publish(cloud_pub_.publisher(), cloud_);
  }

private:
  static constexpr double kInfinity = std::numeric_limits<double>::infinity();

  // The angle upstream gives sample `i` of `count` rays over [min, max]: the mean of ray i's and
  // ray i + 1's (the last ray's own), rays being spaced (max - min) / (count - 1).
  static double pairAngle(int i, int count, double min, double max)
  {
    if (count < 2)
      return min;
    const int next = std::min(i + 1, count - 1);
    return 0.5 * (i + next) * (max - min) / (count - 1) + min;
  }

  Lidar* lidar_ = nullptr;
  sensor_msgs::PointCloud cloud_;
  double gaussian_noise_ = 0.0;
  GaussianKernel gaussian_kernel_;
  CountedPublisher cloud_pub_;
};

GAZEBO_ROS_SENSOR_PLUGIN(GazeboRosBlockLaser, "libgazebo_ros_block_laser.so");

}  // namespace bullet_plant
