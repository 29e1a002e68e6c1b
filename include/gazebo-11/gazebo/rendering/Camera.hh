// rendering::Camera: a camera sensor's camera as CameraSensor::Camera() gives it to plugins
// (CameraPlugin and gazebo_ros_camera_utils read its image size, format and field of view and take
// its frames from ConnectNewImageFrame). Its frames are the simulator's renders of the sensor (the
// plant's OpenGL camera, one simulation of each sensor), handed over by its sensor; it renders
// nothing itself and there is no OGRE scene behind it. What differs: docs/gazebo_api.md.
#pragma once

#include <functional>
#include <mutex>
#include <string>
#include <vector>

#include <ignition/math/Angle.hh>
#include <ignition/math/Pose3.hh>
#include <sdf/sdf.hh>

#include "gazebo/common/Event.hh"
#include "gazebo/common/Time.hh"
#include "gazebo/rendering/Distortion.hh"
#include "gazebo/rendering/RenderTypes.hh"
#include "gazebo/util/system.hh"

namespace gazebo
{
namespace rendering
{
class GZ_RENDERING_VISIBLE Camera : public std::enable_shared_from_this<Camera>
{
public:
  // Not Gazebo's (its scene makes cameras: Scene::CreateCamera): its sensor makes it, named, with the
  // sensor's world pose.
  Camera(const std::string& _name, std::function<ignition::math::Pose3d()> _worldPose);
  virtual ~Camera();

  // The <camera> element: image size and format, field of view, clip planes, lens distortion
  // (SDF's defaults: 320 x 240 R8G8B8, 1.047 rad, 0.1 to 100 m).
  virtual void Load(sdf::ElementPtr _sdf);
  virtual void Init() {}
  virtual void Fini() {}
  bool IsInitialized() const { return true; }

  std::string Name() const { return name_; }
  std::string ScopedName() const { return name_; }
  unsigned int ImageWidth() const { return width_; }
  unsigned int ImageHeight() const { return height_; }
  // Bytes a pixel of its format (Gazebo's: L8 1, L16 2, R8G8B8 and B8G8R8 3, R16G16B16 6, Bayer 1 ...).
  unsigned int ImageDepth() const;
  std::string ImageFormat() const { return format_; }
  size_t ImageByteSize() const { return size_t(width_) * height_ * ImageDepth(); }
  // The latest frame, in its format's bytes; null before the first.
  const unsigned char* ImageData(unsigned int _i = 0) const;

  ignition::math::Angle HFOV() const { return hfov_; }
  // Gazebo's: the vertical field of view of the image's aspect ratio.
  ignition::math::Angle VFOV() const;
  // What HFOV reports from now on (the simulator renders the <horizontal_fov> it was made with).
  void SetHFOV(ignition::math::Angle _angle) { hfov_ = _angle; }
  double AspectRatio() const { return height_ ? double(width_) / height_ : 1.0; }
  double NearClip() const { return near_; }
  double FarClip() const { return far_; }
  // Its <lens><distortion>, or null where it has none (as Gazebo's).
  DistortionPtr LensDistortion() const { return distortion_; }

  ignition::math::Pose3d WorldPose() const { return world_pose_(); }
  ignition::math::Vector3d WorldPosition() const { return WorldPose().Pos(); }
  ignition::math::Quaterniond WorldRotation() const { return WorldPose().Rot(); }
  // The wall time its latest frame came, and its frames a second over the last ones.
  common::Time LastRenderWallTime() const;
  double RenderRate() const;

  // After each frame: its bytes, width, height, depth (bytes a pixel) and format.
  event::ConnectionPtr ConnectNewImageFrame(
      std::function<void(const unsigned char*, unsigned int, unsigned int, unsigned int, const std::string&)> _subscriber);
  void DisconnectNewImageFrame(event::ConnectionPtr& _c) { _c.reset(); }

  // Not Gazebo's: the simulator's new frame (ImageByteSize bytes), kept and handed to the
  // subscribers (its sensor calls it).
  void TakeFrame(const unsigned char* _image);

private:
  std::string name_;
  std::function<ignition::math::Pose3d()> world_pose_;
  unsigned int width_ = 320, height_ = 240;
  std::string format_ = "R8G8B8";
  ignition::math::Angle hfov_{1.047};
  double near_ = 0.1, far_ = 100;
  DistortionPtr distortion_;
  mutable std::mutex mutex_;
  std::vector<unsigned char> image_;
  common::Time last_render_wall_time_;
  std::vector<common::Time> recent_frames_;  // wall times of the last frames, for RenderRate
  event::EventT<void(const unsigned char*, unsigned int, unsigned int, unsigned int, const std::string&)> new_image_frame_;
};
}  // namespace rendering
}  // namespace gazebo
