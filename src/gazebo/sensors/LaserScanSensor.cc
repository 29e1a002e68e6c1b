// sensors::LaserScanSensor (gazebo/sensors/LaserScanSensor.hh): the scan RaySensor and GpuRaySensor share.
#include "gazebo/sensors/LaserScanSensor.hh"

#include <algorithm>
#include <cmath>
#include <limits>

#include <boost/algorithm/string/replace.hpp>
#include <boost/make_shared.hpp>

#include "gazebo/common/Console.hh"
#include "gazebo/msgs/msgs.hh"
#include "gazebo/transport/Node.hh"
#include "gazebo/transport/Publisher.hh"
#include "link_sensor.h"

namespace gazebo
{
namespace sensors
{
LaserScanSensor::LaserScanSensor(SensorCategory category)
  : Sensor(category),
    laserShape(new physics::MultiRayShape(physics::CollisionPtr())),
    laser_msg_(boost::make_shared<msgs::LaserScanStamped>())
{
}

LaserScanSensor::~LaserScanSensor() = default;

std::string LaserScanSensor::Topic() const
{
  std::string topic = "~/" + ParentName() + "/" + Name() + "/scan";
  boost::replace_all(topic, "::", "/");
  return topic;
}

void LaserScanSensor::Load(const std::string& worldName)
{
  Sensor::Load(worldName);
  laserShape->Load(sdf);
  laserShape->Init();
  if (world)
    scan_pub_ = node->Advertise<msgs::LaserScanStamped>(Topic(), 50);
  // its <ray><noise> as Gazebo's model, for a plugin that reads it; the simulator's lidar applies it
  // (one simulation of the sensor), so the model is not applied again here
  detail::loadNoise(noises, Category() == IMAGE ? GPU_RAY_NOISE : RAY_NOISE, sdf, "ray");
}

void LaserScanSensor::Init()
{
  Sensor::Init();
  std::lock_guard<std::mutex> lock(mutex_);
  laser_msg_->mutable_scan()->set_frame(ParentName());
}

void LaserScanSensor::Fini()
{
  scan_pub_.reset();
  Sensor::Fini();
}

ignition::math::Angle LaserScanSensor::AngleMin() const { return laserShape->MinAngle(); }

ignition::math::Angle LaserScanSensor::AngleMax() const { return laserShape->MaxAngle(); }

double LaserScanSensor::AngleResolution() const { return (AngleMax() - AngleMin()).Radian() / (RangeCount() - 1); }

double LaserScanSensor::RangeMin() const { return laserShape->GetMinRange(); }

double LaserScanSensor::RangeMax() const { return laserShape->GetMaxRange(); }

double LaserScanSensor::RangeResolution() const { return laserShape->GetResRange(); }

int LaserScanSensor::RayCount() const { return laserShape->GetSampleCount(); }

int LaserScanSensor::RangeCount() const
{
  return static_cast<int>(laserShape->GetSampleCount() * laserShape->GetScanResolution());
}

int LaserScanSensor::VerticalRayCount() const { return laserShape->GetVerticalSampleCount(); }

int LaserScanSensor::VerticalRangeCount() const
{
  return static_cast<int>(laserShape->GetVerticalSampleCount() * laserShape->GetVerticalScanResolution());
}

ignition::math::Angle LaserScanSensor::VerticalAngleMin() const { return laserShape->VerticalMinAngle(); }

ignition::math::Angle LaserScanSensor::VerticalAngleMax() const { return laserShape->VerticalMaxAngle(); }

double LaserScanSensor::VerticalAngleResolution() const
{
  return (VerticalAngleMax() - VerticalAngleMin()).Radian() / (VerticalRangeCount() - 1);
}

double LaserScanSensor::ScanValue(bool intensities, unsigned int index) const
{
  std::lock_guard<std::mutex> lock(mutex_);
  const google::protobuf::RepeatedField<double>& values =
      intensities ? laser_msg_->scan().intensities() : laser_msg_->scan().ranges();
  if (values.empty())
  {
    gzwarn << (intensities ? "Intensities not constructed yet (zero size)" : "ranges not constructed yet (zero sized)")
           << "\n";
    return 0.0;
  }
  if (static_cast<int>(index) >= values.size())
  {
    gzerr << (intensities ? "Invalid intensity index[" : "Invalid range index[") << index << "]\n";
    return 0.0;
  }
  return values.Get(static_cast<int>(index));
}

void LaserScanSensor::Ranges(std::vector<double>& out) const
{
  std::lock_guard<std::mutex> lock(mutex_);
  out.assign(laser_msg_->scan().ranges().begin(), laser_msg_->scan().ranges().end());
}

boost::shared_ptr<const msgs::LaserScanStamped> LaserScanSensor::LatestScan() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  return laser_msg_;
}

bool LaserScanSensor::IsActive() const { return Sensor::IsActive() || (scan_pub_ && scan_pub_->HasConnections()); }

bool LaserScanSensor::UpdateImpl(bool /*force*/)
{
  const auto* rays = dynamic_cast<const RayBridge*>(bridge.get());
  if (!rays || rays->ranges().empty())
    return false;
  laserShape->SetRanges(rays->ranges());
  lastMeasurementTime = rays->measurementTime();
  boost::shared_ptr<msgs::LaserScanStamped> message;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    for (auto& spare : spare_msgs_)
      if (spare.use_count() == 1)
      {
        message.swap(spare);
        break;
      }
    if (!message)
      message = boost::make_shared<msgs::LaserScanStamped>();
  }
  {
    msgs::Set(message->mutable_time(), lastMeasurementTime);
    msgs::LaserScan* scan = message->mutable_scan();
    scan->set_frame(parentName);
    msgs::Set(scan->mutable_world_pose(), rays->scanOrigin());
    scan->set_angle_min(AngleMin().Radian());
    scan->set_angle_max(AngleMax().Radian());
    scan->set_angle_step(AngleResolution());
    scan->set_count(static_cast<uint32_t>(RangeCount()));
    scan->set_vertical_angle_min(VerticalAngleMin().Radian());
    scan->set_vertical_angle_max(VerticalAngleMax().Radian());
    scan->set_vertical_angle_step(VerticalAngleResolution());
    scan->set_vertical_count(static_cast<uint32_t>(VerticalRangeCount()));
    scan->set_range_min(RangeMin());
    scan->set_range_max(RangeMax());
    // Gazebo's ranges from its rays: interpolated between neighbouring rays where the <resolution>
    // asks for more ranges than rays; +inf at or past the maximum, -inf at or before the minimum.
    // The simulator's scan carries its noise already (Gazebo's adds it here).
    const unsigned int ray_count = static_cast<unsigned int>(RayCount());
    const unsigned int range_count = static_cast<unsigned int>(std::max(RangeCount(), 0));
    const unsigned int vertical_rays = static_cast<unsigned int>(VerticalRayCount());
    const unsigned int vertical_ranges = static_cast<unsigned int>(std::max(VerticalRangeCount(), 0));
    const bool interpolate = ray_count != range_count || vertical_rays != vertical_ranges;
    auto* ranges = scan->mutable_ranges();
    ranges->Clear();
    ranges->Reserve(static_cast<int>(range_count * vertical_ranges));
    double* out = ranges->AddNAlreadyReserved(static_cast<int>(range_count * vertical_ranges));
    const double range_min = RangeMin(), range_max = RangeMax();
    const auto edge = [range_min, range_max](double range) {
      if (range >= range_max)
        return std::numeric_limits<double>::infinity();
      if (range <= range_min)
        return -std::numeric_limits<double>::infinity();
      return range;
    };
    const std::vector<float>& measured = laserShape->Ranges();
    if (!interpolate && measured.size() == size_t(range_count) * vertical_ranges)
    {
      // the plant's own rays, one range each: no shape calls, a loop the compiler vectorizes
      const float* in = measured.data();
      for (size_t i = 0, n = measured.size(); i < n; ++i)
        out[i] = edge(in[i]);
    }
    else
      for (unsigned int j = 0; j < vertical_ranges; ++j)
      {
        double vb = 0;
        unsigned int vja = j, vjb = j;
        if (interpolate)
        {
          vb = vertical_ranges == 1 ? 0 : double(j * (vertical_rays - 1)) / (vertical_ranges - 1);
          vja = static_cast<unsigned int>(std::floor(vb));
          vjb = std::min(vja + 1, vertical_rays - 1);
          vb -= std::floor(vb);
        }
        for (unsigned int i = 0; i < range_count; ++i)
        {
          double range;
          if (interpolate)
          {
            double hb = range_count == 1 ? 0 : double(i * (ray_count - 1)) / (range_count - 1);
            const unsigned int hja = static_cast<unsigned int>(std::floor(hb));
            const unsigned int hjb = std::min(hja + 1, ray_count - 1);
            hb -= std::floor(hb);
            range = (1 - vb) * ((1 - hb) * laserShape->GetRange(hja + vja * ray_count) +
                                hb * laserShape->GetRange(hjb + vja * ray_count)) +
                    vb * ((1 - hb) * laserShape->GetRange(hja + vjb * ray_count) +
                          hb * laserShape->GetRange(hjb + vjb * ray_count));
          }
          else
            range = laserShape->GetRange(j * ray_count + i);
          *out++ = edge(range);
        }
      }
    // the plant's rays see no <laser_retro>: every intensity 0 (a message filled again has them)
    if (scan->intensities_size() != ranges->size())
    {
      scan->clear_intensities();
      scan->mutable_intensities()->Resize(ranges->size(), 0.0);
    }
  }
  {
    std::lock_guard<std::mutex> lock(mutex_);
    // the one it replaces becomes a spare (a few at most: the transport hands scans over in order)
    auto empty = std::find_if(spare_msgs_.begin(), spare_msgs_.end(), [](const auto& m) { return !m; });
    if (empty != spare_msgs_.end())
      empty->swap(laser_msg_);
    else if (spare_msgs_.size() < 4)
      spare_msgs_.push_back(laser_msg_);
    laser_msg_ = message;
  }
  if (scan_pub_ && scan_pub_->HasConnections())
    scan_pub_->PublishOwned(message);
  return true;
}
}  // namespace sensors
}  // namespace gazebo
