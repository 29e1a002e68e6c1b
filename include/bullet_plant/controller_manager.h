// controller_manager::ControllerManager's semantics (docs/interfaces.md section 2) for one robot:
// load, switch, unload, list, list types, reload, with the same states, resource rules and error
// texts. Service calls from the ROS node and Python land here; update() runs in the control loop.
// It sees the robot only through its joint handles (hardware_interface.h).
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "bullet_plant/controllers.h"

namespace bullet_plant
{
class Param;
class Log;

// A loaded controller's place in its lifecycle: load -> Initialized, a switch starts it (Running) or
// stops it (Stopped), unload removes it (only when not Running).
enum class ControllerState { Initialized, Running, Stopped };

// The state as controller_manager_msgs/ControllerState.state has it: "initialized", "running",
// "stopped" (docs/interfaces.md section 1).
const char* controllerStateName(ControllerState state);

struct ControllerInfo
{
  std::string name;
  ControllerState state;
  std::string type;
  std::vector<ClaimedResources> claimed_resources;
};

class ControllerManager
{
public:
  enum Strictness { BEST_EFFORT = 1, STRICT = 2 };

  ControllerManager(JointHandles& joints, const Param& params, Log& log, std::string ns);
  ~ControllerManager();
  ControllerManager(const ControllerManager&) = delete;
  ControllerManager& operator=(const ControllerManager&) = delete;

  const std::string& ns() const { return ns_; }
  // While the world is paused a switch is applied at once (the real manager would wait for a
  // control update that never comes).
  void setPaused(bool paused) { paused_ = paused; }

  bool loadController(const std::string& name);
  bool unloadController(const std::string& name);
  // Validates at once; the change itself happens after the next control update's controller
  // updates (applyPendingSwitch), or at once when the world is not stepping (paused).
  bool switchController(const std::vector<std::string>& start, const std::vector<std::string>& stop,
                        int strictness, bool start_asap = false, double timeout = 0.0);
  bool switchPending() const { return pending_; }
  std::vector<ControllerInfo> listControllers() const;
  std::vector<std::string> listControllerTypes() const;
  bool reloadControllerLibraries(bool force_kill);

  Controller* controller(const std::string& name);
  // Whether a running controller satisfies the predicate (no copies: the node asks after every step).
  bool anyRunning(const std::function<bool(const Controller&)>& predicate) const;
  std::vector<std::string> controllerNames() const;

  // The control loop: update running controllers in load order, then apply a pending switch.
  void update(int64_t time_ns, double period);
  void applyPendingSwitch(int64_t time_ns);
  // Simulation reset: running controllers are stopped and started again (as gazebo_ros_control does).
  void reset(int64_t time_ns);

private:
  struct Entry;
  Entry* find(const std::string& name);
  const Entry* find(const std::string& name) const;

  JointHandles& joints_;
  const Param& params_;
  Log& log_;
  std::string ns_;
  std::vector<std::unique_ptr<Entry>> entries_;  // load order
  bool pending_ = false;
  std::vector<std::string> pending_start_, pending_stop_;
  int64_t last_time_ns_ = 0;
  bool paused_ = false;
};

}  // namespace bullet_plant
