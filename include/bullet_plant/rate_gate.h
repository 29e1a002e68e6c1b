// Rates in simulated time, in one place: a period from a rate, and the gate Gazebo's sensors and
// gazebo_ros's plugins update through (the sensors, the ground-truth odometry, /clock).
#pragma once

#include <cmath>
#include <cstdint>

namespace bullet_plant
{
// The period of `rate_hz` in nanoseconds, rounded; 0 (no throttling) for a rate of 0 or below.
inline int64_t periodNsOfRate(double rate_hz)
{
  return rate_hz > 0 ? static_cast<int64_t>(std::llround(1e9 / rate_hz)) : 0;
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
    return last_ns_ < 0 || time_ns - last_ns_ >= period_ns_ || time_ns < last_ns_;
  }

private:
  int64_t period_ns_ = 0;
  int64_t last_ns_ = -1;
};

}  // namespace bullet_plant
