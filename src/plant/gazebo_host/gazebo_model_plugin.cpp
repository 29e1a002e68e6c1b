// A Gazebo model plugin library of the user's own, hosted as Gazebo hosts one: its file found on
// the plugin paths (the description's `library`), made by its RegisterPlugin (PluginT::Create),
// Load(ModelPtr, its <plugin> element read by sdformat) then Init; each step's start signals
// event::Events::worldUpdateBegin and beforePhysicsUpdate once for all such plugins; reset_world
// and reset_simulation call its Reset. Its physics::Model, Link and Joint reach the model through
// the plugin context (ModelPluginContext), as the plant's own plugins do.
#include <dlfcn.h>

#include <cmath>
#include <exception>
#include <memory>
#include <set>
#include <string>

#include <gazebo/common/Events.hh>
#include <gazebo/common/Plugin.hh>
#include <gazebo/physics/Model.hh>
#include <gazebo/physics/PlantBridge.hh>
#include <gazebo/physics/World.hh>
#include <sdf/sdf.hh>

#include "bullet_plant/log.h"
#include "bullet_plant/model_plugin.h"

namespace bullet_plant
{
namespace
{
ignition::math::Vector3d toIgnition(const urdf::Vector3& v) { return {v.x, v.y, v.z}; }

urdf::Vector3 toUrdf(const ignition::math::Vector3d& v) { return urdf::Vector3(v.X(), v.Y(), v.Z()); }

bool finite(const ignition::math::Vector3d& v) { return std::isfinite(v.X()) && std::isfinite(v.Y()) && std::isfinite(v.Z()); }

class ContextJoint final : public gazebo::physics::JointBridge
{
public:
  ContextJoint(ModelPluginContext& context, std::string name, std::string label)
    : context_(context), name_(std::move(name)), label_(std::move(label))
  {
  }

  double position() const override
  {
    double position = 0.0, velocity = 0.0;
    context_.jointState(name_, position, velocity);
    return position;
  }
  double velocity() const override
  {
    double position = 0.0, velocity = 0.0;
    context_.jointState(name_, position, velocity);
    return velocity;
  }
  bool setVelocity(double velocity) override
  {
    ModelJoint* joint = driven();
    if (joint)
      joint->setPosition(joint->position(), velocity);  // Gazebo's SetVelocity: the rate now, no motor
    return joint != nullptr;
  }
  bool setForce(double effort) override
  {
    ModelJoint* joint = driven();
    if (joint)
      joint->setForce(effort);
    return joint != nullptr;
  }
  bool setPosition(double position) override
  {
    ModelJoint* joint = driven();
    if (joint)
      joint->setPosition(position, 0.0);
    return joint != nullptr;
  }

private:
  // The joint taken for driving at the first call that drives it (the context says once why it
  // cannot be: a transmission drives it).
  ModelJoint* driven()
  {
    if (!asked_)
    {
      joint_ = context_.modelJoint(name_, label_);
      asked_ = true;
    }
    return joint_;
  }

  ModelPluginContext& context_;
  std::string name_, label_;
  ModelJoint* joint_ = nullptr;
  bool asked_ = false;
};

class ContextModel final : public gazebo::physics::ModelBridge
{
public:
  ContextModel(ModelPluginContext& context, std::string label) : context_(context), label_(std::move(label)) {}

  std::string name() const override { return context_.modelName(); }
  std::string canonicalLink() const override { return context_.rootLink(); }
  std::vector<std::string> linkNames() const override
  {
    std::vector<std::string> names;
    for (const auto& link : context_.robotDescription().model->links_)
      if (!context_.robotDescription().frame_links.count(link.first))
        names.push_back(link.first);
    return names;
  }
  std::vector<std::string> jointNames() const override
  {
    std::vector<std::string> names;
    double position, velocity;
    for (const auto& joint : context_.robotDescription().model->joints_)
      if (context_.jointState(joint.first, position, velocity))
        names.push_back(joint.first);
    return names;
  }
  ignition::math::Pose3d linkPose(const std::string& link) const override
  {
    const urdf::Pose pose = context_.linkMotion(link).pose;
    return {pose.position.x, pose.position.y, pose.position.z, pose.rotation.w, pose.rotation.x, pose.rotation.y,
            pose.rotation.z};
  }
  ignition::math::Vector3d linkLinearVel(const std::string& link) const override
  {
    return toIgnition(context_.linkMotion(link).velocity);
  }
  ignition::math::Vector3d linkAngularVel(const std::string& link) const override
  {
    return toIgnition(context_.linkMotion(link).angular_velocity);
  }
  void setVelocity(const ignition::math::Vector3d& linear, const ignition::math::Vector3d& angular) override
  {
    if (finite(linear) && finite(angular))
      context_.setModelVelocity(toUrdf(linear), toUrdf(angular));
    else
      context_.log().warn(label_ + ": a non-finite model velocity is ignored");
  }
  void addLinkWrench(const std::string& link, const ignition::math::Vector3d& force,
                     const ignition::math::Vector3d& torque) override
  {
    if (finite(force) && finite(torque))
      context_.addLinkWrench(link, toUrdf(force), toUrdf(torque));
    else
      context_.log().warn(label_ + ": a non-finite force or torque on link '" + link + "' is ignored");
  }
  std::unique_ptr<gazebo::physics::JointBridge> joint(const std::string& name) override
  {
    double position, velocity;
    if (!context_.jointState(name, position, velocity))
      return nullptr;
    return std::make_unique<ContextJoint>(context_, name, label_);
  }

private:
  ModelPluginContext& context_;
  std::string label_;
};

// The world as the plugins see it: one for the process, as Gazebo's (the plugins' events are too).
class HostWorld final : public gazebo::physics::WorldBridge
{
public:
  std::string name() const override { return "default"; }
  gazebo::common::Time simTime() const override { return time_; }
  ignition::math::Vector3d gravity() const override { return gravity_; }
  double stepSize() const override { return step_; }
  uint64_t iterations() const override { return step_ > 0 ? static_cast<uint64_t>(std::llround(time_.Double() / step_)) : 0; }

  void set(int64_t time_ns, const ModelPluginContext& context)
  {
    time_ = gazebo::common::Time(static_cast<int32_t>(time_ns / 1000000000), static_cast<int32_t>(time_ns % 1000000000));
    gravity_ = toIgnition(context.gravity());
    step_ = context.stepSize();
  }

  // Signals the start of the step at `time_ns` once, whichever hosted plugin comes first.
  void beginStep(int64_t time_ns)
  {
    if (signalled_ns_ == time_ns)
      return;
    signalled_ns_ = time_ns;
    gazebo::common::UpdateInfo info;
    info.worldName = name();
    info.simTime = time_;
    info.realTime = gazebo::common::Time::GetWallTime();
    gazebo::event::Events::worldUpdateBegin(info);
    gazebo::event::Events::beforePhysicsUpdate(info);
  }

private:
  gazebo::common::Time time_;
  ignition::math::Vector3d gravity_;
  double step_ = 0.0;
  int64_t signalled_ns_ = -1;
};

struct HostedWorld
{
  std::shared_ptr<HostWorld> bridge = std::make_shared<HostWorld>();
  gazebo::physics::WorldPtr world{new gazebo::physics::World(bridge)};
};

HostedWorld& hostedWorld()
{
  static HostedWorld world;
  return world;
}

// The <plugin> element as sdformat reads it inside a model, for the plugin's Load.
sdf::ElementPtr pluginElement(const ModelPluginDescription& d, std::string& error)
{
  sdf::SDFPtr sdf(new sdf::SDF());
  sdf::init(sdf);
  sdf::Errors errors;
  const std::string text = "<sdf version='1.7'><model name='__plugin_host__'><link name='__link__'/>" + d.xml +
                           "</model></sdf>";
  if (!sdf::readString(text, sdf, errors) || !sdf->Root()->HasElement("model"))
  {
    error = errors.empty() ? "sdformat could not read it" : errors.front().Message();
    return sdf::ElementPtr();
  }
  sdf::ElementPtr model = sdf->Root()->GetElement("model");
  return model->HasElement("plugin") ? model->GetElement("plugin") : sdf::ElementPtr();
}

// Why Gazebo could not load `library` as a plugin (dlopen's reason, or no RegisterPlugin), "" where
// it can: the error then names the reason beside the plugin, not only on gzerr.
std::string whyNotLoadable(const std::string& library)
{
  void* handle = dlopen(library.c_str(), RTLD_LAZY | RTLD_GLOBAL);
  if (!handle)
  {
    const char* reason = dlerror();
    return "cannot load " + library + ": " + (reason ? reason : "dlopen failed");
  }
  if (!dlsym(handle, "RegisterPlugin"))
    return library + " is not a Gazebo plugin: it has no RegisterPlugin (GZ_REGISTER_MODEL_PLUGIN)";
  return "";  // the handle stays: Gazebo keeps plugin libraries loaded, and Create opens it again
}

class GazeboModelPluginHost final : public ModelPlugin
{
public:
  bool Load(const ModelPluginDescription& d, ModelPluginContext& context, int64_t time_ns) override
  {
    context_ = &context;
    const std::string label = pluginLabel(d);
    const std::string unloadable = whyNotLoadable(d.library);
    if (!unloadable.empty())
    {
      context.log().error(label + ": " + unloadable + "; the plugin is not loaded");
      return false;
    }
    try
    {
      plugin_ = gazebo::ModelPlugin::Create(d.library, d.name);
    }
    catch (const std::exception& e)
    {
      context.log().error(label + ": loading " + d.library + " threw: " + e.what() + "; the plugin is not loaded");
      return false;
    }
    if (!plugin_)
    {
      context.log().error(label + ": " + d.library + " made no plugin; the plugin is not loaded");
      return false;
    }
    if (plugin_->GetType() != gazebo::MODEL_PLUGIN)
    {
      context.log().error(label + ": " + d.library + " registers a plugin that is not a model plugin; a <plugin> "
                          "in a model loads a model plugin (GZ_REGISTER_MODEL_PLUGIN)");
      plugin_.reset();
      return false;
    }
    std::string error;
    sdf::ElementPtr element = pluginElement(d, error);
    if (!element)
    {
      context.log().error(label + ": its <plugin> element: " + error + "; the plugin is not loaded");
      plugin_.reset();
      return false;
    }
    HostedWorld& world = hostedWorld();
    world.bridge->set(time_ns, context);
    model_.reset(new gazebo::physics::Model(std::make_shared<ContextModel>(context, label), world.world));
    try
    {
      plugin_->Load(model_, element);
      plugin_->Init();
    }
    catch (const std::exception& e)
    {
      context.log().error(label + ": its Load threw: " + e.what() + "; the plugin is not loaded");
      plugin_.reset();
      return false;
    }
    return true;
  }

  void OnUpdate(int64_t time_ns) override
  {
    HostedWorld& world = hostedWorld();
    world.bridge->set(time_ns, *context_);
    try
    {
      world.bridge->beginStep(time_ns);
    }
    catch (const std::exception& e)
    {
      context_->log().error(pluginLabel(description()) + ": a world update callback threw: " + e.what());
    }
  }

  void Reset(int64_t time_ns) override
  {
    hostedWorld().bridge->set(time_ns, *context_);
    plugin_->Reset();
  }

private:
  ModelPluginContext* context_ = nullptr;
  gazebo::ModelPlugin::TPtr plugin_;
  gazebo::physics::ModelPtr model_;
};
}  // namespace

std::unique_ptr<ModelPlugin> createGazeboModelPlugin() { return std::make_unique<GazeboModelPluginHost>(); }
}  // namespace bullet_plant
