#include "sensor_publishers.h"

#include "ros_names.h"

#include <cstring>

#include <sensor_msgs/CameraInfo.h>
#include <sensor_msgs/Image.h>
#include <sensor_msgs/LaserScan.h>
#include <sensor_msgs/PointCloud2.h>

#include "bullet_plant/robot.h"
#include "ros_time.h"

namespace bullet_plant
{
namespace
{
sensor_msgs::CameraInfo cameraInfo(const CameraFrame& f, const std_msgs::Header& header)
{
  sensor_msgs::CameraInfo info;
  info.header = header;
  info.width = f.width;
  info.height = f.height;
  info.distortion_model = "plumb_bob";
  info.D.assign(5, 0.0);
  info.K = {f.fx, 0, f.cx, 0, f.fy, f.cy, 0, 0, 1};
  info.R = {1, 0, 0, 0, 1, 0, 0, 0, 1};
  info.P = {f.fx, 0, f.cx, 0, 0, f.fy, f.cy, 0, 0, 0, 1, 0};
  return info;
}

// x y z float32 and rgb packed in a float32, as gazebo_ros_openni_kinect publishes
sensor_msgs::PointCloud2 pointCloud(const CameraFrame& f, const std_msgs::Header& header)
{
  sensor_msgs::PointCloud2 cloud;
  cloud.header = header;
  cloud.width = f.width;
  cloud.height = f.height;
  cloud.is_bigendian = false;
  cloud.is_dense = false;
  cloud.point_step = 16;
  cloud.row_step = cloud.point_step * f.width;
  const char* names[] = {"x", "y", "z", "rgb"};
  for (int i = 0; i < 4; ++i)
  {
    sensor_msgs::PointField field;
    field.name = names[i];
    field.offset = 4 * i;
    field.datatype = sensor_msgs::PointField::FLOAT32;
    field.count = 1;
    cloud.fields.push_back(field);
  }
  cloud.data.resize(size_t(cloud.row_step) * f.height);
  for (size_t p = 0; p < size_t(f.width) * f.height; ++p)
  {
    uint8_t* out = &cloud.data[p * 16];
    std::memcpy(out, &f.points[3 * p], 12);
    uint32_t rgb = (uint32_t(f.rgb[3 * p]) << 16) | (uint32_t(f.rgb[3 * p + 1]) << 8) | f.rgb[3 * p + 2];
    std::memcpy(out + 12, &rgb, 4);
  }
  return cloud;
}
}  // namespace

SensorPublishers::SensorPublishers(Robot& robot, ros::NodeHandle& nh) : robot_(robot)
{
  for (Lidar* lidar : robot_.lidars())
  {
    const std::string owner = "sensor '" + lidar->name() + "' topic";
    lidars_.push_back({lidar, nh.advertise<sensor_msgs::LaserScan>(requireValidRosName(lidar->topic(), owner), 5)});
  }
  for (Camera* camera : robot_.cameras())
  {
    const std::string owner = "sensor '" + camera->name() + "' topic";
    CameraTopics t;
    t.camera = camera;
    t.image = nh.advertise<sensor_msgs::Image>(requireValidRosName(camera->topic(), owner), 2);
    t.info = nh.advertise<sensor_msgs::CameraInfo>(requireValidRosName(camera->cameraInfoTopic(), owner), 2);
    if (camera->depthSensor())
    {
      t.depth = nh.advertise<sensor_msgs::Image>(requireValidRosName(camera->depthTopic(), owner), 2);
      t.depth_info = nh.advertise<sensor_msgs::CameraInfo>(requireValidRosName(camera->depthCameraInfoTopic(), owner), 2);
      t.points = nh.advertise<sensor_msgs::PointCloud2>(requireValidRosName(camera->pointsTopic(), owner), 2);
    }
    cameras_.push_back(t);
  }
}

void SensorPublishers::updateSubscriptions()
{
  for (LidarTopic& t : lidars_)
    setActive(t.lidar, t.scan.getNumSubscribers() > 0);
  for (CameraTopics& t : cameras_)
  {
    uint32_t listeners = t.image.getNumSubscribers() + t.info.getNumSubscribers();
    if (t.camera->depthSensor())
      listeners += t.depth.getNumSubscribers() + t.depth_info.getNumSubscribers() + t.points.getNumSubscribers();
    setActive(t.camera, listeners > 0);
  }
}

void SensorPublishers::setActive(Sensor* sensor, bool active)
{
  if (sensor->active() != active)
    ROS_INFO("%s sensor '%s': %s", robot_.name().c_str(), sensor->name().c_str(),
             active ? "subscribed, computing" : "no subscribers, idle");
  sensor->setActive(active);
}

void SensorPublishers::publish()
{
  publishScans();
  publishCameras();
}

void SensorPublishers::publishScans()
{
  for (LidarTopic& t : lidars_)
  {
    if (t.lidar->updates() == t.updates)
      continue;
    t.updates = t.lidar->updates();
    const LaserScan& s = t.lidar->latest();
    sensor_msgs::LaserScan msg;
    msg.header.stamp = rosTime(s.stamp_ns);
    msg.header.frame_id = s.frame_id;
    msg.angle_min = s.angle_min;
    msg.angle_max = s.angle_max;
    msg.angle_increment = s.angle_increment;
    msg.time_increment = s.time_increment;
    msg.scan_time = s.scan_time;
    msg.range_min = s.range_min;
    msg.range_max = s.range_max;
    msg.ranges = s.ranges;
    t.scan.publish(msg);
  }
}

void SensorPublishers::publishCameras()
{
  for (CameraTopics& t : cameras_)
  {
    if (t.camera->updates() == t.updates)
      continue;
    t.updates = t.camera->updates();
    const CameraFrame& f = t.camera->latest();
    std_msgs::Header header;
    header.stamp = rosTime(f.stamp_ns);
    header.frame_id = f.frame_id;
    sensor_msgs::Image image;
    image.header = header;
    image.width = f.width;
    image.height = f.height;
    image.encoding = "rgb8";
    image.step = f.width * 3;
    image.data = f.rgb;
    t.image.publish(image);
    t.info.publish(cameraInfo(f, header));
    if (!t.camera->depthSensor())
      continue;
    sensor_msgs::Image depth;
    depth.header = header;
    depth.width = f.width;
    depth.height = f.height;
    depth.encoding = "32FC1";
    depth.step = f.width * 4;
    depth.data.resize(f.depth.size() * 4);
    std::memcpy(depth.data.data(), f.depth.data(), depth.data.size());
    t.depth.publish(depth);
    t.depth_info.publish(cameraInfo(f, header));
    if (t.points.getNumSubscribers() == 0)
      continue;
    t.points.publish(pointCloud(f, header));
  }
}

}  // namespace bullet_plant
