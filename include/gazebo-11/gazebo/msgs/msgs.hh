// Gazebo's messages, as plugins include them: every gazebo::msgs message and its handles
// (MessageTypes.hh, generated from src/gazebo/msgs/proto by the build).
#pragma once

// Gazebo 11's message and transport headers bring boost's threads in, and plugins lean on that:
// gazebo_ros_pkgs' gazebo_ros_elevator declares a boost::thread having included no more than
// Gazebo's ElevatorPlugin.hh and ROS. Here, not in the common headers every plugin includes, where
// it would cost each plugin file some 2 s to compile.
#include <boost/thread.hpp>

#include <ignition/math/Vector3.hh>

#include "gazebo/msgs/MessageTypes.hh"

namespace gazebo
{
namespace msgs
{
// ignition's vector as a message, and back; Set fills one in place.
Vector3d Convert(const ignition::math::Vector3d& v);
ignition::math::Vector3d ConvertIgn(const Vector3d& v);
void Set(Vector3d* out, const ignition::math::Vector3d& v);
}  // namespace msgs
}  // namespace gazebo
