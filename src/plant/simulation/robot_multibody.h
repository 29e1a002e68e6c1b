// A robot's Bullet multibody and what the plant keeps beside it: which URDF links make up each
// rigid body, the movable joints with their limits and the constraint rows that act on them, SDF's
// ball joints and joint couplings, and the colliders. Built by robot_builder.cpp; read and driven by
// the joint layer, the sensors and the Robot; its methods are in robot_multibody.cpp.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <btBulletDynamicsCommon.h>
#include <BulletDynamics/Featherstone/btMultiBody.h>
#include <BulletDynamics/Featherstone/btMultiBodyLinkCollider.h>

#include "bullet_plant/inertial_sensors.h"
#include "bullet_plant/joint_layer.h"
#include "bullet_plant/log.h"
#include "physics/bullet_conversions.h"
#include "physics/contact_surfaces.h"
#include "physics/dynamics_world.h"
#include "physics/joint_drive.h"
#include "physics/movable_joint.h"
#include "rendering/ray_caster.h"

namespace bullet_plant
{
// A rigid body of the multibody: one URDF link with a movable parent joint (or the root) and every
// link fixed to it. Bullet wants each body's frame at its centre of mass along its principal axes;
// urdf_from_com places that frame in the body's URDF link frame.
struct Body
{
  Body() = default;
  Body(Body&&) noexcept = default;
  Body& operator=(Body&&) noexcept = default;

  std::string link;              // the URDF link that owns the body
  int parent = -2;               // index of the parent body in RobotMultibody::bodies; -2 for the base itself
  double mass = 0.0;
  btVector3 inertia_diagonal{0, 0, 0};
  btTransform urdf_from_com = btTransform::getIdentity();
  // The collider's shape: null when no member link has a collision; the compound of the
  // member links' shapes, or (compound null) the only shape where it sits in the COM frame as it is.
  btCollisionShape* shape = nullptr;
  std::unique_ptr<btCompoundShape> compound;
  std::vector<std::shared_ptr<btCollisionShape>> child_shapes;  // a static mesh's may be shared (collision_shapes.h)
  // The SDF names of the collisions, in the compound's child order (sdfCollisionNames): what
  // contact sensors and contact messages call them.
  std::vector<std::string> collision_names;
  std::vector<RayPrimitive> ray_shapes;  // for sensors, in the COM frame: the collisions (lidars) and visuals (cameras)
  double mu = 1.0;
  double restitution = 0.0, restitution_threshold = 100000.0;  // SDF's <bounce>, as SurfaceDescription
  // An SDF body's collisions' surfaces, in the compound's child order; left empty where `mu` says
  // all of them (one coefficient, the same for each, nothing of <contact>).
  std::vector<ContactSurface> surfaces;
  bool surfaces_plain = true;

  // The name of the collision Bullet reports as `child` (a compound's child index); the only one
  // of a body with one collision; empty for an index that is none of them.
  const std::string& collisionName(int child) const
  {
    static const std::string none;
    if (collision_names.size() == 1)
      return collision_names[0];
    return child >= 0 && size_t(child) < collision_names.size() ? collision_names[size_t(child)] : none;
  }
};

struct RobotMultibody
{
  std::vector<Body> bodies;                         // [0] is the base
  std::map<std::string, std::pair<int, btTransform>> link_in_body;  // link -> (body, link frame in COM frame)
  // The SDF name of each link's collisions (Body::collision_names): (link, index in its
  // collision_array) -> name.
  std::map<std::pair<std::string, size_t>, std::string> link_collision_names;
  std::vector<MovableJoint> joints;                 // URDF order
  std::map<std::string, size_t> joint_index;
  std::vector<BallJoint> balls;                     // SDF's ball joints
  std::vector<JointCoupling> couplings;             // SDF's screws and gearboxes
  std::unique_ptr<btMultiBody> bullet;
  std::vector<std::unique_ptr<btMultiBodyLinkCollider>> colliders;
  // Where some links feel no gravity (SDF's <gravity>false): what it pulls on each body, the
  // multibody's user pointer (DynamicsWorld::applyGravity). Null where every link feels it.
  std::unique_ptr<PartialGravity> partial_gravity;

  btTransform bodyWorldTransform(int body) const;
  // Throws std::out_of_range naming the robot for an unknown link.
  btTransform linkWorldTransform(const std::string& link, const std::string& robot) const;
  // The URDF root link's pose in the world.
  btTransform rootWorldTransform() const { return bullet->getBaseWorldTransform() * bodies[0].urdf_from_com.inverse(); }
  // The one kinematics query (Robot::linkMotion, robot.h), which the sensors' and the model
  // plugins' contexts answer with too. std::out_of_range for an unknown link.
  LinkMotion linkMotion(const std::string& link, const urdf::Pose& offset, const std::string& robot) const;
  // Link::AddForce and AddTorque on a body: a force at its centre of mass and a torque, world axes,
  // for the coming step.
  void addBodyWrench(int body, const btVector3& force, const btVector3& torque);
  // After positions were set by hand: link transforms and colliders follow.
  void updateKinematics();
  // Every JointDrive leaves the world's constraints with its impulse forgotten, as when built
  // (the warm start and the world's constraint order would otherwise carry the past on).
  void disableJointRows();
  // Each coupling's row for the coming step (holdCoupling).
  void holdCouplings(double dt);
  // A ball joint by name, or null.
  const BallJoint* ball(const std::string& name) const;
};

}  // namespace bullet_plant
