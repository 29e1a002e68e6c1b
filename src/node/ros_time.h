// Simulated time as ROS stamps.
#pragma once

#include <algorithm>
#include <cstdint>

#include <ros/time.h>

namespace bullet_plant
{
// A stamp from the world's time in ns (never before 0).
inline ros::Time rosTime(int64_t ns)
{
  ros::Time t;
  t.fromNSec(static_cast<uint64_t>(std::max<int64_t>(ns, 0)));
  return t;
}

}  // namespace bullet_plant
