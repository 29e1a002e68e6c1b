// The IMU (gazebo_ros_imu_sensor, gazebo_ros_imu) and ground-truth odometry (gazebo_ros_p3d) models.
#include "bullet_plant/inertial_sensors.h"

#include <algorithm>
#include <cmath>
#include <random>

#include "bullet_plant/geometry.h"
#include "description/sdf_elements.h"
#include "description/xml_util.h"
#include "sensors/sensor_context.h"

namespace bullet_plant
{
namespace
{

// "x y z" of an offset element; zeros when absent.
urdf::Vector3 vectorParam(const SensorDescription& d, const std::string& key)
{
  const std::string text = d.pluginParam(key);
  if (text.empty())
    return urdf::Vector3();
  const std::vector<double> xyz = xml::numbers(text, 3, "<" + key + "> of plugin '" + d.plugin_name + "'");
  return urdf::Vector3(xyz[0], xyz[1], xyz[2]);
}

urdf::Rotation rpyParam(const SensorDescription& d, const std::string& key)
{
  const urdf::Vector3 rpy = vectorParam(d, key);
  return poseFromXyzRpy(0, 0, 0, rpy.x, rpy.y, rpy.z).rotation;
}

}  // namespace

// ------------------------------------------------------------------------------------------ Imu

Imu::Imu(const SensorDescription& d, uint32_t noise_seed) : Sensor(d, noise_seed)
{
  if (readByGazeboSensor())
    return;  // the sensor's own rate, no noise, no offset
  stddev_ = std::abs(d.pluginNumber("gaussianNoise", 0.0));
  offset_ = rpyParam(d, "rpyOffset");
  initial_orientation_as_reference_ = !d.model_plugin && sdf::isTrue(d.pluginParam("initialOrientationAsReference"));
  if (d.model_plugin)  // gazebo_ros_imu: <updateRate>, 0 = every step (updateRateHZ accepted too)
    gate_.setPeriodNs(periodNsOfRate(d.pluginNumber("updateRate", d.pluginNumber("updateRateHZ", 0.0))));
  else  // gazebo_ros_imu_sensor: <updateRateHZ>, default 1 Hz, within the sensor's <update_rate>
    gate_.setPeriodNs(std::max(gate_.periodNs(), periodNsOfRate(d.pluginNumber("updateRateHZ", 1.0))));
}

double Imu::noise()
{
  if (stddev_ <= 0)
    return 0.0;
  return std::normal_distribution<double>(0.0, stddev_)(noise_);
}

bool Imu::update(SensorContext& context, int64_t time_ns)
{
  sample(context.linkMotion(description_.link, description_.pose), context.gravity(), time_ns);
  return true;
}

void Imu::sample(const LinkMotion& motion, const urdf::Vector3& gravity, int64_t time_ns)
{
  const urdf::Rotation world_to_imu = motion.pose.rotation.GetInverse();
  // Finite difference of the velocity, as Gazebo's ImuSensor, over consecutive samples only.
  const int64_t gap = time_ns - last_sample_ns_;
  const bool consecutive = last_sample_ns_ >= 0 && gap > 0 && gap <= periodNs() + std::max<int64_t>(periodNs() / 2, 2000000);
  urdf::Vector3 acceleration = consecutive ? scaled(sub(motion.velocity, last_velocity_), 1e9 / double(gap)) : urdf::Vector3();
  acceleration = rotate(world_to_imu, sub(acceleration, gravity));
  const urdf::Vector3 rate = rotate(world_to_imu, motion.angular_velocity);
  last_velocity_ = motion.velocity;
  last_sample_ns_ = time_ns;

  ImuReading& r = reading_;
  r.stamp_ns = time_ns;
  r.orientation = modelPlugin() ? offset_ * motion.pose.rotation : offset_ * (reference_ * motion.pose.rotation);
  r.orientation.normalize();
  if (!modelPlugin())  // gazebo_ros_imu_sensor adds its noise to the quaternion's components too
  {
    r.orientation.x += noise();
    r.orientation.y += noise();
    r.orientation.z += noise();
    r.orientation.w += noise();
  }
  r.angular_velocity = urdf::Vector3(rate.x + noise(), rate.y + noise(), rate.z + noise());
  r.linear_acceleration = urdf::Vector3(acceleration.x + noise(), acceleration.y + noise(), acceleration.z + noise());
  r.variance = stddev_ * stddev_;
  ++samples_;
}

// -------------------------------------------------------------------------- GroundTruthOdometry

GroundTruthOdometry::GroundTruthOdometry(const SensorDescription& d, uint32_t noise_seed) : Sensor(d, noise_seed)
{
  stddev_ = std::abs(d.pluginNumber("gaussianNoise", 0.0));
  offset_.position = vectorParam(d, "xyzOffset");
  offset_.rotation = rpyParam(d, "rpyOffset");
  gate_.setPeriodNs(periodNsOfRate(d.pluginNumber("updateRate", 0.0)));
}

std::string GroundTruthOdometry::referenceLink() const
{
  const std::string frame = description_.pluginParam("frameName", "world");
  return frame == "world" || frame == "/world" || frame == "map" || frame == "/map" ? "" : frame;
}

bool GroundTruthOdometry::update(SensorContext& context, int64_t time_ns)
{
  const std::string reference = referenceLink();
  if (!reference.empty() && !context.hasLink(reference))
    return false;  // said at spawn: gazebo_ros_p3d publishes nothing then
  const LinkMotion frame = reference.empty() ? LinkMotion() : context.linkMotion(reference, urdf::Pose());
  sample(context.linkMotion(description_.link, urdf::Pose()), reference.empty() ? nullptr : &frame, time_ns);
  return true;
}

void GroundTruthOdometry::sample(const LinkMotion& body, const LinkMotion* reference, int64_t time_ns)
{
  GroundTruthReading& r = reading_;
  urdf::Pose pose = body.pose;
  urdf::Vector3 v = body.velocity, w = body.angular_velocity;
  if (reference)
  {
    // As gazebo_ros_p3d: the position in the reference frame, the rates rotated by its orientation.
    pose.position = rotate(reference->pose.rotation.GetInverse(), sub(pose.position, reference->pose.position));
    pose.rotation = pose.rotation * reference->pose.rotation.GetInverse();
    v = rotate(reference->pose.rotation, sub(v, reference->velocity));
    w = rotate(reference->pose.rotation, sub(w, reference->angular_velocity));
  }
  pose.position = urdf::Vector3(pose.position.x + offset_.position.x, pose.position.y + offset_.position.y,
                                pose.position.z + offset_.position.z);
  pose.rotation = offset_.rotation * pose.rotation;
  pose.rotation.normalize();
  auto noisy = [this](double x) { return stddev_ > 0 ? x + std::normal_distribution<double>(0.0, stddev_)(noise_) : x; };
  r.stamp_ns = time_ns;
  r.pose = pose;
  r.linear = urdf::Vector3(noisy(v.x), noisy(v.y), noisy(v.z));
  r.angular = urdf::Vector3(noisy(w.x), noisy(w.y), noisy(w.z));
  r.variance = stddev_ * stddev_;
  ++samples_;
}

}  // namespace bullet_plant
