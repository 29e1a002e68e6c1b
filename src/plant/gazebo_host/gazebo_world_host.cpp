#include "gazebo_host/gazebo_world_host.h"

#include <dlfcn.h>

#include <cmath>
#include <exception>
#include <limits>
#include <map>
#include <mutex>

#include <gazebo/common/Console.hh>
#include <gazebo/common/Events.hh>
#include <gazebo/physics/PhysicsEngine.hh>
#include <gazebo/physics/World.hh>

#include "bullet_plant/log.h"
#include "bullet_plant/robot_description.h"

namespace bullet_plant
{
// physics::World's side in the plant: the world's context, and the models' bridges the host keeps.
// Joints a plugin made hold it too, and may outlive the host (a model plugin's, destroyed with its
// robot after the world's host): released with the host, it answers nothing and changes nothing.
class HostWorld final : public gazebo::physics::WorldBridge, public std::enable_shared_from_this<HostWorld>
{
public:
  explicit HostWorld(PlantGazeboHost& host) : host_(&host), context_(&host.context()) {}
  void release()
  {
    host_ = nullptr;
    context_ = nullptr;
  }

  std::string name() const override { return context_ ? context_->worldName() : ""; }
  gazebo::common::Time simTime() const override
  {
    // a plugin asks every step (gazebo_ros_diff_drive twice): sec and nsec set as they are, never
    // negative, without the general constructor's normalising
    const int64_t ns = context_ ? context_->timeNs() : 0;
    gazebo::common::Time time;
    time.sec = static_cast<int32_t>(ns / 1000000000);
    time.nsec = static_cast<int32_t>(ns % 1000000000);
    return time;
  }
  ignition::math::Vector3d gravity() const override
  {
    const urdf::Vector3 g = context_ ? context_->gravity() : urdf::Vector3();
    return {g.x, g.y, g.z};
  }
  void setGravity(const ignition::math::Vector3d& g) override
  {
    if (!context_)
      return;
    if (std::isfinite(g.X()) && std::isfinite(g.Y()) && std::isfinite(g.Z()))
      context_->setGravity(urdf::Vector3(g.X(), g.Y(), g.Z()));
    else
      context_->log().error("a Gazebo plugin's gravity is not finite; the world keeps its gravity");
  }
  ignition::math::Vector3d magneticField() const override
  {
    return context_ ? toIgnition(context_->magneticField()) : ignition::math::Vector3d::Zero;
  }
  ignition::math::Vector3d sphericalOrigin() const override
  {
    if (!context_)
      return ignition::math::Vector3d::Zero;
    const WorldDescription::SphericalCoordinates& s = context_->sphericalCoordinates();
    return {s.latitude_deg, s.longitude_deg, s.elevation};
  }
  double headingDeg() const override { return context_ ? context_->sphericalCoordinates().heading_deg : 0.0; }
  double stepSize() const override { return context_ ? context_->stepSize() : 0.0; }
  bool setStepSize(double seconds) override { return context_ && context_->setStepSize(seconds); }
  double realTimeUpdateRate() const override { return context_ ? context_->realTimeUpdateRate() : 0.0; }
  double realTimeFactor() const override { return context_ ? context_->realTimeFactor() : 0.0; }
  uint64_t iterations() const override { return context_ ? context_->iterations() : 0; }
  std::vector<std::string> modelNames() const override
  {
    return context_ ? context_->modelNames() : std::vector<std::string>();
  }
  std::shared_ptr<gazebo::physics::ModelBridge> model(const std::string& name) override
  {
    return host_ ? host_->modelBridge(name) : nullptr;
  }
  bool paused() const override { return context_ && context_->paused(); }
  void setPaused(bool paused) override
  {
    if (context_)
      context_->setPaused(paused);
  }
  bool physicsEnabled() const override { return context_ && context_->physicsEnabled(); }
  void setPhysicsEnabled(bool enable) override
  {
    if (context_)
      context_->setPhysicsEnabled(enable);
  }
  void reset() override
  {
    if (context_)
      context_->resetSimulation();
  }
  std::unique_ptr<gazebo::physics::JointBridge> attach(const gazebo::physics::RunTimeJointSpec& joint) override;
  WorldPluginContext* context() const { return context_; }
  // The physics update mutex, or null once the host is gone.
  boost::recursive_mutex* physicsMutex() const { return host_ ? &host_->physicsMutex() : nullptr; }
  void insertModel(const std::string& sdf_xml) override
  {
    if (context_)
      context_->insertModel(sdf_xml);
  }

private:
  PlantGazeboHost* host_;
  WorldPluginContext* context_;
};

// A joint made at run time, over the world's context by its id; it lets go when destroyed, and
// answers nothing once the world's host is gone. What only a model's joint does (a velocity or a
// position set, a motor, the wrench it passed) is one warning naming it.
class RunTimeJointBridge final : public gazebo::physics::JointBridge
{
public:
  RunTimeJointBridge(std::shared_ptr<HostWorld> world, int id, gazebo::physics::RunTimeJointSpec spec)
    : world_(std::move(world)), id_(id), spec_(std::move(spec))
  {
  }
  // Attached, driven and released from any thread (a plugin's ROS callback): between steps.
  ~RunTimeJointBridge() override
  {
    if (boost::recursive_mutex* mutex = world_->physicsMutex())
    {
      std::lock_guard<boost::recursive_mutex> between_steps(*mutex);
      world_->context()->detach(id_);
    }
  }
  double position() const override { return world_->context() ? world_->context()->jointPosition(id_) : 0.0; }
  double velocity() const override { return world_->context() ? world_->context()->jointVelocity(id_) : 0.0; }
  bool setVelocity(double) override { return unsupported("SetVelocity"); }
  bool setForce(double effort) override
  {
    boost::recursive_mutex* mutex = world_->physicsMutex();
    if (!mutex)
      return false;
    std::lock_guard<boost::recursive_mutex> between_steps(*mutex);
    WorldPluginContext* context = world_->context();
    const uint64_t step = context->iterations();
    if (step != force_step_)
      applied_ = 0.0;  // the efforts of a step gone by
    force_step_ = step;
    applied_ += effort;
    context->addJointEffort(id_, effort);
    return true;
  }
  double appliedForce() const override { return applied_; }
  bool setPosition(double) override { return unsupported("SetPosition"); }
  double lowerLimit() const override { return spec_.lower; }
  double upperLimit() const override { return spec_.upper; }
  double effortLimit() const override { return spec_.effort_limit; }
  double velocityLimit() const override { return std::numeric_limits<double>::infinity(); }
  std::string parentLink() const override { return spec_.parent_link; }
  std::string childLink() const override { return spec_.child_link; }
  // Joint::InitialAnchorPose answers from the joint itself, which keeps the anchor it was loaded with.
  ignition::math::Pose3d anchorPose() const override { return ignition::math::Pose3d::Zero; }
  // Joint::LocalAxis answers from the joint itself, which keeps the axis it was loaded with.
  ignition::math::Vector3d localAxis() const override { return ignition::math::Vector3d::Zero; }
  ignition::math::Vector3d globalAxis() const override
  {
    const urdf::Vector3 axis = world_->context() ? world_->context()->jointAxis(id_) : urdf::Vector3();
    return {axis.x, axis.y, axis.z};
  }
  bool setMotorVelocity(double) override { return unsupported("SetParam(\"vel\")"); }
  bool setMotorMaxForce(double) override { return unsupported("SetParam(\"fmax\")"); }
  void childWrench(ignition::math::Vector3d& force, ignition::math::Vector3d& torque) override
  {
    unsupported("GetForceTorque");
    force = torque = ignition::math::Vector3d::Zero;
  }

private:
  bool unsupported(const char* call)
  {
    if (!warned_)
      gzwarn << "Joint::" << call << " on joint [" << spec_.name << "], made at run time: the plant does not "
             << "simulate it for such a joint (it holds its links, takes SetForce and reads Position and "
             << "GetVelocity); nothing is changed" << std::endl;
    warned_ = true;
    return false;
  }

  std::shared_ptr<HostWorld> world_;
  int id_;
  gazebo::physics::RunTimeJointSpec spec_;
  double applied_ = 0.0;
  uint64_t force_step_ = 0;
  bool warned_ = false;
};

std::unique_ptr<gazebo::physics::JointBridge> HostWorld::attach(const gazebo::physics::RunTimeJointSpec& spec)
{
  static const std::map<std::string, RunTimeJoint::Type> types{{"fixed", RunTimeJoint::Type::Fixed},
                                                                {"prismatic", RunTimeJoint::Type::Prismatic},
                                                                {"revolute", RunTimeJoint::Type::Revolute},
                                                                {"ball", RunTimeJoint::Type::Ball}};
  if (!context_ || !host_)
    return nullptr;
  auto type = types.find(spec.type);
  // Gazebo's other types (revolute2, universal, screw, gearbox) hold their links fixed here, as
  // every joint made at run time did before the plant made the four: a grasp still holds.
  if (type == types.end())
    gzwarn << "Joint [" << spec.name << "] of type " << spec.type << " made at run time: the plant makes fixed, "
           << "prismatic, revolute and ball joints at run time; this one holds its links fixed" << std::endl;
  std::lock_guard<boost::recursive_mutex> between_steps(host_->physicsMutex());
  RunTimeJoint joint;
  joint.type = type == types.end() ? RunTimeJoint::Type::Fixed : type->second;
  joint.parent_model = spec.parent_model;
  joint.parent_link = spec.parent_link;
  joint.child_model = spec.child_model;
  joint.child_link = spec.child_link;
  joint.anchor = urdf::Vector3(spec.anchor.X(), spec.anchor.Y(), spec.anchor.Z());
  joint.axis = urdf::Vector3(spec.axis.X(), spec.axis.Y(), spec.axis.Z());
  joint.lower = spec.lower;
  joint.upper = spec.upper;
  joint.damping = spec.damping;
  joint.effort_limit = spec.effort_limit;
  const int id = context_->attach(joint);
  if (id < 0)
    return nullptr;
  return std::make_unique<RunTimeJointBridge>(shared_from_this(), id, spec);
}

namespace
{
constexpr const char* kWithout = "; the world runs without it";

std::string worldPluginLabel(const std::string& name, const std::string& filename)
{
  return "world plugin '" + name + "' (" + filename + ")";
}
}  // namespace

std::string whyNotLoadable(const std::string& library, const std::string& registration)
{
  void* handle = dlopen(library.c_str(), RTLD_LAZY | RTLD_GLOBAL);
  if (!handle)
  {
    const char* reason = dlerror();
    return "cannot load " + library + ": " + (reason ? reason : "dlopen failed");
  }
  if (!dlsym(handle, "RegisterPlugin"))
    return library + " is not a Gazebo plugin: it has no RegisterPlugin (" + registration + ")";
  return "";  // the handle stays: Gazebo keeps plugin libraries loaded, and Create opens it again
}

const char* pluginKindName(gazebo::PluginType kind)
{
  switch (kind)
  {
    case gazebo::WORLD_PLUGIN: return "world";
    case gazebo::MODEL_PLUGIN: return "model";
    case gazebo::SENSOR_PLUGIN: return "sensor";
    case gazebo::SYSTEM_PLUGIN: return "system";
    case gazebo::VISUAL_PLUGIN: return "visual";
    case gazebo::GUI_PLUGIN: return "GUI";
  }
  return "Gazebo";
}

const char* pluginRegistration(gazebo::PluginType kind)
{
  switch (kind)
  {
    case gazebo::WORLD_PLUGIN: return "GZ_REGISTER_WORLD_PLUGIN";
    case gazebo::MODEL_PLUGIN: return "GZ_REGISTER_MODEL_PLUGIN";
    case gazebo::SENSOR_PLUGIN: return "GZ_REGISTER_SENSOR_PLUGIN";
    case gazebo::SYSTEM_PLUGIN: return "GZ_REGISTER_SYSTEM_PLUGIN";
    case gazebo::VISUAL_PLUGIN: return "GZ_REGISTER_VISUAL_PLUGIN";
    case gazebo::GUI_PLUGIN: return "GZ_REGISTER_GUI_PLUGIN";
  }
  return "GZ_REGISTER_*_PLUGIN";
}

sdf::ElementPtr pluginElement(const sdf::ElementPtr& read)
{
  if (!read)
    return sdf::ElementPtr();
  sdf::ElementPtr copy = read->Clone();
  copy->SetParent(read->GetParent());
  return copy;
}

void addSpawnNamespace(const sdf::ElementPtr& plugin, const std::string& spawn_namespace)
{
  if (spawn_namespace.empty() || plugin->HasElement("robotNamespace"))
    return;
  // (as sdformat keeps a plugin's own elements: a string value, no description)
  sdf::ElementPtr ns(new sdf::Element);
  ns->SetName("robotNamespace");
  ns->AddValue("string", spawn_namespace, true);
  ns->SetParent(plugin);
  plugin->InsertElement(ns);
}

PlantGazeboHost::PlantGazeboHost(WorldPluginContext& world)
  : context_(world), bridge_(std::make_shared<HostWorld>(*this)), world_(new gazebo::physics::World(bridge_))
{
  physics_mutex_ = world_->Physics()->GetPhysicsUpdateMutex();
  step_info_.worldName = world_->Name();
  sensors_ = std::make_unique<GazeboSensorHost>(*this);
}

PlantGazeboHost::~PlantGazeboHost()
{
  if (stepping_)
    physics_mutex_->unlock();
  // The plugins go before the models and the world they hold, as Gazebo's world unloads them.
  sensors_.reset();
  world_plugins_.clear();
  system_plugins_.clear();
  for (auto& model : models_)
    model.second->release();
  world_->Fini();
  bridge_->release();
}

std::shared_ptr<ContextModel> PlantGazeboHost::modelBridge(ModelPluginContext& context)
{
  std::shared_ptr<ContextModel>& bridge = models_[context.modelName()];
  if (!bridge)
    bridge = std::make_shared<ContextModel>(context);
  return bridge;
}

std::shared_ptr<ContextModel> PlantGazeboHost::modelBridge(const std::string& name)
{
  auto known = models_.find(name);
  if (known != models_.end())
    return known->second;
  ModelPluginContext* model = context_.model(name);
  return model ? modelBridge(*model) : nullptr;
}

void PlantGazeboHost::modelRemoved(const std::string& name)
{
  sensors_->modelRemoved(name);
  auto known = models_.find(name);
  if (known == models_.end())
    return;
  known->second->release();
  models_.erase(known);
  gazebo::event::Events::deleteEntity(name);
}

bool PlantGazeboHost::loadWorldPlugin(const WorldPluginDescription& d)
{
  const std::string label = worldPluginLabel(d.name, d.filename);
  Log& log = context_.log();
  const gazebo::WorldPlugin::TPtr plugin =
      createPlugin<gazebo::WorldPlugin>(log, label, d.library, d.name, gazebo::WORLD_PLUGIN, kWithout);
  if (!plugin)
    return false;
  sdf::ElementPtr element = pluginElement(d.element);
  if (!element)
  {
    log.error(label + ": no <plugin> element was read for it" + kWithout);
    return false;
  }
  if (!pluginCall(log, [&] { return label + ": its Load threw"; }, kWithout, [&] {
        plugin->Load(world_, element);
        plugin->Init();
      }))
    return false;
  world_plugins_.push_back(plugin);
  world_plugin_documents_.push_back(d.document);
  return true;
}

bool PlantGazeboHost::loadSystemPlugin(const std::string& filename, const std::vector<std::string>& arguments)
{
  const std::string label = "system plugin (" + filename + ")";
  Log& log = context_.log();
  const std::string library = findGazeboPluginLibrary(filename);
  if (library.empty())
  {
    log.error(label + ": no such file on GAZEBO_PLUGIN_PATH or LD_LIBRARY_PATH; the world runs without it");
    return false;
  }
  const gazebo::SystemPlugin::TPtr plugin =
      createPlugin<gazebo::SystemPlugin>(log, label, library, filename, gazebo::SYSTEM_PLUGIN, kWithout);
  if (!plugin)
    return false;
  // Load(argc, argv) with gzserver's command line, as Gazebo's server hands it on.
  std::vector<char*> argv;
  for (const std::string& argument : arguments)
  {
    system_arguments_.emplace_back(argument.begin(), argument.end());
    system_arguments_.back().push_back('\0');
    argv.push_back(system_arguments_.back().data());
  }
  argv.push_back(nullptr);
  if (!pluginCall(log, [&] { return label + ": its Load threw"; }, kWithout, [&] {
        plugin->Load(static_cast<int>(arguments.size()), argv.data());
        plugin->Init();
        // Gazebo's server loads system plugins before the world, which then says it was made.
        gazebo::event::Events::worldCreated(world_->Name());
      }))
    return false;
  system_plugins_.push_back(plugin);
  return true;
}

void PlantGazeboHost::beginStep()
{
  // The world update holds the physics update mutex, so that what a plugin's ROS callbacks do
  // between steps (under the same mutex) never lands in the middle of one.
  physics_mutex_->lock();
  stepping_ = true;
  step_info_.simTime = world_->SimTime();
  step_info_.realTime = world_->RealTime();
  pluginCall(context_.log(), [] { return std::string("a Gazebo plugin's world update callback threw"); }, "", [&] {
    gazebo::event::Events::worldUpdateBegin(step_info_);
    gazebo::event::Events::beforePhysicsUpdate(step_info_);
  });
  // What the plugins changed of the surfaces they hold goes to the solver for this step (Gazebo's
  // ODE reads its surfaces as it makes the step's contacts).
  for (auto& model : models_)
    model.second->pushSurfaces();
}

void PlantGazeboHost::endStep()
{
  pluginCall(context_.log(), [] { return std::string("a Gazebo plugin's world update end callback threw"); }, "",
             [] { gazebo::event::Events::worldUpdateEnd(); });
  if (stepping_)
  {
    stepping_ = false;
    physics_mutex_->unlock();
  }
  // Gazebo's sensors update outside the world update, in threads of their own; here after it.
  sensors_->update();
}

bool PlantGazeboHost::loadSensorPlugin(const SensorDescription& d, const std::vector<Sensor*>& sensors,
                                       ModelPluginContext& model)
{
  return sensors_->load(d, sensors, model);
}

void PlantGazeboHost::reset(bool simulation)
{
  pluginCall(context_.log(), [] { return std::string("a Gazebo world plugin's Reset threw"); }, "", [&] {
    for (auto& plugin : world_plugins_)
      plugin->Reset();
    if (simulation)
      gazebo::event::Events::timeReset();
    gazebo::event::Events::worldReset();
  });
  sensors_->reset();
}

std::unique_ptr<GazeboHost> createGazeboHost(WorldPluginContext& world) { return std::make_unique<PlantGazeboHost>(world); }

void setGazeboVerbose(bool verbose) { gazebo::common::Console::SetQuiet(!verbose); }

}  // namespace bullet_plant
