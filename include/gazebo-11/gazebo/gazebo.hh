// Gazebo's top header, as a plugin includes it first: its version and the common library.
#pragma once

#include "gazebo/common/common.hh"
#include "gazebo/gazebo_config.h"
