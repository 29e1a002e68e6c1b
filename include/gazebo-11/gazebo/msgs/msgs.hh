// Gazebo's messages, as plugins include them: every gazebo::msgs message and its handles
// (MessageTypes.hh, generated from src/gazebo/msgs/proto by the build).
#pragma once

#include "gazebo/msgs/MessageTypes.hh"
