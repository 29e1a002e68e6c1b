// sensors::RaySensor (gazebo/sensors/RaySensor.hh).
#include "gazebo/sensors/RaySensor.hh"

#include <algorithm>
#include <cmath>
#include <limits>

#include <boost/algorithm/string/replace.hpp>
#include <boost/make_shared.hpp>

#include "gazebo/common/Console.hh"
#include "gazebo/msgs/msgs.hh"
#include "gazebo/transport/Node.hh"
#include "gazebo/transport/Publisher.hh"

namespace gazebo
{
namespace sensors
{
RaySensor::RaySensor()
  : Sensor(RAY),
    laser_shape_(new physics::MultiRayShape(physics::CollisionPtr())),
    laser_msg_(boost::make_shared<msgs::LaserScanStamped>())
{
}

RaySensor::~RaySensor() = default;

std::string RaySensor::Topic() const
{
  std::string topic = "~/" + ParentName() + "/" + Name() + "/scan";
  boost::replace_all(topic, "::", "/");
  return topic;
}

void RaySensor::Load(const std::string& worldName)
{
  Sensor::Load(worldName);
  laser_shape_->Load(sdf);
  laser_shape_->Init();
  if (world)
    scan_pub_ = node->Advertise<msgs::LaserScanStamped>(Topic(), 50);
}

void RaySensor::Init()
{
  Sensor::Init();
  std::lock_guard<std::mutex> lock(mutex_);
  laser_msg_->mutable_scan()->set_frame(ParentName());
}

void RaySensor::Fini()
{
  scan_pub_.reset();
  Sensor::Fini();
}

ignition::math::Angle RaySensor::AngleMin() const { return laser_shape_->MinAngle(); }

ignition::math::Angle RaySensor::AngleMax() const { return laser_shape_->MaxAngle(); }

double RaySensor::AngleResolution() const { return (AngleMax() - AngleMin()).Radian() / (RangeCount() - 1); }

double RaySensor::RangeMin() const { return laser_shape_->GetMinRange(); }

double RaySensor::RangeMax() const { return laser_shape_->GetMaxRange(); }

double RaySensor::RangeResolution() const { return laser_shape_->GetResRange(); }

int RaySensor::RayCount() const { return laser_shape_->GetSampleCount(); }

int RaySensor::RangeCount() const
{
  return static_cast<int>(laser_shape_->GetSampleCount() * laser_shape_->GetScanResolution());
}

int RaySensor::VerticalRayCount() const { return laser_shape_->GetVerticalSampleCount(); }

int RaySensor::VerticalRangeCount() const
{
  return static_cast<int>(laser_shape_->GetVerticalSampleCount() * laser_shape_->GetVerticalScanResolution());
}

ignition::math::Angle RaySensor::VerticalAngleMin() const { return laser_shape_->VerticalMinAngle(); }

ignition::math::Angle RaySensor::VerticalAngleMax() const { return laser_shape_->VerticalMaxAngle(); }

double RaySensor::VerticalAngleResolution() const
{
  return (VerticalAngleMax() - VerticalAngleMin()).Radian() / (VerticalRangeCount() - 1);
}

namespace
{
// Element `index` of the last scan's `values` (its ranges or intensities), with Gazebo's warning for
// a scan not made yet and its error for an index past the end (0 for both).
double scanValue(const google::protobuf::RepeatedField<double>& values, unsigned int index, const char* empty,
                 const char* invalid)
{
  if (values.empty())
  {
    gzwarn << empty << "\n";
    return 0.0;
  }
  if (static_cast<int>(index) >= values.size())
  {
    gzerr << invalid << "[" << index << "]\n";
    return 0.0;
  }
  return values.Get(static_cast<int>(index));
}
}  // namespace

double RaySensor::Range(unsigned int index) const
{
  std::lock_guard<std::mutex> lock(mutex_);
  return scanValue(laser_msg_->scan().ranges(), index, "ranges not constructed yet (zero sized)",
                   "Invalid range index");
}

void RaySensor::Ranges(std::vector<double>& out) const
{
  std::lock_guard<std::mutex> lock(mutex_);
  out.assign(laser_msg_->scan().ranges().begin(), laser_msg_->scan().ranges().end());
}

double RaySensor::Retro(unsigned int index) const
{
  std::lock_guard<std::mutex> lock(mutex_);
  return scanValue(laser_msg_->scan().intensities(), index, "Intensities not constructed yet (zero size)",
                   "Invalid intensity index");
}

int RaySensor::Fiducial(unsigned int index) const
{
  // Gazebo's: the range's index mapped onto the rays'
  const int range_count = RangeCount(), ray_count = RayCount();
  const int vertical = (static_cast<int>(index) / range_count) * VerticalRayCount() / VerticalRangeCount();
  const int horizontal = (static_cast<int>(index) % range_count) * ray_count / range_count;
  const int ray = vertical * ray_count + horizontal;
  if (ray >= ray_count * VerticalRayCount())
  {
    gzerr << "Invalid fiducial index[" << index << "]\n";
    return 0;
  }
  return laser_shape_->GetFiducial(static_cast<unsigned int>(ray));
}

bool RaySensor::IsActive() const { return Sensor::IsActive() || (scan_pub_ && scan_pub_->HasConnections()); }

bool RaySensor::UpdateImpl(bool /*force*/)
{
  const auto* rays = dynamic_cast<const RayBridge*>(bridge.get());
  if (!rays || rays->ranges().empty())
    return false;
  laser_shape_->SetRanges(rays->ranges());
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
    scan->set_frame(ParentName());
    msgs::Set(scan->mutable_world_pose(), rays->worldPose());
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
    const std::vector<float>& measured = laser_shape_->Ranges();
    if (!interpolate && measured.size() == size_t(range_count) * vertical_ranges)
    {
      // the plant's own rays, one range each: no shape calls, a loop the compiler vectorizes
      const float* in = measured.data();
      const double inf = std::numeric_limits<double>::infinity();
      for (size_t i = 0, n = measured.size(); i < n; ++i)
      {
        const double range = in[i];
        out[i] = range >= range_max ? inf : (range <= range_min ? -inf : range);
      }
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
            range = (1 - vb) * ((1 - hb) * laser_shape_->GetRange(hja + vja * ray_count) +
                                hb * laser_shape_->GetRange(hjb + vja * ray_count)) +
                    vb * ((1 - hb) * laser_shape_->GetRange(hja + vjb * ray_count) +
                          hb * laser_shape_->GetRange(hjb + vjb * ray_count));
          }
          else
            range = laser_shape_->GetRange(j * ray_count + i);
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
  laser_shape_->Update();
  return true;
}
}  // namespace sensors
}  // namespace gazebo
