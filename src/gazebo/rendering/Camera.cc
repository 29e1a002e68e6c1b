// rendering::Camera (gazebo/rendering/Camera.hh).
#include "gazebo/rendering/Camera.hh"

#include <cmath>

namespace gazebo
{
namespace rendering
{
namespace
{
constexpr size_t kRateFrames = 10;  // RenderRate averages over the last ones
}

Camera::Camera(const std::string& _name, std::function<ignition::math::Pose3d()> _worldPose)
  : name_(_name), world_pose_(std::move(_worldPose))
{
}

Camera::~Camera() = default;

void Camera::Load(sdf::ElementPtr _sdf)
{
  if (!_sdf)
    return;
  hfov_ = _sdf->Get<double>("horizontal_fov");
  const sdf::ElementPtr image = _sdf->GetElement("image");
  width_ = image->Get<unsigned int>("width");
  height_ = image->Get<unsigned int>("height");
  format_ = image->Get<std::string>("format");
  const sdf::ElementPtr clip = _sdf->GetElement("clip");
  near_ = clip->Get<double>("near");
  far_ = clip->Get<double>("far");
  if (_sdf->HasElement("distortion"))
  {
    distortion_ = std::make_shared<Distortion>();
    distortion_->Load(_sdf->GetElement("distortion"));
  }
}

unsigned int Camera::ImageDepth() const
{
  // Gazebo's Camera::ImageDepth
  const std::string& f = format_;
  if (f == "L8" || f == "L_INT8" || f.rfind("BAYER", 0) == 0)
    return 1;
  if (f == "L16" || f == "L_INT16" || f == "R_FLOAT16")
    return 2;
  if (f == "R16G16B16" || f == "RGB_INT16" || f == "RGB_FLOAT16")
    return 6;
  if (f == "R_FLOAT32")
    return 4;
  if (f == "RGB_FLOAT32")
    return 12;
  return 3;
}

const unsigned char* Camera::ImageData(unsigned int /*_i*/) const
{
  std::lock_guard<std::mutex> lock(mutex_);
  return image_.empty() ? nullptr : image_.data();
}

ignition::math::Angle Camera::VFOV() const
{
  return 2.0 * std::atan(std::tan(hfov_.Radian() / 2.0) / AspectRatio());
}

common::Time Camera::LastRenderWallTime() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  return last_render_wall_time_;
}

double Camera::RenderRate() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  if (recent_frames_.size() < 2)
    return 0.0;
  const double span = (recent_frames_.back() - recent_frames_.front()).Double();
  return span > 0 ? (recent_frames_.size() - 1) / span : 0.0;
}

event::ConnectionPtr Camera::ConnectNewImageFrame(
    std::function<void(const unsigned char*, unsigned int, unsigned int, unsigned int, const std::string&)> _subscriber)
{
  return new_image_frame_.Connect(_subscriber);
}

void Camera::TakeFrame(const unsigned char* _image)
{
  const common::Time now = common::Time::GetWallTime();
  {
    std::lock_guard<std::mutex> lock(mutex_);
    image_.assign(_image, _image + ImageByteSize());
    last_render_wall_time_ = now;
    recent_frames_.push_back(now);
    if (recent_frames_.size() > kRateFrames)
      recent_frames_.erase(recent_frames_.begin());
  }
  new_image_frame_(image_.data(), width_, height_, ImageDepth(), format_);
}
}  // namespace rendering
}  // namespace gazebo
