// Gazebo's plugin classes, as a plugin library derives from them (WorldPlugin, ModelPlugin,
// SensorPlugin, SystemPlugin) and registers its class (GZ_REGISTER_MODEL_PLUGIN ...: the entry
// point RegisterPlugin, which the simulator looks up with dlsym), and PluginT::Create, which finds
// a library on the plugin paths (common::SystemPaths) and makes its plugin.
#pragma once

#include <dlfcn.h>
#include <sys/stat.h>

#include <list>
#include <string>

#include <boost/shared_ptr.hpp>
#include <sdf/sdf.hh>

#include "gazebo/common/CommonTypes.hh"
#include "gazebo/common/Console.hh"
#include "gazebo/common/SystemPaths.hh"
#include "gazebo/gazebo_config.h"
#include "gazebo/physics/PhysicsTypes.hh"
#include "gazebo/sensors/SensorTypes.hh"
#include "gazebo/util/system.hh"

namespace gazebo
{
enum PluginType
{
  WORLD_PLUGIN,
  MODEL_PLUGIN,
  SENSOR_PLUGIN,
  SYSTEM_PLUGIN,
  VISUAL_PLUGIN,
  GUI_PLUGIN
};

template <class T>
class PluginT
{
public:
  typedef boost::shared_ptr<T> TPtr;

  PluginT() = default;
  // The library stays loaded (Gazebo does not dlclose a plugin's library either: objects it made
  // may outlive the plugin).
  virtual ~PluginT() = default;

  std::string GetFilename() const { return filename; }
  std::string GetHandle() const { return handleName; }
  PluginType GetType() const { return type; }

  // The plugin of the library `file_name` (a bare name is looked for on the plugin paths first,
  // then by dlopen), known as `name`; null, with the reason on gzerr, where the library cannot be
  // loaded or has no RegisterPlugin.
  static TPtr Create(const std::string& file_name, const std::string& name)
  {
    std::string full_name = file_name;
    struct stat found;
    for (const std::string& folder : common::SystemPaths::Instance()->GetPluginPaths())
    {
      if (stat((folder + "/" + file_name).c_str(), &found) == 0)
      {
        full_name = folder + "/" + file_name;
        break;
      }
    }
    void* library = dlopen(full_name.c_str(), RTLD_LAZY | RTLD_GLOBAL);
    if (!library)
    {
      gzerr << "Failed to load plugin " << full_name << ": " << dlerror() << "\n";
      return TPtr();
    }
    union
    {
      T* (*function)();
      void* pointer;
    } register_plugin;
    register_plugin.pointer = dlsym(library, "RegisterPlugin");
    if (!register_plugin.pointer)
    {
      gzerr << "Failed to resolve RegisterPlugin: " << dlerror() << "\n";
      return TPtr();
    }
    TPtr plugin(register_plugin.function());
    plugin->handleName = name;
    plugin->filename = file_name;
    return plugin;
  }

protected:
  // _target = the plugin element's <_name> (its text as V), or _defaultValue where it has none;
  // gzmsg says which.
  template <typename V>
  void LoadParam(const sdf::ElementPtr& _sdf, const std::string& _name, V& _target, V _defaultValue = V()) const
  {
    auto result = _sdf->Get<V>(_name, _defaultValue);
    if (!result.second)
      gzmsg << handleName << " Plugin missing <" << _name << ">, defaults to " << result.first << std::endl;
    else
      gzmsg << handleName << " Plugin <" << _name << "> set to " << result.first << std::endl;
    _target = result.first;
  }
  void LoadParam(sdf::ElementPtr& _sdf, const std::string& _name, std::string& _target, const char* _defaultValue) const
  {
    LoadParam<std::string>(_sdf, _name, _target, _defaultValue);
  }

  PluginType type = WORLD_PLUGIN;
  std::string filename;
  std::string handleName;
};

class WorldPlugin : public PluginT<WorldPlugin>
{
public:
  WorldPlugin() { type = WORLD_PLUGIN; }
  virtual ~WorldPlugin() {}
  virtual void Load(physics::WorldPtr _world, sdf::ElementPtr _sdf) = 0;
  virtual void Init() {}
  virtual void Reset() {}
};

class ModelPlugin : public PluginT<ModelPlugin>
{
public:
  ModelPlugin() { type = MODEL_PLUGIN; }
  virtual ~ModelPlugin() {}
  virtual void Load(physics::ModelPtr _model, sdf::ElementPtr _sdf) = 0;
  virtual void Init() {}
  virtual void Reset() {}
};

class SensorPlugin : public PluginT<SensorPlugin>
{
public:
  SensorPlugin() { type = SENSOR_PLUGIN; }
  virtual ~SensorPlugin() {}
  virtual void Load(sensors::SensorPtr _sensor, sdf::ElementPtr _sdf) = 0;
  virtual void Init() {}
  virtual void Reset() {}
};

class SystemPlugin : public PluginT<SystemPlugin>
{
public:
  SystemPlugin() { type = SYSTEM_PLUGIN; }
  virtual ~SystemPlugin() {}
  virtual void Load(int _argc = 0, char** _argv = nullptr) = 0;
  virtual void Init() {}
  virtual void Reset() {}
};
}  // namespace gazebo

#define GZ_REGISTER_MODEL_PLUGIN(classname)                              \
  extern "C" GZ_PLUGIN_VISIBLE gazebo::ModelPlugin* RegisterPlugin();    \
  gazebo::ModelPlugin* RegisterPlugin() { return new classname(); }

#define GZ_REGISTER_WORLD_PLUGIN(classname)                              \
  extern "C" GZ_PLUGIN_VISIBLE gazebo::WorldPlugin* RegisterPlugin();    \
  gazebo::WorldPlugin* RegisterPlugin() { return new classname(); }

#define GZ_REGISTER_SENSOR_PLUGIN(classname)                             \
  extern "C" GZ_PLUGIN_VISIBLE gazebo::SensorPlugin* RegisterPlugin();   \
  gazebo::SensorPlugin* RegisterPlugin() { return new classname(); }

#define GZ_REGISTER_SYSTEM_PLUGIN(classname)                             \
  extern "C" GZ_PLUGIN_VISIBLE gazebo::SystemPlugin* RegisterPlugin();   \
  gazebo::SystemPlugin* RegisterPlugin() { return new classname(); }
