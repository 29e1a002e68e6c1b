// gazebo_ros_multicamera: a <sensor type="multicamera">'s cameras (the plant builds one per
// <camera>) each published as gazebo_ros_camera under <cameraName>/left or <cameraName>/right, by
// whether the <camera>'s name contains "left" or "right"; one frameName for both, as upstream. The
// left camera's hackBaseline is 0 whatever is given, the right's <hackBaseline> (a stereo pair's
// P[3] = -fx * baseline). A camera named neither is not published, as upstream loads nothing for
// it (docs/interfaces.md section 11). Each camera is gazebo_ros_camera_utils of its own <camera>
// (its format, size, field of view, lens) with the plugin block's parameters, as upstream's.
#include "gazebo_ros_camera.h"

namespace bullet_plant
{
class GazeboRosMultiCamera : public GazeboRosCamera
{
public:
  void Load(Sensor& sensor) override
  {
    const std::string side = multicameraSide(sensor.description());
    if (side.empty())
    {
      ROS_WARN("sensor '%s': gazebo_ros_multicamera publishes only cameras whose name contains 'left' or 'right'; "
               "camera '%s' publishes nothing", sensor.name().c_str(), sensor.description().multicamera_camera.c_str());
      return;
    }
    zero_baseline_ = side == "left";
    GazeboRosCamera::Load(sensor);
  }

  bool subscribed() const override { return camera_ && GazeboRosCamera::subscribed(); }

  void OnUpdate() override
  {
    if (camera_)
      GazeboRosCamera::OnUpdate();
  }
};

GAZEBO_ROS_SENSOR_PLUGIN(GazeboRosMultiCamera, "libgazebo_ros_multicamera.so");

}  // namespace bullet_plant
