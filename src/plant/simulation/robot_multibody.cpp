#include "simulation/robot_multibody.h"

#include <stdexcept>

namespace bullet_plant
{
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

LinkMotion RobotMultibody::linkMotion(const std::string& link, const urdf::Pose& offset, const std::string& robot) const
{
  const int body = link_in_body.at(link).first;
  const btMultiBody& mb = *bullet;
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
    const btMatrix3x3& to_world = bodyWorldTransform(body).getBasis();
    omega = to_world * omegas[body];
    v_com = to_world * velocities[body];
  }
  const btTransform frame = linkWorldTransform(link, robot) * toBullet(offset);
  const btVector3 v = v_com + omega.cross(frame.getOrigin() - bodyWorldTransform(body).getOrigin());
  LinkMotion m;
  m.pose = fromBullet(frame);
  m.velocity = fromBullet(v);
  m.angular_velocity = fromBullet(omega);
  return m;
}

void RobotMultibody::addBodyWrench(int body, const btVector3& force, const btVector3& torque)
{
  if (body == 0)
  {
    bullet->addBaseForce(force);
    bullet->addBaseTorque(torque);
  }
  else
  {
    bullet->addLinkForce(body - 1, force);
    bullet->addLinkTorque(body - 1, torque);
  }
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
    for (JointDrive* c : {j.drive.get(), j.damper.get(), j.spring.get(), j.dry_friction.get(), j.lower_limit.get(),
                          j.upper_limit.get()})
      if (c)
        c->disable();
  for (JointCoupling& c : couplings)
    c.row->disable();
}

void RobotMultibody::holdCouplings(double dt)
{
  for (JointCoupling& c : couplings)
    holdCoupling(c, joints, *bullet, dt);
}

const BallJoint* RobotMultibody::ball(const std::string& name) const
{
  for (const BallJoint& b : balls)
    if (b.name == name)
      return &b;
  return nullptr;
}

}  // namespace bullet_plant
