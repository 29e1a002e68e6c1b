// sensors::Sensor (gazebo/sensors/Sensor.hh): the base of Gazebo's sensors.
#include "gazebo/sensors/Sensor.hh"

#include <atomic>

#include "gazebo/common/Console.hh"
#include "gazebo/common/Exception.hh"
#include "gazebo/physics/PhysicsIface.hh"
#include "gazebo/physics/World.hh"
#include "gazebo/sensors/Noise.hh"
#include "gazebo/transport/Node.hh"

namespace gazebo
{
namespace sensors
{
namespace
{
// Gazebo numbers its entities and sensors from one counter; the plant's sensors from their own.
std::atomic<uint32_t> next_sensor_id{1};

// sensor.sdf's element with the spec's defaults (always_on false, update_rate 0 ...), read once: a
// reading costs some 80 ms, a clone a small fraction of that (Gazebo keeps one too).
sdf::ElementPtr sensorSpec()
{
  static const sdf::ElementPtr spec = [] {
    sdf::ElementPtr element(new sdf::Element);
    sdf::initFile("sensor.sdf", element);
    return element;
  }();
  return spec->Clone();
}
}  // namespace

Sensor::Sensor(SensorCategory category)
  : sdf(sensorSpec()), node(new transport::Node()), category_(category), id_(next_sensor_id++)
{
}

Sensor::~Sensor() = default;

void Sensor::Load(const std::string& worldName, sdf::ElementPtr element)
{
  if (element)
    sdf->Copy(element);
  Load(worldName);
}

void Sensor::Load(const std::string& worldName)
{
  world_name_ = worldName;
  if (sdf->HasElement("pose"))
    pose = sdf->Get<ignition::math::Pose3d>("pose");
  if (sdf->Get<bool>("always_on"))
    SetActive(true);
  if (sdf->HasElement("update_rate"))
    SetUpdateRate(sdf->Get<double>("update_rate"));
  try
  {
    world = physics::get_world(worldName);
    node->Init(world->Name());
  }
  catch (const common::Exception&)
  {
    // get_world said which; the sensor stays and measures nothing (Update says so once)
  }
}

void Sensor::Init() {}

void Sensor::Fini()
{
  for (auto& noise : noises)
    if (noise.second)
      noise.second->Fini();
  noises.clear();
  connections.clear();
  active = false;
  world.reset();
  if (node)
    node->Fini();
}

void Sensor::SetParent(const std::string& name, uint32_t id)
{
  parentName = name;
  parentId = id;
}

std::string Sensor::ParentName() const { return parentName; }

uint32_t Sensor::ParentId() const { return parentId; }

bool Sensor::NeedsUpdate()
{
  const common::Time now = world->SimTime();
  if (now < lastUpdateTime)  // the world's time was reset
    ResetLastUpdateTime();
  return updatePeriod <= common::Time::Zero || now - lastUpdateTime >= updatePeriod;
}

void Sensor::Update(bool force)
{
  if (!world)
  {
    if (!warned_no_world_)
      gzerr << "Sensor [" << Name() << "] is in no world (Load(\"" << world_name_ << "\")): it does not update\n";
    warned_no_world_ = true;
    return;
  }
  if (!(IsActive() || force) || !(force || NeedsUpdate()))
    return;
  if (UpdateImpl(force))
  {
    lastUpdateTime = world->SimTime();
    updated_();
  }
}

double Sensor::UpdateRate() const
{
  return updatePeriod > common::Time::Zero ? 1.0 / updatePeriod.Double() : 0.0;
}

void Sensor::SetUpdateRate(double hz)
{
  // (a rate whose period passes common::Time's seconds, DBL_MIN as gazebo_ros_triggered_camera sets
  // it for "never": the longest time)
  updatePeriod = !(hz > 0.0)                  ? common::Time::Zero
                 : 1.0 / hz < double(INT32_MAX) ? common::Time(1.0 / hz)
                                                : common::Time(INT32_MAX, 0);
  if (bridge)
    bridge->setUpdateRate(hz > 0.0 ? hz : 0.0);
}

void Sensor::SetBridge(std::shared_ptr<SensorBridge> value) { bridge = std::move(value); }

void Sensor::ResetLastUpdateTime()
{
  lastUpdateTime = common::Time::Zero;
}

common::Time Sensor::LastUpdateTime() const { return lastUpdateTime; }

common::Time Sensor::LastMeasurementTime() const { return lastMeasurementTime; }

std::string Sensor::Name() const { return sdf->Get<std::string>("name"); }

std::string Sensor::ScopedName() const { return WorldName() + "::" + parentName + "::" + Name(); }

std::string Sensor::Type() const { return sdf->Get<std::string>("type"); }

std::string Sensor::WorldName() const { return world ? world->Name() : world_name_; }

std::string Sensor::Topic() const
{
  const std::string topic = sdf->HasElement("topic") ? sdf->Get<std::string>("topic") : "";
  return topic == "__default__" ? "" : topic;
}

bool Sensor::Visualize() const { return sdf->Get<bool>("visualize"); }

SensorCategory Sensor::Category() const { return category_; }

uint32_t Sensor::Id() const { return id_; }

ignition::math::Pose3d Sensor::Pose() const { return pose; }

void Sensor::SetPose(const ignition::math::Pose3d& value) { pose = value; }

void Sensor::SetActive(bool value) { active = value; }

bool Sensor::IsActive() const { return active; }

NoisePtr Sensor::Noise(const SensorNoiseType _type) const
{
  const auto found = noises.find(_type);
  if (found != noises.end())
    return found->second;
  gzerr << "Get noise index not valid\n";
  return NoisePtr();
}

event::ConnectionPtr Sensor::ConnectUpdated(std::function<void()> subscriber)
{
  return updated_.Connect(subscriber);
}
}  // namespace sensors
}  // namespace gazebo
