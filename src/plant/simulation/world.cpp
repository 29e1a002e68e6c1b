#include "bullet_plant/world.h"
#include "bullet_plant/world_description.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <limits>
#include <sstream>

#include <BulletCollision/CollisionDispatch/btManifoldResult.h>
#include <BulletCollision/Gimpact/btGImpactCollisionAlgorithm.h>
#include <BulletCollision/NarrowPhaseCollision/btPersistentManifold.h>

#include "physics/bullet_conversions.h"
#include "physics/dense_row_solver.h"
#include "physics/dynamics_world.h"
#include "physics/plane_contact.h"
#include "physics/capsule_contact.h"
#include "physics/wheel_contact.h"
#include "simulation/collision_shapes.h"
#include "simulation/internals.h"
#include "simulation/world_plugin_context.h"
#include "simulation/robot_builder.h"

namespace bullet_plant
{
namespace
{
// Gazebo (ODE) combines the friction of two surfaces by taking the smaller; Bullet multiplies.
btScalar smallerFriction(const btCollisionObject* a, const btCollisionObject* b)
{
  return std::min(a->getFriction(), b->getFriction());
}
// And their bounce (SDF's restitution_coefficient) as well (ODEPhysics::Collide): a body bounces
// only off a surface that declares a <bounce> too.
btScalar smallerRestitution(const btCollisionObject* a, const btCollisionObject* b)
{
  return std::min(a->getRestitution(), b->getRestitution());
}
// How deep a link may start inside another body before the spawn warns: resting contacts are
// well under a millimetre deep.
constexpr btScalar kDeepAtSpawn = 0.01;  // m

// The deepest contact between a robot's links and the rest of the world, by Bullet's contact test.
struct DeepestContact : btCollisionWorld::ContactResultCallback
{
  const btMultiBody* own = nullptr;
  const btMultiBodyLinkCollider* link = nullptr;
  const btCollisionObject* other = nullptr;
  btScalar depth = 0;

  const btMultiBodyLinkCollider* ownLink(const btCollisionObjectWrapper* side) const
  {
    const auto* collider = btMultiBodyLinkCollider::upcast(side->getCollisionObject());
    return collider && collider->m_multiBody == own ? collider : nullptr;
  }
  btScalar addSingleResult(btManifoldPoint& point, const btCollisionObjectWrapper* a, int, int,
                           const btCollisionObjectWrapper* b, int, int) override
  {
    const btMultiBodyLinkCollider* mine_a = ownLink(a);
    const btMultiBodyLinkCollider* mine_b = ownLink(b);
    if ((mine_a != nullptr) == (mine_b != nullptr))
      return 0;  // a link touching its own robot
    if (!a->getCollisionObject()->checkCollideWith(b->getCollisionObject()) ||
        !b->getCollisionObject()->checkCollideWith(a->getCollisionObject()))
      return 0;  // two that never collide: another tree of its model that does not self-collide
    if (-point.getDistance() > depth)
    {
      depth = -point.getDistance();
      link = mine_a ? mine_a : mine_b;
      other = (mine_a ? b : a)->getCollisionObject();
    }
    return 0;
  }
};

// Warns once when a robot starts deep inside something: the contacts then push it out at up to
// contact_max_correcting_vel (DenseRowSolver), which a user should hear about.
void warnIfSpawnedInside(World::Internals& w, Robot::Internals& r)
{
  DeepestContact deepest;
  deepest.own = r.multibody.bullet.get();
  for (auto& collider : r.multibody.colliders)
    w.dynamics->contactTest(collider.get(), deepest);
  if (deepest.depth <= kDeepAtSpawn)
    return;
  std::ostringstream text;
  text << "robot '" << r.name << "' starts " << deepest.depth << " m deep inside '" << w.nameOf(deepest.other)
       << "' (its link '" << r.multibody.bodies[size_t(deepest.link->m_link + 1)].link
       << "'): the contact pushes it out at up to " << w.description.contact_max_correcting_vel
       << " m/s (Gazebo's contact_max_correcting_vel); spawn it clear of other bodies";
  w.log.warn(text.str());
}
}  // namespace

std::string World::Internals::nameOf(const btCollisionObject* object) const
{
  for (size_t i = 0; i < static_objects.size(); ++i)
    if (static_objects[i].get() == object)
      return static_names[i];
  if (const auto* collider = btMultiBodyLinkCollider::upcast(object))
    for (const auto& robot : robots)
      if (internalsOf(*robot).multibody.bullet.get() == collider->m_multiBody)
        return robot->name() + "::" + internalsOf(*robot).multibody.bodies[size_t(collider->m_link + 1)].link;
  return "?";
}

std::string World::Internals::collisionNameOf(const btCollisionObject* object, int child) const
{
  if (const auto* collider = btMultiBodyLinkCollider::upcast(object))
    for (const auto& robot : robots)
    {
      const RobotMultibody& multibody = internalsOf(*robot).multibody;
      if (multibody.bullet.get() == collider->m_multiBody)
      {
        const Body& body = multibody.bodies[size_t(collider->m_link + 1)];
        return robot->name() + "::" + body.link + "::" + body.collisionName(child);
      }
    }
  return nameOf(object);
}

World::World(const WorldDescription& description, LogSink sink) : in_(new Internals)
{
  Internals& w = *in_;
  // First: a world file's model with a Gazebo plugin of the user's own makes the world's plugin host
  // (gazeboHost) as it spawns, and the host's world is this one.
  w.self = this;
  if (sink)
    w.log.setSink(std::move(sink));
  w.description = description;
  w.step_s = description.max_step_size;
  w.step_ns = static_cast<int64_t>(std::llround(description.max_step_size * 1e9));
  gCalculateCombinedFrictionCallback = &smallerFriction;
  gCalculateCombinedRestitutionCallback = &smallerRestitution;
  // Contact points are kept while within this distance of where they were found. Bullet's 2 cm
  // default keeps up to four stale points under a rolling 3 cm wheel: slower and less accurate.
  gContactBreakingThreshold = btScalar(0.001);

  // Bullet's default pools hold 4,096 contact manifolds and as many pair algorithms, 5 MB zeroed
  // for every world: a quarter of making the race track's world (a racing env's reset makes one;
  // 41 page faults and 1.17 ms of CPU a world against 4 and 0.90 ms with 1,024). A world that
  // needs more than 1,024 takes the rest from the heap, as Bullet does when a pool runs out.
  btDefaultCollisionConstructionInfo pools;
  pools.m_defaultMaxPersistentManifoldPoolSize = 1024;
  pools.m_defaultMaxCollisionAlgorithmPoolSize = 1024;
  w.collision_config.reset(new btDefaultCollisionConfiguration(pools));
  w.dispatcher.reset(new btCollisionDispatcher(w.collision_config.get()));
  // A moving mesh's triangles (collision_shapes.h) against everything, before the pairs below take
  // theirs.
  btGImpactCollisionAlgorithm::registerAlgorithm(w.dispatcher.get());
  // A convex shape meets a plane in up to four points at once, as ODE's box-plane test gives them.
  // Bullet's default finds one (the deepest vertex) per step: a box landing flat took its whole
  // impact on one corner, which tipped it over and threw it 14 cm back up from a 1 m drop. With
  // three perturbed queries (Bullet's own multipoint option, asked only near the plane:
  // plane_contact.h) all four corners are in the manifold from the first step of contact.
  registerPlaneContact(*w.dispatcher);
  registerWheelContact(*w.dispatcher);
  registerCapsuleContact(*w.dispatcher);  // ODE's two end points, where Bullet's test gives one end or the other
  w.broadphase.reset(new btDbvtBroadphase());
  auto* solver = new DenseRowSolver();
  solver->setMaxCorrectingVelocity(btScalar(description.contact_max_correcting_vel));
  w.solver.reset(solver);
  w.dynamics.reset(new DynamicsWorld(w.dispatcher.get(), w.broadphase.get(), solver, w.collision_config.get()));
  // A box or a moving mesh (their faces: collision_shapes.h) on a static mesh's triangle touches it
  // in up to four points at once, the face clipped against the triangle (Bullet's polyhedral
  // clipping, asked by its SAT option). With GJK's one point a step a box landed on a corner and
  // rocked on a mesh floor for ever (0.05 rad, never asleep) where on a plane or a box it settled.
  w.dynamics->getDispatchInfo().m_enableSatConvex = true;
  const urdf::Vector3& g = description.gravity;
  w.dynamics->setGravity(toBullet(g));
  btContactSolverInfo& info = w.dynamics->getSolverInfo();
  // Ten passes: with every row warm started (DenseRowSolver) the car creeps 0.15 mm in 10 s at
  // rest; Bullet's cold-started friction needed twenty passes for 0.45 mm.
  info.m_numIterations = 10;
  // Pyramid friction, as ODE (Gazebo's default engine) uses; Bullet's default cone costs trigonometry per contact.
  info.m_solverMode |= SOLVER_DISABLE_IMPLICIT_CONE_FRICTION;
  // Correct position errors (joint limits, contact penetration) in the velocity solve. Bullet's
  // split impulse does not act on multibodies, which would leave joints up to 4 cm or rad past
  // their limits.
  info.m_splitImpulse = false;
  info.m_timeStep = btScalar(w.step_s);
  // The world's <physics><ode> where it gives them (world_description.h): ODE's quick step passes,
  // its over-relaxation (Bullet's m_sor scales each contact row's update as ODE's sor does) and the
  // depth contacts leave (Bullet's slop: a contact pushes only beyond it, as ODE's surface layer).
  if (description.solver_iterations > 0)
    info.m_numIterations = description.solver_iterations;
  if (description.sor > 0)
    info.m_sor = btScalar(description.sor);
  if (description.contact_surface_layer >= 0)
    info.m_linearSlop = btScalar(description.contact_surface_layer);

  for (const StaticCollision& c : description.collisions)
  {
    Collider collider = makeCollider(c.shape, Mobility::Static, c.pose, nullptr);
    if (!collider.shape)
    {
      w.log.warn("world: collision '" + c.name + "': mesh '" + c.shape.mesh_uri + "' " + collider.reason +
                 "; it is left out");
      continue;
    }
    w.static_shapes.push_back(std::move(collider.shape));
    w.static_objects.emplace_back(new btCollisionObject());
    w.static_names.push_back(c.name);
    w.static_object_models.push_back(c.model);
    btCollisionObject* object = w.static_objects.back().get();
    object->setCollisionShape(w.static_shapes.back().get());
    object->setWorldTransform(toBullet(c.pose));
    object->setFriction(btScalar(c.mu));
    w.solver->setBounce(*object, btScalar(c.restitution), btScalar(c.restitution_threshold));
    {
      // Its <surface> beyond one friction coefficient (<mu> is c.mu, said already where wrong).
      SurfaceDescription surface = c.surface;
      surface.mu1 = c.mu;
      bool plain = true;
      ContactSurface contact = contactSurface(surface, btMatrix3x3::getIdentity(), "world: collision '" + c.name + "'",
                                              w.log, plain);
      if (!plain)
        w.solver->setSurfaces(*object, {contact}, false);
    }
    correctInternalEdges(*object);
    w.dynamics->addCollisionObject(object, btBroadphaseProxy::StaticFilter,
                                   btBroadphaseProxy::AllFilter ^ btBroadphaseProxy::StaticFilter);
  }
  w.static_ray_shapes = staticRayShapes(description, &w.log);
  for (const StaticModelDescription& model : description.static_models)
    w.static_file_poses[model.name] = model.pose;
  for (const std::string& warning : description.warnings)
    w.log.warn("world: " + warning);
  for (const std::string& error : description.errors)
    w.log.error("world: " + error);
  if (description.lights.size() > Lighting::kMaxLights)
    w.log.warn("world: " + std::to_string(description.lights.size()) + " lights; each thing cameras see is lit by the " +
               std::to_string(Lighting::kMaxLights) + " nearest that reach it (OGRE's limit on one object, which "
               "Gazebo renders with)");
  // The models that move, as spawn_model would add them; one the plant refuses leaves the rest.
  w.loading_file = true;
  for (const ModelDescription& model : description.models)
    try
    {
      spawn(model.robot, model.name, model.pose);
    }
    catch (const std::exception& e)
    {
      w.log.error("world: model '" + model.name + "' is left out: " + e.what());
    }
  w.loading_file = false;
  // Gazebo loads a world's plugins once its models are in it.
  for (const WorldPluginDescription& plugin : description.plugins)
    w.gazeboHost().loadWorldPlugin(plugin);
}

World::~World()
{
  in_->gazebo_host.reset();  // the plugins go first: they hold the models
  for (auto& attachment : in_->attachments)
    in_->dynamics->removeMultiBodyConstraint(attachment.second.constraint.get());
  in_->attachments.clear();
  for (auto& robot : in_->robots)
    removeRobot(*robot->in_);
  in_->robots.clear();
  for (auto& object : in_->static_objects)
    in_->dynamics->removeCollisionObject(object.get());
}

const WorldDescription& World::description() const { return in_->description; }
Log& World::log() { return in_->log; }
Param& World::params() { return in_->params; }
double World::timeStep() const { return in_->step_s; }
int64_t World::timeStepNs() const { return in_->step_ns; }

int World::solverIterations() const { return in_->dynamics->getSolverInfo().m_numIterations; }
double World::solverRelaxation() const { return in_->dynamics->getSolverInfo().m_sor; }
double World::contactSurfaceLayer() const { return in_->dynamics->getSolverInfo().m_linearSlop; }
double World::contactMaxCorrectingVel() const { return in_->description.contact_max_correcting_vel; }

void World::setSolverSettings(int iterations, double relaxation, double surface_layer, double max_correcting_vel)
{
  if (!(iterations >= 1 && iterations <= kMaxSolverIterations))
    throw std::invalid_argument("sor_pgs_iters " + std::to_string(iterations) + " is not a number of solver passes "
                                "from 1 to " + std::to_string(kMaxSolverIterations));
  if (!(relaxation > 0 && relaxation < 2))
    throw std::invalid_argument("sor_pgs_w " + formatNumber(relaxation) + " is outside (0, 2), where over-relaxation "
                                "converges");
  if (!(surface_layer >= 0 && surface_layer <= 1))
    throw std::invalid_argument("contact_surface_layer " + formatNumber(surface_layer) + " is outside [0, 1] m");
  if (!(max_correcting_vel >= 0 && std::isfinite(max_correcting_vel)))
    throw std::invalid_argument("contact_max_correcting_vel " + formatNumber(max_correcting_vel) +
                                " is not a finite speed >= 0 m/s");
  btContactSolverInfo& info = in_->dynamics->getSolverInfo();
  info.m_numIterations = iterations;
  info.m_sor = btScalar(relaxation);
  info.m_linearSlop = btScalar(surface_layer);
  in_->description.contact_max_correcting_vel = max_correcting_vel;
  in_->solver->setMaxCorrectingVelocity(btScalar(max_correcting_vel));
}

void World::setTimeStep(double seconds)
{
  if (!(seconds >= kMinStepSize && seconds <= kMaxStepSize))
    throw std::invalid_argument("time step " + formatNumber(seconds) + " s is outside [" + formatNumber(kMinStepSize) +
                                ", " + formatNumber(kMaxStepSize) + "] s");
  in_->step_ns = std::llround(seconds * 1e9);
  in_->step_s = in_->step_ns * 1e-9;
  in_->dynamics->getSolverInfo().m_timeStep = btScalar(in_->step_s);
}

urdf::Vector3 World::gravity() const
{
  const btVector3 g = in_->dynamics->getGravity();
  return fromBullet(g);
}

void World::setGravity(const urdf::Vector3& g)
{
  if (!std::isfinite(g.x) || !std::isfinite(g.y) || !std::isfinite(g.z))
    throw std::invalid_argument("gravity must be finite");
  in_->dynamics->setGravity(toBullet(g));
  in_->wakeRobots();  // a body asleep at rest under the old gravity need not be under the new
}
int64_t World::timeNs() const { return in_->time_ns; }
double World::time() const { return in_->time_ns * 1e-9; }
uint64_t World::steps() const { return in_->steps; }

Robot& World::spawn(const std::string& model_xml, const std::string& name, const urdf::Pose& pose,
                    const std::string& robot_namespace, const std::map<std::string, double>& initial_joints)
{
  // gazebo_ros's spawn puts an SDF model's own <pose> in the spawn pose (updateSDFAttributes:
  // model_pose + initial pose); a URDF's is the identity.
  ModelDescription model = parseModelXml(model_xml);
  return spawn(std::move(model.robot), name, compose(pose, model.pose), robot_namespace, initial_joints);
}

Robot& World::spawn(RobotDescription description, const std::string& name, const urdf::Pose& pose,
                    const std::string& robot_namespace, const std::map<std::string, double>& initial_joints)
{
  if (name.empty())
    throw DescriptionError("a robot needs a name (spawn_model -model NAME)");
  // A world file may name a static model and a moving one alike (Gazebo's elevator.world names each
  // shaft as its car, and Gazebo loads both); a spawn afterwards may not take a name in use.
  if (robot(name) || (!in_->loading_file && staticModel(name)))
    throw DescriptionError("a model named '" + name + "' is already in the world; remove it or pick another -model name");
  for (double v : {pose.position.x, pose.position.y, pose.position.z, pose.rotation.x, pose.rotation.y,
                   pose.rotation.z, pose.rotation.w})
    if (!std::isfinite(v))
      throw DescriptionError("spawn pose of '" + name + "' is not finite");
  if (std::max({std::abs(pose.position.x), std::abs(pose.position.y), std::abs(pose.position.z)}) > kMaxLength)
  {
    std::ostringstream text;
    text << "spawn position of '" << name << "' " << pose.position.x << " " << pose.position.y << " " << pose.position.z
         << " is beyond " << kMaxLength << " m (the plant computes in single precision)";
    throw DescriptionError(text.str());
  }
  for (const auto& kv : initial_joints)
    if (!std::isfinite(kv.second))
      throw DescriptionError("initial position of joint '" + kv.first + "' is not finite");

  // A model of several trees: each tree's joints, and the trees apart (the canonical link's first).
  std::vector<RobotDescription> trees;
  trees.push_back(std::move(description));
  for (RobotDescription& other : trees.front().other_trees)
    trees.push_back(std::move(other));
  trees.front().other_trees.clear();
  std::vector<std::map<std::string, double>> tree_joints(trees.size());
  for (const auto& kv : initial_joints)
  {
    size_t t = 0;
    while (t < trees.size() && !trees[t].model->getJoint(kv.first))
      ++t;
    if (t == trees.size())
      throw DescriptionError("initial position given for joint '" + kv.first + "', which '" + name + "' does not have");
    tree_joints[t][kv.first] = kv.second;
  }
  const bool several_trees = trees.size() > 1;
  Robot& model = in_->addTree(std::move(trees.front()), name, pose, robot_namespace, tree_joints.front(), nullptr,
                              several_trees);
  try
  {
    for (size_t t = 1; t < trees.size(); ++t)
      internalsOf(model).other_trees.push_back(&in_->addTree(std::move(trees[t]), name, pose, robot_namespace,
                                                             tree_joints[t], &internalsOf(model), several_trees));
  }
  catch (...)
  {
    remove(name);
    throw;
  }
  return model;
}

Robot& World::Internals::addTree(RobotDescription description, const std::string& name, const urdf::Pose& pose,
                                 const std::string& robot_namespace,
                                 const std::map<std::string, double>& initial_joints, Robot::Internals* canonical,
                                 bool several_trees)
{
  std::unique_ptr<Robot::Internals> internals(new Robot::Internals);
  internals->world = this;
  internals->name = name;
  internals->canonical = canonical;
  internals->several_trees = several_trees;
  internals->description = std::move(description);
  const ControlPluginDescription& control = internals->description.control;
  internals->control_namespace = control.controlNamespace(robot_namespace);
  internals->spawn_namespace = robot_namespace;

  std::unique_ptr<Robot> robot(new Robot(std::move(internals)));
  Robot::Internals& r = internalsOf(*robot);
  try
  {
    buildRobot(r, pose, initial_joints);
  }
  catch (...)
  {
    removeRobot(r);  // takes back whatever was added to the dynamics world
    throw;
  }
  warnIfSpawnedInside(*this, r);
  robots.push_back(std::move(robot));
  loadModelPlugins(r);
  return *robots.back();
}

bool World::remove(const std::string& name)
{
  Robot* model = robot(name);
  if (!model)
    return in_->removeStaticModel(name);
  if (in_->frame_worker)
    in_->frame_worker->waitAll();  // its cameras' frames in the making write into them
  // The model's every tree (robots named as the model), its other trees first.
  std::vector<Robot::Internals*> trees;
  for (Robot* tree : model->in_->other_trees)
    trees.push_back(tree->in_.get());
  trees.push_back(model->in_.get());
  if (in_->gazebo_host)
    in_->gazebo_host->modelRemoved(name);  // before its model plugins go with it
  for (Robot::Internals* tree : trees)
  {
    in_->releaseAttachments(*tree);
    if (in_->ray_scene)
      in_->ray_scene->removeOwner(tree);
    if (in_->gl_scene)
      in_->gl_scene->removeOwner(tree);
    removeRobot(*tree);
    in_->robots.erase(std::find_if(in_->robots.begin(), in_->robots.end(),
                                   [tree](const std::unique_ptr<Robot>& r) { return r->in_.get() == tree; }));
  }
  in_->wakeRobots();  // what rested on it must fall
  return true;
}

void World::Internals::wakeRobots()
{
  for (auto& r : robots)
    if (!r->in_->disabled)
      wakeUp(*r->in_->multibody.bullet);
}

Robot* World::robot(const std::string& name)
{
  for (auto& r : in_->robots)
    if (r->name() == name && !r->in_->canonical)
      return r.get();
  return nullptr;
}

std::vector<Robot*> World::robots()
{
  std::vector<Robot*> out;
  for (auto& r : in_->robots)
    if (!r->in_->canonical)  // a model's other trees are its own (Robot::linkNames ...)
      out.push_back(r.get());
  return out;
}

// Gazebo's order: at world update begin each robot's due wrench and effort jobs, the controllers
// whose control period has come (gazebo_ros_control) and its model plugins; every robot's joint layer
// writes its commands (writeSim), one physics step, then each robot's state is checked and read back
// into its handles (readSim) and its sensors render what is due.
void World::step(int n)
{
  Internals& w = *in_;
  for (int i = 0; i < n; ++i)
  {
    // gazebo_ros's wrench and effort jobs first: its system plugin's world update begin callback
    // runs before any model's, so gazebo_ros_f3d (the plant's own or a Gazebo plugin built over
    // Link::WorldForce) sees apply_body_wrench's force.
    for (auto& r : w.robots)
      if (!r->in_->disabled && !r->in_->external_efforts.empty())
        r->in_->external_efforts.apply(r->in_->multibody, w.time_ns);
    if (w.gazebo_host)
      w.gazebo_host->beginStep();
    for (auto& r : w.robots)
      if (!r->in_->disabled)
      {
        r->in_->updateControllers(w.time_ns);
        r->in_->updateModelPlugins(w.time_ns);
      }
    for (auto& r : w.robots)
      if (!r->in_->disabled && !r->in_->asleep())
      {
        r->in_->joint_layer.writeSim(r->in_->multibody.joints, *r->in_->multibody.bullet, w.step_s);
        if (!r->in_->multibody.couplings.empty())
          r->in_->multibody.holdCouplings(w.step_s);
      }
    if (w.physics_enabled)
    {
      for (auto& r : w.robots)
        if (!r->in_->disabled && !r->in_->wrench_watches.empty())
          r->in_->wrench_watches.beforeStep(r->in_->multibody);
      if (!w.attachments.empty())
        w.applyAttachmentEfforts();
      w.dynamics->stepSimulation(btScalar(w.step_s), 0, btScalar(w.step_s));
      for (auto& r : w.robots)
        if (!r->in_->disabled && !r->in_->wrench_watches.empty())
          r->in_->wrench_watches.afterStep(r->in_->multibody, r->in_->name, btScalar(w.step_s),
                                           w.dynamics->getGravity(), *w.dispatcher);
    }
    w.time_ns += w.step_ns;
    ++w.steps;
    for (auto& r : w.robots)
      if (!r->in_->disabled && !r->in_->asleep())
      {
        recoverIfDiverged(*r->in_);
        r->in_->joint_layer.readSim(r->in_->multibody.joints, *r->in_->multibody.bullet, w.step_s);
      }
    for (auto& r : w.robots)
      if (!r->in_->disabled && !r->in_->asleep())
        r->in_->updateSensors(w.time_ns);
    if (w.gazebo_host)
      w.gazebo_host->endStep();
    if (w.insertions_queued.load(std::memory_order_relaxed))
      w.insertQueuedModels();
  }
  if (!w.frames_ahead)
    w.collectFrames();
  if (!w.lockstep)
    w.reportSkippedFrames();
}

void World::insertModel(const std::string& sdf_xml)
{
  ModelInserter inserter;
  {
    std::lock_guard<std::mutex> lock(in_->insertion_mutex);
    if (!in_->model_inserter)
    {
      in_->insertions.push_back(sdf_xml);
      in_->insertions_queued = true;
      return;
    }
    inserter = in_->model_inserter;
  }
  inserter(sdf_xml);  // not under the lock: the node's reads the model and asks ROS for parameters
}

void World::setModelInserter(ModelInserter inserter)
{
  std::vector<std::string> queued;
  {
    std::lock_guard<std::mutex> lock(in_->insertion_mutex);
    in_->model_inserter = inserter;
    queued.swap(in_->insertions);
    in_->insertions_queued = false;
  }
  for (const std::string& xml : queued)
    inserter ? inserter(xml) : insertModel(xml);
}

std::string World::uniqueModelName(const std::string& name)
{
  std::string unique = name;
  for (int i = 0; robot(unique) || staticModel(unique); ++i)
    unique = name + "_" + std::to_string(i);
  return unique;
}

void World::Internals::insertQueuedModels()
{
  std::vector<std::string> queued;
  {
    std::lock_guard<std::mutex> lock(insertion_mutex);
    queued.swap(insertions);
    insertions_queued = false;
  }
  for (const std::string& xml : queued)
    try
    {
      ModelDescription model = readInsertedModel(xml);
      const std::string name = self->uniqueModelName(model.name);
      self->spawn(std::move(model.robot), name, model.pose);
      log.info("inserted model '" + name + "' (a Gazebo plugin's World::InsertModel)");
    }
    catch (const std::exception& e)
    {
      log.error(std::string("a model a Gazebo plugin inserted (World::InsertModelString, InsertModelFile or "
                            "InsertModelSDF): ") + e.what() + "; the world goes on without it");
    }
}

bool World::framesAhead() const { return in_->frames_ahead; }

bool World::lockstep() const { return in_->lockstep; }

void World::setLockstep(bool lockstep) { in_->lockstep = lockstep; }

void World::prepareCameras()
{
  for (auto& r : in_->robots)
    for (auto& sensor : r->in_->sensors)
      if (dynamic_cast<const Camera*>(sensor.get()))
      {
        in_->glScene();
        return;
      }
}

void World::Internals::reportSkippedFrames()
{
  constexpr auto kReportPeriod = std::chrono::seconds(60);
  const auto now = std::chrono::steady_clock::now();
  if (next_skip_report == std::chrono::steady_clock::time_point{})
    next_skip_report = now + kReportPeriod;
  if (now < next_skip_report)
    return;
  next_skip_report = now + kReportPeriod;
  std::map<const Sensor*, uint64_t> reported_now;  // the sensors there are now (robots come and go)
  for (auto& r : robots)
    for (auto& sensor : r->in_->sensors)
    {
      const auto before = skipped_reported.find(sensor.get());
      const uint64_t reported =
          before != skipped_reported.end() && before->second <= sensor->skipped() ? before->second : 0;
      reported_now[sensor.get()] = sensor->skipped();
      if (sensor->skipped() > reported)
        log.info("camera '" + sensor->name() + "' of '" + r->name() + "': " +
                 std::to_string(sensor->skipped() - reported) +
                 " frames skipped in the last minute: each was due while the one before it was still rendering (the "
                 "simulation does not wait for a camera out of lockstep; gzserver --lockstep renders every frame)");
    }
  skipped_reported.swap(reported_now);
}

void World::setFramesAhead(bool ahead)
{
  in_->frames_ahead = ahead;
  if (!ahead)
    in_->collectFrames();
}

void World::setNoiseSeed(uint32_t seed) { in_->noise_seed = seed; }
uint32_t World::noiseSeed() const { return in_->noise_seed; }

void World::setPaused(bool paused)
{
  in_->paused = paused;
  for (auto& r : in_->robots)
    if (ControllerManager* cm = r->controllerManager())
      cm->setPaused(paused);
}

bool World::paused() const { return in_->paused; }

void World::resetSimulation()
{
  in_->collectFrames();  // the frames of before, before time goes back
  in_->time_ns = 0;
  for (auto& r : in_->robots)
    r->in_->resetToSpawn();
  in_->resetStaticModels();
  if (in_->gazebo_host)
    in_->gazebo_host->reset(true);
}

void World::resetWorld()
{
  for (auto& r : in_->robots)
    r->in_->resetToSpawn();
  in_->resetStaticModels();
  if (in_->gazebo_host)
    in_->gazebo_host->reset(false);
}

bool World::loadSystemPlugin(const std::string& filename, const std::vector<std::string>& arguments)
{
  return in_->gazeboHost().loadSystemPlugin(filename, arguments);
}

GazeboHost& World::Internals::gazeboHost()
{
  if (!gazebo_host)
  {
    gazebo_context.reset(new PlantWorldPluginContext(*self, *this));
    gazebo_host = createGazeboHost(*gazebo_context);
  }
  return *gazebo_host;
}

namespace
{
// The robot (one tree of a model) whose body holds `link`, and that body; null for none.
Robot::Internals* treeOfLink(Robot& model, const std::string& link, int& body)
{
  std::vector<Robot*> trees{&model};
  trees.insert(trees.end(), internalsOf(model).other_trees.begin(), internalsOf(model).other_trees.end());
  for (Robot* tree : trees)
  {
    Robot::Internals& r = internalsOf(*tree);
    auto found = r.multibody.link_in_body.find(link);
    if (found != r.multibody.link_in_body.end())
    {
      body = found->second.first;
      return &r;
    }
  }
  return nullptr;
}
}  // namespace

int World::Internals::attach(const RunTimeJoint& joint)
{
  const bool to_world = joint.parent_model.empty();
  const std::string parent_name = to_world ? "the world" : joint.parent_model + "::" + joint.parent_link;
  const std::string what = "a joint made at run time from " + parent_name + " to " + joint.child_model + "::" +
                           joint.child_link;
  Robot* parent = to_world ? nullptr : self->robot(joint.parent_model);
  Robot* child = self->robot(joint.child_model);
  if ((!to_world && !parent) || !child)
  {
    log.error(what + ": there is no model '" + (child ? joint.parent_model : joint.child_model) +
              "' that moves; nothing is attached");
    return -1;
  }
  int parent_body = 0, child_body = 0;
  Robot::Internals* a = to_world ? nullptr : treeOfLink(*parent, joint.parent_link, parent_body);
  Robot::Internals* b = treeOfLink(*child, joint.child_link, child_body);
  if ((!to_world && !a) || !b)
  {
    log.error(what + ": model '" + (b ? joint.parent_model : joint.child_model) + "' has no link '" +
              (b ? joint.parent_link : joint.child_link) + "'; nothing is attached");
    return -1;
  }
  if (a == b && parent_body == child_body)
  {
    log.error(what + ": both links are one body; nothing is attached");
    return -1;
  }
  const btVector3 anchor = toBullet(joint.anchor), axis = toBullet(joint.axis);
  const bool moves = joint.type == RunTimeJoint::Type::Prismatic || joint.type == RunTimeJoint::Type::Revolute;
  auto finite = [](const btVector3& v) { return std::isfinite(v.x()) && std::isfinite(v.y()) && std::isfinite(v.z()); };
  if (!finite(anchor))
  {
    log.error(what + ": its anchor is not finite; nothing is attached");
    return -1;
  }
  if (moves && (!finite(axis) || axis.fuzzyZero()))
  {
    log.error(what + ": its axis is zero or not finite; nothing is attached");
    return -1;
  }
  if (std::isnan(joint.lower) || std::isnan(joint.upper) || joint.lower > joint.upper || !(joint.damping >= 0) ||
      !(joint.effort_limit >= 0))
  {
    log.error(what + ": its limits (" + std::to_string(joint.lower) + " to " + std::to_string(joint.upper) +
              "), damping or effort limit are not a range, or negative; nothing is attached");
    return -1;
  }
  // The child is the constraint's body A (Bullet's multibody constraints need one there), the
  // parent B, or the world.
  Attachment attachment;
  attachment.constraint.reset(new RunTimeJointConstraint(joint.type, b->multibody.bullet.get(), child_body - 1,
                                                         a ? a->multibody.bullet.get() : nullptr, parent_body - 1,
                                                         anchor, axis));
  attachment.constraint->setLimits(btScalar(joint.lower), btScalar(joint.upper));
  attachment.parent = a;
  attachment.child = b;
  attachment.damping = joint.damping;
  attachment.effort_limit = joint.effort_limit;
  dynamics->addMultiBodyConstraint(attachment.constraint.get());
  if (a)
    wakeUp(*a->multibody.bullet);
  wakeUp(*b->multibody.bullet);
  const int id = next_attachment++;
  attachments[id] = std::move(attachment);
  return id;
}

const World::Internals::Attachment* World::Internals::attachment(int id) const
{
  auto found = attachments.find(id);
  return found == attachments.end() ? nullptr : &found->second;
}

void World::Internals::applyAttachmentEfforts()
{
  for (auto& [id, joint] : attachments)
  {
    if (joint.effort == 0.0 && joint.damping == 0.0)
      continue;
    // Gazebo holds an effort set to the joint's effort limit; the damping, explicit, comes on top.
    const double held = std::max(-joint.effort_limit, std::min(joint.effort_limit, joint.effort));
    const double effort = held - joint.damping * joint.constraint->velocity();
    joint.effort = 0.0;
    if (effort == 0.0)
      continue;
    joint.constraint->applyEffort(btScalar(effort));
    if (joint.parent)
      wakeUp(*const_cast<Robot::Internals*>(joint.parent)->multibody.bullet);
    wakeUp(*const_cast<Robot::Internals*>(joint.child)->multibody.bullet);
  }
}

void World::Internals::detach(int attachment)
{
  auto found = attachments.find(attachment);
  if (found == attachments.end())
    return;  // released already, with a model that left the world
  dynamics->removeMultiBodyConstraint(found->second.constraint.get());
  if (found->second.parent)
    wakeUp(*const_cast<Robot::Internals*>(found->second.parent)->multibody.bullet);
  wakeUp(*const_cast<Robot::Internals*>(found->second.child)->multibody.bullet);
  attachments.erase(found);
}

void World::Internals::releaseAttachments(const Robot::Internals& robot)
{
  for (auto it = attachments.begin(); it != attachments.end();)
  {
    if (it->second.parent == &robot || it->second.child == &robot)
    {
      dynamics->removeMultiBodyConstraint(it->second.constraint.get());
      it = attachments.erase(it);
    }
    else
      ++it;
  }
}

namespace
{
// Every robot's bodies in a sensor scene (RayScene or GlScene): added the first time (their
// handles kept in the robot's `handles`), then at their poses now.
template <class Scene>
void placeBodies(Scene& scene, const std::vector<std::unique_ptr<Robot>>& robots, std::vector<int> Robot::Internals::*handles)
{
  for (const auto& robot : robots)
  {
    Robot::Internals& r = internalsOf(*robot);
    std::vector<int>& in_scene = r.*handles;
    const std::vector<Body>& bodies = r.multibody.bodies;
    if (in_scene.size() != bodies.size())
    {
      in_scene.assign(bodies.size(), -1);
      for (size_t b = 0; b < bodies.size(); ++b)
        if (!bodies[b].ray_shapes.empty())
          in_scene[b] = scene.addBody(&r, bodies[b].ray_shapes);
    }
    for (size_t b = 0; b < bodies.size(); ++b)
      if (in_scene[b] >= 0)
        scene.setPose(in_scene[b], Frame::fromPose(fromBullet(r.multibody.bodyWorldTransform(int(b)))));
  }
}
}  // namespace

const RayScene& World::Internals::rayScene(const void* hidden)
{
  if (!ray_scene)
  {
    ray_scene.reset(new RayScene(static_ray_shapes));
    const EmbreeIsa& isa = ray_scene->isa();
    if (!isa.problem.empty())
      log.warn("sensors: " + isa.problem);
    else if (isa.forced)
      log.info(std::string("sensors: rays cast with Embree's ") + isa.name + " kernels (" + kEmbreeIsaVariable + ")");
  }
  placeBodies(*ray_scene, robots, &Robot::Internals::ray_bodies);
  ray_scene->commit(hidden);
  return *ray_scene;
}

GlScene* World::Internals::glScene()
{
  if (!gl_tried)
  {
    gl_tried = true;
    std::string problem;
    const GlDevice device = glDeviceFromEnvironment(problem);
    if (!problem.empty())
      log.warn("cameras: " + problem);
    problem.clear();
    gl_context = GlContext::create(device, problem);
    if (gl_context)
      try
      {
        gl_scene.reset(new GlScene(*gl_context, static_ray_shapes));
        frame_worker.reset(new FrameWorker);
        log.info("cameras: OpenGL ES on " + gl_context->renderer());
      }
      catch (const std::exception& e)
      {
        problem = e.what();
        gl_context.reset();
      }
    if (!gl_scene)
      log.warn("cameras: off, no OpenGL (" + problem + "): camera sensors give no frames; every other sensor runs");
  }
  if (!gl_scene)
    return nullptr;
  placeBodies(*gl_scene, robots, &Robot::Internals::gl_bodies);
  return gl_scene.get();
}

void World::Internals::collectFrames()
{
  for (auto& r : robots)
    for (auto& sensor : r->in_->sensors)
      sensor->collect(true);
}

Lighting World::Internals::lighting() const
{
  return Lighting::of(description.lights, description.ambient, description.background, description.shadows);
}

std::vector<Contact> World::contacts() const
{
  std::vector<Contact> contacts;
  const btScalar per_step = btScalar(1.0 / in_->step_s);
  btDispatcher& dispatcher = *in_->dispatcher;
  for (int m = 0; m < dispatcher.getNumManifolds(); ++m)
  {
    const btPersistentManifold& manifold = *dispatcher.getManifoldByIndexInternal(m);
    for (int p = 0; p < manifold.getNumContacts(); ++p)
    {
      const btManifoldPoint& point = manifold.getContactPoint(p);
      if (!touching(point))
        continue;
      Contact contact;
      contact.collision1 = in_->collisionNameOf(manifold.getBody0(), point.m_index0);
      contact.collision2 = in_->collisionNameOf(manifold.getBody1(), point.m_index1);
      contact.position = fromBullet(point.getPositionWorldOnA());
      contact.normal = fromBullet(point.m_normalWorldOnB);
      contact.force = fromBullet(per_step * impulseOnA(point));
      contact.depth = -point.getDistance();
      contacts.push_back(std::move(contact));
    }
  }
  return contacts;
}

double World::castRay(const urdf::Vector3& origin, const urdf::Vector3& dir, double max_range, const Robot* exclude) const
{
  const RayScene& scene = in_->rayScene(exclude ? exclude->in_.get() : nullptr);
  double o[3] = {origin.x, origin.y, origin.z};
  double norm = std::sqrt(dir.x * dir.x + dir.y * dir.y + dir.z * dir.z);
  if (!(norm > 0) || !std::isfinite(norm))
    return std::numeric_limits<double>::infinity();
  double d[3] = {dir.x / norm, dir.y / norm, dir.z / norm};
  return scene.cast(o, d, max_range, kSeenByLidars);
}

}  // namespace bullet_plant
