// Rates in simulated time, in one place: a period from a rate, and the two gates updates go through:
// RateGate, Gazebo's sensors' (the sensors, the ground-truth odometry, /clock, gazebo_ros_range), and
// CatchUpRateGate, the `last += period` form of gazebo_plugins' drives and ros_controllers.
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>

namespace bullet_plant
{
// The period of `rate_hz` in nanoseconds, rounded; 0 (no throttling) for a rate of 0 or below.
inline int64_t periodNsOfRate(double rate_hz)
{
  if (!(rate_hz > 0))
    return 0;
  // a rate so low its period passes int64's nanoseconds (DBL_MIN, gazebo_ros_triggered_camera's
  // "never"): the longest period
  const double period_ns = 1e9 / rate_hz;
  return period_ns < 9.2e18 ? static_cast<int64_t>(std::llround(period_ns)) : std::numeric_limits<int64_t>::max();
}

// Open at the first call, then once `period_ns` has passed since it last opened, and at once when
// simulated time went back (a reset): Gazebo's Sensor::Update and its plugins' OnUpdate gate.
class RateGate
{
public:
  explicit RateGate(int64_t period_ns = 0) : period_ns_(period_ns) {}
  int64_t periodNs() const { return period_ns_; }
  void setPeriodNs(int64_t period_ns) { period_ns_ = period_ns; }
  // The next call opens, whatever the time.
  void reset() { last_ns_ = -1; }
  // True when an update is due at `time_ns`, which then counts as the last one.
  bool due(int64_t time_ns)
  {
    if (!wouldOpen(time_ns))
      return false;
    last_ns_ = time_ns;
    return true;
  }
  // Whether a call at `time_ns` would open; as time goes on it only opens later, so this also says
  // whether calls from now until `time_ns` will.
  bool wouldOpen(int64_t time_ns) const
  {
    // the longest period (periodNsOfRate's for a rate of ~0) never opens, its first time included
    if (period_ns_ == std::numeric_limits<int64_t>::max())
      return false;
    return last_ns_ < 0 || time_ns - last_ns_ >= period_ns_ || time_ns < last_ns_;
  }

private:
  int64_t period_ns_ = 0;
  int64_t last_ns_ = -1;
};

// The other form upstream writes, in gazebo_plugins' drives and joint_state_publisher and in
// ros_controllers' odometry and joint state publishers: open once more than `period_ns` has passed
// since its clock (strictly), which then moves on by one period, not to the time of the call, so the
// updates keep to the period's grid and one that came late is caught up at the next call:
//   if (now - last > period) { ...; last += period; }
// Its clock starts where the plugin or controller starts it (restart); time going back does not
// reopen it, as upstream's does not.
class CatchUpRateGate
{
public:
  explicit CatchUpRateGate(int64_t period_ns = 0) : period_ns_(period_ns) {}
  int64_t periodNs() const { return period_ns_; }
  void setPeriodNs(int64_t period_ns) { period_ns_ = period_ns; }
  // The clock, set to `time_ns`: the next opening is more than a period after it.
  void restart(int64_t time_ns) { last_ns_ = time_ns; }
  // The clock: the last opening's place on the grid (what upstream's plugins measure dt from).
  int64_t lastNs() const { return last_ns_; }
  // True when more than a period has passed at `time_ns` since the clock, which then moves on by one period.
  bool due(int64_t time_ns)
  {
    if (time_ns - last_ns_ <= period_ns_)
      return false;
    last_ns_ += period_ns_;
    return true;
  }

private:
  int64_t period_ns_ = 0;
  int64_t last_ns_ = 0;
};

}  // namespace bullet_plant
