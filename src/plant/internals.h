// Private state of World and Robot: the Bullet objects behind the public classes.
#pragma once

#include <map>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include <btBulletDynamicsCommon.h>
#include <BulletDynamics/Featherstone/btMultiBody.h>
#include <BulletDynamics/Featherstone/btMultiBodyConstraintSolver.h>
#include <BulletDynamics/Featherstone/btMultiBodyDynamicsWorld.h>
#include <BulletDynamics/Featherstone/btMultiBodyLinkCollider.h>

#include "bullet_plant/robot.h"
#include "bullet_plant/world.h"
#include "physics/joint_drive.h"
#include "ray_caster.h"

namespace bullet_plant
{
btTransform toBullet(const urdf::Pose& p);
urdf::Pose fromBullet(const btTransform& t);

// A rigid body of the multibody: one URDF link with a movable parent joint (or the root) and every
// link fixed to it. Bullet wants each body's frame at its centre of mass along its principal axes;
// urdf_from_com places that frame in the body's URDF link frame.
struct Body
{
  Body() = default;
  Body(Body&&) noexcept = default;
  Body& operator=(Body&&) noexcept = default;

  std::string link;              // the URDF link that owns the body
  int parent = -2;               // index of the parent body (-1: the base); -2 for the base itself
  double mass = 0.0;
  btVector3 inertia_diagonal{0, 0, 0};
  btTransform urdf_from_com = btTransform::getIdentity();
  // The collider's shape: null when no member link has a collision; the compound of the
  // member links' shapes, or (compound null) the only shape where it sits in the COM frame as it is.
  btCollisionShape* shape = nullptr;
  std::unique_ptr<btCompoundShape> compound;
  std::vector<std::unique_ptr<btCollisionShape>> child_shapes;
  std::vector<RayPrimitive> ray_shapes;  // the same shapes, in the COM frame, for sensors
  double mu = 1.0;
};

// A movable URDF joint and the Bullet pieces that act on it.
struct MovableJoint
{
  std::string name;
  JointType type = JointType::Revolute;
  int link = -1;                 // Bullet link index (= body index - 1)
  JointLimits limits;
  double damping = 0.0, friction = 0.0;
  std::unique_ptr<JointDrive> drive;           // the joint layer's motor / implicit PID
  std::unique_ptr<JointDrive> damper;          // URDF <dynamics damping> where an explicit torque would be unstable
  std::unique_ptr<JointDrive> dry_friction;    // URDF <dynamics friction>
  std::unique_ptr<JointDrive> lower_limit, upper_limit;  // rows only while the joint is at a limit
  double axis_inertia = 0.0;                   // the child body's inertia about the joint axis
  double explicit_effort = 0.0;                // actuator torque applied explicitly this step
  double initial_position = 0.0;
};

struct Robot::Internals
{
  World::Internals* world = nullptr;
  Robot* self = nullptr;
  std::string name;
  std::string control_namespace;
  RobotDescription description;
  std::vector<Body> bodies;                         // [0] is the base
  std::map<std::string, std::pair<int, btTransform>> link_in_body;  // link -> (body, link frame in COM frame)
  std::vector<MovableJoint> joints;                 // URDF order
  std::map<std::string, size_t> joint_index;
  std::vector<JointHandle> handles;
  std::vector<size_t> handle_joint;                 // handle i drives joints[handle_joint[i]]
  std::unique_ptr<btMultiBody> multibody;
  std::vector<std::unique_ptr<btMultiBodyLinkCollider>> colliders;
  std::vector<std::unique_ptr<Sensor>> sensors;
  std::vector<std::mt19937> sensor_noise;           // one generator per sensor
  btTransform spawn_pose;                           // of the URDF root link
  bool e_stop = false;
  std::unique_ptr<ControllerManager> controller_manager;
  int64_t control_period_ns = 0;
  int64_t last_control_ns = 0;
  long recoveries = 0;
  // Last finite state, to fall back to if the physics diverges.
  std::vector<btScalar> good_q, good_qd;
  btTransform good_base;
  btVector3 good_base_vel{0, 0, 0}, good_base_omega{0, 0, 0};

  void updateControllers(int64_t time_ns);
  void applyCommands(double dt);
  void readState(double dt);
  void updateSensors(int64_t time_ns);
  void resetToSpawn();
  btTransform linkWorldTransform(const std::string& link) const;
  btTransform bodyWorldTransform(int body) const;
  void saveGoodState();
  bool stateFinite() const;
  void restoreGoodState();
  void appendRayPrimitives(std::vector<RayPrimitive>& out) const;
};

struct World::Internals
{
  WorldDescription description;
  Log log;
  Param params;
  int64_t step_ns = 1000000;
  double step_s = 0.001;
  int64_t time_ns = 0;
  uint64_t steps = 0;
  bool paused = false;

  std::unique_ptr<btDefaultCollisionConfiguration> collision_config;
  std::unique_ptr<btCollisionDispatcher> dispatcher;
  std::unique_ptr<btBroadphaseInterface> broadphase;
  std::unique_ptr<btMultiBodyConstraintSolver> solver;
  std::unique_ptr<btMultiBodyDynamicsWorld> dynamics;
  std::vector<std::unique_ptr<btCollisionShape>> static_shapes;
  std::vector<std::unique_ptr<btCollisionObject>> static_objects;
  std::vector<RayPrimitive> static_ray_shapes;

  std::vector<std::unique_ptr<Robot>> robots;
};

// A robot's side of the plant (for the library and its tests).
inline Robot::Internals& internalsOf(Robot& robot) { return *robot.in_; }

// Builds the multibody, colliders, joints and sensors of a robot into the world (robot.cpp).
void buildRobot(Robot::Internals& robot, const urdf::Pose& pose, const std::map<std::string, double>& initial_joints);
void destroyRobot(Robot::Internals& robot);

}  // namespace bullet_plant
