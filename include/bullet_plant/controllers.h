// ros_controllers' controller types, hosted by the plant (docs/interfaces.md section 4). Each works
// on joint handles it looks up through JointHandles; what the real ones publish is produced as
// samples that the ROS node publishes and Python reads.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "bullet_plant/hardware_interface.h"
#include "bullet_plant/joint_layer.h"
#include "bullet_plant/pid.h"

namespace bullet_plant
{
class Param;
class Log;

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

// nav_msgs/Odometry of a drive controller (ackermann_steering_controller): a planar pose and twist in
// the odometry frame, with what the message and its transform carry besides.
struct OdometrySample
{
  int64_t stamp_ns = 0;
  double x = 0, y = 0, heading = 0;  // m, m, rad in odom_frame_id
  double linear = 0, angular = 0;    // m/s along the base's x, rad/s about z
};

struct OdometryFrames
{
  std::string odom_frame_id = "odom", base_frame_id = "base_link";
  bool enable_odom_tf = true;
  double pose_covariance_diagonal[6] = {0, 0, 0, 0, 0, 0};
  double twist_covariance_diagonal[6] = {0, 0, 0, 0, 0, 0};
};

// What a controller gets to initialise itself: its parameters and the robot's joint handles.
struct ControllerContext
{
  const Param& params;          // the whole parameter tree
  std::string ns;               // the controller's namespace, e.g. "/tianracer/rear_left_velocity_controller"
  JointHandles& joints;
  Log& log;
};

// The message a controller's command topic carries: none, std_msgs/Float64 on <controller>/command,
// std_msgs/Float64MultiArray on <controller>/command, geometry_msgs/Twist on <controller>/cmd_vel.
enum class CommandTopic { None, Float64, Float64MultiArray, Twist };

class Controller
{
public:
  virtual ~Controller() = default;
  // Reads parameters and takes handles; false (with the reason logged) when it cannot run.
  virtual bool init(ControllerContext& context) = 0;
  virtual void starting(int64_t time_ns) {}
  virtual void update(int64_t time_ns, double period) = 0;
  virtual void stopping(int64_t time_ns) {}

  virtual const std::vector<ClaimedResources>& claimedResources() const { return claimed_; }
  // What the controller's command topic carries (docs/interfaces.md sections 4 and 12).
  virtual CommandTopic commandTopic() const { return CommandTopic::None; }
  // A Float64 on <controller>/command; false for a controller without one or a non-finite value.
  virtual bool setCommand(double value) { return false; }
  // A Float64MultiArray on <controller>/command (the JointGroup controllers): false, with the reason
  // logged, when its size is not the number of joints or a value is not finite.
  virtual bool setCommands(const std::vector<double>& values) { return false; }
  // A geometry_msgs/Twist on <controller>/cmd_vel (linear.x, angular.z); false, with the reason
  // logged, when the controller is not running or a value is not finite.
  virtual bool setTwist(double linear_x, double angular_z) { return false; }
  // The frames and covariances of the nav_msgs/Odometry it publishes on <controller>/odom; null for
  // a controller without odometry.
  virtual const OdometryFrames* odometryFrames() const { return nullptr; }
  // Whether it reports control_msgs/JointControllerState on <controller>/state.
  virtual bool hasState() const { return false; }
  // Samples produced since the last take (joint_states for the joint state controller, state for
  // the PID controllers); the latest is kept for readers that only look.
  std::vector<JointStateSample> takeJointStates();
  std::vector<ControllerStateSample> takeControllerStates();
  std::vector<OdometrySample> takeOdometry();
  const OdometrySample* latestOdometry() const { return has_odometry_ ? &latest_odometry_ : nullptr; }
  const JointStateSample* latestJointState() const { return has_joint_state_ ? &latest_joint_state_ : nullptr; }
  const ControllerStateSample* latestControllerState() const { return has_state_ ? &latest_state_ : nullptr; }
  uint64_t samplesProduced() const { return samples_; }

protected:
  void emit(const JointStateSample& s);
  void emit(const ControllerStateSample& s);
  void emit(const OdometrySample& s);
  std::vector<ClaimedResources> claimed_;

private:
  std::vector<JointStateSample> joint_states_;
  std::vector<ControllerStateSample> controller_states_;
  std::vector<OdometrySample> odometry_;
  JointStateSample latest_joint_state_;
  ControllerStateSample latest_state_;
  OdometrySample latest_odometry_;
  bool has_joint_state_ = false, has_state_ = false, has_odometry_ = false;
  uint64_t samples_ = 0;
};

// The controller types this plant offers (list_controller_types), and a factory for them.
const std::vector<std::string>& controllerTypes();
std::unique_ptr<Controller> createController(const std::string& type);  // null for an unknown type

}  // namespace bullet_plant
