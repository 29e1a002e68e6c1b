#include "sensor_publishers.h"

#include "frame_messages.h"
#include "ros_names.h"

#include <nav_msgs/Odometry.h>
#include <sensor_msgs/CameraInfo.h>
#include <sensor_msgs/Imu.h>
#include <sensor_msgs/LaserScan.h>

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

// True once per update of the sensor: what it computed since `seen` was last set.
bool takeUpdate(uint64_t& seen, const Sensor& sensor)
{
  if (sensor.updates() == seen)
    return false;
  seen = sensor.updates();
  return true;
}

// tf::getPrefixParam: a tf_prefix parameter found by searching up from the plugin's namespace
// replaces the namespace as the prefix of laser and camera frame ids.
void applyTfPrefixParam(Sensor& sensor, const ros::NodeHandle& nh)
{
  std::string key, prefix;
  if (nh.searchParam("tf_prefix", key) && nh.getParam(key, prefix) && !prefix.empty())
    sensor.setTfPrefix(prefix);
}

// The node handle of the sensor's plugin, in its namespace.
ros::NodeHandle sensorNodeHandle(Sensor& sensor)
{
  const std::string& ns = sensor.rosNamespace();
  return ros::NodeHandle(ns.empty() ? "/" : requireValidRosName(ns, "sensor '" + sensor.name() + "' robotNamespace"));
}
}  // namespace

SensorPublishers::SensorPublishers(Robot& robot) : robot_(robot)
{
  for (Lidar* lidar : robot_.lidars())
  {
    if (!lidar->publishesOnRos())
      continue;
    const std::string owner = "sensor '" + lidar->name() + "' topic";
    ros::NodeHandle nh = sensorNodeHandle(*lidar);
    applyTfPrefixParam(*lidar, nh);
    lidars_.push_back({lidar, nh.advertise<sensor_msgs::LaserScan>(requireValidRosName(lidar->topic(), owner), 5)});
  }
  for (Camera* camera : robot_.cameras())
  {
    if (!camera->publishesOnRos())
      continue;
    const std::string owner = "sensor '" + camera->name() + "' topic";
    ros::NodeHandle nh = sensorNodeHandle(*camera);
    const std::string camera_name = camera->description().pluginParam("cameraName");
    applyTfPrefixParam(*camera, camera_name.empty() ? nh : ros::NodeHandle(nh, camera_name));
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
  for (Imu* imu : robot_.imus())
  {
    if (!imu->publishesOnRos())
      continue;
    ros::NodeHandle nh = sensorNodeHandle(*imu);
    imus_.push_back({imu, nh.advertise<sensor_msgs::Imu>(requireValidRosName(imu->topic(), "sensor '" + imu->name() + "' topic"), 10)});
  }
  for (GroundTruthOdometry* odometry : robot_.groundTruths())
  {
    ros::NodeHandle nh = sensorNodeHandle(*odometry);
    std::string prefix;  // gazebo_ros_p3d: getParam("tf_prefix") in its namespace, no search
    nh.getParam("tf_prefix", prefix);
    odometry->setTfPrefix(prefix);
    ground_truths_.push_back(
        {odometry, nh.advertise<nav_msgs::Odometry>(requireValidRosName(odometry->topic(), "plugin '" + odometry->name() + "' topicName"), 10)});
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
  for (ImuTopic& t : imus_)
    setActive(t.imu, t.pub.getNumSubscribers() > 0);
  for (GroundTruthTopic& t : ground_truths_)
    setActive(t.odometry, t.pub.getNumSubscribers() > 0);
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
  publishImus();
  publishGroundTruth();
}

namespace
{
geometry_msgs::Vector3 vector(const urdf::Vector3& v)
{
  geometry_msgs::Vector3 out;
  out.x = v.x;
  out.y = v.y;
  out.z = v.z;
  return out;
}

geometry_msgs::Quaternion quaternion(const urdf::Rotation& q)
{
  geometry_msgs::Quaternion out;
  out.x = q.x;
  out.y = q.y;
  out.z = q.z;
  out.w = q.w;
  return out;
}
}  // namespace

void SensorPublishers::publishImus()
{
  for (ImuTopic& t : imus_)
  {
    if (!takeUpdate(t.updates, *t.imu) || !t.imu->hasReading())
      continue;
    const ImuReading& r = t.imu->latest();
    sensor_msgs::Imu msg;
    msg.header.stamp = rosTime(r.stamp_ns);
    msg.header.frame_id = r.frame_id;
    msg.orientation = quaternion(r.orientation);
    msg.angular_velocity = vector(r.angular_velocity);
    msg.linear_acceleration = vector(r.linear_acceleration);
    for (int i : {0, 4, 8})
      msg.orientation_covariance[i] = msg.angular_velocity_covariance[i] = msg.linear_acceleration_covariance[i] = r.variance;
    t.pub.publish(msg);
  }
}

void SensorPublishers::publishGroundTruth()
{
  for (GroundTruthTopic& t : ground_truths_)
  {
    if (!takeUpdate(t.updates, *t.odometry) || !t.odometry->hasReading())
      continue;
    const GroundTruthReading& r = t.odometry->latest();
    nav_msgs::Odometry msg;
    msg.header.stamp = rosTime(r.stamp_ns);
    msg.header.frame_id = r.frame_id;
    msg.child_frame_id = r.child_frame_id;
    msg.pose.pose.position.x = r.pose.position.x;
    msg.pose.pose.position.y = r.pose.position.y;
    msg.pose.pose.position.z = r.pose.position.z;
    msg.pose.pose.orientation = quaternion(r.pose.rotation);
    msg.twist.twist.linear = vector(r.linear);
    msg.twist.twist.angular = vector(r.angular);
    for (int i : {0, 7, 14, 21, 28, 35})
      msg.pose.covariance[i] = msg.twist.covariance[i] = r.variance;
    t.pub.publish(msg);
  }
}

void SensorPublishers::publishScans()
{
  for (LidarTopic& t : lidars_)
  {
    if (!takeUpdate(t.updates, *t.lidar))
      continue;
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
    if (!takeUpdate(t.updates, *t.camera))
      continue;
    // Images and points are serialized from the frame as roscpp sends them, only for topics with
    // subscribers (frame_messages.h).
    const CameraFrame& f = t.camera->latest();
    const std_msgs::Header header = frameHeader(f);
    t.image.publish(RgbImageOf{f});
    t.info.publish(cameraInfo(f, header));
    if (!t.camera->depthSensor())
      continue;
    const DepthCutoff cutoff{t.camera->pointCloudCutoff(), t.camera->pointCloudCutoffMax()};
    t.depth.publish(DepthImageOf{f, cutoff});
    t.depth_info.publish(cameraInfo(f, header));
    t.points.publish(PointCloudOf{f, cutoff});
  }
}

}  // namespace bullet_plant
