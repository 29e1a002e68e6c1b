// The world's host of Gazebo plugins (GazeboHost, gazebo_host.h): one physics::World over the
// world's context, its world and system plugins, its events each step, and one physics::Model
// bridge for each model (model_bridge.h), which the model plugins' host shares
// (gazebo_model_plugin.cpp).
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include <boost/thread/recursive_mutex.hpp>
#include <gazebo/common/Plugin.hh>
#include <gazebo/common/UpdateInfo.hh>
#include <gazebo/physics/PhysicsTypes.hh>
#include <sdf/sdf.hh>

#include "bullet_plant/gazebo_host.h"
#include "bullet_plant/log.h"
#include "gazebo_host/gazebo_sensor_host.h"
#include "gazebo_host/model_bridge.h"

namespace bullet_plant
{
class HostWorld;

class PlantGazeboHost final : public GazeboHost
{
public:
  explicit PlantGazeboHost(WorldPluginContext& world);
  ~PlantGazeboHost() override;

  bool loadWorldPlugin(const WorldPluginDescription& plugin) override;
  bool loadSensorPlugin(const SensorDescription& d, const std::vector<Sensor*>& sensors,
                        ModelPluginContext& model) override;
  bool loadSystemPlugin(const std::string& filename, const std::vector<std::string>& arguments) override;
  void beginStep() override;
  void endStep() override;
  void reset(bool simulation) override;
  void modelRemoved(const std::string& name) override;

  gazebo::physics::WorldPtr world() const { return world_; }
  // The bridge of the model whose context this is (a model plugin's), made at its first call; by
  // name for a world's lookup (null for no model of that name).
  std::shared_ptr<ContextModel> modelBridge(ModelPluginContext& context);
  std::shared_ptr<ContextModel> modelBridge(const std::string& name);
  WorldPluginContext& context() { return context_; }
  // Held by each world update; what changes the physics from another thread takes it first.
  boost::recursive_mutex& physicsMutex() { return *physics_mutex_; }

private:
  WorldPluginContext& context_;
  std::shared_ptr<HostWorld> bridge_;
  gazebo::physics::WorldPtr world_;
  std::map<std::string, std::shared_ptr<ContextModel>> models_;
  std::vector<gazebo::WorldPlugin::TPtr> world_plugins_;
  std::vector<sdf::ElementPtr> world_plugin_documents_;  // their elements' ancestors, for GetParent()
  std::vector<gazebo::SystemPlugin::TPtr> system_plugins_;
  std::vector<std::vector<char>> system_arguments_;  // argv's strings outlive Load, as Gazebo's do
  std::unique_ptr<GazeboSensorHost> sensors_;
  bool stepping_ = false;  // the physics update mutex is held from beginStep to endStep
  boost::recursive_mutex* physics_mutex_ = nullptr;
  gazebo::common::UpdateInfo step_info_;  // the world's name once, the times each step
};

// Runs a plugin's code: where it throws (anything), one error "<what>: <why><consequence>", where
// `what()` says what threw (made only then: the world's update calls it every step), and false.
// The simulator never dies of a plugin's exception.
template <typename What, typename Call>
bool pluginCall(Log& log, What&& what, const char* consequence, Call&& call)
{
  try
  {
    call();
    return true;
  }
  catch (const std::exception& e)
  {
    // one line: Gazebo's exceptions end their text with a newline (gzthrow)
    std::string why = e.what();
    why.erase(why.find_last_not_of(" \t\r\n") + 1);
    log.error(what() + ": " + why + consequence);
  }
  catch (...)
  {
    log.error(what() + ": something that is no std::exception" + consequence);
  }
  return false;
}

// Why Gazebo could not load `library` as a plugin (dlopen's reason, or no RegisterPlugin), "" where
// it can: the error then names the reason beside the plugin. `registration` names the macro its
// kind registers with (GZ_REGISTER_MODEL_PLUGIN ...).
std::string whyNotLoadable(const std::string& library, const std::string& registration);

// A plugin's kind in words ("model") and the macro a plugin of it registers with
// (GZ_REGISTER_MODEL_PLUGIN), for the errors.
const char* pluginKindName(gazebo::PluginType kind);
const char* pluginRegistration(gazebo::PluginType kind);

// Gazebo's PluginT::Create of `library` as a plugin of `kind` (gazebo::ModelPlugin and MODEL_PLUGIN
// ...): null, with one error "<label>: <why><consequence>", where it cannot be: the library does not
// load or registers nothing, making it throws, it makes no plugin or one of another kind.
template <class Plugin>
typename Plugin::TPtr createPlugin(Log& log, const std::string& label, const std::string& library,
                                   const std::string& name, gazebo::PluginType kind, const char* consequence)
{
  const std::string unloadable = whyNotLoadable(library, pluginRegistration(kind));
  if (!unloadable.empty())
  {
    log.error(label + ": " + unloadable + consequence);
    return nullptr;
  }
  typename Plugin::TPtr plugin;
  if (!pluginCall(log, [&] { return label + ": loading " + library + " threw"; }, consequence,
                  [&] { plugin = Plugin::Create(library, name); }))
    return nullptr;
  if (!plugin)
    log.error(label + ": " + library + " made no plugin" + consequence);
  else if (plugin->GetType() != kind)
    log.error(label + ": " + library + " registers a plugin that is not a " + pluginKindName(kind) + " plugin (" +
              pluginRegistration(kind) + ")" + consequence);
  else
    return plugin;
  return nullptr;
}

// A plugin's own copy of the <plugin> element sdformat read (`read`), for its Load: a plugin may add
// to its element (sdformat's GetElement adds what is missing), and a description is loaded again at
// each reset of a world made from it. Its parent is the element's (the model, the world).
sdf::ElementPtr pluginElement(const sdf::ElementPtr& read);

// gazebo_ros's spawn with -robot_namespace gives each <plugin> of the model that names no
// <robotNamespace> one, the spawn's (gazebo_ros_api_plugin's walkChildAddRobotNamespace walks the
// whole model, its sensors' plugins too): added to a plugin's own element.
void addSpawnNamespace(const sdf::ElementPtr& plugin, const std::string& spawn_namespace);

}  // namespace bullet_plant
