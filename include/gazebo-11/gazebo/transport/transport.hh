// Gazebo's transport library, as a plugin includes it whole. Here it names the classes and their
// handles only (TransportTypes.hh): a plugin that includes it and uses ROS instead (gazebo_plugins'
// gazebo_ros_imu) builds; one that makes a transport::Node does not yet (docs/gazebo_api.md).
#pragma once

#include "gazebo/transport/TransportTypes.hh"
