// rendering::DepthCamera (gazebo/rendering/DepthCamera.hh).
#include "gazebo/rendering/DepthCamera.hh"

namespace gazebo
{
namespace rendering
{
DepthCamera::~DepthCamera() = default;

void DepthCamera::Load(sdf::ElementPtr _sdf)
{
  Camera::Load(_sdf);
  const std::string output = _sdf && _sdf->HasElement("depth_camera")
                                 ? _sdf->GetElement("depth_camera")->Get<std::string>("output")
                                 : std::string("depths");
  output_points_ = output.find("points") != std::string::npos;
}

const float* DepthCamera::DepthData() const { return depths_.empty() ? nullptr : depths_.data(); }

event::ConnectionPtr DepthCamera::ConnectNewDepthFrame(FloatFrame _subscriber)
{
  return new_depth_frame_.Connect(_subscriber);
}

event::ConnectionPtr DepthCamera::ConnectNewRGBPointCloud(FloatFrame _subscriber)
{
  return new_rgb_point_cloud_.Connect(_subscriber);
}

event::ConnectionPtr DepthCamera::ConnectNewReflectanceFrame(FloatFrame _subscriber)
{
  return never_.Connect(_subscriber);
}

event::ConnectionPtr DepthCamera::ConnectNewNormalsPointCloud(FloatFrame _subscriber)
{
  return never_.Connect(_subscriber);
}

void DepthCamera::TakeDepthFrame(const float* _depths)
{
  depths_.assign(_depths, _depths + size_t(ImageWidth()) * ImageHeight());
  new_depth_frame_(depths_.data(), ImageWidth(), ImageHeight(), 1, "FLOAT32");
}

void DepthCamera::TakeRGBPointCloud(const float* _rgbPoints)
{
  points_.assign(_rgbPoints, _rgbPoints + 4 * size_t(ImageWidth()) * ImageHeight());
  new_rgb_point_cloud_(points_.data(), ImageWidth(), ImageHeight(), 1, "RGBPOINTS");
}
}  // namespace rendering
}  // namespace gazebo
