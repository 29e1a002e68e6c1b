// sensors::Sensor, the base of Gazebo's sensors as a plugin reads it: its name, type, parent,
// update rate and pose from its <sensor> element (sdformat's sensor.sdf gives the defaults), its
// update gated by the rate in simulated time, and the updated event. Which of the sensor types the
// plant makes, and what it leaves out (noise models, msgs::Sensor, the rendering scene):
// docs/gazebo_api.md.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <ignition/math/Pose3.hh>
#include <sdf/sdf.hh>

#include "gazebo/common/Event.hh"
#include "gazebo/common/Events.hh"  // as Gazebo's: sensor plugins connect to the world's events through it
#include "gazebo/common/Time.hh"
#include "gazebo/msgs/msgs.hh"
#include "gazebo/physics/PhysicsTypes.hh"
#include "gazebo/rendering/RenderTypes.hh"  // as Gazebo's: camera plugins name rendering::CameraPtr through it
#include "gazebo/sensors/SensorBridge.hh"
#include "gazebo/sensors/SensorTypes.hh"
#include "gazebo/transport/TransportTypes.hh"
#include "gazebo/util/system.hh"

namespace gazebo
{
namespace sensors
{
class GZ_SENSORS_VISIBLE Sensor : public std::enable_shared_from_this<Sensor>
{
public:
  explicit Sensor(SensorCategory category);
  virtual ~Sensor();

  // The <sensor> element's values over sensor.sdf's defaults, then Load(worldName).
  virtual void Load(const std::string& worldName, sdf::ElementPtr sdf);
  // The pose, update rate and always_on read, the world found by name (physics::get_world).
  virtual void Load(const std::string& worldName);
  virtual void Init();
  virtual void Fini();

  // The sensor's parent: its link's scoped name (MODEL::LINK) and id.
  void SetParent(const std::string& name, uint32_t id);
  std::string ParentName() const;
  uint32_t ParentId() const;

  // UpdateImpl where the sensor is active and its period has passed in simulated time (or `force`);
  // when it reports an update, the last update time is the world's time and the updated event fires.
  void Update(bool force);
  double UpdateRate() const;  // 0: every step
  void SetUpdateRate(double hz);
  void ResetLastUpdateTime();
  common::Time LastUpdateTime() const;
  common::Time LastMeasurementTime() const;

  std::string Name() const;
  // WORLD::MODEL::LINK::SENSOR
  std::string ScopedName() const;
  std::string Type() const;
  std::string WorldName() const;
  // The <topic> element; "" where it is not set.
  virtual std::string Topic() const;
  bool Visualize() const;
  SensorCategory Category() const;
  uint32_t Id() const;

  // Relative to the parent link.
  virtual ignition::math::Pose3d Pose() const;
  virtual void SetPose(const ignition::math::Pose3d& pose);

  virtual void SetActive(bool value);
  virtual bool IsActive() const;

  event::ConnectionPtr ConnectUpdated(std::function<void()> subscriber);

  // Its noise model of that type (the sensor made it from its <noise> elements); null, with
  // Gazebo's error, where it has none.
  NoisePtr Noise(const SensorNoiseType _type) const;

  // Not Gazebo's: the simulator's sensor this one is (set by the simulator before Load); its rate
  // follows SetUpdateRate. Null for a sensor that is no simulation's (it then measures nothing).
  void SetBridge(std::shared_ptr<SensorBridge> bridge);

protected:
  // What a sensor type measures; true where it made a measurement.
  virtual bool UpdateImpl(bool /*force*/) { return false; }
  // Whether the update period has passed since the last update, in simulated time.
  bool NeedsUpdate();

  bool active = false;
  sdf::ElementPtr sdf;
  ignition::math::Pose3d pose;
  std::vector<event::ConnectionPtr> connections;
  // Initialized in the sensor's world by Load, as Gazebo's ("~/" is /gazebo/WORLD/).
  transport::NodePtr node;
  std::shared_ptr<SensorBridge> bridge;
  std::string parentName;
  uint32_t parentId = 0;
  physics::WorldPtr world;
  common::Time updatePeriod;
  common::Time lastUpdateTime;
  common::Time lastMeasurementTime;
  std::map<SensorNoiseType, NoisePtr> noises;

private:
  SensorCategory category_;
  uint32_t id_;
  std::string world_name_;
  event::EventT<void()> updated_;
  bool warned_no_world_ = false;
};
}  // namespace sensors
}  // namespace gazebo
