// Gazebo's rendering library, as a plugin includes it whole: the cameras its camera sensors give
// plugins (no scene, visuals or user camera: docs/gazebo_api.md).
#pragma once

#include "gazebo/rendering/Camera.hh"
#include "gazebo/rendering/DepthCamera.hh"
#include "gazebo/rendering/Distortion.hh"
#include "gazebo/rendering/RenderTypes.hh"
