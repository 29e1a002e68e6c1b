// velodyne_simulator's gazebo_ros_velodyne_laser and gazebo_ros_velodyne_gpu_laser (1.0.13, ROS 1):
// a multi-row ray sensor's scan as sensor_msgs/PointCloud2 with Velodyne's point layout (x y z
// intensity float32, ring uint16, time float32: 22 bytes) on <topicName> (default "/points"), frame
// tf::resolve(tf_prefix, <frameName>) (default "/world"). Rays at or inside max(<min_range>, the
// ray's min) or at or beyond min(<max_range>, the ray's max), or under <min_intensity>, are dropped
// (or NaN in an <organize_cloud>); <gaussianNoise> is added to the kept ranges. Points go azimuth by
// azimuth, every ring at each, ring 0 the lowest, as the driver orders them. Upstream's rules
// (docs/interfaces.md section 11).
#include <cmath>
#include <cstring>
#include <limits>

#include <sensor_msgs/PointCloud2.h>

#include "msg_conversions.h"
#include "ros_names.h"
#include "sensor_plugin.h"

namespace bullet_plant
{
class GazeboRosVelodyneLaser : public SensorPlugin
{
public:
  static constexpr uint32_t kPointStep = 22;

  void Load(Sensor& sensor) override
  {
    lidar_ = &sensorAs<Lidar>(sensor, "gazebo_ros_velodyne_laser");
    const SensorDescription& d = sensor.description();
    ros::NodeHandle nh = nodeHandle(sensor);
    std::string prefix;
    nh.getParam("tf_prefix", prefix);  // its own namespace only, no search
    cloud_.header.frame_id = pluginFrameId(d, prefix);
    const std::string organize = d.pluginParam("organize_cloud", "false");
    organize_cloud_ = organize == "true" || organize == "1";
    min_range_ = d.pluginNumber("min_range", 0.0);
    max_range_ = d.pluginNumber("max_range", std::numeric_limits<double>::infinity());
    min_intensity_ = d.pluginNumber("min_intensity", std::numeric_limits<double>::lowest());
    gaussian_noise_ = d.pluginNumber("gaussianNoise", 0.0);
    cloud_.fields = fields();
    cloud_.point_step = kPointStep;
    cloud_.is_bigendian = false;
    cloud_pub_ = advertiseUnlessEmpty<sensor_msgs::PointCloud2>(nh, sensor, pluginTopic(d), 10);
  }

  bool subscribed() const override { return cloud_pub_.subscribed(); }

  void OnUpdate() override
  {
    if (!takeUpdate(*lidar_))
      return;
    const LaserScan& scan = lidar_->latest();
    const SensorDescription& d = lidar_->description();
    const int columns = d.horizontal_samples, rings = scan.vertical_samples;
    const double near = std::max(min_range_, double(scan.range_min)), far = std::min(max_range_, double(scan.range_max));
    const double yaw_step = columns > 1 ? (d.horizontal_max_angle - d.horizontal_min_angle) / (columns - 1) : 0.0;
    const double pitch_step = rings > 1 ? (d.vertical_max_angle - d.vertical_min_angle) / (rings - 1) : 0.0;
    const float nan = std::numeric_limits<float>::quiet_NaN();
    cloud_.header.stamp = rosTime(scan.stamp_ns);
    cloud_.data.resize(size_t(columns) * rings * kPointStep);
    uint8_t* out = cloud_.data.data();
    for (int i = 0; i < columns; ++i)
      for (int j = 0; j < rings; ++j)
      {
        double r = scan.ranges[size_t(i) + size_t(j) * columns];
        const float intensity = 0.0f;  // Gazebo's ray intensity is the hit surface's <laser_retro>: 0
        const bool kept = near < r && r < far && intensity >= min_intensity_;
        if (!kept && !organize_cloud_)
          continue;
        if (kept && gaussian_noise_ != 0.0)
          r += gaussian_kernel_(0.0, gaussian_noise_);
        const double yaw = d.horizontal_min_angle + i * yaw_step, pitch = d.vertical_min_angle + j * pitch_step;
        const bool inside = near < r && r < far;  // noise may push a kept range out: upstream drops it
        if (!inside && !organize_cloud_)
          continue;
        const float point[4] = {inside ? float(r * std::cos(pitch) * std::cos(yaw)) : nan,
                                inside ? float(r * std::cos(pitch) * std::sin(yaw)) : nan,
                                inside ? float(r * std::sin(pitch)) : nan, inside ? intensity : nan};
        const uint16_t ring = uint16_t(j);
        const float time = 0.0f;  // a simulated scan is instantaneous
        std::memcpy(out, point, sizeof(point));
        std::memcpy(out + 16, &ring, sizeof(ring));
        std::memcpy(out + 18, &time, sizeof(time));
        out += kPointStep;
      }
    const size_t bytes = size_t(out - cloud_.data.data());
    cloud_.data.resize(bytes);
    if (organize_cloud_)
    {
      cloud_.width = uint32_t(rings);
      cloud_.height = uint32_t(bytes / kPointStep / std::max(1, rings));
      cloud_.row_step = kPointStep * cloud_.width;
      cloud_.is_dense = false;
    }
    else
    {
      cloud_.height = 1;
      cloud_.width = uint32_t(bytes / kPointStep);
      cloud_.row_step = uint32_t(bytes);
      cloud_.is_dense = true;
    }
    outbox().publish(cloud_pub_.publisher(), cloud_);
  }

private:
  static std::vector<sensor_msgs::PointField> fields()
  {
    auto field = [](const char* name, uint32_t offset, uint8_t type) {
      sensor_msgs::PointField f;
      f.name = name;
      f.offset = offset;
      f.datatype = type;
      f.count = 1;
      return f;
    };
    using P = sensor_msgs::PointField;
    return {field("x", 0, P::FLOAT32), field("y", 4, P::FLOAT32), field("z", 8, P::FLOAT32),
            field("intensity", 12, P::FLOAT32), field("ring", 16, P::UINT16), field("time", 18, P::FLOAT32)};
  }

  Lidar* lidar_ = nullptr;
  sensor_msgs::PointCloud2 cloud_;
  bool organize_cloud_ = false;
  double min_range_ = 0, max_range_ = 0, min_intensity_ = 0, gaussian_noise_ = 0;
  GaussianKernel gaussian_kernel_;
  CountedPublisher cloud_pub_;
};

GAZEBO_ROS_SENSOR_PLUGIN(GazeboRosVelodyneLaser, "libgazebo_ros_velodyne_laser.so",
                         "libgazebo_ros_velodyne_gpu_laser.so");

}  // namespace bullet_plant
