// Gazebo's symbol visibility macros: plugins mark their RegisterPlugin entry point with
// GZ_PLUGIN_VISIBLE (GZ_REGISTER_MODEL_PLUGIN does), so that dlsym finds it in a library built
// with -fvisibility=hidden.
#pragma once

#define GZ_VISIBLE __attribute__((visibility("default")))
#define GZ_HIDDEN __attribute__((visibility("hidden")))
#define GZ_PLUGIN_VISIBLE GZ_VISIBLE
#define GZ_COMMON_VISIBLE GZ_VISIBLE
#define GZ_PHYSICS_VISIBLE GZ_VISIBLE
#define GZ_SENSORS_VISIBLE GZ_VISIBLE
#define GZ_RENDERING_VISIBLE GZ_VISIBLE
#define GZ_TRANSPORT_VISIBLE GZ_VISIBLE
#define GZ_MSGS_VISIBLE GZ_VISIBLE
#define GZ_UTIL_VISIBLE GZ_VISIBLE
#define GAZEBO_VISIBLE GZ_VISIBLE
#define GAZEBO_HIDDEN GZ_HIDDEN
#define GAZEBO_DEPRECATED(version) __attribute__((deprecated))
