// The plant as a ROS node, as gzserver hosts gazebo_ros: the world, the simulation loop and its
// pacing, /clock, pausing, resetting, spawning and removing. What runs around it attaches as
// Gazebo's plugins do, through events: each robot's model plugins (RobotInterface: gazebo_ros_control
// and the sensor plugins) are loaded when it spawns, or at start for the world file's models, and
// updated after every step; system plugins
// (GazeboRosApiPlugin) connect to the end of each step. main.cpp wires them. ROS callbacks never
// touch the world: they queue work that the simulation thread runs between steps, and wait for its
// result when they must answer.
#pragma once

#include <atomic>
#include <condition_variable>
#include <deque>
#include <functional>
#include <future>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include <ros/ros.h>

#include "bullet_plant/rate_gate.h"
#include "bullet_plant/sdf_model.h"
#include "bullet_plant/world.h"
#include "outbox.h"

namespace bullet_plant
{
// One robot's model plugins as the plant drives them (RobotInterface), on the simulation thread.
class ModelPlugins
{
public:
  virtual ~ModelPlugins() = default;
  // Sensors compute only while someone subscribes: asked now and then, not every step.
  virtual void updateSubscriptions() = 0;
  // After each step (Gazebo's world update end).
  virtual void OnUpdate(int64_t time_ns) = 0;
};

class RosPlant;
// Loads a robot's model plugins as it spawns; an exception refuses the robot (no half of it can run).
using ModelPluginLoader = std::function<std::unique_ptr<ModelPlugins>(RosPlant&, Robot&)>;

class RosPlant
{
public:
  RosPlant(ros::NodeHandle& nh, ros::NodeHandle& private_nh, ModelPluginLoader load_model_plugins);
  ~RosPlant();
  // The simulation loop; returns when ROS shuts down.
  void run();

  // For ROS callbacks: runs `work` on the simulation thread and waits for its result.
  template <class Result>
  Result onSimThread(std::function<Result()> work);
  // For ROS callbacks: queues `work` for the simulation thread without waiting.
  void post(std::function<void()> work);
  // Copies `key` of the ROS parameter server (or its absence) into the world's parameter tree
  // before any work queued after this call runs.
  void copyParams(const std::string& key);
  // Gazebo's ConnectWorldUpdateEnd: `callback` runs on the simulation thread after every step.
  void connectWorldUpdateEnd(std::function<void()> callback);

  // On the simulation thread (the services' work, posted there).
  World& world() { return *world_; }
  // Where everything the node publishes after a step goes (~publishing_threads).
  Outbox& outbox() { return *outbox_; }
  // Paused, /clock says at once where the simulation stopped.
  void applyPaused(bool paused);
  // gzclient's step button (Gazebo's WorldControl multi_step): while paused, `iterations` more
  // steps at the world's pace, each publishing as any step does, then /clock at once whatever its
  // rate so that the stepper sees the time it reached. Ignored, with a warning, while running.
  void requestSteps(uint32_t iterations);
  // In the world update end callbacks: whether this step is the last a requestSteps asked for (what
  // a stepper waits to see).
  bool lastRequestedStep() const { return paused_ && steps_requested_ == 0; }
  void resetSimulation();
  double realTimeFactor() const { return real_time_factor_; }
  void setRealTimeFactor(double factor);
  // From a ROS callback (they wait on the simulation thread): false with the reason in `message`.
  // `model_xml`: URDF or SDF (readSpawnedModel), named `name` whatever it calls itself; `pose` places
  // its model frame as gazebo_ros does (SDF: the model's own <pose> taken relative to it).
  bool spawn(const std::string& name, const std::string& model_xml, const std::string& ns, const urdf::Pose& pose,
             const std::map<std::string, double>& joints, std::string& message);
  bool remove(const std::string& name, std::string& message);
  // Gazebo's factory (a plugin's World::InsertModelString, InsertModelFile, InsertModelSDF; the
  // world's model inserter), from any thread: read and its parameters copied now, added on the
  // simulation thread between steps, paused or not, as spawn adds a model, under its own name made
  // unique as Gazebo's world makes it (NAME_0, NAME_1 ...). What cannot be read or added is an error.
  void insertModel(const std::string& sdf_xml);
  // Gazebo's model events as gazebo_ros's scene follows them: `callback` runs on the simulation
  // thread after a model came (spawn, insertModel) or went (remove).
  void connectModelsChanged(std::function<void()> callback);

private:
  // A model read for spawn and insertModel, its parameters copied: what the simulation thread adds.
  struct SpawnRequest
  {
    std::string name;
    RobotDescription description;
    urdf::Pose pose;
    std::string ns;
    std::map<std::string, double> joints;
    std::string control_ns;  // where its controllers' parameters are
  };
  // The model read (readSpawnedModel, readInsertedModel), placed, and the parameters its controllers
  // and plugins read copied (`name` empty: the model's own); throws naming what is wrong. Any thread.
  SpawnRequest prepareSpawn(const std::string& name, ModelDescription model, const std::string& ns,
                            const urdf::Pose& pose, const std::map<std::string, double>& joints);
  // On the simulation thread: the model added and its plugins loaded; false with why in `message`.
  bool addModel(SpawnRequest& request, std::string& message);
  // The world file's models, which the World spawned as it was made: their model plugins, as spawn's.
  void loadWorldModels();
  // A robot just added: its model plugins; throws (the robot taken out again) when they cannot load.
  void loadModelPlugins(Robot& robot);
  void runQueuedWork();
  void stepAndPublish();
  void publishClock(bool force = false);
  bool stepping() const { return !paused_ || steps_requested_ > 0; }
  void publishStatus();
  void pace();

  ros::NodeHandle nh_, private_nh_;
  std::unique_ptr<Outbox> outbox_;  // before the plugins that publish into it: it goes after them
  std::unique_ptr<World> world_;
  ModelPluginLoader load_model_plugins_;
  std::map<std::string, std::unique_ptr<ModelPlugins>> robots_;
  std::vector<std::function<void()>> world_update_end_;
  std::vector<std::function<void()>> models_changed_;
  ros::Publisher clock_pub_;

  std::mutex queue_mutex_;
  std::condition_variable queue_cv_;
  std::deque<std::function<void()>> queue_;

  std::atomic<bool> paused_{false};
  uint64_t steps_requested_ = 0;  // left of requestSteps' while paused
  double real_time_factor_ = 1.0;
  uint64_t iterations_ = 0;  // ~iterations: steps to simulate before stopping (0: until shut down)
  RateGate clock_gate_;  // pub_clock_frequency
  ros::WallTime pace_start_wall_;
  int64_t pace_start_sim_ns_ = 0;
  ros::WallTime last_status_;
  int64_t status_start_sim_ns_ = 0;
};

template <class Result>
Result RosPlant::onSimThread(std::function<Result()> work)
{
  auto task = std::make_shared<std::packaged_task<Result()>>(std::move(work));
  std::future<Result> result = task->get_future();
  post([task] { (*task)(); });
  return result.get();
}

}  // namespace bullet_plant
