#include "simulation/joint_wrench_watch.h"

#include <algorithm>

#include "physics/dynamics_world.h"
#include "simulation/internals.h"

namespace bullet_plant
{
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

bool JointWrenchWatches::watch(const RobotMultibody& multibody, const RobotDescription& robot, const std::string& joint)
{
  auto index = multibody.joint_index.find(joint);
  urdf::JointConstSharedPtr described = robot.model->getJoint(joint);
  if (index == multibody.joint_index.end() || !described)
    return false;
  for (const Watch& w : watches_)
    if (w.joint == joint)
      return true;
  const btMultiBody& mb = *multibody.bullet;
  Watch w;
  w.joint = joint;
  w.child_link = w.axes_link = described->child_link_name;
  // an SDF joint's frame apart from its child link's is a frame link fixed to the child (sdf_model.cpp)
  const urdf::LinkConstSharedPtr child_link = robot.model->getLink(w.child_link);
  if (robot.frame_links.count(w.child_link) && child_link && child_link->child_joints.size() == 1)
    w.axes_link = child_link->child_joints.front()->child_link_name;
  const int child = multibody.joints[index->second].link;  // Bullet link index
  for (int i = 0; i < mb.getNumLinks(); ++i)
  {
    int up = i;
    while (up >= 0 && up != child)
      up = mb.getParent(up);
    if (up == child)
      w.bodies.push_back(i + 1);
  }
  watches_.push_back(std::move(w));
  return true;
}

void JointWrenchWatches::wrench(const std::string& joint, urdf::Vector3& force, urdf::Vector3& torque) const
{
  force = torque = urdf::Vector3();
  for (const Watch& w : watches_)
    if (w.joint == joint)
    {
      force = w.force;
      torque = w.torque;
    }
}

void JointWrenchWatches::beforeStep(const RobotMultibody& multibody)
{
  const btMultiBody& mb = *multibody.bullet;
  std::vector<btVector3> momentum, angular_momentum;
  bodyMomenta(multibody, momentum, angular_momentum);
  for (Watch& w : watches_)
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
// the bumper reads them); the subtree pushed back with the opposite, which is what is kept. Forces
// between bodies of the subtree cancel in the sums.
void JointWrenchWatches::afterStep(const RobotMultibody& multibody, const std::string& robot, btScalar dt,
                                   const btVector3& gravity, btDispatcher& dispatcher)
{
  const btMultiBody& mb = *multibody.bullet;
  std::vector<btVector3> momentum, angular_momentum;
  bodyMomenta(multibody, momentum, angular_momentum);
  for (Watch& w : watches_)
  {
    const btTransform frame = multibody.linkWorldTransform(w.child_link, robot);
    const btVector3 at = frame.getOrigin();
    btVector3 force(0, 0, 0), torque(0, 0, 0);
    for (size_t k = 0; k < w.bodies.size(); ++k)
    {
      const int b = w.bodies[k];
      const btVector3 com = multibody.bodyWorldTransform(b).getOrigin();
      btVector3 weight, weight_torque;  // a link without <gravity> feels none (PartialGravity)
      gravityOn(mb, b, gravity, weight, weight_torque);
      const btVector3 external = weight + w.force_added[k];
      const btVector3 needed = (momentum[size_t(b)] - w.momentum[k]) / dt;
      const btVector3 turning = (angular_momentum[size_t(b)] - w.angular_momentum[k]) / dt;
      force += needed - external;
      torque += turning + (com - at).cross(needed) - w.torque_added[k] - (com - at).cross(external) - weight_torque;
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
    // Gazebo's sign (JointWrench body2): what the child passes back to the joint
    const btMatrix3x3 to_child = multibody.linkWorldTransform(w.axes_link, robot).getBasis().transpose();
    w.force = fromBullet(to_child * -force);
    w.torque = fromBullet(to_child * -torque);
  }
}

}  // namespace bullet_plant
