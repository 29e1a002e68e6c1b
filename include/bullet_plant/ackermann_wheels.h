// The tutorial's cmdvel2gazebo.py geometry, once for every caller (tianracer_description.ackermann
// binds it: the converter script and the racing environments): a ground speed and an ideal middle
// front wheel angle become two rear wheel speeds and two front steering angles. The car turns about
// a point on the rear axle line; with t = tan(steering) the turn's curvature is t / wheelbase, and a
// wheel d to the left of the middle runs on a circle (1 - d t / wheelbase) times the middle's: each
// rear wheel turns that much faster or slower, and each front wheel points at the turn's centre,
// atan2(wheelbase t, wheelbase - d t). Straight ahead (t = 0) is the same formula, no special case.
#pragma once

#include <algorithm>
#include <cmath>

namespace bullet_plant
{
struct AckermannGeometry
{
  double wheelbase = 0, rear_track = 0, front_track = 0, wheel_radius = 0;  // m
};

// out: rear left, rear right (rad/s), steer left, steer right (rad); the steering held within
// [-max_steering, max_steering] (a NaN stays NaN: the plant refuses it downstream).
inline void ackermannWheelCommands(double speed, double steering, double max_steering, const AckermannGeometry& g,
                                   double out[4])
{
  const double t = std::tan(std::min(std::max(steering, -max_steering), max_steering));
  const double wheel_rate = speed / g.wheel_radius;
  for (int side = 0; side < 2; ++side)
  {
    const double side_t = (side == 0 ? 1.0 : -1.0) * t;  // d t / (track / 2): the left wheel +1, the right -1
    out[side] = wheel_rate * (1.0 - g.rear_track / (2.0 * g.wheelbase) * side_t);
    out[2 + side] = std::atan2(g.wheelbase * t, g.wheelbase - g.front_track / 2.0 * side_t);
  }
}
}  // namespace bullet_plant
