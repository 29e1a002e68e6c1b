// Sensors from the URDF's <gazebo reference> blocks, and how each one renders what it sees.
#include "bullet_plant/sensors.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <boost/random/normal_distribution.hpp>

#include "bullet_plant/geometry.h"
#include "bullet_plant/image_encoding.h"
#include "sensors/sensor_context.h"
#include "sensors/sensor_rendering.h"

namespace bullet_plant
{
Sensor::Sensor(const SensorDescription& d, uint32_t noise_seed)
  : description_(d), noise_seed_(noise_seed), noise_(noise_seed), gate_(periodNsOfRate(d.update_rate))
{
}

bool Sensor::publishesOnRos() const
{
  return description_.plugin_file != nullptr;
}

void Sensor::updateIfDue(SensorContext& context, int64_t time_ns)
{
  if (gate_.due(time_ns) && update(context, time_ns))
    ++updates_;
}

Lidar::Lidar(const SensorDescription& d, uint32_t noise_seed) : Sensor(d, noise_seed) {}

namespace
{
// The sensor's frame in the world: its link's frame, then its <pose> in the link.
Frame sensorPose(const SensorContext& context, const SensorDescription& d)
{
  return Frame::fromPose(context.linkPose(d.link)) * Frame::fromPose(d.pose);
}
}  // namespace

bool Lidar::update(SensorContext& context, int64_t time_ns)
{
  const urdf::Pose link = context.linkPose(description_.link);
  scan_.origin = compose(link, description_.pose);
  detail::SensorRendering::scan(*this, context.lidarScene(), Frame::fromPose(link) * Frame::fromPose(description_.pose),
                                time_ns);
  return true;
}

bool ContactSensor::update(SensorContext& context, int64_t time_ns)
{
  reading_.stamp_ns = time_ns;
  reading_.states = context.contacts(description_.link, description_.contact_collisions);
  return true;
}

bool Camera::update(SensorContext& context, int64_t time_ns)
{
  GlScene* gl = context.glScene();
  if (!gl)
    return false;  // cameras are off: the world has said why, once
  Rendering& r = *rendering_;
  if (!context.lockstep() && r.pending && r.worker && !r.worker->done(r.ticket))
  {
    ++skipped_;  // late: Gazebo's rendering thread drops the frame and the simulation goes on
    return false;
  }
  collect(true);  // the previous frame first: frames come in their order
  detail::SensorRendering::render(*this, *gl, context.frameWorker(), sensorPose(context, description_),
                                  context.lighting(), time_ns);
  return false;  // the reading counts when collected
}

void Camera::collect(bool wait)
{
  Rendering& r = *rendering_;
  if (!r.pending || (r.worker && !wait && !r.worker->done(r.ticket)))
    return;
  if (r.worker)
    r.worker->wait(r.ticket);
  r.pending = false;
  if (!r.error.empty())
    throw std::runtime_error("camera '" + description_.name + "': " + r.error);
  detail::SensorRendering::finish(*this);
  ++updates_;
}

bool Camera::frameInFlight() const { return rendering_->pending; }

Camera::~Camera()
{
  if (rendering_->pending && rendering_->worker)
    rendering_->worker->wait(rendering_->ticket);  // its job writes into this camera
}

Camera::Camera(const SensorDescription& d, uint32_t noise_seed)
  : Sensor(d, noise_seed), rendering_(new Rendering), distortion_crop_(d.distortion.k1 < 0)  // Distortion::Load
{
  // The plugin's <updateRate> throttles what the sensor renders (0: the sensor's rate).
  gate_.setPeriodNs(std::max(gate_.periodNs(), periodNsOfRate(d.pluginNumber("updateRate", 0.0))));
}

bool Camera::sixteenBit() const { return imageEncodingOf(description_.image_format).sixteenBit(); }

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

void detail::SensorRendering::scan(Lidar& lidar, const RayScene& scene, const Frame& pose, int64_t time_ns)
{
  const SensorDescription& d = lidar.description();
  const int n = d.horizontal_samples;
  const double da = n > 1 ? (d.horizontal_max_angle - d.horizontal_min_angle) / (n - 1) : 0.0;
  if (lidar.directions_.empty())
  {
    std::vector<double> elevations(d.vertical_samples, d.vertical_min_angle);
    for (int v = 1; v < d.vertical_samples; ++v)
      elevations[v] = d.vertical_min_angle + v * (d.vertical_max_angle - d.vertical_min_angle) / (d.vertical_samples - 1);
    lidar.directions_ = fanDirections(d.horizontal_min_angle, da, n, elevations);
  }
  std::vector<double> distances;
  // Gazebo's gpu_ray renders the visuals, its ray lidar hits the collisions. Both see nothing nearer
  // than the minimum range and what lies beyond it: the ray lidar's rays start there, gpu_ray's near
  // clip plane is there.
  scene.castRays(pose, lidar.directions_, std::max(0.0, d.range_min), d.range_max,
                 d.type == "gpu_ray" ? kSeenByCameras : kSeenByLidars, distances);

  LaserScan& scan = lidar.scan_;
  scan.stamp_ns = time_ns;
  scan.angle_min = float(d.horizontal_min_angle);
  scan.angle_max = float(d.horizontal_max_angle);
  scan.angle_increment = float(da);
  scan.time_increment = 0.0f;
  scan.scan_time = d.update_rate > 0 ? float(1.0 / d.update_rate) : 0.0f;
  scan.range_min = float(d.range_min);
  scan.range_max = float(d.range_max);
  scan.vertical_samples = d.vertical_samples;
  scan.ranges.resize(distances.size());
  // Boost's ziggurat: a sample for 14 ns where std::normal_distribution's polar method takes 24 (a
  // 1081-ray scan's noise was 4 % of a racing env step); Gazebo draws each ray's from a normal too.
  boost::random::normal_distribution<double> noise(d.noise.mean, d.noise.stddev > 0 ? d.noise.stddev : 1.0);
  const bool noisy = d.noise.gaussian && d.noise.stddev > 0;
  for (size_t i = 0; i < distances.size(); ++i)
  {
    double r = distances[i];
    if (std::isinf(r))
      scan.ranges[i] = std::numeric_limits<float>::infinity();
    else
    {
      if (noisy)
        r += noise(lidar.noise_);
      scan.ranges[i] = float(std::max(d.range_min, std::min(r, d.range_max)));
    }
  }
}

namespace
{
// A clean frame (8 or 16 bits) through the lens, then the camera's noise; `undistorted` keeps the
// frame as rendered (its buffer kept from frame to frame).
template <class Value>
void throughTheLens(const DistortionRemap& remap, const PinholeCamera& camera, std::vector<Value>& frame,
                    std::vector<Value>& undistorted)
{
  undistorted.swap(frame);
  frame.resize(undistorted.size());
  remapRgb(remap, undistorted.data(), frame.data());
  addNoise(camera, frame.data());
}
}  // namespace

// A pinhole camera's frame by GL rasterization (lit colours with noise, and depths); the noise
// comes from a table of gaussian samples drawn once from the camera's own generator and a
// per-frame offset from it, drawn here in the simulation's order, so frames are the same on every
// run whichever thread renders them.
void detail::SensorRendering::render(Camera& camera, GlScene& scene, FrameWorker* worker, const Frame& pose,
                                     const Lighting& lighting, int64_t time_ns)
{
  const SensorDescription& d = camera.description();
  const int w = d.image_width, h = d.image_height;
  PinholeCamera pinhole;
  pinhole.width = w;
  pinhole.height = h;
  camera.intrinsics(pinhole.fx, pinhole.fy, pinhole.cx, pinhole.cy);
  pinhole.depth = camera.depthSensor();
  pinhole.near = d.clip_near > 0 ? d.clip_near : 0.0;
  pinhole.far = d.clip_far > 0 ? d.clip_far : 100.0;
  pinhole.bits = camera.sixteenBit() ? 16 : 8;
  if (d.noise.gaussian && d.noise.stddev > 0)
  {
    // drawn once: the table stays where it is while a job reads it
    std::normal_distribution<double> noise(d.noise.mean, d.noise.stddev);
    auto draw = [&] { return noise(camera.noise_); };
    if (pinhole.bits == 16)
    {
      if (camera.noise16_table_.empty())
        camera.noise16_table_ = noiseSamples16(size_t(w) * size_t(h), draw);
      pinhole.noise16 = camera.noise16_table_.data();
    }
    else
    {
      if (camera.noise_table_.empty())
        camera.noise_table_ = noiseSamples(size_t(w) * size_t(h), draw);
      pinhole.noise = camera.noise_table_.data();
    }
    pinhole.noise_offset = size_t(camera.noise_() % PinholeCamera::kNoiseOffsets);
  }
  Camera::Rendering& r = *camera.rendering_;
  if (!r.distortion_ready || r.distortion_cropped != camera.distortion_crop_)
  {
    // No frame renders now (update collected the last): the job may read the remap from here on.
    r.distortion = distortionRemap(d.distortion, w, h, d.horizontal_fov, camera.distortion_crop_);
    r.distortion_ready = true;
    r.distortion_cropped = camera.distortion_crop_;
  }
  r.stamp_ns = time_ns;
  r.pending = true;
  r.worker = worker;
  r.error.clear();
  auto job = [&scene, &r, draws = scene.snapshot(), pose, pinhole, lighting] {
    try
    {
      if (r.distortion.empty())
        scene.render(draws, pose, pinhole, lighting, r.image);
      else
      {
        // The lens after the render, as Gazebo's compositor warps the rendered texture, and the
        // noise after the lens, as Gazebo's noise compositor follows the distortion's.
        PinholeCamera clean = pinhole;
        clean.noise = nullptr;
        clean.noise16 = nullptr;
        scene.render(draws, pose, clean, lighting, r.image);
        if (pinhole.bits == 16)
        {
          throughTheLens(r.distortion, pinhole, r.image.rgb16, r.undistorted16);
          rgb8FromRgb16(r.image.rgb16.data(), r.image.rgb8.data(), r.image.rgb8.size());
        }
        else
          throughTheLens(r.distortion, pinhole, r.image.rgb8, r.undistorted);
      }
    }
    catch (const std::exception& e)
    {
      r.error = e.what();
    }
  };
  if (worker)
    r.ticket = worker->submit(job);
  else
    job();
}

void detail::SensorRendering::finish(Camera& camera)
{
  Camera::Rendering& r = *camera.rendering_;
  const SensorDescription& d = camera.description();
  CameraFrame& out = camera.frame_;
  const int w = d.image_width, h = d.image_height;
  const bool depth = camera.depthSensor();
  camera.intrinsics(out.fx, out.fy, out.cx, out.cy);
  out.stamp_ns = r.stamp_ns;
  out.width = w;
  out.height = h;
  out.rgb.swap(r.image.rgb8);  // the previous frame's buffer goes back to the renderer
  out.rgb16.swap(r.image.rgb16);

  const size_t pixels = size_t(w) * h;
  // Every pixel written once: its depth and point, or NaN where nothing is within the clip range.
  constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
  out.depth.resize(depth ? pixels : 0);
  out.points.resize(depth ? pixels * 3 : 0);
  std::vector<float> x_per_depth(depth ? size_t(w) : 0);  // per column: no division per pixel
  for (int u = 0; depth && u < w; ++u)
    x_per_depth[size_t(u)] = float((u - out.cx) / out.fx);
  for (int v = 0; depth && v < h; ++v)
  {
    const float y = float((v - out.cy) / out.fy);
    for (int u = 0; u < w; ++u)
    {
      const size_t pixel = size_t(v) * w + u;
      const float z = r.image.depth[pixel];
      const bool hit = !std::isinf(z);
      out.depth[pixel] = hit ? z : kNaN;
      out.points[3 * pixel] = hit ? x_per_depth[size_t(u)] * z : kNaN;
      out.points[3 * pixel + 1] = hit ? y * z : kNaN;
      out.points[3 * pixel + 2] = hit ? z : kNaN;
    }
  }
}

}  // namespace bullet_plant
