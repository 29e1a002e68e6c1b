// Gazebo classic's version, as gazebo/gazebo_config.h gives it to plugins that branch on it
// (`#if GAZEBO_MAJOR_VERSION >= 9`): the API under include/gazebo-11/ is Gazebo 11's, over the
// Bullet plant. docs/gazebo_api.md lists what of it the plant offers.
#pragma once

#define GAZEBO_MAJOR_VERSION 11
#define GAZEBO_MINOR_VERSION 15
#define GAZEBO_PATCH_VERSION 1

#define GAZEBO_VERSION "11.15"
#define GAZEBO_VERSION_FULL "11.15.1"
#define GAZEBO_VERSION_NAME

#define GAZEBO_VERSION_HEADER \
  "Gazebo 11 C++ API on the Bullet plant (tianracer_description), version " GAZEBO_VERSION_FULL "\n"

#define HAVE_DL 1
#define HAVE_BULLET 1
