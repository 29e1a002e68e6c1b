// Private state of World and Robot: what the public classes stand for in Bullet.
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include <btBulletDynamicsCommon.h>
#include <BulletDynamics/Featherstone/btMultiBodyConstraintSolver.h>
#include <BulletDynamics/Featherstone/btMultiBodyDynamicsWorld.h>

#include "bullet_plant/gazebo_host.h"
#include "bullet_plant/inertial_sensors.h"
#include "bullet_plant/robot.h"
#include "bullet_plant/world.h"
#include "bullet_plant/model_plugin.h"
#include "hardware/joint_layer_sim.h"
#include "physics/dense_row_solver.h"
#include "physics/run_time_joint.h"
#include "hardware/model_joint_sim.h"
#include "rendering/frame_worker.h"
#include "rendering/ray_caster.h"
#include "simulation/divergence_recovery.h"
#include "simulation/external_efforts.h"
#include "simulation/joint_wrench_watch.h"
#include "simulation/robot_model_plugin_context.h"
#include "simulation/robot_multibody.h"
#include "simulation/robot_sensor_context.h"
#include "simulation/world_plugin_context.h"

namespace bullet_plant
{
// A robot's state in the plant; each of its jobs is a unit of its own: the step's phases
// (robot_step.cpp), divergence recovery (divergence_recovery.h), gazebo_ros's wrench and effort
// jobs (external_efforts.h), joint wrench watching (joint_wrench_watch.h), what its sensors read
// (robot_sensor_context.h) and what its model plugins reach (robot_model_plugin_context.h).
struct Robot::Internals
{
  World::Internals* world = nullptr;
  Robot* self = nullptr;
  std::string name;
  std::string control_namespace;
  std::string spawn_namespace;  // spawn_model -robot_namespace, for plugins without <robotNamespace>
  RobotDescription description;
  RobotMultibody multibody;
  JointLayer joint_layer;
  std::unique_ptr<ControllerManager> controller_manager;  // with a gazebo_ros_control block only
  int64_t control_period_ns = 0;
  int64_t last_control_ns = 0;
  std::vector<std::unique_ptr<Sensor>> sensors;
  std::vector<std::unique_ptr<ModelPlugin>> model_plugins;  // gazebo_plugins' drives (model_plugin.h)
  std::map<size_t, std::unique_ptr<ModelJointSim>> model_joints;  // by joint index: the ones model plugins drive
  btTransform spawn_pose;                                  // of the URDF root link
  DivergenceRecovery recovery;
  bool disabled = false;                  // out of the physics after diverging step after step
  // SDF's <kinematic> base: a fixed base, which contacts, gravity and forces do not move and Bullet
  // carries on at the base velocity set on it (setLinkState), as ODE moves a kinematic body.
  bool kinematic = false;
  ExternalEfforts external_efforts;       // Robot::applyLinkWrench, applyJointEffort
  JointWrenchWatches wrench_watches;      // ModelPluginContext::watchJointWrench
  std::vector<int> ray_bodies;            // each body's handle in the world's RayScene (-1: no shapes)
  std::vector<int> gl_bodies;             // the same in its GlScene
  // A model of several trees (RobotDescription::other_trees): its canonical link's tree is the Robot
  // the world lists, holding its other trees, each a Robot of its own in the world's step (named as
  // the model, so its collisions are "model::link::collision"), `canonical` pointing back.
  std::vector<Robot*> other_trees;
  Robot::Internals* canonical = nullptr;
  bool several_trees = false;  // a tree of a model of several, known as it is built
  // The other tree of this model holding `link`, or null (this tree holds it, or none does).
  Robot* otherTreeWithLink(const std::string& link) const;
  RobotSensorContext sensor_context{*this};              // what its sensors are handed
  RobotModelPluginContext model_plugin_context{*this};   // what its model plugins are handed

  // One step, as World::step calls them (robot_step.cpp): controllers (each control period), model
  // plugins' OnUpdate and the rows and forces of the joints they drive for the coming step,
  // [writeSim, physics, recovery, readSim], sensors.
  void updateControllers(int64_t time_ns);
  void updateModelPlugins(int64_t time_ns);
  void updateSensors(int64_t time_ns);
  void resetToSpawn();
  // After positions or velocities were set by hand: kinematics, stale contact pairs, the last good
  // state, and a body asleep woken.
  void settleAfterTeleport();
  // Asleep (DynamicsWorld's deactivation): World::step leaves its joint layer, recovery and
  // read-back alone, as the physics leaves its bodies. Only a model nothing drives from inside
  // may sleep (buildRobot).
  bool asleep() const;
  // The joint rows' and contacts' impulses (the solver's warm start) and the contacts themselves.
  void forgetSolverHistory();
};

struct World::Internals
{
  WorldDescription description;
  Log log;
  Param params;
  uint32_t noise_seed = 0;  // World::setNoiseSeed
  int64_t step_ns = 1000000;
  double step_s = 0.001;
  int64_t time_ns = 0;
  uint64_t steps = 0;
  bool paused = false;
  bool physics_enabled = true;  // World::SetPhysicsEnabled (gazebo_ros_joint_pose_trajectory)
  bool loading_file = false;    // spawning the world file's own models (World::spawn's name check)

  std::unique_ptr<btDefaultCollisionConfiguration> collision_config;
  std::unique_ptr<btCollisionDispatcher> dispatcher;
  std::unique_ptr<btBroadphaseInterface> broadphase;
  std::unique_ptr<DenseRowSolver> solver;
  std::unique_ptr<btMultiBodyDynamicsWorld> dynamics;
  std::vector<std::shared_ptr<btCollisionShape>> static_shapes;  // a static mesh's may be shared (collision_shapes.h)
  std::vector<std::unique_ptr<btCollisionObject>> static_objects;
  std::vector<std::string> static_names;  // of static_objects, model::link::collision
  std::vector<std::string> static_object_models;  // of static_objects, the static model each is of
  // Where the world file put each static model (description.static_models holds where it is now):
  // where reset_world puts it back.
  std::map<std::string, urdf::Pose> static_file_poses;
  std::vector<RayPrimitive> static_ray_shapes;
  std::unique_ptr<RayScene> ray_scene;  // built when a sensor first needs it
  // The cameras' OpenGL: tried when a camera first renders; null (said once, in the log) where
  // there is none.
  bool gl_tried = false;
  std::unique_ptr<GlContext> gl_context;
  std::unique_ptr<GlScene> gl_scene;

  // Every tree of every model (a model of several trees has a robot for each: Robot::Internals::
  // other_trees), in the order they were added.
  std::vector<std::unique_ptr<Robot>> robots;
  // Builds one tree of a model into the world and lists it (World::spawn): the canonical link's
  // tree (canonical null) or another tree of that model.
  Robot& addTree(RobotDescription description, const std::string& name, const urdf::Pose& pose,
                 const std::string& robot_namespace, const std::map<std::string, double>& initial_joints,
                 Robot::Internals* canonical, bool several_trees);
  // Renders camera frames while the simulation goes on (made with the GL scene). Declared after
  // the robots, so it stops, its jobs done, before their cameras go.
  std::unique_ptr<FrameWorker> frame_worker;
  // step() returns without waiting for the frames still rendering (World::setFramesAhead).
  bool frames_ahead = false;
  // Every camera frame due renders (World::setLockstep); out of it, the skipped ones are said once a
  // minute of wall time (reportSkippedFrames), each camera's count at the last report kept.
  bool lockstep = true;
  std::chrono::steady_clock::time_point next_skip_report{};
  std::map<const Sensor*, uint64_t> skipped_reported;
  void reportSkippedFrames();

  // "robot::link" or the static collision's name, for messages.
  std::string nameOf(const btCollisionObject* object) const;
  // "model::link::collision" of the collision Bullet reports as `child` of `object` (a compound's
  // child index), as Gazebo's contacts name it.
  std::string collisionNameOf(const btCollisionObject* object, int child) const;
  // The static models (static_models.cpp): moved (World::moveStaticModel), removed (World::remove),
  // back where the file put them (World::resetWorld); after a change, what sensors see of them made
  // again from the description (once a change, not once a frame), the robots' bodies added anew.
  bool moveStaticModel(const std::string& name, const urdf::Pose& pose);
  bool removeStaticModel(const std::string& name);
  void resetStaticModels();
  void rebuildStaticScenes();
  // Every robot in the physics woken: after the world under them changed (a body removed or moved,
  // gravity), what rested must not stay asleep.
  void wakeRobots();
  // Everything sensors can see: the static scene and every robot's bodies where they are now
  // (a robot's bodies are built into it once). `hidden` as RayScene::commit.
  const RayScene& rayScene(const void* hidden);
  // The same for cameras, or null without OpenGL.
  GlScene* glScene();
  // Every camera's frame in the making collected (rendered, made the latest).
  void collectFrames();
  Lighting lighting() const;

  // Joints made at run time by Gazebo plugins (WorldPluginContext::attach): each holds a link of one
  // robot to a link of another, of the same, or to the world, by its id.
  struct Attachment
  {
    std::unique_ptr<RunTimeJointConstraint> constraint;
    const Robot::Internals* parent = nullptr;  // null: the world
    const Robot::Internals* child = nullptr;
    double damping = 0.0, effort_limit = 0.0;
    double effort = 0.0;  // what Joint::SetForce gave for the coming step
  };
  std::map<int, Attachment> attachments;
  int next_attachment = 0;
  int attach(const RunTimeJoint& joint);
  void detach(int attachment);
  const Attachment* attachment(int id) const;
  // Each joint's effort for the coming step and its damping, as forces on its links; then none.
  void applyAttachmentEfforts();
  // The attachments on a robot that leaves the world.
  void releaseAttachments(const Robot::Internals& robot);

  // World::insertModel's queue, without an inserter (added at the end of a step: insertQueuedModels),
  // and the inserter; guarded by insertion_mutex, `insertions_queued` read each step without it.
  std::mutex insertion_mutex;
  std::vector<std::string> insertions;
  World::ModelInserter model_inserter;
  std::atomic<bool> insertions_queued{false};
  void insertQueuedModels();

  // Gazebo's plugins of the user's own (gazebo_host.h), made at the first (gazeboHost): the world's
  // side of them and their host. Last, so that they go before the robots whose models they hold.
  World* self = nullptr;
  std::unique_ptr<PlantWorldPluginContext> gazebo_context;
  std::unique_ptr<GazeboHost> gazebo_host;
  GazeboHost& gazeboHost();
};

// What sensors see of a world's static models where its description has them now: each collision
// (lidars) and visual (cameras). `log`: where a visual's mesh that cannot be read and its textures'
// problems are said (the world's first build); null: said already.
std::vector<RayPrimitive> staticRayShapes(const WorldDescription& description, Log* log);

// The impulse the last step's solver gave a manifold's point on its body A, normal and friction
// rows (Bullet's normal points from B into A; B took the opposite).
inline btVector3 impulseOnA(const btManifoldPoint& point)
{
  return point.m_appliedImpulse * point.m_normalWorldOnB + point.m_appliedImpulseLateral1 * point.m_lateralFrictionDir1 +
         point.m_appliedImpulseLateral2 * point.m_lateralFrictionDir2;
}

// Whether a manifold's point touched in the last step: the manifold also keeps points a little
// apart (up to Bullet's breaking threshold), which only count when the solver pushed on them.
inline bool touching(const btManifoldPoint& point) { return point.getDistance() <= 0 || point.getAppliedImpulse() != 0; }

// visit(point, ours_is_a, other) for each touching point between one of ours (`ours(object)`) and
// anything that is not: the one walk over the manifolds of Robot::contactNormals and of a contact
// sensor's link (RobotSensorContext::contacts). Bullet's normal points from B into A.
template <class Ours, class Visit>
void forTouchingPoints(btDispatcher& dispatcher, Ours ours, Visit visit)
{
  for (int m = 0; m < dispatcher.getNumManifolds(); ++m)
  {
    const btPersistentManifold& manifold = *dispatcher.getManifoldByIndexInternal(m);
    const bool ours_is_a = ours(manifold.getBody0());
    if (ours_is_a == ours(manifold.getBody1()))
      continue;  // none of ours, or two of ours
    const btCollisionObject* other = ours_is_a ? manifold.getBody1() : manifold.getBody0();
    for (int p = 0; p < manifold.getNumContacts(); ++p)
      if (touching(manifold.getContactPoint(p)))
        visit(manifold.getContactPoint(p), ours_is_a, other);
  }
}

// A robot's side of the plant (for the library and its tests).
inline Robot::Internals& internalsOf(Robot& robot) { return *robot.in_; }

}  // namespace bullet_plant
