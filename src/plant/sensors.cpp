// Sensors from the URDF's <gazebo reference> blocks, and how each one renders what it sees.
#include "bullet_plant/sensors.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "sensor_rendering.h"

namespace bullet_plant
{
Sensor::Sensor(const SensorDescription& d, uint32_t noise_seed) : description_(d), noise_(noise_seed)
{
  period_ns_ = d.update_rate > 0 ? static_cast<int64_t>(std::llround(1e9 / d.update_rate)) : 0;
}

std::string resolveTfFrame(const std::string& prefix, const std::string& frame)
{
  if (!frame.empty() && frame[0] == '/')
    return frame.substr(1);
  if (prefix.empty())
    return frame;
  return (prefix[0] == '/' ? prefix.substr(1) : prefix) + "/" + frame;
}

// Laser and camera plugins: tf::resolve(tf_prefix, frameName). A camera without <frameName> would
// get "tf_prefix/" from gazebo_ros_camera, which no tf consumer accepts: the plant uses its link.
std::string Sensor::frameId() const
{
  return resolveTfFrame(tf_prefix_, description_.pluginParam("frameName", description_.link));
}

void Sensor::setNamespace(const std::string& spawn_namespace, const std::string& model_name)
{
  if (description_.hasPluginParam("robotNamespace"))
  {
    namespace_ = description_.plugin.at("robotNamespace");
    if (namespace_.empty())  // GetRobotNamespace: an empty element means the model's name
      namespace_ = model_name;
  }
  else
    namespace_ = spawn_namespace.empty() ? defaultNamespace(model_name) : spawn_namespace;
  tf_prefix_ = namespace_;
  while (!tf_prefix_.empty() && tf_prefix_.back() == '/')
    tf_prefix_.pop_back();
}

std::string Sensor::defaultNamespace(const std::string&) const { return ""; }

bool Sensor::publishesOnRos() const
{
  const PluginKind kind = description_.plugin_kind;
  return kind != PluginKind::None && kind != PluginKind::Unknown;
}

bool Sensor::due(int64_t time_ns)
{
  if (last_update_ns_ >= 0 && time_ns - last_update_ns_ < period_ns_ && time_ns >= last_update_ns_)
    return false;
  last_update_ns_ = time_ns;
  ++updates_;
  return true;
}

Lidar::Lidar(const SensorDescription& d, uint32_t noise_seed) : Sensor(d, noise_seed) {}

// gazebo_ros_laser: no <frameName> means "/world".
std::string Lidar::frameId() const { return resolveTfFrame(tf_prefix_, description_.pluginParam("frameName", "/world")); }

Camera::Camera(const SensorDescription& d, uint32_t noise_seed) : Sensor(d, noise_seed)
{
  // The plugin's <updateRate> throttles what the sensor renders (0: the sensor's rate).
  const double plugin_rate = d.pluginNumber("updateRate", 0.0);
  if (plugin_rate > 0)
    period_ns_ = std::max(period_ns_, static_cast<int64_t>(std::llround(1e9 / plugin_rate)));
}

namespace
{
std::string joinTopic(const std::string& camera, const std::string& topic)
{
  if (!topic.empty() && topic[0] == '/')
    return topic;
  return camera.empty() ? topic : camera + "/" + topic;
}
}  // namespace

// Topics of gazebo_ros_camera and gazebo_ros_openni_kinect: under <cameraName> (default empty),
// with the defaults of their sources.
std::string Camera::topic() const
{
  return joinTopic(description_.pluginParam("cameraName"), description_.pluginParam("imageTopicName", "image_raw"));
}

std::string Camera::cameraInfoTopic() const
{
  return joinTopic(description_.pluginParam("cameraName"), description_.pluginParam("cameraInfoTopicName", "camera_info"));
}

std::string Camera::depthTopic() const
{
  return joinTopic(description_.pluginParam("cameraName"),
                   description_.pluginParam("depthImageTopicName", "depth/image_raw"));
}

std::string Camera::depthCameraInfoTopic() const
{
  return joinTopic(description_.pluginParam("cameraName"),
                   description_.pluginParam("depthImageCameraInfoTopicName", "depth/camera_info"));
}

std::string Camera::pointsTopic() const
{
  return joinTopic(description_.pluginParam("cameraName"), description_.pluginParam("pointCloudTopicName", "points"));
}

double Camera::pointCloudCutoff() const { return description_.pluginNumber("pointCloudCutoff", 0.4); }
double Camera::pointCloudCutoffMax() const { return description_.pluginNumber("pointCloudCutoffMax", 5.0); }

void Camera::intrinsics(double& fx, double& fy, double& cx, double& cy) const
{
  const int w = description_.image_width, h = description_.image_height;
  fx = fy = w / (2.0 * std::tan(description_.horizontal_fov / 2.0));
  cx = (w - 1) / 2.0;
  cy = (h - 1) / 2.0;
}

// ------------------------------------------------------------------------------------ rendering

void detail::SensorRendering::scan(Lidar& lidar, const RayCaster& caster, const Frame& pose, int64_t time_ns)
{
  const SensorDescription& d = lidar.description();
  const int n = d.horizontal_samples;
  const double da = n > 1 ? (d.horizontal_max_angle - d.horizontal_min_angle) / (n - 1) : 0.0;
  std::vector<double> elevations(d.vertical_samples, d.vertical_min_angle);
  for (int v = 1; v < d.vertical_samples; ++v)
    elevations[v] = d.vertical_min_angle + v * (d.vertical_max_angle - d.vertical_min_angle) / (d.vertical_samples - 1);
  std::vector<double> distances;
  caster.castFan(pose, d.horizontal_min_angle, da, n, elevations, d.range_max, distances);

  LaserScan& scan = lidar.scan_;
  scan.stamp_ns = time_ns;
  scan.frame_id = lidar.frameId();
  scan.angle_min = float(d.horizontal_min_angle);
  scan.angle_max = float(d.horizontal_max_angle);
  scan.angle_increment = float(da);
  scan.time_increment = 0.0f;
  scan.scan_time = d.update_rate > 0 ? float(1.0 / d.update_rate) : 0.0f;
  scan.range_min = float(d.range_min);
  scan.range_max = float(d.range_max);
  scan.vertical_samples = d.vertical_samples;
  scan.ranges.resize(distances.size());
  std::normal_distribution<double> noise(d.noise.mean, d.noise.stddev > 0 ? d.noise.stddev : 1.0);
  const bool noisy = d.noise.gaussian && d.noise.stddev > 0;
  for (size_t i = 0; i < distances.size(); ++i)
  {
    double r = distances[i];
    if (std::isinf(r))
      scan.ranges[i] = std::numeric_limits<float>::infinity();
    else if (r < d.range_min)
      scan.ranges[i] = -std::numeric_limits<float>::infinity();
    else
    {
      if (noisy)
        r += noise(lidar.noise_);
      scan.ranges[i] = float(std::max(d.range_min, std::min(r, d.range_max)));
    }
  }
}

// Ray casting through every pixel centre of a pinhole camera: the colour of what is hit, lit by one
// directional light with an ambient term, the sky where nothing is hit.
void detail::SensorRendering::render(Camera& camera, const RayCaster& caster, const Frame& pose,
                                     const urdf::Vector3& light_direction, int64_t time_ns)
{
  const SensorDescription& d = camera.description();
  CameraFrame& out = camera.frame_;
  const int w = d.image_width, h = d.image_height;
  const bool depth = camera.depthSensor();
  camera.intrinsics(out.fx, out.fy, out.cx, out.cy);
  out.stamp_ns = time_ns;
  out.frame_id = camera.frameId();
  out.width = w;
  out.height = h;
  out.rgb.resize(size_t(w) * h * 3);
  out.depth.assign(depth ? size_t(w) * h : 0, std::numeric_limits<float>::quiet_NaN());
  out.points.assign(depth ? size_t(w) * h * 3 : 0, std::numeric_limits<float>::quiet_NaN());
  const double near = d.clip_near > 0 ? d.clip_near : 0.0, far = d.clip_far > 0 ? d.clip_far : 100.0;
  double light[3] = {-light_direction.x, -light_direction.y, -light_direction.z};  // towards the light
  const double light_norm = std::sqrt(light[0] * light[0] + light[1] * light[1] + light[2] * light[2]);
  for (double& l : light)
    l = light_norm > 0 ? l / light_norm : 0.0;
  static const float kSky[3] = {0.70f, 0.80f, 0.95f};
  constexpr double kAmbient = 0.35;
  const bool noisy = d.noise.gaussian && d.noise.stddev > 0;
  std::normal_distribution<double> noise(d.noise.mean, noisy ? d.noise.stddev : 1.0);
  for (int v = 0; v < h; ++v)
    for (int u = 0; u < w; ++u)
    {
      // optical (x right, y down, z forward) -> camera link (x forward, y left, z up)
      const double xo = (u - out.cx) / out.fx, yo = (v - out.cy) / out.fy;
      const double length = std::sqrt(1.0 + xo * xo + yo * yo);
      const double in_link[3] = {1.0 / length, -xo / length, -yo / length};
      double dir[3];
      pose.rotate(in_link, dir);
      const RayHit hit = caster.castHit(pose.t, dir, far * length);
      const double z = hit.distance / length;  // depth along the optical axis
      const size_t pixel = size_t(v) * w + u;
      float colour[3] = {kSky[0], kSky[1], kSky[2]};
      if (hit.primitive && z >= near)
      {
        double point[3] = {pose.t[0] + dir[0] * hit.distance, pose.t[1] + dir[1] * hit.distance,
                           pose.t[2] + dir[2] * hit.distance};
        double normal[3];
        hit.primitive->normalAt(point, normal, hit.triangle);
        if (normal[0] * dir[0] + normal[1] * dir[1] + normal[2] * dir[2] > 0)  // a triangle seen from behind
          for (double& n : normal)
            n = -n;
        const double diffuse = std::max(0.0, normal[0] * light[0] + normal[1] * light[1] + normal[2] * light[2]);
        const double shade = kAmbient + (1.0 - kAmbient) * diffuse;
        const Rgba& c = hit.primitive->colourAt(hit.triangle);
        colour[0] = float(c.r * shade);
        colour[1] = float(c.g * shade);
        colour[2] = float(c.b * shade);
        if (depth)
        {
          out.depth[pixel] = float(z);
          out.points[3 * pixel] = float(xo * z);
          out.points[3 * pixel + 1] = float(yo * z);
          out.points[3 * pixel + 2] = float(z);
        }
      }
      for (int k = 0; k < 3; ++k)
      {
        double value = colour[k] + (noisy ? noise(camera.noise_) : 0.0);
        out.rgb[3 * pixel + k] = uint8_t(std::lround(std::max(0.0, std::min(1.0, value)) * 255.0));
      }
    }
}

}  // namespace bullet_plant
