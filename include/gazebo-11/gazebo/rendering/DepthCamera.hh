// rendering::DepthCamera: a depth camera sensor's camera as DepthCameraSensor::DepthCamera() gives it
// to plugins (DepthCameraPlugin; gazebo_ros_depth_camera and gazebo_ros_openni_kinect): a Camera
// whose frames also come, as its <depth_camera><output> says (Gazebo's: "depths" by default), as
// depths (metres along the optical axis, one float a pixel) or, where it names "points", as an RGB
// point cloud instead (x, y, z in the optical frame and the colour packed r << 16 | g << 8 | b in a
// float's bits, four floats a pixel). The simulator's renders, handed over by its sensor.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "gazebo/rendering/Camera.hh"

namespace gazebo
{
namespace rendering
{
class GZ_RENDERING_VISIBLE DepthCamera : public Camera
{
public:
  using Camera::Camera;
  ~DepthCamera() override;

  // The <camera> element as Camera's, and <depth_camera><output>.
  void Load(sdf::ElementPtr _sdf) override;

  // The latest frame's depths; null before the first, and where its output is points.
  const float* DepthData() const;

  using FloatFrame = std::function<void(const float*, unsigned int, unsigned int, unsigned int, const std::string&)>;
  // After each frame where its output is depths: its depths (width x height, depth 1, "FLOAT32").
  event::ConnectionPtr ConnectNewDepthFrame(FloatFrame _subscriber);
  void DisconnectNewDepthFrame(event::ConnectionPtr& _c) { _c.reset(); }
  // After each frame where its output names points: its points (width x height, 4 floats each,
  // "RGBPOINTS").
  event::ConnectionPtr ConnectNewRGBPointCloud(FloatFrame _subscriber);
  void DisconnectNewRGBPointCloud(event::ConnectionPtr& _c) { _c.reset(); }
  // Gazebo's reflectance and normals outputs: the plant renders neither, so these never fire.
  event::ConnectionPtr ConnectNewReflectanceFrame(FloatFrame _subscriber);
  event::ConnectionPtr ConnectNewNormalsPointCloud(FloatFrame _subscriber);

  // Not Gazebo's: whether its output names points (its frames come as RGB points, not depths), and
  // the simulator's new frame's depths or points (its sensor hands over the one its output asks
  // for, after the frame's image), kept and handed to the subscribers.
  bool OutputsPoints() const { return output_points_; }
  void TakeDepthFrame(const float* _depths);
  void TakeRGBPointCloud(const float* _rgbPoints);

private:
  bool output_points_ = false;
  std::vector<float> depths_, points_;
  event::EventT<void(const float*, unsigned int, unsigned int, unsigned int, const std::string&)> new_depth_frame_,
      new_rgb_point_cloud_, never_;
};
}  // namespace rendering
}  // namespace gazebo
