#include "simulation/robot_model_plugin_context.h"

#include <cmath>

#include "bullet_plant/plugin_names.h"
#include "physics/bullet_conversions.h"
#include "physics/dynamics_world.h"
#include "simulation/internals.h"
#include "simulation/robot_builder.h"

namespace bullet_plant
{
const std::string& RobotModelPluginContext::modelName() const { return robot_.name; }

const RobotDescription& RobotModelPluginContext::robotDescription() const { return robot_.description; }

const std::string& RobotModelPluginContext::spawnNamespace() const { return robot_.spawn_namespace; }

const std::string& RobotModelPluginContext::rootLink() const { return robot_.description.model->getRoot()->name; }

ModelJoint* RobotModelPluginContext::modelJoint(const std::string& joint, const std::string& plugin)
{
  RobotMultibody& multibody = robot_.multibody;
  auto index = multibody.joint_index.find(joint);
  std::string problem;
  if (index == multibody.joint_index.end())
    problem = robot_.description.model->getJoint(joint)
                  ? "which is fixed; a motor needs a revolute, continuous or prismatic joint"
                  : "which robot '" + robot_.name + "' does not have";
  else if (robot_.joint_layer.drives(index->second))
    problem = "which a gazebo_ros_control transmission drives already; give the joint to one of them";
  if (!problem.empty())
  {
    robot_.world->log.error(plugin + " names joint '" + joint + "', " + problem + "; the plugin is not loaded");
    return nullptr;
  }
  std::unique_ptr<ModelJointSim>& motor = robot_.model_joints[index->second];
  if (!motor)
    motor.reset(new ModelJointSim(multibody.joints[index->second], *multibody.bullet));
  return motor.get();
}

bool RobotModelPluginContext::jointState(const std::string& joint, double& position, double& velocity) const
{
  const RobotMultibody& multibody = robot_.multibody;
  auto it = multibody.joint_index.find(joint);
  if (it == multibody.joint_index.end())
    return false;
  position = multibody.bullet->getJointPos(multibody.joints[it->second].link);
  velocity = multibody.bullet->getJointVel(multibody.joints[it->second].link);
  return true;
}

LinkMotion RobotModelPluginContext::linkMotion(const std::string& link) const
{
  return robot_.multibody.linkMotion(link, urdf::Pose(), robot_.name);
}

void RobotModelPluginContext::setModelVelocity(const urdf::Vector3& linear, const urdf::Vector3& angular)
{
  btMultiBody& mb = *robot_.multibody.bullet;
  if (mb.hasFixedBase() || !std::isfinite(linear.x + linear.y + linear.z + angular.x + angular.y + angular.z))
    return;
  mb.setBaseVel(toBullet(linear));
  mb.setBaseOmega(toBullet(angular));
}

uint32_t RobotModelPluginContext::noiseSeed(const ModelPluginDescription& plugin) const
{
  return seedFor(robot_.name + "/" + plugin.name);
}

void RobotModelPluginContext::addLinkWrench(const std::string& link, const urdf::Vector3& force, const urdf::Vector3& torque)
{
  auto it = robot_.multibody.link_in_body.find(link);
  if (it == robot_.multibody.link_in_body.end() ||
      !std::isfinite(force.x + force.y + force.z + torque.x + torque.y + torque.z))
    return;
  robot_.multibody.addBodyWrench(it->second.first, toBullet(force), toBullet(torque));
}

void RobotModelPluginContext::addedLinkWrench(const std::string& link, urdf::Vector3& force, urdf::Vector3& torque) const
{
  force = torque = urdf::Vector3();
  auto it = robot_.multibody.link_in_body.find(link);
  if (it == robot_.multibody.link_in_body.end())
    return;
  const btMultiBody& mb = *robot_.multibody.bullet;
  const int body = it->second.first;
  force = fromBullet(body == 0 ? mb.getBaseForce() : mb.getLinkForce(body - 1));
  torque = fromBullet(body == 0 ? mb.getBaseTorque() : mb.getLinkTorque(body - 1));
}

urdf::Vector3 RobotModelPluginContext::bodyCentreOfMass(const std::string& link) const
{
  auto it = robot_.multibody.link_in_body.find(link);
  if (it == robot_.multibody.link_in_body.end())
    return urdf::Vector3();
  return fromBullet(robot_.multibody.bodyWorldTransform(it->second.first).getOrigin());
}

bool RobotModelPluginContext::transmissionDrives(const std::string& joint) const
{
  auto index = robot_.multibody.joint_index.find(joint);
  return index != robot_.multibody.joint_index.end() && robot_.joint_layer.drives(index->second);
}

bool RobotModelPluginContext::setJointPosition(const std::string& joint, double position)
{
  if (!robot_.multibody.joint_index.count(joint) || !std::isfinite(position))
    return false;
  robot_.self->setJointPositions({{joint, position}});
  return true;
}

void RobotModelPluginContext::setLinkWorldPose(const std::string& link, const urdf::Pose& pose)
{
  // A static or kinematic model moves where it is put, as Gazebo's; one held by a joint to the
  // world does not.
  const bool placeable = !robot_.multibody.bullet->hasFixedBase() || robot_.description.is_static || robot_.kinematic;
  if (!robot_.multibody.link_in_body.count(link) || !placeable)
    return;
  robot_.self->setLinkState(link, pose, Twist());
}

void RobotModelPluginContext::setPhysicsEnabled(bool enabled) { robot_.world->physics_enabled = enabled; }

bool RobotModelPluginContext::physicsEnabled() const { return robot_.world->physics_enabled; }

bool RobotModelPluginContext::watchJointWrench(const std::string& joint)
{
  return robot_.wrench_watches.watch(robot_.multibody, robot_.description, joint);
}

void RobotModelPluginContext::jointWrench(const std::string& joint, urdf::Vector3& force, urdf::Vector3& torque) const
{
  robot_.wrench_watches.wrench(joint, force, torque);
}

urdf::Vector3 RobotModelPluginContext::gravity() const { return robot_.world->description.gravity; }

std::vector<LinkCollision> RobotModelPluginContext::linkCollisions(const std::string& link) const
{
  std::vector<LinkCollision> out;
  const urdf::LinkConstSharedPtr l = robot_.description.model->getLink(link);
  if (!l)
    return out;
  const auto sdf_surfaces = robot_.description.collision_surfaces.find(link);
  const auto urdf_surface = robot_.description.surfaces.find(link);
  for (size_t c = 0; c < l->collision_array.size(); ++c)
  {
    const urdf::CollisionSharedPtr& collision = l->collision_array[c];
    if (!collision || !collision->geometry)
      continue;
    LinkCollision entry;
    auto name = robot_.multibody.link_collision_names.find({link, c});
    entry.name = name != robot_.multibody.link_collision_names.end() ? name->second : collision->name;
    entry.geometry = collision->geometry;
    entry.origin = collision->origin;
    if (sdf_surfaces != robot_.description.collision_surfaces.end() && c < sdf_surfaces->second.size())
      entry.surface = sdf_surfaces->second[c];
    else if (urdf_surface != robot_.description.surfaces.end())
      entry.surface = urdf_surface->second;
    out.push_back(std::move(entry));
  }
  return out;
}

bool RobotModelPluginContext::setCollisionFriction(const std::string& link, const std::string& collision,
                                                   const CollisionFriction& friction)
{
  for (double value : {friction.mu1, friction.mu2, friction.slip1, friction.slip2})
    if (!(value >= 0) || !std::isfinite(value))
      return false;
  RobotMultibody& multibody = robot_.multibody;
  auto in_body = multibody.link_in_body.find(link);
  if (in_body == multibody.link_in_body.end())
    return false;
  const int b = in_body->second.first;
  const Body& body = multibody.bodies[size_t(b)];
  btMultiBody& mb = *multibody.bullet;
  const btCollisionObject* object = b == 0 ? mb.getBaseCollider() : mb.getLink(b - 1).m_collider;
  if (!object)
    return false;
  std::vector<size_t> children;  // a mesh of convex pieces is several children under one name
  for (size_t k = 0; k < body.collision_names.size(); ++k)
    if (body.collision_names[k] == collision)
      children.push_back(k);
  if (children.empty())
    return false;
  ContactSurface plain;
  plain.mu1 = plain.mu2 = object->getFriction();
  std::vector<ContactSurface>& surfaces = robot_.world->solver->editSurfaces(
      *object, body.collision_names.size(), plain, !(b == 0 && mb.hasFixedBase()));
  for (size_t k : children)
  {
    ContactSurface& surface = surfaces[surfaces.size() > 1 ? k : 0];
    surface.mu1 = btScalar(friction.mu1);
    surface.mu2 = btScalar(friction.mu2);
    surface.slip1 = btScalar(friction.slip1);
    surface.slip2 = btScalar(friction.slip2);
  }
  return true;
}

bool RobotModelPluginContext::setLinkGravity(const std::string& link, bool gravity)
{
  if (!robot_.multibody.link_in_body.count(link))
    return false;
  robot_.description.link_physics[link].gravity = gravity;
  updatePartialGravity(robot_);
  wakeUp(*robot_.multibody.bullet);
  return true;
}

bool RobotModelPluginContext::lumpedInertia(const std::string& link, double& mass, urdf::Pose& com,
                                            urdf::Vector3& moments) const
{
  auto in_body = robot_.multibody.link_in_body.find(link);
  if (robot_.description.format != RobotDescription::Format::Urdf || in_body == robot_.multibody.link_in_body.end())
    return false;
  const Body& body = robot_.multibody.bodies[size_t(in_body->second.first)];
  if (body.link != link)
    return false;
  mass = body.mass;
  com = fromBullet(body.urdf_from_com);
  moments = fromBullet(body.inertia_diagonal);
  return true;
}

double RobotModelPluginContext::linkMass(const std::string& link) const
{
  auto it = robot_.multibody.link_in_body.find(link);
  return it == robot_.multibody.link_in_body.end() ? 0.0 : robot_.multibody.bodies[size_t(it->second.first)].mass;
}

double RobotModelPluginContext::linkIxx(const std::string& link) const
{
  urdf::LinkConstSharedPtr l = robot_.description.model->getLink(link);
  return l && l->inertial ? l->inertial->ixx : 0.0;
}

double RobotModelPluginContext::stepSize() const { return robot_.world->step_s; }

const Param& RobotModelPluginContext::params() const { return robot_.world->params; }

std::string RobotModelPluginContext::pluginNamespace(const ModelPluginDescription& plugin) const
{
  return modelPluginNamespace(plugin, robot_.spawn_namespace, robot_.name);
}

std::string RobotModelPluginContext::tfPrefix(const ModelPluginDescription& plugin) const
{
  return modelPluginTfPrefix(plugin, pluginNamespace(plugin), robot_.world->params);
}

Log& RobotModelPluginContext::log() { return robot_.world->log; }

GazeboHost& RobotModelPluginContext::gazeboHost() { return robot_.world->gazeboHost(); }

}  // namespace bullet_plant
