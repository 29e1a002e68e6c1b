// The simulated world: static scenery and moving models from SDF, robots from URDF or SDF, fixed-step
// Bullet physics.
// Deterministic: the same description, spawns and commands give bit-identical trajectories.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "bullet_plant/log.h"
#include "bullet_plant/params.h"
#include "bullet_plant/robot.h"
#include "bullet_plant/world_description.h"

namespace bullet_plant
{
// A point where two collisions touch ("model::link::collision" each, as Gazebo names them), in the
// world: the normal points out of collision2 into collision1, depth > 0 is penetration, and force
// is what the last step's solver pushed collision1 with (normal and friction; collision2 got the
// opposite).
struct Contact
{
  std::string collision1, collision2;
  urdf::Vector3 position, normal, force;
  double depth = 0;
};

// One of the world's lights as gazebo_ros's light services reach it (World::light, setLight): a
// directional light (a sun), a point or a spot light, which cameras render as world_description.h
// says (a directional light is not attenuated; only the first directional light that casts shadows
// draws them).
struct WorldLight
{
  bool directional = false;
  LightDescription light;     // name, colours, attenuation; position and direction in the world
  bool cast_shadows = false;  // light.cast_shadows, as gazebo_msgs/Light has it
};

class World
{
public:
  // `sink`: where the world's messages go from its first on (the models of the description it
  // spawns while built say theirs); without one, stderr until log().setSink.
  explicit World(const WorldDescription& description = emptyWorldDescription(), LogSink sink = nullptr);
  ~World();
  World(const World&) = delete;
  World& operator=(const World&) = delete;

  const WorldDescription& description() const;
  Log& log();
  // Parameter tree read at spawn time (NS/gazebo_ros_control/pid_gains/<joint>/...): the node's
  // copy of the parameter server.
  Param& params();

  // The seed of the noise of the sensors of robots spawned from now on, with the robot's and the
  // sensor's names: 0 (the default) seeds by the names alone, the same in every world. A learning
  // environment sets one per episode, from its own seed.
  void setNoiseSeed(uint32_t seed);
  uint32_t noiseSeed() const;

  double timeStep() const;        // s, the SDF's max_step_size
  int64_t timeStepNs() const;     // the same in ns, as the clock counts it
  // gazebo_ros's set_physics_properties: a new step (throws std::invalid_argument outside
  // [1e-9, 0.1] s, naming the value) and gravity (m/s^2, world frame), from the next step on.
  void setTimeStep(double seconds);
  urdf::Vector3 gravity() const;
  void setGravity(const urdf::Vector3& gravity);
  // The constraint solver's passes per step (get_physics_properties' sor_pgs_iters), its contact
  // rows' over-relaxation (sor_pgs_w) and the depth its contacts leave, m (contact_surface_layer).
  int solverIterations() const;
  double solverRelaxation() const;
  double contactSurfaceLayer() const;
  // The fastest a contact pushes a penetration out, m/s (contact_max_correcting_vel).
  double contactMaxCorrectingVel() const;
  // set_physics_properties' ODE settings the solver has, from the next step on: passes (1 ..
  // kMaxSolverIterations), over-relaxation (strictly between 0 and 2), surface layer (0 .. 1 m) and
  // max correcting velocity (>= 0 m/s), the ranges a world file's <physics><ode> takes. Throws
  // std::invalid_argument naming the first value out of range; nothing is changed then.
  void setSolverSettings(int iterations, double relaxation, double surface_layer, double max_correcting_vel);
  int64_t timeNs() const;         // simulated time
  double time() const;
  uint64_t steps() const;

  // Adds a model from URDF or SDF text (parseModelXml), its model frame (URDF: the root link) at
  // pose. robot_namespace is the spawn namespace (spawn_model -robot_namespace); initial_joints sets
  // joint positions (-J). Throws DescriptionError (bad URDF or SDF, transmission naming a missing
  // joint, duplicate name); the world is unchanged then.
  Robot& spawn(const std::string& model_xml, const std::string& name, const urdf::Pose& pose,
               const std::string& robot_namespace = "",
               const std::map<std::string, double>& initial_joints = {});
  // The same from a description already parsed (parseRobotDescription), e.g. by a caller that
  // reads its control namespace first.
  Robot& spawn(RobotDescription description, const std::string& name, const urdf::Pose& pose,
               const std::string& robot_namespace = "",
               const std::map<std::string, double>& initial_joints = {});
  // Gazebo's factory: a model a Gazebo plugin asks for (World::InsertModelString, InsertModelFile,
  // InsertModelSDF), as SDF text readInsertedModel reads, from any thread. It comes between steps, as
  // Gazebo's world adds it after its next update, under its own <model name> made unique as Gazebo
  // makes it (uniqueModelName), where its <pose> puts it: through the model inserter where one is set
  // (the node's, which loads its plugins as a spawn's, paused or not), otherwise at the end of the
  // step in progress or the next. One that cannot be read or added is an error in the log, naming
  // why; the world goes on.
  void insertModel(const std::string& sdf_xml);
  using ModelInserter = std::function<void(const std::string& sdf_xml)>;
  // The inserter takes the insertions over, those queued so far first.
  void setModelInserter(ModelInserter inserter);
  // `name` where no model has it, else Gazebo's World::UniqueModelName: NAME_0, NAME_1 ...
  std::string uniqueModelName(const std::string& name);
  // Takes out the model `name`: a robot, or one of the world's static models (its collisions, and what
  // lidars and cameras see of it); false for no such model.
  bool remove(const std::string& name);
  Robot* robot(const std::string& name);
  std::vector<Robot*> robots();

  // The world file's static models (Gazebo's models that never move: the ground plane, a building's
  // walls, a goal marker) where they are now, in file order: models as gazebo_ros has them beside the
  // robots (description().static_models; their links' poses follow the model's).
  const std::vector<StaticModelDescription>& staticModels() const;
  const StaticModelDescription* staticModel(const std::string& name) const;
  // set_model_state on a static model: a teleport (Gazebo moves a static model so), its links,
  // collisions and what sensors and the viewer see of it moved with its model frame to `pose`; what
  // rests on it wakes. False for no such model; throws std::invalid_argument for a pose that is not
  // finite.
  bool moveStaticModel(const std::string& name, const urdf::Pose& pose);

  // n physics steps. Camera frames due on the way render on a thread of their own while the
  // following steps run (each from the bodies' poses at its own time); step returns once they are
  // all done, unless frames ahead are allowed.
  void step(int n = 1);
  // With `ahead`, step returns without waiting for frames still rendering: each becomes its camera's
  // latest (Sensor::updates counts it) at a later step, once done. The node runs so; the Python
  // module and the tests see every frame due by the time step returns.
  void setFramesAhead(bool ahead);
  bool framesAhead() const;
  // Lockstep (the default, as the Python module and the tests run): every camera frame due renders,
  // and a step that makes a frame due waits for that camera's previous one (Gazebo's --lockstep).
  // Out of it (the node, as Gazebo runs by default): a frame due while its camera's previous one is
  // still rendering is skipped (Sensor::skipped counts it) and the simulation goes on; the skipped
  // frames are said in the log once a minute.
  void setLockstep(bool lockstep);
  bool lockstep() const;
  // Builds the cameras' scene now where a robot has a camera (the OpenGL context, the visuals'
  // meshes and their levels of detail), as Gazebo loads its rendering scene with the world: the first
  // frame asked for then costs a frame, not the scene's build (a second for a world of fine curved
  // shapes on llvmpipe). Without it the scene is built when the first frame is due.
  void prepareCameras();
  // Paused: the node stops stepping; controller switches then apply at once.
  void setPaused(bool paused);
  bool paused() const;
  // time to 0, robots to their spawn poses and joint positions, static models where the file put them
  void resetSimulation();
  void resetWorld();  // robots to their spawn poses, static models where the file put them; time goes on
  // gzserver -s FILE: a Gazebo system plugin of the user's own, found on the plugin paths, loaded
  // with `arguments` (gzserver's command line) as Gazebo's server loads it (gazebo_host.h); false
  // where it could not be (the log says why), and the world runs without it.
  bool loadSystemPlugin(const std::string& filename, const std::vector<std::string>& arguments);

  // The lights by name, gazebo_ros's get_light_properties, set_light_properties and delete_light:
  // the world's lights in file order (model://sun's where the world includes it). A change
  // shows in every camera frame rendered from then on. light: false for no such light. setLight
  // sets the light named light.light.name (its kind stays; a zero direction leaves the direction
  // as it was): false for no such light; throws std::invalid_argument naming a value that is not
  // finite or an attenuation that lights nothing (negative, or all three 0). removeLight: false
  // for no such light; without a directional light, cameras are lit by the scene's ambient light and
  // the point and spot lights alone.
  std::vector<std::string> lightNames() const;
  bool light(const std::string& name, WorldLight& out) const;
  bool setLight(const WorldLight& light);
  bool removeLight(const std::string& name);

  // Every contact at the end of the last step (what gzclient's contact view draws, Gazebo's
  // ~/physics/contacts), those of a pair of collisions one after the other.
  std::vector<Contact> contacts() const;

  // Ray casting against everything but `exclude` (may be null): distance along dir (unit) to the
  // first hit within max_range, or +inf.
  double castRay(const urdf::Vector3& origin, const urdf::Vector3& dir, double max_range,
                 const Robot* exclude) const;

  struct Internals;  // the plant's side, private to the library

private:
  std::unique_ptr<Internals> in_;
};

}  // namespace bullet_plant
