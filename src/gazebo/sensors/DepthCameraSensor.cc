// sensors::DepthCameraSensor (gazebo/sensors/DepthCameraSensor.hh).
#include "gazebo/sensors/DepthCameraSensor.hh"

#include "gazebo/rendering/DepthCamera.hh"

namespace gazebo
{
namespace sensors
{
DepthCameraSensor::DepthCameraSensor() = default;

DepthCameraSensor::~DepthCameraSensor() = default;

rendering::DepthCameraPtr DepthCameraSensor::DepthCamera() const
{
  return std::dynamic_pointer_cast<rendering::DepthCamera>(camera);
}

const float* DepthCameraSensor::DepthData() const
{
  const rendering::DepthCameraPtr depth = DepthCamera();
  return depth ? depth->DepthData() : nullptr;
}

rendering::CameraPtr DepthCameraSensor::MakeCamera()
{
  std::shared_ptr<SensorBridge> simulated = bridge;
  return std::make_shared<rendering::DepthCamera>(ParentName() + "::" + Name(), [simulated] {
    return simulated ? simulated->worldPose() : ignition::math::Pose3d::Zero;
  });
}

bool DepthCameraSensor::UpdateImpl(bool force)
{
  if (!CameraSensor::UpdateImpl(force))
    return false;
  auto* frames = dynamic_cast<DepthCameraBridge*>(bridge.get());
  const rendering::DepthCameraPtr depth = DepthCamera();
  if (!frames || !depth)
    return true;
  // Gazebo's camera reads one of the two back from its render targets, as its <output> asks
  if (depth->OutputsPoints())
  {
    if (const float* points = frames->rgbPoints())
      depth->TakeRGBPointCloud(points);
  }
  else if (const float* depths = frames->depths())
    depth->TakeDepthFrame(depths);
  return true;
}
}  // namespace sensors
}  // namespace gazebo
