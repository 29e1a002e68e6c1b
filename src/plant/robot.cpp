// Robot: a robot in the world, its state (poses, joints, the last good state it falls back to) and
// the per-step work World::step asks of it. Built by robot_builder.cpp; its joint layer is in
// joint_layer.cpp, its sensors in sensors.cpp.
#include <cmath>

#include "internals.h"
#include "robot_builder.h"
#include "sensor_rendering.h"

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
    if (!sensor->active() || !sensor->due(time_ns))
      continue;
    const SensorDescription& d = sensor->description();
    const Frame pose = Frame::fromPose(fromBullet(multibody.linkWorldTransform(d.link, name))) * Frame::fromPose(d.pose);
    if (auto* camera = dynamic_cast<Camera*>(sensor.get()))
      detail::SensorRendering::render(*camera, world->rayScene(nullptr), pose, world->lighting(), time_ns);
    else if (auto* lidar = dynamic_cast<Lidar*>(sensor.get()))
      detail::SensorRendering::scan(*lidar, world->rayScene(this), pose, time_ns);
  }
}

void Robot::Internals::resetToSpawn()
{
  if (disabled)  // out of the physics: it stays as it was until removed
    return;
  last_control_ns = world->time_ns;
  if (controller_manager)
    controller_manager->reset(world->time_ns);
  last_good.base = spawn_pose * multibody.bodies[0].urdf_from_com;
  for (size_t i = 0; i < multibody.joints.size(); ++i)
    last_good.q[i] = btScalar(multibody.joints[i].initial_position);
  last_good.restore(multibody);
  joint_layer.resetPids();
  for (auto& col : multibody.colliders)
    world->dynamics->getBroadphase()->getOverlappingPairCache()->cleanProxyFromPairs(
        col->getBroadphaseHandle(), world->dynamics->getDispatcher());
  last_good.save(multibody);
}

// ---------------------------------------------------------------------------------------- Robot

Robot::Robot(std::unique_ptr<Internals> internals) : in_(std::move(internals)) { in_->self = this; }
Robot::~Robot() = default;  // World takes its pieces out of the dynamics world first (removeRobot)

ControllerManager* Robot::controllerManager() { return in_->controller_manager.get(); }
double Robot::controlPeriod() const { return in_->control_period_ns * 1e-9; }
const std::string& Robot::name() const { return in_->name; }
const std::string& Robot::controlNamespace() const { return in_->control_namespace; }
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

Twist Robot::baseTwist() const
{
  const btMultiBody& mb = *in_->multibody.bullet;
  btVector3 omega = mb.getBaseOmega();
  btVector3 root = in_->multibody.rootWorldTransform().getOrigin();
  btVector3 v = mb.getBaseVel() + omega.cross(root - mb.getBasePos());
  Twist t;
  for (int i = 0; i < 3; ++i)
  {
    t.linear[i] = v[i];
    t.angular[i] = omega[i];
  }
  return t;
}

urdf::Pose Robot::linkPose(const std::string& link) const
{
  return fromBullet(in_->multibody.linkWorldTransform(link, in_->name));
}

std::vector<Sensor*> Robot::sensors()
{
  std::vector<Sensor*> out;
  for (auto& s : in_->sensors)
    out.push_back(s.get());
  return out;
}

namespace
{
template <class Kind>
std::vector<Kind*> sensorsOfKind(const std::vector<std::unique_ptr<Sensor>>& sensors)
{
  std::vector<Kind*> out;
  for (auto& s : sensors)
    if (auto* kind = dynamic_cast<Kind*>(s.get()))
      out.push_back(kind);
  return out;
}
}  // namespace

std::vector<Camera*> Robot::cameras() { return sensorsOfKind<Camera>(in_->sensors); }
std::vector<Lidar*> Robot::lidars() { return sensorsOfKind<Lidar>(in_->sensors); }

Sensor* Robot::sensor(const std::string& name)
{
  for (auto& s : in_->sensors)
    if (s->name() == name)
      return s.get();
  return nullptr;
}

}  // namespace bullet_plant
