// physics::World (gazebo/physics/World.hh), over the simulator's WorldBridge.
#include "gazebo/physics/World.hh"

#include <time.h>

#include <algorithm>
#include <cstdint>
#include <mutex>
#include <sstream>
#include <vector>

#include <sdf/sdf.hh>

#include "gazebo/common/Console.hh"
#include "gazebo/common/Events.hh"
#include "gazebo/common/Exception.hh"
#include "gazebo/common/SphericalCoordinates.hh"

#include "gazebo/physics/Collision.hh"
#include "gazebo/physics/Link.hh"
#include "gazebo/physics/Model.hh"
#include "gazebo/physics/PhysicsEngine.hh"
#include "gazebo/physics/PhysicsIface.hh"
#include "gazebo/physics/PlantBridge.hh"
#include "gazebo/msgs/msgs.hh"
#include "gazebo/transport/Node.hh"
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
  node_.reset(new transport::Node());
  node_->Init(this->Name());
  factory_sub_ = node_->Subscribe("~/factory", &World::OnFactoryMsg, this);
  // (else a world whose models come and go under new names keeps every one's handle: its links and
  // joints with it)
  delete_entity_ = event::Events::ConnectDeleteEntity([this](const std::string& name) { models_.erase(name); });
  std::lock_guard<std::mutex> lock(worlds_mutex);
  worlds.push_back(this);
}

World::~World()
{
  delete_entity_.reset();
  factory_sub_.reset();  // no message may come to a world that is going
  node_->Fini();
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

ignition::math::Vector3d World::MagneticField() const { return bridge_->magneticField(); }

common::SphericalCoordinatesPtr World::SphericalCoords() const
{
  if (!spherical_)
  {
    const ignition::math::Vector3d origin = bridge_->sphericalOrigin();
    spherical_.reset(new common::SphericalCoordinates(
        common::SphericalCoordinates::EARTH_WGS84, IGN_DTOR(origin.X()), IGN_DTOR(origin.Y()), origin.Z(),
        IGN_DTOR(bridge_->headingDeg())));
  }
  return spherical_;
}

void World::SetGravity(const ignition::math::Vector3d& gravity) { physics_->SetGravity(gravity); }

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
  const std::string parent = name.substr(0, split), own = name.substr(split + 2);
  if (const ModelPtr model = ModelByName(parent))
    return model->GetLink(own);
  const LinkPtr link = boost::dynamic_pointer_cast<Link>(EntityByName(parent));
  return link ? EntityPtr(link->GetCollision(own)) : EntityPtr();
}

unsigned int World::ModelCount() const { return static_cast<unsigned int>(bridge_->modelNames().size()); }

void World::SetPaused(bool paused) { bridge_->setPaused(paused); }

bool World::PhysicsEnabled() const { return bridge_->physicsEnabled(); }

void World::SetPhysicsEnabled(bool enable) { bridge_->setPhysicsEnabled(enable); }

bool World::IsPaused() const { return bridge_->paused(); }

void World::Reset() { bridge_->reset(); }

namespace
{
// A world's <include> of the URI (a model:// URI or a path), at `pose` where given: what Gazebo's
// factory makes of a file name.
std::string includeOf(const std::string& sdfFilename, const ignition::math::Pose3d* pose)
{
  std::string uri;
  for (const char c : sdfFilename)
    switch (c)
    {
      case '&': uri += "&amp;"; break;
      case '<': uri += "&lt;"; break;
      case '>': uri += "&gt;"; break;
      default: uri += c;
    }
  std::string placed;
  if (pose)
  {
    const ignition::math::Vector3d rpy = pose->Rot().Euler();
    std::ostringstream text;
    text.precision(17);
    text << "<pose>" << pose->Pos().X() << ' ' << pose->Pos().Y() << ' ' << pose->Pos().Z() << ' ' << rpy.X() << ' '
         << rpy.Y() << ' ' << rpy.Z() << "</pose>";
    placed = text.str();
  }
  return "<sdf version='1.6'><world name='default'><include><uri>" + uri + "</uri>" + placed +
         "</include></world></sdf>";
}
}  // namespace

void World::InsertModelFile(const std::string& sdfFilename)
{
  // gazebo_ros's model database request (spawn_model -database): the world's <include> of the URI
  bridge_->insertModel(includeOf(sdfFilename, nullptr));
}

void World::OnFactoryMsg(const boost::shared_ptr<const msgs::Factory>& msg)
{
  if (msg->has_edit_name() || msg->has_clone_model_name())
  {
    gzerr << "~/factory on world [" << Name() << "]: "
          << (msg->has_edit_name() ? "edit_name [" + msg->edit_name() : "clone_model_name [" + msg->clone_model_name())
          << "]: the plant neither edits nor clones models from the factory; nothing is added" << std::endl;
    return;
  }
  const ignition::math::Pose3d pose = msg->has_pose() ? msgs::ConvertIgn(msg->pose()) : ignition::math::Pose3d();
  if (msg->has_sdf() && !msg->sdf().empty())
  {
    if (!msg->has_pose())
    {
      InsertModelString(msg->sdf());
      return;
    }
    sdf::SDFPtr model(new sdf::SDF());
    sdf::init(model);
    sdf::ElementPtr found;
    if (sdf::readString(msg->sdf(), model))
      found = model->Root()->HasElement("model") ? model->Root()->GetElement("model") : sdf::ElementPtr();
    if (!found)
    {
      gzerr << "~/factory on world [" << Name() << "]: its sdf is no <sdf><model> sdformat reads; nothing is added"
            << std::endl;
      return;
    }
    found->GetElement("pose")->Set(pose);
    InsertModelSDF(*model);
  }
  else if (msg->has_sdf_filename() && !msg->sdf_filename().empty())
    bridge_->insertModel(includeOf(msg->sdf_filename(), msg->has_pose() ? &pose : nullptr));
  else
    gzerr << "Unable to load sdf from factory message (world [" << Name() << "]): it has neither sdf nor sdf_filename"
          << std::endl;
}

void World::InsertModelString(const std::string& sdfString) { bridge_->insertModel(sdfString); }

void World::InsertModelSDF(const sdf::SDF& sdf) { bridge_->insertModel(sdf.ToString()); }

void World::Fini() { models_.clear(); }
}  // namespace physics
}  // namespace gazebo
