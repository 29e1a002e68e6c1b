#include "gazebo_host/gazebo_world_host.h"

#include <dlfcn.h>

#include <cmath>
#include <exception>

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
class HostWorld final : public gazebo::physics::WorldBridge
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
  int attach(const std::string& parent_model, const std::string& parent_link, const std::string& child_model,
             const std::string& child_link) override
  {
    return context_ ? context_->attach(parent_model, parent_link, child_model, child_link) : -1;
  }
  void detach(int attachment) override
  {
    if (context_)
      context_->detach(attachment);
  }
  void insertModel(const std::string& sdf_xml) override
  {
    if (context_)
      context_->insertModel(sdf_xml);
  }

private:
  PlantGazeboHost* host_;
  WorldPluginContext* context_;
};

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

sdf::ElementPtr pluginElement(const std::string& xml, const std::string& parent, std::string& error)
{
  sdf::SDFPtr sdf(new sdf::SDF());
  sdf::init(sdf);
  sdf::Errors errors;
  const std::string body = parent == "model" ? "<link name='__link__'/>" + xml : xml;
  const std::string text = "<sdf version='1.7'><" + parent + " name='__plugin_host__'>" + body + "</" + parent + "></sdf>";
  if (!sdf::readString(text, sdf, errors) || !sdf->Root()->HasElement(parent))
  {
    error = errors.empty() ? "sdformat could not read it" : errors.front().Message();
    return sdf::ElementPtr();
  }
  sdf::ElementPtr element = sdf->Root()->GetElement(parent);
  if (!element->HasElement("plugin"))
  {
    error = "sdformat found no <plugin> in it";
    return sdf::ElementPtr();
  }
  return element->GetElement("plugin");
}

PlantGazeboHost::PlantGazeboHost(WorldPluginContext& world)
  : context_(world), bridge_(std::make_shared<HostWorld>(*this)), world_(new gazebo::physics::World(bridge_))
{
  physics_mutex_ = world_->Physics()->GetPhysicsUpdateMutex();
  step_info_.worldName = world_->Name();
}

PlantGazeboHost::~PlantGazeboHost()
{
  if (stepping_)
    physics_mutex_->unlock();
  // The plugins go before the models and the world they hold, as Gazebo's world unloads them.
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
  std::string error;
  sdf::ElementPtr element = pluginElement(d.xml, "world", error);
  if (!element)
  {
    log.error(label + ": its <plugin> element: " + error + kWithout);
    return false;
  }
  if (!pluginCall(log, [&] { return label + ": its Load threw"; }, kWithout, [&] {
        plugin->Load(world_, element);
        plugin->Init();
      }))
    return false;
  world_plugins_.push_back(plugin);
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
}

std::unique_ptr<GazeboHost> createGazeboHost(WorldPluginContext& world) { return std::make_unique<PlantGazeboHost>(world); }

void setGazeboVerbose(bool verbose) { gazebo::common::Console::SetQuiet(!verbose); }

}  // namespace bullet_plant
