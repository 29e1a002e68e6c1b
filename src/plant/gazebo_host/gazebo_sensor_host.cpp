#include "gazebo_host/gazebo_sensor_host.h"

#include <cmath>
#include <cstring>

#include <gazebo/physics/World.hh>
#include <gazebo/msgs/msgs.hh>
#include <gazebo/sensors/AltimeterSensor.hh>
#include <gazebo/sensors/CameraSensor.hh>
#include <gazebo/sensors/ContactSensor.hh>
#include <gazebo/sensors/DepthCameraSensor.hh>
#include <gazebo/sensors/ForceTorqueSensor.hh>
#include <gazebo/sensors/GpsSensor.hh>
#include <gazebo/sensors/GpuRaySensor.hh>
#include <gazebo/sensors/ImuSensor.hh>
#include <gazebo/sensors/MagnetometerSensor.hh>
#include <gazebo/sensors/MultiCameraSensor.hh>
#include <gazebo/sensors/RaySensor.hh>
#include <gazebo/sensors/SensorManager.hh>
#include <gazebo/sensors/SonarSensor.hh>
#include <gazebo/transport/TopicManager.hh>

#include "bullet_plant/image_encoding.h"
#include "bullet_plant/inertial_sensors.h"
#include "bullet_plant/log.h"
#include "bullet_plant/model_plugin.h"
#include "bullet_plant/rate_gate.h"
#include "bullet_plant/sensors.h"
#include "gazebo_host/gazebo_world_host.h"

namespace bullet_plant
{
namespace
{
constexpr const char* kNotLoaded = "; the plugin is not loaded";

// A plant sensor as Gazebo's sensor of its kind sees it (`GazeboBridge`, gazebo/sensors/SensorBridge.hh):
// its activity and rate, its pose in the world (its link's, which the model's bridge answers while
// the model is in the world), its latest reading's time; the kind's readings in the classes below.
// The host removes the Gazebo sensor before the plant's goes.
template <class GazeboBridge, class PlantSensor>
class PlantSensorBridge : public GazeboBridge
{
public:
  PlantSensorBridge(PlantSensor& sensor, std::shared_ptr<ContextModel> model)
    : sensor_(sensor), model_(std::move(model)), link_(sensor.description().link), pose_(toIgnition(sensor.description().pose))
  {
  }
  void setActive(bool active) final { sensor_.setActive(active); }
  void setUpdateRate(double hz) final { sensor_.setUpdatePeriodNs(periodNsOfRate(hz)); }
  ignition::math::Pose3d worldPose() const final { return pose_ + model_->linkPose(link_); }
  gazebo::common::Time measurementTime() const final
  {
    const int64_t ns = sensor_.latest().stamp_ns;
    gazebo::common::Time t;
    t.sec = static_cast<int32_t>(ns / 1000000000);
    t.nsec = static_cast<int32_t>(ns % 1000000000);
    return t;
  }

protected:
  PlantSensor& sensor_;

private:
  std::shared_ptr<ContextModel> model_;
  std::string link_;
  ignition::math::Pose3d pose_;  // in its link's frame
};

class LidarBridge final : public PlantSensorBridge<gazebo::sensors::RayBridge, Lidar>
{
public:
  using PlantSensorBridge::PlantSensorBridge;
  const std::vector<float>& ranges() const override { return sensor_.latest().ranges; }
  ignition::math::Pose3d scanOrigin() const override { return toIgnition(sensor_.latest().origin); }
};

// A sonar over the plant's lidar that samples its shape (robot_builder's sonarSampling: rings of rays
// about the sensor's -z axis, or all round, in the sonar's own frame): the nearest hit within the
// cone (or sphere), `sonar` the sonar's description.
class SonarBridge final : public PlantSensorBridge<gazebo::sensors::SonarBridge, Lidar>
{
public:
  SonarBridge(Lidar& rays, std::shared_ptr<ContextModel> model, const SensorDescription& sonar)
    : PlantSensorBridge(rays, std::move(model)), height_(sonar.range_max - sonar.range_min),
      sphere_(sonar.sonar_geometry == "sphere")
  {
  }
  bool nearest(double& range, ignition::math::Vector3d& point) const override
  {
    const SensorDescription& d = sensor_.description();
    const std::vector<float>& ranges = sensor_.latest().ranges;
    const int across = d.horizontal_samples, rings = d.vertical_samples;
    bool seen = false;
    for (int v = 0; v < rings && size_t(v + 1) * across <= ranges.size(); ++v)
    {
      const double elevation =
          d.vertical_min_angle + (rings > 1 ? v * (d.vertical_max_angle - d.vertical_min_angle) / (rings - 1) : 0.0);
      for (int h = 0; h < across; ++h)
      {
        const double distance = ranges[size_t(v) * across + h];
        if (!std::isfinite(distance) || (seen && distance >= range))
          continue;
        const double azimuth = d.horizontal_min_angle + h * (d.horizontal_max_angle - d.horizontal_min_angle) /
                                                            std::max(1, across - 1);
        const ignition::math::Vector3d direction(std::cos(elevation) * std::cos(azimuth),
                                                 std::cos(elevation) * std::sin(azimuth), std::sin(elevation));
        // within the cone: no farther down its axis (-z) than its height; the sphere: its radius
        if (sphere_ ? distance > height_ : -direction.Z() * distance > height_)
          continue;
        range = distance;
        point = distance * direction;
        seen = true;
      }
    }
    return seen;
  }

private:
  double height_;
  bool sphere_;
};

// A camera's frames in Gazebo's bytes of its format (and, for a depth camera, Gazebo's depths and RGB
// points), as its camera reads the render target back.
class CameraBridge final : public PlantSensorBridge<gazebo::sensors::DepthCameraBridge, Camera>
{
public:
  CameraBridge(Camera& camera, std::shared_ptr<ContextModel> model)
    : PlantSensorBridge(camera, std::move(model)), encoding_(imageEncodingOf(camera.description().image_format))
  {
  }
  const unsigned char* image() override
  {
    const CameraFrame& frame = sensor_.latest();
    if (!sensor_.hasFrame() || frame.rgb.empty())
      return nullptr;
    image_.resize(size_t(frame.width) * frame.height * encoding_.bytes_per_pixel);
    encodeImage(encoding_, frame.rgb.data(), frame.rgb16.empty() ? nullptr : frame.rgb16.data(), frame.width,
                frame.height, image_.data());
    return image_.data();
  }
  void setDistortionCrop(bool crop) override { sensor_.setDistortionCrop(crop); }
  const float* depths() override
  {
    const CameraFrame& frame = sensor_.latest();
    return sensor_.hasFrame() && !frame.depth.empty() ? frame.depth.data() : nullptr;
  }
  const float* rgbPoints() override
  {
    const CameraFrame& frame = sensor_.latest();
    const size_t pixels = size_t(frame.width) * frame.height;
    if (!sensor_.hasFrame() || frame.points.size() != 3 * pixels || frame.rgb.size() != 3 * pixels)
      return nullptr;
    points_.resize(4 * pixels);
    for (size_t i = 0; i < pixels; ++i)
    {
      const uint8_t* c = &frame.rgb[3 * i];
      const uint32_t packed = uint32_t(c[0]) << 16 | uint32_t(c[1]) << 8 | uint32_t(c[2]);
      std::memcpy(&points_[4 * i], &frame.points[3 * i], 3 * sizeof(float));
      std::memcpy(&points_[4 * i + 3], &packed, sizeof(float));
    }
    return points_.data();
  }

private:
  ImageEncoding encoding_;
  std::vector<uint8_t> image_;
  std::vector<float> points_;
};

// A multicamera's cameras (the plant's camera of each <camera>, in their order); its pose is the
// <sensor>'s, the first camera's with that camera's own pose in the sensor taken away.
class MultiCameraBridge final : public gazebo::sensors::MultiCameraBridge
{
public:
  MultiCameraBridge(std::vector<std::unique_ptr<CameraBridge>> cameras, const ignition::math::Pose3d& first_in_sensor)
    : cameras_(std::move(cameras)), sensor_in_first_(first_in_sensor.Inverse())
  {
  }
  void setActive(bool active) override
  {
    for (auto& camera : cameras_)
      camera->setActive(active);
  }
  void setUpdateRate(double hz) override
  {
    for (auto& camera : cameras_)
      camera->setUpdateRate(hz);
  }
  ignition::math::Pose3d worldPose() const override { return sensor_in_first_ + cameras_.front()->worldPose(); }
  gazebo::common::Time measurementTime() const override { return cameras_.front()->measurementTime(); }
  unsigned int cameraCount() const override { return static_cast<unsigned int>(cameras_.size()); }
  gazebo::sensors::CameraBridge& camera(unsigned int index) override { return *cameras_.at(index); }

private:
  std::vector<std::unique_ptr<CameraBridge>> cameras_;
  ignition::math::Pose3d sensor_in_first_;
};

class ContactBridge final : public PlantSensorBridge<gazebo::sensors::ContactBridge, ContactSensor>
{
public:
  using PlantSensorBridge::PlantSensorBridge;
  // Gazebo's msgs::Contact of each state: body 1 is the sensor's (its wrench as the plant measures
  // it, in its link frame); body 2's wrench is not measured (zero).
  void contacts(google::protobuf::RepeatedPtrField<gazebo::msgs::Contact>& out) const override
  {
    const std::vector<ContactState>& states = sensor_.latest().states;
    out.Clear();
    out.Reserve(static_cast<int>(states.size()));
    for (const ContactState& state : states)
    {
      gazebo::msgs::Contact& contact = *out.Add();
      contact.set_collision1(state.collision1);
      contact.set_collision2(state.collision2);
      for (const ContactPoint& point : state.points)
      {
        gazebo::msgs::Set(contact.add_position(), toIgnition(point.position));
        gazebo::msgs::Set(contact.add_normal(), toIgnition(point.normal));
        contact.add_depth(point.depth);
        gazebo::msgs::JointWrench& wrench = *contact.add_wrench();
        wrench.set_body_1_name(state.collision1);
        wrench.set_body_1_id(0);
        wrench.set_body_2_name(state.collision2);
        wrench.set_body_2_id(0);
        gazebo::msgs::Set(wrench.mutable_body_1_wrench()->mutable_force(), toIgnition(point.force));
        gazebo::msgs::Set(wrench.mutable_body_1_wrench()->mutable_torque(), toIgnition(point.torque));
        gazebo::msgs::Set(wrench.mutable_body_2_wrench()->mutable_force(), ignition::math::Vector3d::Zero);
        gazebo::msgs::Set(wrench.mutable_body_2_wrench()->mutable_torque(), ignition::math::Vector3d::Zero);
      }
    }
  }
};

class ImuBridge final : public PlantSensorBridge<gazebo::sensors::ImuBridge, Imu>
{
public:
  using PlantSensorBridge::PlantSensorBridge;
  ignition::math::Quaterniond orientation() const override
  {
    const urdf::Rotation& q = sensor_.latest().orientation;
    return {q.w, q.x, q.y, q.z};
  }
  ignition::math::Vector3d angularVelocity() const override { return toIgnition(sensor_.latest().angular_velocity); }
  ignition::math::Vector3d linearAcceleration() const override { return toIgnition(sensor_.latest().linear_acceleration); }
};

// Gazebo's sensor of a type it measures itself (measuredByGazeboApi): no bridge, its link or joint
// found in the world by its parent's name, as Gazebo's.
gazebo::sensors::SensorPtr gazeboPhysicsSensor(const std::string& type)
{
  if (type == "altimeter")
    return std::make_shared<gazebo::sensors::AltimeterSensor>();
  if (type == "magnetometer")
    return std::make_shared<gazebo::sensors::MagnetometerSensor>();
  if (type == "gps")
    return std::make_shared<gazebo::sensors::GpsSensor>();
  if (type == "force_torque")
    return std::make_shared<gazebo::sensors::ForceTorqueSensor>();
  return nullptr;
}

// Gazebo's SonarSensor over the plant's lidar sampling its shape; null where it is no lidar.
gazebo::sensors::SensorPtr gazeboSonar(const SensorDescription& d, Sensor& plant, const std::shared_ptr<ContextModel>& model,
                                       std::string& why)
{
  auto* rays = dynamic_cast<Lidar*>(&plant);
  if (!rays)
  {
    why = "its sonar is not sampled by the plant's rays";
    return nullptr;
  }
  auto sonar = std::make_shared<gazebo::sensors::SonarSensor>();
  sonar->SetBridge(std::make_shared<SonarBridge>(*rays, model, d));
  return sonar;
}

// A multicamera's first <camera>'s own pose in its <sensor> (`d` that camera's description, whose
// pose is the sensor's composed with it); identity for any other sensor.
ignition::math::Pose3d firstCameraInSensor(const SensorDescription& d)
{
  if (d.multicamera_camera.empty() || !d.element || !d.element->HasElement("camera"))
    return ignition::math::Pose3d::Zero;
  const sdf::ElementPtr first = d.element->GetElement("camera");
  return first->HasElement("pose") ? first->Get<ignition::math::Pose3d>("pose") : ignition::math::Pose3d::Zero;
}

// Gazebo's MultiCameraSensor over the plant's camera of each of a multicamera's <camera> elements
// (`d` the first one's description); null where one is no camera.
gazebo::sensors::SensorPtr gazeboMultiCamera(const SensorDescription& d, const std::vector<Sensor*>& plant,
                                             const std::shared_ptr<ContextModel>& model, std::string& why)
{
  std::vector<std::unique_ptr<CameraBridge>> cameras;
  for (Sensor* sensor : plant)
  {
    auto* camera = dynamic_cast<Camera*>(sensor);
    if (!camera)
    {
      why = "its camera '" + sensor->name() + "' is not simulated as a camera";
      return nullptr;
    }
    cameras.push_back(std::make_unique<CameraBridge>(*camera, model));
  }
  auto multicamera = std::make_shared<gazebo::sensors::MultiCameraSensor>();
  multicamera->SetBridge(std::make_shared<MultiCameraBridge>(std::move(cameras), firstCameraInSensor(d)));
  return multicamera;
}

// The Gazebo sensor of the plant's sensor's kind over it; null where the plant has none yet (the
// reason in `why`).
gazebo::sensors::SensorPtr gazeboSensor(Sensor& sensor, std::shared_ptr<ContextModel> model, std::string& why)
{
  const std::string& type = sensor.description().type;
  if (auto* lidar = dynamic_cast<Lidar*>(&sensor))
  {
    gazebo::sensors::SensorPtr scanner;
    if (type == "ray")
      scanner = std::make_shared<gazebo::sensors::RaySensor>();
    else if (type == "gpu_ray")
      scanner = std::make_shared<gazebo::sensors::GpuRaySensor>();
    if (scanner)
    {
      scanner->SetBridge(std::make_shared<LidarBridge>(*lidar, std::move(model)));
      return scanner;
    }
  }
  if (auto* imu = dynamic_cast<Imu*>(&sensor))
    if (type == "imu" && !imu->modelPlugin())
    {
      auto gazebo_imu = std::make_shared<gazebo::sensors::ImuSensor>();
      gazebo_imu->SetBridge(std::make_shared<ImuBridge>(*imu, std::move(model)));
      return gazebo_imu;
    }
  if (auto* camera = dynamic_cast<Camera*>(&sensor))
  {
    std::shared_ptr<gazebo::sensors::CameraSensor> gazebo_camera;
    if (type == "camera")
      gazebo_camera = std::make_shared<gazebo::sensors::CameraSensor>();
    else if (type == "depth")
      gazebo_camera = std::make_shared<gazebo::sensors::DepthCameraSensor>();
    if (gazebo_camera)
    {
      gazebo_camera->SetBridge(std::make_shared<CameraBridge>(*camera, std::move(model)));
      return gazebo_camera;
    }
  }
  if (auto* contact = dynamic_cast<ContactSensor*>(&sensor))
  {
    auto gazebo_contact = std::make_shared<gazebo::sensors::ContactSensor>();
    gazebo_contact->SetBridge(std::make_shared<ContactBridge>(*contact, std::move(model)));
    return gazebo_contact;
  }
  why = "Gazebo's sensor of type '" + type +
        "' is not offered to plugins yet (those of types ray, gpu_ray, imu, contact, camera, depth, multicamera, "
        "altimeter, magnetometer, gps, force_torque and sonar are: docs/gazebo_api.md)";
  return nullptr;
}
}  // namespace

GazeboSensorHost::~GazeboSensorHost()
{
  for (Hosted& hosted : hosted_)
    remove(hosted);
}

bool GazeboSensorHost::load(const SensorDescription& d, const std::vector<Sensor*>& plant, ModelPluginContext& model)
{
  Log& log = model.log();
  // a multicamera by its <sensor>'s name (its cameras' descriptions are SENSOR::CAMERA)
  const std::string name = d.multicamera_camera.empty() ? d.name : d.name.substr(0, d.name.rfind("::"));
  const std::string label = model.modelName() + ": sensor '" + name + "' plugin '" + d.plugin_name + "' (" +
                            d.plugin_filename + ")";
  std::string why;
  Hosted hosted;
  hosted.model = model.modelName();
  hosted.plant = plant;
  if (measuredByGazeboApi(d.type))
    hosted.sensor = gazeboPhysicsSensor(d.type);
  else if (d.type == "sonar")
    hosted.sensor = gazeboSonar(d, *plant.front(), host_.modelBridge(model), why);
  else if (!d.multicamera_camera.empty())
    hosted.sensor = gazeboMultiCamera(d, plant, host_.modelBridge(model), why);
  else
    hosted.sensor = gazeboSensor(*plant.front(), host_.modelBridge(model), why);
  if (!hosted.sensor)
  {
    log.error(label + ": " + why + kNotLoaded);
    return false;
  }
  hosted.plugin = createPlugin<gazebo::SensorPlugin>(log, label, d.library, d.plugin_name, gazebo::SENSOR_PLUGIN,
                                                     kNotLoaded);
  if (!hosted.plugin)
    return false;
  hosted.document = d.document;
  const sdf::ElementPtr element = pluginElement(d.plugin_element);
  if (element)
    addSpawnNamespace(element, model.spawnNamespace());
  // Gazebo's sensor is loaded from its <sensor> element and named in its link or joint as Gazebo
  // scopes it (MODEL::LINK, MODEL::JOINT): the plugin's topics and SensorManager's names are Gazebo's.
  hosted.sensor->SetParent(model.modelName() + "::" + (d.joint.empty() ? d.link : d.joint), 0);
  const std::string world = host_.world()->Name();
  if (!pluginCall(log, [&] { return label + ": its Load threw"; }, kNotLoaded, [&] {
        hosted.sensor->Load(world, d.element);
        // in its link as the plant has it (a link fixed to its parent is one body with it, the
        // sensor's pose composed with the joint's, as sdformat's URDF reading does)
        hosted.sensor->SetPose(firstCameraInSensor(d).Inverse() + toIgnition(d.pose));
        hosted.sensor->Init();
        gazebo::sensors::SensorManager::Instance()->AddSensor(hosted.sensor);
        hosted.plugin->Load(hosted.sensor, element);
        hosted.plugin->Init();
      }))
  {
    remove(hosted);
    return false;
  }
  for (Sensor* sensor : plant)
    hosted.readings_seen.push_back(sensor->updates());
  handActivityBack(hosted);
  log.info(label + ": loaded from " + d.library);
  hosted_.push_back(std::move(hosted));
  return true;
}

void GazeboSensorHost::update()
{
  const int64_t next_step_ns =
      host_.context().timeNs() + static_cast<int64_t>(std::llround(host_.context().stepSize() * 1e9));
  bool rendering = false;
  for (Hosted& hosted : hosted_)
  {
    // a sensor over the plant's takes its new readings; one Gazebo's measures from its link
    // measures at its own rate, as Gazebo's sensor manager updates it
    const bool measured_here = hosted.plant.empty();
    if (measured_here || takeNewReadings(hosted))
      pluginCall(host_.context().log(),
                 [&] { return hosted.model + ": sensor '" + hosted.sensor->Name() + "': a callback on its update threw"; },
                 "", [&] { hosted.sensor->Update(!measured_here); });
    rendering = rendering || hosted.sensor->Category() == gazebo::sensors::IMAGE;
  }
  if (rendering)
    pluginCall(host_.context().log(), [] { return std::string("a callback on the render events threw"); }, "", [] {
      gazebo::event::Events::preRender();
      gazebo::event::Events::preRenderEnded();
      gazebo::event::Events::render();
      gazebo::event::Events::postRender();
    });
  // Whether the plant measures at the next step it may (asked then only: a RaySensor's IsActive
  // looks its topic's subscribers up).
  for (Hosted& hosted : hosted_)
    if (!hosted.plant.empty() && hosted.plant.front()->rateDueBy(next_step_ns))
      handActivityBack(hosted);
}

bool GazeboSensorHost::takeNewReadings(Hosted& hosted)
{
  for (size_t i = 0; i < hosted.plant.size(); ++i)
    if (hosted.plant[i]->updates() == hosted.readings_seen[i])
      return false;
  for (size_t i = 0; i < hosted.plant.size(); ++i)
    hosted.readings_seen[i] = hosted.plant[i]->updates();
  return true;
}

void GazeboSensorHost::handActivityBack(Hosted& hosted)
{
  const bool active = hosted.sensor->IsActive();
  for (Sensor* sensor : hosted.plant)
  {
    // Gazebo renders a camera and hands its frame over before it renders the next; the plant's
    // frames come a step or more after it renders them, so a camera rendering every step (a
    // triggered camera's, once triggered) waits for the last one: one frame per trigger.
    const auto* camera = dynamic_cast<const Camera*>(sensor);
    const bool waits = camera && sensor->periodNs() == 0 && camera->frameInFlight();
    sensor->setActive(active && !waits);
  }
}

void GazeboSensorHost::reset()
{
  for (Hosted& hosted : hosted_)
  {
    hosted.sensor->ResetLastUpdateTime();
    pluginCall(host_.context().log(), [&] { return hosted.model + ": sensor '" + hosted.sensor->Name() + "' plugin's Reset threw"; },
               "", [&] { hosted.plugin->Reset(); });
  }
}

void GazeboSensorHost::modelRemoved(const std::string& model)
{
  for (auto it = hosted_.begin(); it != hosted_.end();)
    if (it->model == model)
    {
      remove(*it);
      it = hosted_.erase(it);
    }
    else
      ++it;
}

void GazeboSensorHost::remove(Hosted& hosted)
{
  // The sensor stops publishing (Fini), and what it published is handed over, before its plugin
  // goes: a plugin's destructor shuts its ROS publishers before its transport subscriber goes
  // (upstream's gazebo_ros_laser does), and a scan delivered in between would publish on one shut.
  if (hosted.sensor)
  {
    gazebo::sensors::SensorManager& manager = *gazebo::sensors::SensorManager::Instance();
    if (manager.GetSensor(hosted.sensor->ScopedName()) == hosted.sensor)
      manager.RemoveSensor(hosted.sensor->ScopedName());  // Fini
    else
      hosted.sensor->Fini();  // its Load failed before it was added
    gazebo::transport::TopicManager::Instance()->WaitForAll();
  }
  hosted.plugin.reset();
  hosted.sensor.reset();
}
}  // namespace bullet_plant
