// Gazebo's core headers, as gazebo.hh includes them: the common library, the messages and the
// transport (a plugin that includes only gazebo/gazebo.hh uses transport::Node and msgs::).
#pragma once

#include "gazebo/common/common.hh"
#include "gazebo/msgs/msgs.hh"
#include "gazebo/transport/transport.hh"
