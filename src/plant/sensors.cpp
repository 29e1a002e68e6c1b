#include "bullet_plant/sensors.h"

#include <cmath>

namespace bullet_plant
{
Sensor::Sensor(const SensorDescription& d) : description_(d)
{
  period_ns_ = d.update_rate > 0 ? static_cast<int64_t>(std::llround(1e9 / d.update_rate)) : 0;
}

std::string Sensor::frameId() const
{
  return description_.pluginParam("frameName", description_.link);
}

bool Sensor::due(int64_t time_ns)
{
  if (last_update_ns_ >= 0 && time_ns - last_update_ns_ < period_ns_ && time_ns >= last_update_ns_)
    return false;
  last_update_ns_ = time_ns;
  ++updates_;
  return true;
}

Lidar::Lidar(const SensorDescription& d) : Sensor(d) {}

}  // namespace bullet_plant
