// The world's static models as models (World::staticModels, staticModel, moveStaticModel, and the
// static side of remove and resetWorld in include/bullet_plant/world.h): Gazebo lists a world's
// static models with the others, deletes them and teleports them. The world keeps where each is now
// in its description (as it keeps its lights), its Bullet objects in the static scene; a change
// moves or removes those objects and makes what sensors see of the static models again, once.
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "bullet_plant/world.h"
#include "physics/bullet_conversions.h"
#include "description/mesh_loader.h"
#include "physics/dynamics_world.h"
#include "simulation/internals.h"

namespace bullet_plant
{
namespace
{
bool finite(const urdf::Pose& p)
{
  for (double v : {p.position.x, p.position.y, p.position.z, p.rotation.x, p.rotation.y, p.rotation.z, p.rotation.w})
    if (!std::isfinite(v))
      return false;
  return true;
}

// Moves what `name` holds of `items` (collisions or visuals, by their model) by `moved` (new from old).
template <class Item>
void moveItems(std::vector<Item>& items, const std::string& name, const urdf::Pose& moved)
{
  for (Item& item : items)
    if (item.model == name)
      item.pose = compose(moved, item.pose);
}

template <class Item>
void eraseItems(std::vector<Item>& items, const std::string& name)
{
  items.erase(std::remove_if(items.begin(), items.end(), [&](const Item& item) { return item.model == name; }),
              items.end());
}

}  // namespace

// A collision whose mesh cannot be read was said by the physics (the world's constructor).
std::vector<RayPrimitive> staticRayShapes(const WorldDescription& description, Log* log)
{
  std::vector<RayPrimitive> shapes;
  for (const StaticCollision& c : description.collisions)
  {
    std::string reason;
    if (c.shape.kind != Shape::Kind::Mesh)
      shapes.push_back(RayPrimitive::fromShape(c.shape, c.pose, nullptr));
    else if (std::shared_ptr<const MeshData> mesh = loadMesh(c.shape.mesh_file, c.shape.scale, reason))
      shapes.push_back(RayPrimitive::fromMesh(mesh, c.pose, nullptr));
    else
      continue;
    shapes.back().seen_by = kSeenByLidars;
  }
  for (const StaticVisual& v : description.visuals)
  {
    std::string reason;
    std::shared_ptr<const MeshData> mesh =
        v.shape.kind == Shape::Kind::Mesh ? loadMesh(v.shape.mesh_file, v.shape.scale, reason) : nullptr;
    if (v.shape.kind == Shape::Kind::Mesh && !mesh)
    {
      if (log)
        log->warn("world: visual '" + v.name + "': mesh '" + v.shape.mesh_uri + "' " + reason +
                  "; cameras do not see it");
      continue;
    }
    shapes.push_back(mesh ? RayPrimitive::fromMesh(mesh, v.pose, nullptr) : RayPrimitive::fromShape(v.shape, v.pose, nullptr));
    shapes.back().seen_by = kSeenByCameras;
    shapes.back().material = v.material;
    if (mesh && log)
      for (const std::string& problem : textureProblems(*mesh))
        log->warn("world: visual '" + v.name + "': mesh '" + v.shape.mesh_uri + "': " + problem +
                  "; cameras see it without that texture");
  }
  return shapes;
}

const std::vector<StaticModelDescription>& World::staticModels() const { return in_->description.static_models; }

const StaticModelDescription* World::staticModel(const std::string& name) const
{
  for (const StaticModelDescription& model : in_->description.static_models)
    if (model.name == name)
      return &model;
  return nullptr;
}

bool World::moveStaticModel(const std::string& name, const urdf::Pose& pose) { return in_->moveStaticModel(name, pose); }

bool World::Internals::moveStaticModel(const std::string& name, const urdf::Pose& pose)
{
  Internals& w = *this;
  auto model = std::find_if(w.description.static_models.begin(), w.description.static_models.end(),
                            [&](const StaticModelDescription& m) { return m.name == name; });
  if (model == w.description.static_models.end())
    return false;
  if (!finite(pose))
    throw std::invalid_argument("the pose of static model '" + name + "' is not finite");
  const urdf::Pose moved = compose(pose, inverse(model->pose));  // new from old
  model->pose = pose;
  for (StaticModelDescription::Link& link : model->links)
    link.pose = compose(moved, link.pose);
  moveItems(w.description.collisions, name, moved);
  moveItems(w.description.visuals, name, moved);
  const btTransform by = toBullet(moved);
  for (size_t i = 0; i < w.static_objects.size(); ++i)
    if (w.static_object_models[i] == name)
    {
      btCollisionObject& object = *w.static_objects[i];
      object.setWorldTransform(by * object.getWorldTransform());
      w.dynamics->updateSingleAabb(&object);
      w.dynamics->getBroadphase()->getOverlappingPairCache()->cleanProxyFromPairs(object.getBroadphaseHandle(),
                                                                                  w.dispatcher.get());
    }
  w.rebuildStaticScenes();
  w.wakeRobots();  // what rested on it must fall
  return true;
}

bool World::Internals::removeStaticModel(const std::string& name)
{
  auto model = std::find_if(description.static_models.begin(), description.static_models.end(),
                            [&](const StaticModelDescription& m) { return m.name == name; });
  if (model == description.static_models.end())
    return false;
  description.static_models.erase(model);
  eraseItems(description.collisions, name);
  eraseItems(description.visuals, name);
  for (size_t i = static_objects.size(); i-- > 0;)
    if (static_object_models[i] == name)
    {
      dynamics->removeCollisionObject(static_objects[i].get());
      static_objects.erase(static_objects.begin() + long(i));
      static_shapes.erase(static_shapes.begin() + long(i));
      static_names.erase(static_names.begin() + long(i));
      static_object_models.erase(static_object_models.begin() + long(i));
    }
  rebuildStaticScenes();
  wakeRobots();  // what rested on it must fall
  return true;
}

void World::Internals::resetStaticModels()
{
  std::vector<std::pair<std::string, urdf::Pose>> moved;
  for (const StaticModelDescription& model : description.static_models)
  {
    const urdf::Pose& file_pose = static_file_poses.at(model.name);
    const urdf::Pose& now = model.pose;
    if (now.position.x != file_pose.position.x || now.position.y != file_pose.position.y ||
        now.position.z != file_pose.position.z || now.rotation.x != file_pose.rotation.x ||
        now.rotation.y != file_pose.rotation.y || now.rotation.z != file_pose.rotation.z ||
        now.rotation.w != file_pose.rotation.w)
      moved.emplace_back(model.name, file_pose);
  }
  for (const auto& back : moved)
    moveStaticModel(back.first, back.second);
}

void World::Internals::rebuildStaticScenes()
{
  if (frame_worker)
    frame_worker->waitAll();  // frames in the making draw the scenes of before
  static_ray_shapes = staticRayShapes(description, nullptr);
  for (auto& r : robots)
  {
    internalsOf(*r).ray_bodies.clear();
    internalsOf(*r).gl_bodies.clear();
  }
  ray_scene.reset();
  if (gl_scene)
    gl_scene.reset(new GlScene(*gl_context, static_ray_shapes));
}

}  // namespace bullet_plant
