#include "simulation/robot_sensor_context.h"

#include <algorithm>

#include "physics/bullet_conversions.h"
#include "simulation/internals.h"

namespace bullet_plant
{
bool RobotSensorContext::hasLink(const std::string& link) const { return robot_.multibody.link_in_body.count(link) > 0; }

urdf::Pose RobotSensorContext::linkPose(const std::string& link) const
{
  return fromBullet(robot_.multibody.linkWorldTransform(link, robot_.name));
}

LinkMotion RobotSensorContext::linkMotion(const std::string& link, const urdf::Pose& offset) const
{
  return robot_.multibody.linkMotion(link, offset, robot_.name);
}

urdf::Vector3 RobotSensorContext::gravity() const { return robot_.world->description.gravity; }

// The robot's own bodies, added to the scene with the robot as their owner, are the ones hidden.
const RayScene& RobotSensorContext::lidarScene() { return robot_.world->rayScene(&robot_); }

GlScene* RobotSensorContext::glScene() { return robot_.world->glScene(); }

FrameWorker* RobotSensorContext::frameWorker() { return robot_.world->frame_worker.get(); }

bool RobotSensorContext::lockstep() const { return robot_.world->lockstep; }

Lighting RobotSensorContext::lighting() const { return robot_.world->lighting(); }

std::vector<ContactState> RobotSensorContext::contacts(const std::string& link, const std::vector<std::string>& collisions) const
{
  const RobotMultibody& multibody = robot_.multibody;
  const std::string& name = robot_.name;
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
  const World::Internals& world = *robot_.world;
  const btScalar per_step = btScalar(1.0 / world.step_s);
  forTouchingPoints(*world.dispatcher, [ours](const btCollisionObject* object) { return object == ours; },
                    [&](const btManifoldPoint& point, bool ours_is_a, const btCollisionObject* other) {
    const std::string& mine = body.collisionName(ours_is_a ? point.m_index0 : point.m_index1);
    if (std::find(collisions.begin(), collisions.end(), mine) == collisions.end())
      return;
    const std::string collision1 = name + "::" + body.link + "::" + mine;
    const std::string collision2 = world.collisionNameOf(other, ours_is_a ? point.m_index1 : point.m_index0);
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

}  // namespace bullet_plant
