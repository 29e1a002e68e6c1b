// Robot: the public face of a robot in the world (robot.h): its state read and set by hand, the
// wrench and effort jobs it is given, and going back to where it was spawned. Built by
// robot_builder.cpp; its step is in robot_step.cpp and the units that file names, its joint layer
// in joint_layer.cpp, its sensors in sensors.cpp.
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "physics/bullet_conversions.h"
#include "physics/dynamics_world.h"
#include "simulation/internals.h"

namespace bullet_plant
{
// ------------------------------------------------------------------- set by hand, reset to spawn

void Robot::Internals::settleAfterTeleport()
{
  multibody.updateKinematics();
  wakeUp(*multibody.bullet);
  joint_layer.resetPids();
  forgetSolverHistory();
  recovery.last_good.save(multibody);
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
  LastGoodState& last_good = recovery.last_good;  // made the spawn state, then gone back to
  last_good.base = spawn_pose * multibody.bodies[0].urdf_from_com;
  for (size_t i = 0; i < multibody.joints.size(); ++i)
    last_good.q[i] = btScalar(multibody.joints[i].initial_position);
  for (size_t i = 0; i < multibody.balls.size(); ++i)  // as built: the joint frame's own orientation
  {
    std::fill(&last_good.ball_q[4 * i], &last_good.ball_q[4 * i] + 3, btScalar(0));
    last_good.ball_q[4 * i + 3] = 1;
  }
  last_good.restore(multibody);
  settleAfterTeleport();
}

Robot* Robot::Internals::otherTreeWithLink(const std::string& link) const
{
  if (multibody.link_in_body.count(link))
    return nullptr;
  for (Robot* tree : other_trees)
    if (tree->in_->multibody.link_in_body.count(link))
      return tree;
  return nullptr;
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
std::vector<const RobotDescription*> Robot::treeDescriptions() const
{
  std::vector<const RobotDescription*> out{&in_->description};
  for (const Robot* tree : in_->other_trees)
    out.push_back(&tree->description());
  return out;
}
std::vector<JointHandle>& Robot::handles() { return in_->joint_layer.handles(); }
JointHandle* Robot::handle(const std::string& joint) { return in_->joint_layer.handle(joint); }
long Robot::recoveries() const
{
  long recoveries = in_->recovery.recoveries;
  for (const Robot* tree : in_->other_trees)
    recoveries += tree->recoveries();
  return recoveries;
}
bool Robot::disabled() const { return in_->disabled; }
bool Robot::asleep() const
{
  return in_->asleep() &&
         std::all_of(in_->other_trees.begin(), in_->other_trees.end(), [](const Robot* tree) { return tree->asleep(); });
}
void Robot::setEStop(bool on) { in_->joint_layer.setEStop(on); }
bool Robot::eStop() const { return in_->joint_layer.eStop(); }

std::vector<std::string> Robot::jointNames() const
{
  std::vector<std::string> names;
  for (const MovableJoint& j : in_->multibody.joints)
    if (!j.internal)
      names.push_back(j.name);
  for (const Robot* tree : in_->other_trees)
    for (const std::string& name : tree->jointNames())
      names.push_back(name);
  return names;
}

std::vector<std::string> Robot::ballJointNames() const
{
  std::vector<std::string> names;
  for (const BallJoint& b : in_->multibody.balls)
    names.push_back(b.name);
  for (const Robot* tree : in_->other_trees)
    for (const std::string& name : tree->ballJointNames())
      names.push_back(name);
  return names;
}

bool Robot::jointState(const std::string& joint, double& position, double& velocity, double& effort) const
{
  const RobotMultibody& mb = in_->multibody;
  auto it = mb.joint_index.find(joint);
  if (it == mb.joint_index.end())
  {
    for (const Robot* tree : in_->other_trees)
      if (tree->jointState(joint, position, velocity, effort))
        return true;
    if (!mb.ball(joint))
      return false;
    // Gazebo 11's ODEBallJoint: no position (NaN), velocity 0, no effort.
    position = std::numeric_limits<double>::quiet_NaN();
    velocity = effort = 0.0;
    return true;
  }
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
  if (const Robot* tree = in_->otherTreeWithLink(link))
    return tree->linkPose(link);
  return fromBullet(in_->multibody.linkWorldTransform(link, in_->name));
}

std::vector<std::string> Robot::linkNames() const
{
  std::vector<std::string> names;
  for (const auto& kv : in_->multibody.link_in_body)
    if (!in_->description.frame_links.count(kv.first))  // SDF's frames are no links
      names.push_back(kv.first);
  for (const Robot* tree : in_->other_trees)
    for (const std::string& name : tree->linkNames())
      names.push_back(name);
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
  if (it != multibody.joint_index.end())
    return multibody.joints[it->second];
  if (multibody.ball(joint))
    throw std::invalid_argument("joint '" + joint + "' of robot '" + robot + "' is a ball joint, which has no one "
                                "position or effort (Gazebo's ODE ball joint has neither)");
  throw std::out_of_range("robot '" + robot + "' has no movable joint '" + joint + "'");
}
}  // namespace

Twist Robot::linkTwist(const std::string& link) const
{
  if (const Robot* tree = in_->otherTreeWithLink(link))
    return tree->linkTwist(link);
  bodyOfLink(in_->multibody, link, in_->name);  // an unknown link: std::out_of_range naming it
  return twistOf(linkMotion(link));
}

LinkMotion Robot::linkMotion(const std::string& link, const urdf::Pose& offset) const
{
  if (const Robot* tree = in_->otherTreeWithLink(link))
    return tree->linkMotion(link, offset);
  bodyOfLink(in_->multibody, link, in_->name);
  return in_->multibody.linkMotion(link, offset, in_->name);
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
  for (const Robot* tree : in_->other_trees)
    for (const urdf::Vector3& normal : tree->contactNormals())
      normals.push_back(normal);
  return normals;
}

void Robot::setLinkState(const std::string& link, const urdf::Pose& pose, const Twist& twist)
{
  if (Robot* tree = in_->otherTreeWithLink(link))
    return tree->setLinkState(link, pose, twist);
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
  const btScalar at_rest[3] = {0, 0, 0};
  for (const BallJoint& b : multibody.balls)
    mb.setJointVelMultiDof(b.link, at_rest);
  in_->settleAfterTeleport();
}

void Robot::setModelState(const urdf::Pose& pose, const Twist& twist)
{
  const btTransform moved = toBullet(pose) * in_->multibody.rootWorldTransform().inverse();
  const btVector3 omega = toBullet(urdf::Vector3(twist.angular[0], twist.angular[1], twist.angular[2]));
  const btVector3 v = toBullet(urdf::Vector3(twist.linear[0], twist.linear[1], twist.linear[2]));
  for (Robot* tree : in_->other_trees)
  {
    // Each other tree's root where the model's rigid motion takes it, with that motion's velocity there.
    const btTransform root = moved * tree->in_->multibody.rootWorldTransform();
    const btVector3 v_root = v + omega.cross(root.getOrigin() - toBullet(pose.position));
    tree->setLinkState(tree->description().model->getRoot()->name, fromBullet(root),
                       {{{v_root.x(), v_root.y(), v_root.z()}}, twist.angular});
  }
  setLinkState(in_->description.model->getRoot()->name, pose, twist);
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
  // Coupled joints stay in mesh: a follower set alone moves its leader, else it follows its leader.
  for (const JointCoupling& c : multibody.couplings)
  {
    const MovableJoint& leader = multibody.joints[c.leader];
    const MovableJoint& follower = multibody.joints[c.follower];
    if (positions.count(follower.name) && !positions.count(leader.name) && c.multiplier != 0)
    {
      const double q = mb.getJointPos(follower.link) / c.multiplier;
      mb.setJointPos(leader.link, btScalar(positionWithinLimits(leader, q, in_->world->log, in_->name, "position")));
      mb.setJointVel(leader.link, 0);
    }
    mb.setJointPos(follower.link, btScalar(c.multiplier * mb.getJointPos(leader.link)));
    mb.setJointVel(follower.link, 0);
  }
  in_->settleAfterTeleport();
}

void Robot::applyLinkWrench(const std::string& link, const urdf::Vector3& force, const urdf::Vector3& torque,
                            int64_t start_ns, int64_t duration_ns)
{
  if (Robot* tree = in_->otherTreeWithLink(link))
    return tree->applyLinkWrench(link, force, torque, start_ns, duration_ns);
  const int body = bodyOfLink(in_->multibody, link, in_->name);
  in_->external_efforts.addLinkWrench(link, body, toBullet(force), toBullet(torque), start_ns, duration_ns);
}

void Robot::clearLinkWrenches(const std::string& link)
{
  if (Robot* tree = in_->otherTreeWithLink(link))
    return tree->clearLinkWrenches(link);
  in_->external_efforts.clearLinkWrenches(link);
}

void Robot::applyJointEffort(const std::string& joint, double effort, int64_t start_ns, int64_t duration_ns)
{
  const MovableJoint& j = movableJoint(in_->multibody, joint, in_->name);
  if (!std::isfinite(effort))
    throw std::invalid_argument("effort on joint '" + joint + "' is not finite");
  in_->external_efforts.addJointEffort(joint, j.link, effort, start_ns, duration_ns);
}

void Robot::clearJointEfforts(const std::string& joint) { in_->external_efforts.clearJointEfforts(joint); }

std::vector<Sensor*> Robot::sensors()
{
  std::vector<Sensor*> out;
  for (auto& s : in_->sensors)
    out.push_back(s.get());
  for (Robot* tree : in_->other_trees)
    for (Sensor* s : tree->sensors())
      out.push_back(s);
  return out;
}

Sensor* Robot::sensor(const std::string& name)
{
  for (auto& s : in_->sensors)
    if (s->name() == name)
      return s.get();
  for (Robot* tree : in_->other_trees)
    if (Sensor* s = tree->sensor(name))
      return s;
  return nullptr;
}

}  // namespace bullet_plant
