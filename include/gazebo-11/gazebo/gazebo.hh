// Gazebo's top header, as a plugin includes it first: its version and its core (the common library,
// the messages and the transport: gazebo_core.hh), as Gazebo 11's.
#pragma once

#include "gazebo/gazebo_config.h"
#include "gazebo/gazebo_core.hh"
