// The plant as a ROS node: what gazebo_ros offers around bullet_plant::World (the simulation loop
// and its pacing, /clock, the pause, reset, spawn and delete services), with one RobotInterface per
// robot for what gazebo_ros_control and the sensor plugins offer. ROS callbacks never touch the
// world: they queue work that the simulation thread runs between steps, and wait for its result
// when they must answer.
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

#include <ros/ros.h>

#include "bullet_plant/rate_gate.h"
#include "bullet_plant/world.h"

namespace bullet_plant
{
class GazeboRosApiPlugin;
class RobotInterface;

class RosPlant
{
public:
  RosPlant(ros::NodeHandle& nh, ros::NodeHandle& private_nh);
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

private:
  friend class GazeboRosApiPlugin;  // gazebo_ros's services: the world, spawning, pausing, pacing
  void runQueuedWork();

  void stepAndPublish();
  void publishClock();
  void publishStatus();
  void pace();
  void applyPaused(bool paused);
  void resetSimulation();
  void setRealTimeFactor(double factor);

  bool spawn(const std::string& name, const std::string& urdf, const std::string& ns, const urdf::Pose& pose,
             const std::map<std::string, double>& joints, std::string& message);
  bool remove(const std::string& name, std::string& message);

  ros::NodeHandle nh_, private_nh_;
  std::unique_ptr<World> world_;
  std::map<std::string, std::unique_ptr<RobotInterface>> robots_;
  std::unique_ptr<GazeboRosApiPlugin> gazebo_;
  ros::Publisher clock_pub_;

  std::mutex queue_mutex_;
  std::condition_variable queue_cv_;
  std::deque<std::function<void()>> queue_;

  std::atomic<bool> paused_{false};
  double real_time_factor_ = 1.0;
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
