// Messages the model plugins publish beyond the controllers' (controllers.h), one struct per ROS
// message with the fields the plugins fill; the node maps each to its ROS type once
// (src/node/port_topics.cpp), Python once (src/python/port_bindings.cpp).
#pragma once

#include <array>
#include <cstdint>
#include <string>

#include <urdf_model/pose.h>

namespace bullet_plant
{
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
