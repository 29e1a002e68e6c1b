// Sensors built from the URDF's <gazebo reference> blocks. They do their work only while active
// (someone subscribes), at their own update rate in simulated time.
#pragma once

#include <cstdint>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include <urdf_model/pose.h>

#include "bullet_plant/rate_gate.h"
#include "bullet_plant/robot_description.h"

namespace bullet_plant
{
class SensorContext;  // what a sensor reads of the simulation (sensors/sensor_context.h)
namespace detail
{
struct SensorRendering;  // casts the rays and fills sensors' outputs (sensors.cpp)
}

// sensor_msgs/LaserScan's fields. Ranges follow REP 117: +inf where nothing is hit within
// range_max, -inf where a hit is closer than range_min.
struct LaserScan
{
  int64_t stamp_ns = 0;
  float angle_min = 0, angle_max = 0, angle_increment = 0;
  float time_increment = 0, scan_time = 0;
  float range_min = 0, range_max = 0;
  int vertical_samples = 1;  // rows of `ranges` (1 for a planar lidar)
  std::vector<float> ranges;
  urdf::Pose origin;  // the sensor's frame in the world, where the rays were cast from
};

class Sensor
{
public:
  // noise_seed: the same on every run, so noisy sensors are deterministic too.
  Sensor(const SensorDescription& d, uint32_t noise_seed);
  virtual ~Sensor() = default;
  const SensorDescription& description() const { return description_; }
  const std::string& name() const { return description_.name; }
  // The seed of its noise: a plugin with a noise model of its own seeds its generator from it.
  uint32_t noiseSeed() const { return noise_seed_; }
  // Whether the plugin publishes on ROS at all (a known gazebo_ros plugin that loaded).
  bool publishesOnRos() const;

  void setActive(bool active) { active_ = active; }
  bool active() const { return active_; }
  // The readings made so far, and those skipped (a camera frame due while the one before it was
  // still rendering, out of lockstep: World::setLockstep).
  uint64_t updates() const { return updates_; }
  uint64_t skipped() const { return skipped_; }
  int64_t periodNs() const { return gate_.periodNs(); }
  // What a plugin makes of the rate, as Gazebo's Sensor::SetUpdateRate (0: every step it is active).
  void setUpdatePeriodNs(int64_t period_ns) { gate_.setPeriodNs(period_ns); }
  // Reads the simulation through `context` when a reading is due at `time_ns` (the robot calls it
  // for each active sensor every step).
  void updateIfDue(SensorContext& context, int64_t time_ns);
  // Whether a reading is due by `time_ns`: it is active and its rate lets it update by then.
  bool dueBy(int64_t time_ns) const { return active_ && gate_.wouldOpen(time_ns); }
  // Whether its rate lets it update by `time_ns`, active or not.
  bool rateDueBy(int64_t time_ns) const { return gate_.wouldOpen(time_ns); }
  // A reading made elsewhere (a camera frame rendering while the simulation goes on) becomes the
  // latest once it is done; with `wait`, this waits for it. The robot asks every step.
  virtual void collect(bool wait) {}

protected:
  // The reading at `time_ns`; false when the sensor could make none (a camera without OpenGL).
  virtual bool update(SensorContext& context, int64_t time_ns) = 0;

  SensorDescription description_;
  uint32_t noise_seed_;
  // 64 bits a draw: Boost's ziggurat (the lidar's noise) takes a normal sample from one draw of a
  // 64-bit engine and from two of a 32-bit one
  std::mt19937_64 noise_;
  bool active_ = false;
  uint64_t updates_ = 0;
  uint64_t skipped_ = 0;
  RateGate gate_;  // <update_rate>, or what the plugin makes of it
};

class Lidar : public Sensor
{
public:
  Lidar(const SensorDescription& d, uint32_t noise_seed);
  bool update(SensorContext& context, int64_t time_ns) override;
  bool hasScan() const { return updates_ > 0; }
  const LaserScan& latest() const { return scan_; }

private:
  friend struct detail::SensorRendering;
  LaserScan scan_;
  std::vector<double> directions_;  // its rays in its frame, computed at the first scan
};

// A camera frame: sensor_msgs/Image (rgb8; rgb16 too for a 16-bit <format>) and, for depth
// cameras, a 32FC1 depth image and the points of a PointCloud2, all in the optical frame (z
// forward, x right, y down).
struct CameraFrame
{
  int64_t stamp_ns = 0;
  int width = 0, height = 0;
  double fx = 0, fy = 0, cx = 0, cy = 0;  // pinhole: u = cx + fx * x / z, v = cy + fy * y / z
  std::vector<uint8_t> rgb;               // height * width * 3
  std::vector<uint16_t> rgb16;            // 16-bit formats (L16, R16G16B16 ...): the frame at 16 bits, rgb it rounded
  std::vector<float> depth;               // depth cameras: metres along z, NaN where nothing is hit
  std::vector<float> points;              // depth cameras: x y z per pixel, NaN where nothing is hit
};

// gazebo_ros_camera (type "camera") and gazebo_ros_openni_kinect (type "depth"). Pixels by OpenGL
// (rendering/gl_scene.h): the colour of what is seen, lit by one directional light, the sky colour
// elsewhere. Without OpenGL a camera makes no frames.
class Camera : public Sensor
{
public:
  Camera(const SensorDescription& d, uint32_t noise_seed);
  ~Camera() override;
  bool update(SensorContext& context, int64_t time_ns) override;
  void collect(bool wait) override;
  bool depthSensor() const { return description_.type == "depth"; }
  // Whether its <image><format> is a 16-bit one (L16, R16G16B16 ...): its frames render at 16 bits.
  bool sixteenBit() const;
  // gazebo_ros_openni_kinect publishes depths and points only within (pointCloudCutoff,
  // pointCloudCutoffMax), NaN elsewhere (defaults 0.4 and 5.0 m).
  double pointCloudCutoff() const;
  double pointCloudCutoffMax() const;
  bool hasFrame() const { return updates_ > 0; }
  // Whether a frame it rendered is still to be collected (its reading not yet counted).
  bool frameInFlight() const;
  const CameraFrame& latest() const { return frame_; }
  // Pinhole intrinsics from the horizontal field of view and the image size (square pixels).
  void intrinsics(double& fx, double& fy, double& cx, double& cy) const;
  // Whether a barrel <distortion> (k1 < 0) is cropped to hide its black border: Gazebo's default,
  // which gazebo_ros_camera_utils overrides with <borderCrop> (Distortion::SetCrop). The frames
  // after the call follow it.
  void setDistortionCrop(bool crop) { distortion_crop_ = crop; }
  bool distortionCrop() const { return distortion_crop_; }

private:
  friend struct detail::SensorRendering;
  CameraFrame frame_;
  struct Rendering;  // the frame being rendered (sensor_rendering.h)
  std::unique_ptr<Rendering> rendering_;
  std::vector<int16_t> noise_table_;   // the image noise's samples in levels of 1/255 (noiseSamples), drawn at the first frame
  std::vector<int32_t> noise16_table_;  // a 16-bit camera's, in levels of 1/65535 (noiseSamples16)
  bool distortion_crop_ = false;
};

// One touching point of a contact sensor's collision, as Gazebo's ContactSensor reports it: the
// point and the normal in the world, the normal pointing out of the other collision into the
// sensor's (the direction the contact pushes it); depth > 0 is penetration. The wrench is what the
// contact exerts on the sensor's body in its link frame, the torque about the body's centre of mass.
struct ContactPoint
{
  urdf::Vector3 position, normal;
  double depth = 0;
  urdf::Vector3 force, torque;
};

// The touching points between one of the sensor's collisions (collision1) and another
// (collision2), both "model::link::collision".
struct ContactState
{
  std::string collision1, collision2;
  std::vector<ContactPoint> points;
};

struct ContactReading
{
  int64_t stamp_ns = 0;
  std::vector<ContactState> states;
};

// A <sensor type="contact">: each update, the contacts of its <contact><collision>s at the end of
// the step (the impulses the step's solver applied, over the step).
class ContactSensor : public Sensor
{
public:
  ContactSensor(const SensorDescription& d, uint32_t noise_seed) : Sensor(d, noise_seed) {}
  bool update(SensorContext& context, int64_t time_ns) override;
  bool hasReading() const { return updates_ > 0; }
  const ContactReading& latest() const { return reading_; }

private:
  ContactReading reading_;
};

}  // namespace bullet_plant
