#include "gazebo_ros_camera.h"

#include <cmath>

#include "bullet_plant/log.h"
#include "ros_names.h"

namespace bullet_plant
{
namespace
{
// A number of the plugin block (pluginNumber: a word is a DescriptionError naming it); one that
// is not finite is `fallback`, with a warning.
double finiteParam(const SensorDescription& d, const char* key, double fallback, std::vector<std::string>& warnings)
{
  const double value = d.pluginNumber(key, fallback);
  if (std::isfinite(value))
    return value;
  warnings.push_back("<" + std::string(key) + "> is not a finite number; " + formatNumber(fallback) + " is used");
  return fallback;
}
}  // namespace

sensor_msgs::CameraInfo cameraInfoOf(const SensorDescription& d, double hack_baseline, std::vector<std::string>& warnings)
{
  const int width = d.image_width, height = d.image_height;
  // Upstream's defaults: 0 means "compute it", (size + 1) / 2 for the centre.
  double cx = finiteParam(d, "Cx", 0.0, warnings), cy = finiteParam(d, "Cy", 0.0, warnings);
  if (cx == 0)
    cx = (width + 1.0) / 2.0;
  if (cy == 0)
    cy = (height + 1.0) / 2.0;
  const double computed_focal = width / (2.0 * std::tan(d.horizontal_fov / 2.0));
  double focal = finiteParam(d, "focalLength", 0.0, warnings);
  if (focal == 0)
    focal = computed_focal;
  else if (std::abs(focal - computed_focal) > 1e-6)  // ignition::math::equal's tolerance
    warnings.push_back("The <focal_length>[" + formatNumber(focal) + "] you have provided for camera_ [" + d.name +
                       "] is inconsistent with specified image_width [" + std::to_string(width) + "] and HFOV [" +
                       formatNumber(d.horizontal_fov) + "]. Please double check to see that focal_length = width_ / "
                       "(2.0 * tan(HFOV/2.0)), the explected focal_lengtth value is [" +
                       formatNumber(computed_focal) + "], please update your camera_ model description accordingly.");

  // D = {k1, k2, t1, t2, k3}: the plugin's, or the sensor's lens with autoDistortion.
  double k1 = finiteParam(d, "distortionK1", 0.0, warnings), k2 = finiteParam(d, "distortionK2", 0.0, warnings);
  double k3 = finiteParam(d, "distortionK3", 0.0, warnings), t1 = finiteParam(d, "distortionT1", 0.0, warnings);
  double t2 = finiteParam(d, "distortionT2", 0.0, warnings);
  if (d.pluginBlock().flag("autoDistortion", false))
  {
    if (d.distortion.given)
    {
      k1 = d.distortion.k1, k2 = d.distortion.k2, k3 = d.distortion.k3;
      t1 = d.distortion.p1, t2 = d.distortion.p2;
    }
    else  // upstream reads the sensor's lens through a null pointer and crashes
      warnings.push_back("<autoDistortion> is true but the sensor's <camera> has no <distortion>; CameraInfo's D "
                         "is the plugin's distortionK1..T2. Add a <distortion> or set autoDistortion false");
  }

  sensor_msgs::CameraInfo info;
  info.width = width;
  info.height = height;
  info.distortion_model = "plumb_bob";
  info.D = {k1, k2, t1, t2, k3};
  info.K = {focal, 0, cx, 0, focal, cy, 0, 0, 1};
  info.R = {1, 0, 0, 0, 1, 0, 0, 0, 1};
  info.P = {focal, 0, cx, -focal * hack_baseline, 0, focal, cy, 0, 0, 0, 1, 0};
  return info;
}

void GazeboRosCamera::Load(Sensor& sensor)
{
  camera_ = &sensorAs<Camera>(sensor, "gazebo_ros_camera");
  nh_ = nodeHandle(sensor);
  const SensorDescription& d = sensor.description();
  const std::string camera_name = d.pluginParam("cameraName");
  frame_id_ = pluginFrameId(d, searchedTfPrefix(camera_name.empty() ? nh_ : ros::NodeHandle(nh_, camera_name)));
  image_pub_ = CountedPublisher::advertise<sensor_msgs::Image>(nh_, requireValidRosName(pluginTopic(d), owner()), 2);
  info_pub_ = CountedPublisher::advertise<sensor_msgs::CameraInfo>(
      nh_, requireValidRosName(pluginTopic(d, PluginTopic::CameraInfo), owner()), 2);
  hack_baseline_ = zero_baseline_ ? 0.0 : d.pluginNumber("hackBaseline", 0.0);
  encoding_ = imageEncodingOf(d.image_format);
  if (!encoding_.known)
    ROS_ERROR("Unsupported Gazebo ImageFormat '%s' of sensor '%s': its image is published as bgr8. Use L8, L16, "
              "R8G8B8, B8G8R8, R16G16B16 or BAYER_RGGB8/BGGR8/GBRG8/GRBG8 (or their *_INT* names)",
              d.image_format.c_str(), sensor.name().c_str());
  // Upstream's Init sets the lens's crop from <borderCrop>, true unless given.
  camera_->setDistortionCrop(d.pluginBlock().flag("borderCrop", true));
  computeCameraInfo();
}

void GazeboRosCamera::computeCameraInfo()
{
  std::vector<std::string> warnings;
  info_ = cameraInfoOf(camera_->description(), hack_baseline_, warnings);
  for (const std::string& warning : warnings)
    ROS_WARN("sensor '%s' (gazebo_ros_camera): %s", camera_->name().c_str(), warning.c_str());
}

bool GazeboRosCamera::subscribed() const
{
  return image_pub_.subscribed() || info_pub_.subscribed();
}

void GazeboRosCamera::OnUpdate()
{
  if (!takeUpdate(*camera_))
    return;
  publish(camera_->latest());
}

void GazeboRosCamera::publish(const CameraFrame& frame)
{
  // Images are serialized from the frame as roscpp sends them, only for topics with subscribers
  // (frame_messages.h). Published here, not through the outbox: the message is a view of the
  // frame's pixels, which the camera's next frame overwrites, and queuing a copy would cost what
  // serializing it does. Camera frames are rare beside a fleet's odometry and scans.
  const std_msgs::Header header = frameHeader(frame, frame_id_);
  image_pub_.publisher().publish(EncodedImageOf{frame, header, encoding_});
  info_pub_.publisher().publish(cameraInfo(frame, header));
  publishFrame(frame, header);
}

sensor_msgs::CameraInfo GazeboRosCamera::cameraInfo(const CameraFrame& f, const std_msgs::Header& header) const
{
  sensor_msgs::CameraInfo info = info_;
  info.header = header;
  return info;
}

GAZEBO_ROS_SENSOR_PLUGIN(GazeboRosCamera, "libgazebo_ros_camera.so");

}  // namespace bullet_plant
