// A Gazebo model plugin library of the user's own, hosted as Gazebo hosts one: its file found on
// the plugin paths (the description's `library`), made by its RegisterPlugin (PluginT::Create),
// Load(ModelPtr, its <plugin> element read by sdformat) then Init; reset_world and
// reset_simulation call its Reset; it goes when its model is deleted. Its model is the world's
// (gazebo_world_host.h): physics::World::ModelByName gives world plugins the same handle, and the
// world's events (worldUpdateBegin ...) reach its callbacks each step.
#include <memory>
#include <string>

#include <gazebo/common/Plugin.hh>
#include <gazebo/physics/Model.hh>
#include <gazebo/physics/World.hh>

#include "bullet_plant/log.h"
#include "bullet_plant/model_plugin.h"
#include "gazebo_host/gazebo_world_host.h"

namespace bullet_plant
{
namespace
{
constexpr const char* kNotLoaded = "; the plugin is not loaded";

class GazeboModelPluginHost final : public ModelPlugin
{
public:
  ~GazeboModelPluginHost() override
  {
    plugin_.reset();  // before its model, as Gazebo's model unloads its plugins
  }

  bool Load(const ModelPluginDescription& d, ModelPluginContext& context, int64_t /*time_ns*/) override
  {
    const std::string label = pluginLabel(d);
    plugin_ = createPlugin<gazebo::ModelPlugin>(context.log(), label, d.library, d.name, gazebo::MODEL_PLUGIN,
                                                kNotLoaded);
    if (!plugin_)
      return false;
    sdf::ElementPtr element = pluginElement(d.element);
    if (!element)
    {
      context.log().error(label + ": no <plugin> element was read for it" + kNotLoaded);
      plugin_.reset();
      return false;
    }
    addSpawnNamespace(element, context.spawnNamespace());
    document_ = d.document;
    auto& host = static_cast<PlantGazeboHost&>(context.gazeboHost());
    host.modelBridge(context);  // the world knows the model from now on, though its spawn is not done
    model_ = host.world()->ModelByName(context.modelName());
    if (!pluginCall(context.log(), [&] { return label + ": its Load threw"; }, kNotLoaded, [&] {
          plugin_->Load(model_, element);
          plugin_->Init();
        }))
    {
      plugin_.reset();
      return false;
    }
    // Which file it is (a file found on the paths wins over the plant's own plugin of the name).
    context.log().info(label + ": loaded from " + d.library);
    return true;
  }

  // Nothing of its own: the plugin's callbacks are on the world's events, which the world signals
  // once a step for all of Gazebo's plugins.
  void OnUpdate(int64_t /*time_ns*/) override {}

  void Reset(int64_t /*time_ns*/) override
  {
    if (plugin_)
      plugin_->Reset();
  }

private:
  gazebo::ModelPlugin::TPtr plugin_;
  gazebo::physics::ModelPtr model_;
  sdf::ElementPtr document_;  // its element's ancestors, for GetParent()
};
}  // namespace

std::unique_ptr<ModelPlugin> createGazeboModelPlugin() { return std::make_unique<GazeboModelPluginHost>(); }
}  // namespace bullet_plant
