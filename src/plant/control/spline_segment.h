// One joint's stretch of a trajectory between two waypoints, as trajectory_interface's
// QuinticSplineSegment interpolates it: linear when either end gives only a position, cubic when
// both give velocities, quintic when both give accelerations too (the lowest common order).
// Before its start it holds the start position, after its end the end position, both at rest.
#pragma once

#include <cmath>

namespace bullet_plant
{
struct SplineState
{
  double position = 0, velocity = 0, acceleration = 0;
  bool has_velocity = false, has_acceleration = false;
};

class SplineSegment
{
public:
  SplineSegment() = default;
  // end_time >= start_time (s); a zero-length segment is its start state until it ends.
  SplineSegment(double start_time, const SplineState& start, double end_time, const SplineState& end)
    : start_time_(start_time), duration_(end_time - start_time)
  {
    const double T = duration_, p0 = start.position, p1 = end.position;
    c_[0] = p0;
    const bool cubic = start.has_velocity && end.has_velocity;
    const bool quintic = cubic && start.has_acceleration && end.has_acceleration;
    if (T <= 0.0)
    {
      if (cubic)
        c_[1] = start.velocity;
      if (quintic)
        c_[2] = 0.5 * start.acceleration;
      return;
    }
    if (!cubic)
    {
      c_[1] = (p1 - p0) / T;
      return;
    }
    const double v0 = start.velocity, v1 = end.velocity, T2 = T * T, T3 = T2 * T;
    c_[1] = v0;
    if (!quintic)
    {
      c_[2] = (3.0 * (p1 - p0) - (2.0 * v0 + v1) * T) / T2;
      c_[3] = (2.0 * (p0 - p1) + (v0 + v1) * T) / T3;
      return;
    }
    const double a0 = start.acceleration, a1 = end.acceleration;
    c_[2] = 0.5 * a0;
    c_[3] = (20.0 * (p1 - p0) - (8.0 * v1 + 12.0 * v0) * T - (3.0 * a0 - a1) * T2) / (2.0 * T3);
    c_[4] = (30.0 * (p0 - p1) + (14.0 * v1 + 16.0 * v0) * T + (3.0 * a0 - 2.0 * a1) * T2) / (2.0 * T3 * T);
    c_[5] = (12.0 * (p1 - p0) - 6.0 * (v1 + v0) * T - (a0 - a1) * T2) / (2.0 * T3 * T2);
  }

  double startTime() const { return start_time_; }
  double endTime() const { return start_time_ + duration_; }

  // The state at `time` (s).
  SplineState sample(double time) const
  {
    SplineState s;
    s.has_velocity = s.has_acceleration = true;
    const double t = time - start_time_;
    if (t < 0.0)
    {
      s.position = c_[0];
      return s;
    }
    const double tau = std::fmin(t, duration_);
    s.position = ((((c_[5] * tau + c_[4]) * tau + c_[3]) * tau + c_[2]) * tau + c_[1]) * tau + c_[0];
    if (t > duration_)
      return s;
    s.velocity = (((5.0 * c_[5] * tau + 4.0 * c_[4]) * tau + 3.0 * c_[3]) * tau + 2.0 * c_[2]) * tau + c_[1];
    s.acceleration = ((20.0 * c_[5] * tau + 12.0 * c_[4]) * tau + 6.0 * c_[3]) * tau + 2.0 * c_[2];
    return s;
  }

private:
  double start_time_ = 0, duration_ = 0;
  double c_[6] = {0, 0, 0, 0, 0, 0};  // polynomial in the time since the start
};

}  // namespace bullet_plant
