// The messages the plant's ports carry (message_ports.h), whoever sends them: controllers and model
// plugins alike publish JointState and Odometry, so their structs live in one home, not with either
// family. One struct per ROS message with the fields the plant fills (std_msgs/Float64 is a double,
// std_msgs/Float64MultiArray a std::vector<double>); the node maps each to its ROS type once
// (src/node/port_topics.cpp), Python once (src/python/port_bindings.cpp). An action's messages stay
// with the action's shape, four ports on actionlib's topics (action_messages.h).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <urdf_model/pose.h>

namespace bullet_plant
{
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

// geometry_msgs/Wrench, as a command: a force (N) and a torque (N m).
struct WrenchCommand
{
  urdf::Vector3 force, torque;
};

// geometry_msgs/WrenchStamped: a force (N) and a torque (N m).
struct WrenchStampedSample
{
  int64_t stamp_ns = 0;
  std::string frame_id;
  urdf::Vector3 force, torque;
};

// std_srvs/Empty, as a request and as its (empty) answer.
struct EmptyRequest
{
};

// hector_gazebo_plugins/SetBias: a bias for one of the IMU's error models (m/s^2 or rad/s).
struct SetBiasRequest
{
  urdf::Vector3 bias;
};

// sensor_msgs/NavSatFix with a diagonal covariance (COVARIANCE_TYPE_DIAGONAL_KNOWN).
struct NavSatFixSample
{
  int64_t stamp_ns = 0;
  std::string frame_id;
  int status = 0;   // sensor_msgs/NavSatStatus: -1 no fix, 0 fix, 1 SBAS, 2 GBAS
  int service = 0;  // its bit mask: 1 GPS, 2 GLONASS, 4 COMPASS, 8 GALILEO
  double latitude = 0, longitude = 0, altitude = 0;  // degrees, degrees, metres
  std::array<double, 3> position_covariance_diagonal{};  // m^2: east-west, north-south, up
};

// geometry_msgs/Vector3Stamped.
struct Vector3StampedSample
{
  int64_t stamp_ns = 0;
  std::string frame_id;
  urdf::Vector3 vector;
};

// sensor_msgs/Imu with diagonal covariances (-1 in the first element: not provided).
struct ImuSample
{
  int64_t stamp_ns = 0;
  std::string frame_id;
  urdf::Rotation orientation;
  urdf::Vector3 angular_velocity, linear_acceleration;
  std::array<double, 3> orientation_covariance_diagonal{}, angular_velocity_covariance_diagonal{},
      linear_acceleration_covariance_diagonal{};
};

}  // namespace bullet_plant
