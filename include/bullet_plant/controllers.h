// ros_controllers' controller types, hosted by the plant (docs/interfaces.md section 4). Each works
// on joint handles it looks up through JointHandles and exchanges messages through its ports
// (message_ports.h), which the ROS node and Python carry.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <urdf_model/pose.h>

#include "bullet_plant/message_ports.h"
#include "bullet_plant/hardware_interface.h"
#include "bullet_plant/joint_layer.h"
#include "bullet_plant/pid.h"
#include "bullet_plant/registry.h"

namespace bullet_plant
{
class Param;
class Log;

// The messages controllers exchange, as the ROS ones they stand for (std_msgs/Float64 is a double,
// std_msgs/Float64MultiArray a std::vector<double>).

// sensor_msgs/JointState
struct JointStateSample
{
  int64_t stamp_ns = 0;
  std::vector<std::string> name;
  std::vector<double> position, velocity, effort;
};

// control_msgs/JointControllerState
struct ControllerStateSample
{
  int64_t stamp_ns = 0;
  double set_point = 0, process_value = 0, process_value_dot = 0, error = 0, time_step = 0, command = 0;
  double p = 0, i = 0, d = 0, i_clamp = 0;
  bool antiwindup = false;
};

// geometry_msgs/Twist as a planar drive reads it: linear.x and angular.z.
struct TwistCommand
{
  double linear_x = 0, angular_z = 0;
  double linear_y = 0;  // holonomic bases (planar_move)
};

// nav_msgs/Odometry: pose and twist of child_frame_id in frame_id, the covariances' diagonals.
struct OdometrySample
{
  int64_t stamp_ns = 0;
  std::string frame_id = "odom", child_frame_id = "base_link";
  urdf::Pose pose;
  urdf::Vector3 linear, angular;  // twist, in child_frame_id (as nav_msgs/Odometry has it)
  std::array<double, 6> pose_covariance_diagonal{}, twist_covariance_diagonal{};
};

// geometry_msgs/TransformStamped, for /tf.
struct TransformSample
{
  int64_t stamp_ns = 0;
  std::string frame_id, child_frame_id;
  urdf::Pose pose;  // of child_frame_id in frame_id
};

// tf2_msgs/TFMessage as something that listens to /tf takes it: every transform of one message.
struct TransformsCommand
{
  std::vector<TransformSample> transforms;
};

// A pose in the plane, the yaw about z (as the drives' odometry has it).
inline urdf::Pose planarPose(double x, double y, double heading)
{
  urdf::Pose pose;
  pose.position = urdf::Vector3(x, y, 0.0);
  pose.rotation.setFromRPY(0.0, 0.0, heading);
  return pose;
}

// What a controller gets to initialise itself: its parameters and the robot's joint handles.
struct ControllerContext
{
  const Param& params;          // the whole parameter tree
  std::string ns;               // the controller's namespace, e.g. "/tianracer/rear_left_velocity_controller"
  JointHandles& joints;
  Log& log;
};

class Controller : public MessagePorts
{
public:
  // Reads parameters, takes handles and opens its ports; false (with the reason logged) when it
  // cannot run.
  virtual bool init(ControllerContext& context) = 0;
  virtual void starting(int64_t time_ns) {}
  virtual void update(int64_t time_ns, double period) = 0;
  virtual void stopping(int64_t time_ns) {}

  virtual const std::vector<ClaimedResources>& claimedResources() const { return claimed_; }

protected:
  std::vector<ClaimedResources> claimed_;
};

using ControllerFactory = std::function<std::unique_ptr<Controller>()>;

// The controller types this plant offers (list_controller_types), sorted, and a factory for them:
// whatever registered itself (ROS_CONTROLLER_TYPE).
inline const std::vector<std::string>& controllerTypes()
{
  static const std::vector<std::string> names = Registry<ControllerFactory>::instance().names();
  return names;
}
// Null for an unknown type.
inline std::unique_ptr<Controller> createController(const std::string& type)
{
  const ControllerFactory* make = Registry<ControllerFactory>::instance().find(type);
  return make ? (*make)() : nullptr;
}

}  // namespace bullet_plant

// In a controller's .cpp, as pluginlib's PLUGINLIB_EXPORT_CLASS: `factory` (a function returning a
// std::unique_ptr<Controller>) makes the controller type `type_name`
// ("diff_drive_controller/DiffDriveController"); `id` names the registration, unique in its file.
#define ROS_CONTROLLER_TYPE(id, type_name, factory) \
  BULLET_PLANT_REGISTER(::bullet_plant::ControllerFactory, id, factory, type_name)
