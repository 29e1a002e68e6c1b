// Gazebo's common library, as a plugin includes it whole: time, the console, events, exceptions, images, PID,
// plugins, animations.
#pragma once

#include "gazebo/common/Animation.hh"
#include "gazebo/common/CommonTypes.hh"
#include "gazebo/common/Console.hh"
#include "gazebo/common/Event.hh"
#include "gazebo/common/Events.hh"
#include "gazebo/common/Exception.hh"
#include "gazebo/common/Image.hh"
#include "gazebo/common/KeyFrame.hh"
#include "gazebo/common/PID.hh"
#include "gazebo/common/SphericalCoordinates.hh"
#include "gazebo/common/Plugin.hh"
#include "gazebo/common/SystemPaths.hh"
#include "gazebo/common/Time.hh"
#include "gazebo/common/UpdateInfo.hh"
