// rendering::DepthCamera (gazebo/rendering/DepthCamera.hh).
#include "gazebo/rendering/DepthCamera.hh"

namespace gazebo
{
namespace rendering
{
DepthCamera::~DepthCamera() = default;

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

void DepthCamera::TakeDepthFrame(const float* _depths, const float* _rgbPoints)
{
  const size_t pixels = size_t(ImageWidth()) * ImageHeight();
  depths_.assign(_depths, _depths + pixels);
  points_.assign(_rgbPoints, _rgbPoints + 4 * pixels);
  new_depth_frame_(depths_.data(), ImageWidth(), ImageHeight(), 1, "FLOAT32");
  new_rgb_point_cloud_(points_.data(), ImageWidth(), ImageHeight(), 1, "RGBPOINTS");
}
}  // namespace rendering
}  // namespace gazebo
