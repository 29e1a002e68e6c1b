// Robot: a robot in the world, its state (poses, joints, the last good state it falls back to) and
// the per-step work World::step asks of it. Built by robot_builder.cpp; its joint layer is in
// joint_layer.cpp, its sensors in sensors.cpp.
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "bullet_plant/plugin_names.h"
#include "physics/bullet_conversions.h"
#include "simulation/internals.h"
#include "simulation/robot_builder.h"

namespace bullet_plant
{
// ------------------------------------------------------------------------------------ multibody

btTransform RobotMultibody::bodyWorldTransform(int body) const
{
  if (body == 0)
    return bullet->getBaseWorldTransform();
  btVector3 origin = bullet->localPosToWorld(body - 1, btVector3(0, 0, 0));
  btMatrix3x3 basis = bullet->localFrameToWorld(body - 1, btMatrix3x3::getIdentity());
  return btTransform(basis, origin);
}

btTransform RobotMultibody::linkWorldTransform(const std::string& link, const std::string& robot) const
{
  auto it = link_in_body.find(link);
  if (it == link_in_body.end())
    throw std::out_of_range("robot '" + robot + "' has no link '" + link + "'");
  return bodyWorldTransform(it->second.first) * it->second.second;
}

void RobotMultibody::updateKinematics()
{
  btAlignedObjectArray<btQuaternion> scratch_q;
  btAlignedObjectArray<btVector3> scratch_m;
  bullet->forwardKinematics(scratch_q, scratch_m);
  bullet->updateCollisionObjectWorldTransforms(scratch_q, scratch_m);
}

void RobotMultibody::disableJointRows()
{
  for (MovableJoint& j : joints)
    for (JointDrive* c : {j.drive.get(), j.damper.get(), j.dry_friction.get(), j.lower_limit.get(), j.upper_limit.get()})
      if (c)
        c->disable();
}

// ------------------------------------------------------------------------------ last good state

void LastGoodState::save(const RobotMultibody& robot)
{
  const btMultiBody* mb = robot.bullet.get();
  q.resize(robot.joints.size());
  qd.resize(robot.joints.size());
  for (size_t i = 0; i < robot.joints.size(); ++i)
  {
    q[i] = mb->getJointPos(robot.joints[i].link);
    qd[i] = mb->getJointVel(robot.joints[i].link);
  }
  base = mb->getBaseWorldTransform();
  base_velocity = mb->getBaseVel();
  base_omega = mb->getBaseOmega();
}

void LastGoodState::restore(RobotMultibody& robot) const
{
  btMultiBody* mb = robot.bullet.get();
  mb->setBaseWorldTransform(base);
  mb->setBaseVel(btVector3(0, 0, 0));
  mb->setBaseOmega(btVector3(0, 0, 0));
  for (size_t i = 0; i < robot.joints.size(); ++i)
  {
    mb->setJointPos(robot.joints[i].link, q[i]);
    mb->setJointVel(robot.joints[i].link, 0);
  }
  robot.updateKinematics();
}

namespace
{
bool stateFinite(const RobotMultibody& robot)
{
  const btMultiBody* mb = robot.bullet.get();
  auto finite3 = [](const btVector3& v) { return std::isfinite(v.x()) && std::isfinite(v.y()) && std::isfinite(v.z()); };
  if (!finite3(mb->getBasePos()) || !finite3(mb->getBaseVel()) || !finite3(mb->getBaseOmega()))
    return false;
  btQuaternion q = mb->getWorldToBaseRot();
  if (!std::isfinite(q.x()) || !std::isfinite(q.y()) || !std::isfinite(q.z()) || !std::isfinite(q.w()))
    return false;
  for (const MovableJoint& j : robot.joints)
    if (!std::isfinite(mb->getJointPos(j.link)) || !std::isfinite(mb->getJointVel(j.link)))
      return false;
  return true;
}
}  // namespace

// ------------------------------------------------------------------------------- per-step work

void Robot::Internals::updateModelPlugins(int64_t time_ns)
{
  for (std::unique_ptr<ModelPlugin>& plugin : model_plugins)
    plugin->OnUpdate(time_ns);
  for (auto& joint : model_joints)
    joint.second->apply(world->step_s);
}

void Robot::Internals::updateControllers(int64_t time_ns)
{
  if (!controller_manager || time_ns - last_control_ns < control_period_ns)
    return;
  controller_manager->update(time_ns, (time_ns - last_control_ns) * 1e-9);
  last_control_ns = time_ns;
}

// The error is said at the first recovery of each simulated second with the count so far (a robot
// that diverges every step would otherwise log a line per step); after kRecoveriesBeforeDisabling
// within one second the robot is taken out of the physics, said once.
void Robot::Internals::recoverIfDiverged()
{
  if (stateFinite(multibody))
  {
    last_good.save(multibody);
    return;
  }
  ++recoveries;
  last_good.restore(multibody);
  joint_layer.resetPids();
  forgetSolverHistory();  // the diverged step's impulses would seed the next one (and read as NaN efforts)
  const int64_t now = world->time_ns;
  if (recovery_window_start_ns < 0 || now - recovery_window_start_ns >= 1000000000 || now < recovery_window_start_ns)
  {
    recovery_window_start_ns = now;
    recoveries_in_window = 0;
    world->log.error("robot '" + name + "': the physics produced a non-finite state; restored the last good state "
                     "with zero velocity (" + std::to_string(recoveries) + " recoveries so far; further ones in "
                     "this simulated second are counted, not logged)");
  }
  if (++recoveries_in_window < Robot::kRecoveriesBeforeDisabling)
    return;
  disabled = true;
  detachFromPhysics(*this);
  world->log.error("robot '" + name + "' is disabled: its physics diverged on " +
                   std::to_string(recoveries_in_window) + " steps within one simulated second (" +
                   std::to_string(recoveries) + " recoveries in all). Check its URDF's masses, inertias and "
                   "limits and its gains; remove it (delete_model) and spawn it again once fixed");
}

void Robot::Internals::updateSensors(int64_t time_ns)
{
  for (auto& sensor : sensors)
  {
    if (sensor->active())
      sensor->updateIfDue(*this, time_ns);
    sensor->collect(false);  // a frame rendered while the simulation went on, when it is done
  }
}

bool Robot::Internals::hasLink(const std::string& link) const { return multibody.link_in_body.count(link) > 0; }

urdf::Pose Robot::Internals::linkPose(const std::string& link) const
{
  return fromBullet(multibody.linkWorldTransform(link, name));
}

urdf::Vector3 Robot::Internals::gravity() const { return world->description.gravity; }

const RayScene& Robot::Internals::lidarScene() { return world->rayScene(this); }

GlScene* Robot::Internals::glScene() { return world->glScene(); }
FrameWorker* Robot::Internals::frameWorker() { return world->frame_worker.get(); }

Lighting Robot::Internals::lighting() const { return world->lighting(); }

std::vector<ContactState> Robot::Internals::contacts(const std::string& link, const std::vector<std::string>& collisions) const
{
  std::vector<ContactState> states;
  const auto placed = multibody.link_in_body.find(link);
  if (placed == multibody.link_in_body.end())
    return states;
  const int bi = placed->second.first;
  const Body& body = multibody.bodies[size_t(bi)];
  const btCollisionObject* ours = bi == 0 ? multibody.bullet->getBaseCollider() : multibody.bullet->getLink(bi - 1).m_collider;
  if (!ours)
    return states;
  const btVector3 com = multibody.bodyWorldTransform(bi).getOrigin();
  // The body's link frame: the link Gazebo keeps after lumping the fixed joints.
  const btMatrix3x3 to_link = multibody.linkWorldTransform(body.link, name).getBasis().transpose();
  const btScalar per_step = btScalar(1.0 / world->step_s);
  forTouchingPoints(*world->dispatcher, [ours](const btCollisionObject* object) { return object == ours; },
                    [&](const btManifoldPoint& point, bool ours_is_a, const btCollisionObject* other) {
    const std::string& mine = body.collisionName(ours_is_a ? point.m_index0 : point.m_index1);
    if (std::find(collisions.begin(), collisions.end(), mine) == collisions.end())
      return;
    const std::string collision1 = name + "::" + body.link + "::" + mine;
    const std::string collision2 = world->collisionNameOf(other, ours_is_a ? point.m_index1 : point.m_index0);
    auto state = std::find_if(states.begin(), states.end(), [&](const ContactState& s) {
      return s.collision1 == collision1 && s.collision2 == collision2;
    });
    if (state == states.end())
      state = states.insert(states.end(), ContactState{collision1, collision2, {}});
    // An impulse pushes A along the normal, B the other way.
    const btScalar sign = ours_is_a ? 1 : -1;
    const btVector3 position = ours_is_a ? point.getPositionWorldOnA() : point.getPositionWorldOnB();
    const btVector3 force = sign * per_step * impulseOnA(point);
    ContactPoint out;
    out.position = fromBullet(position);
    out.normal = fromBullet(sign * point.m_normalWorldOnB);
    out.depth = -point.getDistance();
    out.force = fromBullet(to_link * force);
    out.torque = fromBullet(to_link * (position - com).cross(force));
    state->points.push_back(out);
  });
  return states;
}

// ------------------------------------------------------------------ joint wrenches (ft sensors)

namespace
{
// Each body's linear and angular momentum in the world, the linear at its centre of mass, the
// angular about it (Bullet's bodies sit at their centres of mass along their principal axes).
void bodyMomenta(const RobotMultibody& m, std::vector<btVector3>& momentum, std::vector<btVector3>& angular_momentum)
{
  const btMultiBody& mb = *m.bullet;
  const int n = mb.getNumLinks() + 1;
  btAlignedObjectArray<btVector3> omegas, velocities;
  omegas.resize(n);
  velocities.resize(n);
  mb.compTreeLinkVelocities(&omegas[0], &velocities[0]);  // the links' in their own frames
  momentum.resize(size_t(n));
  angular_momentum.resize(size_t(n));
  for (int b = 0; b < n; ++b)
  {
    const btMatrix3x3 to_world = m.bodyWorldTransform(b).getBasis();
    const btScalar mass = b == 0 ? mb.getBaseMass() : mb.getLink(b - 1).m_mass;
    const btVector3 inertia = b == 0 ? mb.getBaseInertia() : mb.getLink(b - 1).m_inertiaLocal;
    const btVector3 omega_local = b == 0 ? to_world.transpose() * mb.getBaseOmega() : omegas[b];
    const btVector3 v = b == 0 ? mb.getBaseVel() : to_world * velocities[b];
    momentum[size_t(b)] = mass * v;
    angular_momentum[size_t(b)] = to_world * (inertia * omega_local);
  }
}
}  // namespace

double Robot::Internals::linkMass(const std::string& link) const
{
  auto it = multibody.link_in_body.find(link);
  return it == multibody.link_in_body.end() ? 0.0 : multibody.bodies[size_t(it->second.first)].mass;
}

double Robot::Internals::linkIxx(const std::string& link) const
{
  urdf::LinkConstSharedPtr l = description.model->getLink(link);
  return l && l->inertial ? l->inertial->ixx : 0.0;
}

bool Robot::Internals::setJointPosition(const std::string& joint, double position)
{
  if (!multibody.joint_index.count(joint) || !std::isfinite(position))
    return false;
  self->setJointPositions({{joint, position}});
  return true;
}

void Robot::Internals::setLinkWorldPose(const std::string& link, const urdf::Pose& pose)
{
  if (!multibody.link_in_body.count(link) || multibody.bullet->hasFixedBase())
    return;
  self->setLinkState(link, pose, Twist());
}

void Robot::Internals::setPhysicsEnabled(bool enabled) { world->physics_enabled = enabled; }

bool Robot::Internals::physicsEnabled() const { return world->physics_enabled; }

bool Robot::Internals::watchJointWrench(const std::string& joint)
{
  auto index = multibody.joint_index.find(joint);
  urdf::JointConstSharedPtr described = description.model->getJoint(joint);
  if (index == multibody.joint_index.end() || !described)
    return false;
  for (const JointWrenchWatch& w : wrench_watches)
    if (w.joint == joint)
      return true;
  const btMultiBody& mb = *multibody.bullet;
  JointWrenchWatch w;
  w.joint = joint;
  w.child_link = described->child_link_name;
  const int child = multibody.joints[index->second].link;  // Bullet link index
  for (int i = 0; i < mb.getNumLinks(); ++i)
  {
    int up = i;
    while (up >= 0 && up != child)
      up = mb.getParent(up);
    if (up == child)
      w.bodies.push_back(i + 1);
  }
  wrench_watches.push_back(std::move(w));
  return true;
}

void Robot::Internals::jointWrench(const std::string& joint, urdf::Vector3& force, urdf::Vector3& torque) const
{
  force = torque = urdf::Vector3();
  for (const JointWrenchWatch& w : wrench_watches)
    if (w.joint == joint)
    {
      force = w.force;
      torque = w.torque;
    }
}

void Robot::Internals::beginJointWrenches()
{
  const btMultiBody& mb = *multibody.bullet;
  std::vector<btVector3> momentum, angular_momentum;
  bodyMomenta(multibody, momentum, angular_momentum);
  for (JointWrenchWatch& w : wrench_watches)
  {
    w.momentum.clear();
    w.angular_momentum.clear();
    w.force_added.clear();
    w.torque_added.clear();
    for (int b : w.bodies)
    {
      w.momentum.push_back(momentum[size_t(b)]);
      w.angular_momentum.push_back(angular_momentum[size_t(b)]);
      w.force_added.push_back(mb.getLinkForce(b - 1));
      w.torque_added.push_back(mb.getLinkTorque(b - 1));
    }
  }
}

// Newton and Euler for the child's subtree over the step: the joint passed on what its momentum
// change needed beyond gravity, the forces added to it and the contacts' impulses (the step's, as
// the bumper reads them). Forces between bodies of the subtree cancel in the sums.
void Robot::Internals::endJointWrenches()
{
  const btMultiBody& mb = *multibody.bullet;
  const btScalar dt = btScalar(world->step_s);
  const btVector3 gravity = world->dynamics->getGravity();
  std::vector<btVector3> momentum, angular_momentum;
  bodyMomenta(multibody, momentum, angular_momentum);
  btDispatcher& dispatcher = *world->dispatcher;
  for (JointWrenchWatch& w : wrench_watches)
  {
    const btTransform frame = multibody.linkWorldTransform(w.child_link, name);
    const btVector3 at = frame.getOrigin();
    btVector3 force(0, 0, 0), torque(0, 0, 0);
    for (size_t k = 0; k < w.bodies.size(); ++k)
    {
      const int b = w.bodies[k];
      const btVector3 com = multibody.bodyWorldTransform(b).getOrigin();
      const btVector3 external = mb.getLink(b - 1).m_mass * gravity + w.force_added[k];
      const btVector3 needed = (momentum[size_t(b)] - w.momentum[k]) / dt;
      const btVector3 turning = (angular_momentum[size_t(b)] - w.angular_momentum[k]) / dt;
      force += needed - external;
      torque += turning + (com - at).cross(needed) - w.torque_added[k] - (com - at).cross(external);
    }
    for (int m = 0; m < dispatcher.getNumManifolds(); ++m)
    {
      const btPersistentManifold& manifold = *dispatcher.getManifoldByIndexInternal(m);
      for (int side = 0; side < 2; ++side)
      {
        const auto* collider = btMultiBodyLinkCollider::upcast(side == 0 ? manifold.getBody0() : manifold.getBody1());
        if (!collider || collider->m_multiBody != &mb ||
            std::find(w.bodies.begin(), w.bodies.end(), collider->m_link + 1) == w.bodies.end())
          continue;
        // Bullet's normal points from B into A, and an impulse pushes A along it (B the other way).
        const btScalar sign = side == 0 ? 1 : -1;
        for (int p = 0; p < manifold.getNumContacts(); ++p)
        {
          const btManifoldPoint& point = manifold.getContactPoint(p);
          const btVector3 contact = sign / dt * impulseOnA(point);
          const btVector3 position = side == 0 ? point.getPositionWorldOnA() : point.getPositionWorldOnB();
          force -= contact;
          torque -= (position - at).cross(contact);
        }
      }
    }
    const btMatrix3x3 to_child = frame.getBasis().transpose();
    w.force = fromBullet(to_child * force);
    w.torque = fromBullet(to_child * torque);
  }
}

void Robot::Internals::settleAfterTeleport()
{
  multibody.updateKinematics();
  joint_layer.resetPids();
  forgetSolverHistory();
  last_good.save(multibody);
}

// gazebo_ros's job rule: a job acts while start <= now <= start + duration (always with a negative
// duration) and is dropped once now > start + duration.
void Robot::Internals::applyExternalEfforts(int64_t time_ns)
{
  btMultiBody& mb = *multibody.bullet;
  auto due = [time_ns](int64_t start, int64_t end) { return time_ns >= start && (end < 0 || time_ns <= end); };
  auto expired = [time_ns](int64_t end) { return end >= 0 && time_ns > end; };
  for (const LinkWrench& w : wrenches)
    if (due(w.start_ns, w.end_ns))
    {
      if (w.body == 0)
      {
        mb.addBaseForce(w.force);
        mb.addBaseTorque(w.torque);
      }
      else
      {
        mb.addLinkForce(w.body - 1, w.force);
        mb.addLinkTorque(w.body - 1, w.torque);
      }
    }
  for (const JointEffort& e : joint_efforts)
    if (due(e.start_ns, e.end_ns))
      mb.addJointTorque(e.link, btScalar(e.effort));
  wrenches.erase(std::remove_if(wrenches.begin(), wrenches.end(), [&](const LinkWrench& w) { return expired(w.end_ns); }),
                 wrenches.end());
  joint_efforts.erase(std::remove_if(joint_efforts.begin(), joint_efforts.end(),
                                     [&](const JointEffort& e) { return expired(e.end_ns); }),
                      joint_efforts.end());
}

LinkMotion Robot::Internals::linkMotion(const std::string& link, const urdf::Pose& offset) const
{
  const int body = multibody.link_in_body.at(link).first;
  const btMultiBody& mb = *multibody.bullet;
  // Bullet keeps each body's velocities at its centre of mass: the base's in the world frame, the
  // links' (compTreeLinkVelocities) in their own frames.
  btVector3 omega, v_com;
  if (body == 0)
  {
    omega = mb.getBaseOmega();
    v_com = mb.getBaseVel();
  }
  else
  {
    btAlignedObjectArray<btVector3> omegas, velocities;
    omegas.resize(mb.getNumLinks() + 1);
    velocities.resize(mb.getNumLinks() + 1);
    mb.compTreeLinkVelocities(&omegas[0], &velocities[0]);
    const btMatrix3x3& to_world = multibody.bodyWorldTransform(body).getBasis();
    omega = to_world * omegas[body];
    v_com = to_world * velocities[body];
  }
  const btTransform frame = multibody.linkWorldTransform(link, name) * toBullet(offset);
  const btVector3 v = v_com + omega.cross(frame.getOrigin() - multibody.bodyWorldTransform(body).getOrigin());
  LinkMotion m;
  m.pose = fromBullet(frame);
  m.velocity = fromBullet(v);
  m.angular_velocity = fromBullet(omega);
  return m;
}

void Robot::Internals::forgetSolverHistory()
{
  // As built: the joint layer enables the rows again at the next step, in its order, starting cold.
  multibody.disableJointRows();
  for (auto& col : multibody.colliders)
    world->dynamics->getBroadphase()->getOverlappingPairCache()->cleanProxyFromPairs(
        col->getBroadphaseHandle(), world->dynamics->getDispatcher());
}

void Robot::Internals::resetToSpawn()
{
  if (disabled)  // out of the physics: it stays as it was until removed
    return;
  last_control_ns = world->time_ns;
  if (controller_manager)
    controller_manager->reset(world->time_ns);
  for (std::unique_ptr<ModelPlugin>& plugin : model_plugins)
    plugin->Reset(world->time_ns);
  last_good.base = spawn_pose * multibody.bodies[0].urdf_from_com;
  for (size_t i = 0; i < multibody.joints.size(); ++i)
    last_good.q[i] = btScalar(multibody.joints[i].initial_position);
  last_good.restore(multibody);
  settleAfterTeleport();
}

// ------------------------------------------------------------------------ ModelPluginContext

Log& Robot::Internals::log() { return world->log; }

const std::string& Robot::Internals::rootLink() const { return description.model->getRoot()->name; }

ModelJoint* Robot::Internals::modelJoint(const std::string& joint, const std::string& plugin)
{
  auto index = multibody.joint_index.find(joint);
  std::string problem;
  if (index == multibody.joint_index.end())
    problem = description.model->getJoint(joint) ? "which is fixed; a motor needs a revolute, continuous or prismatic joint"
                                                 : "which robot '" + name + "' does not have";
  else if (joint_layer.drives(index->second))
    problem = "which a gazebo_ros_control transmission drives already; give the joint to one of them";
  if (!problem.empty())
  {
    world->log.error(plugin + " names joint '" + joint + "', " + problem + "; the plugin is not loaded");
    return nullptr;
  }
  std::unique_ptr<ModelJointSim>& motor = model_joints[index->second];
  if (!motor)
    motor.reset(new ModelJointSim(multibody.joints[index->second], *multibody.bullet));
  return motor.get();
}

bool Robot::Internals::jointState(const std::string& joint, double& position, double& velocity) const
{
  auto it = multibody.joint_index.find(joint);
  if (it == multibody.joint_index.end())
    return false;
  position = multibody.bullet->getJointPos(multibody.joints[it->second].link);
  velocity = multibody.bullet->getJointVel(multibody.joints[it->second].link);
  return true;
}

void Robot::Internals::setModelVelocity(const urdf::Vector3& linear, const urdf::Vector3& angular)
{
  btMultiBody& mb = *multibody.bullet;
  if (mb.hasFixedBase() || !std::isfinite(linear.x + linear.y + linear.z + angular.x + angular.y + angular.z))
    return;
  mb.setBaseVel(btVector3(btScalar(linear.x), btScalar(linear.y), btScalar(linear.z)));
  mb.setBaseOmega(btVector3(btScalar(angular.x), btScalar(angular.y), btScalar(angular.z)));
}

uint32_t Robot::Internals::noiseSeed(const ModelPluginDescription& plugin) const { return seedFor(name + "/" + plugin.name); }

void Robot::Internals::addLinkWrench(const std::string& link, const urdf::Vector3& force, const urdf::Vector3& torque)
{
  auto it = multibody.link_in_body.find(link);
  if (it == multibody.link_in_body.end() || !std::isfinite(force.x + force.y + force.z + torque.x + torque.y + torque.z))
    return;
  btMultiBody& mb = *multibody.bullet;
  const btVector3 f(btScalar(force.x), btScalar(force.y), btScalar(force.z));
  const btVector3 t(btScalar(torque.x), btScalar(torque.y), btScalar(torque.z));
  const int body = it->second.first;
  if (body == 0)
  {
    mb.addBaseForce(f);
    mb.addBaseTorque(t);
  }
  else
  {
    mb.addLinkForce(body - 1, f);
    mb.addLinkTorque(body - 1, t);
  }
}

void Robot::Internals::addedLinkWrench(const std::string& link, urdf::Vector3& force, urdf::Vector3& torque) const
{
  force = torque = urdf::Vector3();
  auto it = multibody.link_in_body.find(link);
  if (it == multibody.link_in_body.end())
    return;
  const btMultiBody& mb = *multibody.bullet;
  const int body = it->second.first;
  const btVector3 f = body == 0 ? mb.getBaseForce() : mb.getLinkForce(body - 1);
  const btVector3 t = body == 0 ? mb.getBaseTorque() : mb.getLinkTorque(body - 1);
  force = urdf::Vector3(f.x(), f.y(), f.z());
  torque = urdf::Vector3(t.x(), t.y(), t.z());
}

double Robot::Internals::stepSize() const { return world->step_s; }

const Param& Robot::Internals::params() const { return world->params; }

std::string Robot::Internals::pluginNamespace(const ModelPluginDescription& plugin) const
{
  return modelPluginNamespace(plugin, spawn_namespace, name);
}

std::string Robot::Internals::tfPrefix(const ModelPluginDescription& plugin) const
{
  return modelPluginTfPrefix(plugin, pluginNamespace(plugin));
}

// ---------------------------------------------------------------------------------------- Robot

Robot::Robot(std::unique_ptr<Internals> internals) : in_(std::move(internals)) { in_->self = this; }
Robot::~Robot() = default;  // World takes its pieces out of the dynamics world first (removeRobot)

ControllerManager* Robot::controllerManager() { return in_->controller_manager.get(); }
double Robot::controlPeriod() const { return in_->control_period_ns * 1e-9; }
const std::string& Robot::name() const { return in_->name; }
const std::string& Robot::controlNamespace() const { return in_->control_namespace; }
const std::string& Robot::spawnNamespace() const { return in_->spawn_namespace; }
std::vector<ModelPlugin*> Robot::modelPlugins()
{
  std::vector<ModelPlugin*> out;
  for (std::unique_ptr<ModelPlugin>& p : in_->model_plugins)
    out.push_back(p.get());
  return out;
}
const RobotDescription& Robot::description() const { return in_->description; }
std::vector<JointHandle>& Robot::handles() { return in_->joint_layer.handles(); }
JointHandle* Robot::handle(const std::string& joint) { return in_->joint_layer.handle(joint); }
long Robot::recoveries() const { return in_->recoveries; }
bool Robot::disabled() const { return in_->disabled; }
void Robot::setEStop(bool on) { in_->joint_layer.setEStop(on); }
bool Robot::eStop() const { return in_->joint_layer.eStop(); }

std::vector<std::string> Robot::jointNames() const
{
  std::vector<std::string> names;
  for (const MovableJoint& j : in_->multibody.joints)
    names.push_back(j.name);
  return names;
}

bool Robot::jointState(const std::string& joint, double& position, double& velocity, double& effort) const
{
  const RobotMultibody& mb = in_->multibody;
  auto it = mb.joint_index.find(joint);
  if (it == mb.joint_index.end())
    return false;
  const MovableJoint& j = mb.joints[it->second];
  position = mb.bullet->getJointPos(j.link);
  velocity = mb.bullet->getJointVel(j.link);
  effort = actuatorEffort(j, velocity, in_->world->step_s);
  return true;
}

urdf::Pose Robot::basePose() const { return fromBullet(in_->multibody.rootWorldTransform()); }

namespace
{
Twist twistOf(const LinkMotion& m)
{
  Twist t;
  t.linear = {{m.velocity.x, m.velocity.y, m.velocity.z}};
  t.angular = {{m.angular_velocity.x, m.angular_velocity.y, m.angular_velocity.z}};
  return t;
}
}  // namespace

Twist Robot::baseTwist() const { return twistOf(linkMotion(in_->description.model->getRoot()->name)); }

urdf::Pose Robot::linkPose(const std::string& link) const
{
  return fromBullet(in_->multibody.linkWorldTransform(link, in_->name));
}

std::vector<std::string> Robot::linkNames() const
{
  std::vector<std::string> names;
  for (const auto& kv : in_->multibody.link_in_body)
    names.push_back(kv.first);
  return names;
}

namespace
{
int bodyOfLink(const RobotMultibody& multibody, const std::string& link, const std::string& robot)
{
  auto it = multibody.link_in_body.find(link);
  if (it == multibody.link_in_body.end())
    throw std::out_of_range("robot '" + robot + "' has no link '" + link + "'");
  return it->second.first;
}

const MovableJoint& movableJoint(const RobotMultibody& multibody, const std::string& joint, const std::string& robot)
{
  auto it = multibody.joint_index.find(joint);
  if (it == multibody.joint_index.end())
    throw std::out_of_range("robot '" + robot + "' has no movable joint '" + joint + "'");
  return multibody.joints[it->second];
}

int64_t jobEnd(int64_t start_ns, int64_t duration_ns) { return duration_ns < 0 ? -1 : start_ns + duration_ns; }
}  // namespace

Twist Robot::linkTwist(const std::string& link) const
{
  bodyOfLink(in_->multibody, link, in_->name);  // an unknown link: std::out_of_range naming it
  return twistOf(linkMotion(link));
}

LinkMotion Robot::linkMotion(const std::string& link, const urdf::Pose& offset) const
{
  bodyOfLink(in_->multibody, link, in_->name);
  return in_->linkMotion(link, offset);
}

std::vector<urdf::Vector3> Robot::contactNormals() const
{
  std::vector<urdf::Vector3> normals;
  const btMultiBody* ours = in_->multibody.bullet.get();
  const auto isOurs = [ours](const btCollisionObject* object) {
    const auto* collider = btMultiBodyLinkCollider::upcast(object);
    return collider && collider->m_multiBody == ours;
  };
  forTouchingPoints(*in_->world->dispatcher, isOurs,
                    [&](const btManifoldPoint& point, bool ours_is_a, const btCollisionObject*) {
                      normals.push_back(fromBullet((ours_is_a ? 1 : -1) * point.m_normalWorldOnB));
                    });
  return normals;
}

void Robot::setLinkState(const std::string& link, const urdf::Pose& pose, const Twist& twist)
{
  RobotMultibody& multibody = in_->multibody;
  bodyOfLink(multibody, link, in_->name);
  const btTransform root = multibody.rootWorldTransform();
  const btTransform link_in_root = root.inverse() * multibody.linkWorldTransform(link, in_->name);
  const btTransform new_root = toBullet(pose) * link_in_root.inverse();
  btMultiBody& mb = *multibody.bullet;
  const btTransform base = new_root * multibody.bodies[0].urdf_from_com;
  mb.setBaseWorldTransform(base);
  const btVector3 omega(btScalar(twist.angular[0]), btScalar(twist.angular[1]), btScalar(twist.angular[2]));
  const btVector3 v(btScalar(twist.linear[0]), btScalar(twist.linear[1]), btScalar(twist.linear[2]));
  mb.setBaseOmega(omega);
  mb.setBaseVel(v + omega.cross(base.getOrigin() - toBullet(pose).getOrigin()));
  for (const MovableJoint& j : multibody.joints)
    mb.setJointVel(j.link, 0);
  in_->settleAfterTeleport();
}

void Robot::setJointPositions(const std::map<std::string, double>& positions)
{
  RobotMultibody& multibody = in_->multibody;
  for (const auto& kv : positions)
  {
    movableJoint(multibody, kv.first, in_->name);
    if (!std::isfinite(kv.second))
      throw std::invalid_argument("position of joint '" + kv.first + "' is not finite");
  }
  btMultiBody& mb = *multibody.bullet;
  for (const auto& kv : positions)
  {
    const MovableJoint& j = movableJoint(multibody, kv.first, in_->name);
    mb.setJointPos(j.link, btScalar(positionWithinLimits(j, kv.second, in_->world->log, in_->name, "position")));
    mb.setJointVel(j.link, 0);
  }
  in_->settleAfterTeleport();
}

void Robot::applyLinkWrench(const std::string& link, const urdf::Vector3& force, const urdf::Vector3& torque,
                            int64_t start_ns, int64_t duration_ns)
{
  const int body = bodyOfLink(in_->multibody, link, in_->name);
  in_->wrenches.push_back({link, body, toBullet(force), toBullet(torque), start_ns, jobEnd(start_ns, duration_ns)});
}

void Robot::clearLinkWrenches(const std::string& link)
{
  auto& w = in_->wrenches;
  w.erase(std::remove_if(w.begin(), w.end(), [&](const Internals::LinkWrench& x) { return x.link == link; }), w.end());
}

void Robot::applyJointEffort(const std::string& joint, double effort, int64_t start_ns, int64_t duration_ns)
{
  const MovableJoint& j = movableJoint(in_->multibody, joint, in_->name);
  if (!std::isfinite(effort))
    throw std::invalid_argument("effort on joint '" + joint + "' is not finite");
  in_->joint_efforts.push_back({joint, j.link, effort, start_ns, jobEnd(start_ns, duration_ns)});
}

void Robot::clearJointEfforts(const std::string& joint)
{
  auto& e = in_->joint_efforts;
  e.erase(std::remove_if(e.begin(), e.end(), [&](const Internals::JointEffort& x) { return x.joint == joint; }), e.end());
}

std::vector<Sensor*> Robot::sensors()
{
  std::vector<Sensor*> out;
  for (auto& s : in_->sensors)
    out.push_back(s.get());
  return out;
}

Sensor* Robot::sensor(const std::string& name)
{
  for (auto& s : in_->sensors)
    if (s->name() == name)
      return s.get();
  return nullptr;
}

}  // namespace bullet_plant
