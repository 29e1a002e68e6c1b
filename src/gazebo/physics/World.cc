// physics::World (gazebo/physics/World.hh), over the simulator's WorldBridge.
#include "gazebo/physics/World.hh"

#include <time.h>

#include <algorithm>
#include <cstdint>
#include <mutex>
#include <vector>

#include "gazebo/common/Console.hh"
#include "gazebo/common/Exception.hh"

#include "gazebo/physics/Link.hh"
#include "gazebo/physics/Model.hh"
#include "gazebo/physics/PhysicsEngine.hh"
#include "gazebo/physics/PhysicsIface.hh"
#include "gazebo/physics/PlantBridge.hh"
#include "gazebo/transport/TopicManager.hh"

namespace gazebo
{
namespace physics
{
namespace
{
// The worlds alive in the process, in the order they were made, for get_world. A World is always
// owned by a WorldPtr (the simulator's host makes it so): get_world hands out a handle from it, none
// from a world whose last handle has gone and whose destructor waits on the lock to leave the list.
std::mutex worlds_mutex;
std::vector<World*> worlds;

int64_t wallClockNs()
{
  struct timespec now;
  clock_gettime(CLOCK_REALTIME, &now);
  return static_cast<int64_t>(now.tv_sec) * 1000000000 + now.tv_nsec;
}
}  // namespace

World::World(std::shared_ptr<WorldBridge> bridge)
  : bridge_(std::move(bridge)), physics_(new PhysicsEngine(bridge_)), started_ns_(wallClockNs())
{
  // Its name is a transport namespace, as Gazebo's world's node makes it: a plugin's
  // transport::Node::Init() with no name takes the first world's ("~/x" is /gazebo/WORLD/x).
  transport::TopicManager::Instance()->RegisterTopicNamespace(this->Name());
  std::lock_guard<std::mutex> lock(worlds_mutex);
  worlds.push_back(this);
}

World::~World()
{
  std::lock_guard<std::mutex> lock(worlds_mutex);
  worlds.erase(std::remove(worlds.begin(), worlds.end(), this), worlds.end());
}

WorldPtr get_world(const std::string& name)
{
  {
    std::lock_guard<std::mutex> lock(worlds_mutex);
    for (World* world : worlds)
      if (WorldPtr alive = world->weak_from_this().lock())
        if (name.empty() || alive->Name() == name)
          return alive;
    if (name.empty())
      gzerr << "no worlds\n";
  }
  gzerr << "Unable to find world by name in physics::get_world[" << name << "]\n";
  gzthrow("Unable to find world by name in physics::get_world(world_name)");
}

std::string World::Name() const { return bridge_->name(); }

common::Time World::SimTime() const { return bridge_->simTime(); }

common::Time World::RealTime() const
{
  // every step's UpdateInfo has it: one reading of the clock, no normalising where it is positive
  const int64_t ns = wallClockNs() - started_ns_;
  if (ns < 0)  // the wall clock was set back
    return common::Time(0, static_cast<int32_t>(0));
  common::Time time;
  time.sec = static_cast<int32_t>(ns / 1000000000);
  time.nsec = static_cast<int32_t>(ns % 1000000000);
  return time;
}

uint32_t World::Iterations() const { return static_cast<uint32_t>(bridge_->iterations()); }

ignition::math::Vector3d World::Gravity() const { return bridge_->gravity(); }

PhysicsEnginePtr World::Physics() const { return physics_; }

ModelPtr World::ModelByName(const std::string& name) const
{
  const std::string prefix = Name() + "::";
  const std::string bare = name.compare(0, prefix.size(), prefix) == 0 ? name.substr(prefix.size()) : name;
  std::shared_ptr<ModelBridge> model = bridge_->model(bare);
  if (!model)
  {
    models_.erase(bare);  // gone (delete_model): a model that comes again under the name is a new one
    return ModelPtr();
  }
  ModelPtr& known = models_[bare];
  if (!known || known->bridge_ != model)
  {
    known.reset(new Model(model, boost::const_pointer_cast<World>(shared_from_this())));
    known->adoptLinks();
  }
  return known;
}

Model_V World::Models() const
{
  Model_V models;
  for (const std::string& name : bridge_->modelNames())
    if (ModelPtr model = ModelByName(name))
      models.push_back(model);
  return models;
}

EntityPtr World::EntityByName(const std::string& name) const
{
  if (ModelPtr model = ModelByName(name))
    return model;
  const size_t split = name.rfind("::");
  if (split == std::string::npos)
    return EntityPtr();
  const ModelPtr model = ModelByName(name.substr(0, split));
  return model ? EntityPtr(model->GetLink(name.substr(split + 2))) : EntityPtr();
}

unsigned int World::ModelCount() const { return static_cast<unsigned int>(bridge_->modelNames().size()); }

void World::SetPaused(bool paused) { bridge_->setPaused(paused); }

bool World::PhysicsEnabled() const { return bridge_->physicsEnabled(); }

void World::SetPhysicsEnabled(bool enable) { bridge_->setPhysicsEnabled(enable); }

bool World::IsPaused() const { return bridge_->paused(); }

void World::Reset() { bridge_->reset(); }

void World::InsertModelFile(const std::string& sdfFilename)
{
  // gazebo_ros's model database request (spawn_model -database): the world's <include> of the URI
  std::string uri;
  for (const char c : sdfFilename)
    switch (c)
    {
      case '&': uri += "&amp;"; break;
      case '<': uri += "&lt;"; break;
      case '>': uri += "&gt;"; break;
      default: uri += c;
    }
  bridge_->insertModel("<sdf version='1.6'><world name='default'><include><uri>" + uri +
                       "</uri></include></world></sdf>");
}

void World::InsertModelString(const std::string& sdfString) { bridge_->insertModel(sdfString); }

void World::InsertModelSDF(const sdf::SDF& sdf) { bridge_->insertModel(sdf.ToString()); }

void World::Fini() { models_.clear(); }
}  // namespace physics
}  // namespace gazebo
