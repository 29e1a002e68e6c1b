// Gazebo's messages, as plugins include them: every gazebo::msgs message and its handles
// (MessageTypes.hh, generated from src/gazebo/msgs/proto by the build).
#pragma once

// Gazebo 11's message and transport headers bring boost's threads in, and plugins lean on that:
// gazebo_ros_pkgs' gazebo_ros_elevator declares a boost::thread having included no more than
// Gazebo's ElevatorPlugin.hh and ROS. Here, not in the common headers every plugin includes, where
// it would cost each plugin file some 2 s to compile.
#include <boost/thread.hpp>

#include <ignition/math/Pose3.hh>
#include <ignition/math/Quaternion.hh>
#include <ignition/math/Vector3.hh>

#include "gazebo/common/Time.hh"
#include "gazebo/msgs/MessageTypes.hh"

namespace gazebo
{
namespace msgs
{
// ignition's vectors, quaternions and poses as messages, and back; Set fills one in place.
Vector3d Convert(const ignition::math::Vector3d& v);
Quaternion Convert(const ignition::math::Quaterniond& q);
Pose Convert(const ignition::math::Pose3d& p);
ignition::math::Vector3d ConvertIgn(const Vector3d& v);
ignition::math::Quaterniond ConvertIgn(const Quaternion& q);
ignition::math::Pose3d ConvertIgn(const Pose& p);
void Set(Vector3d* out, const ignition::math::Vector3d& v);
void Set(Quaternion* out, const ignition::math::Quaterniond& q);
void Set(Pose* out, const ignition::math::Pose3d& p);
// Times (a sensor's measurement's stamp) as messages, and back.
Time Convert(const common::Time& t);
common::Time Convert(const Time& t);
void Set(Time* out, const common::Time& t);
}  // namespace msgs
}  // namespace gazebo
