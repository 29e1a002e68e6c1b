#include "bullet_plant/controller_manager.h"

#include <algorithm>
#include <map>
#include <set>

#include "bullet_plant/log.h"
#include "bullet_plant/params.h"

namespace bullet_plant
{
const char* controllerStateName(ControllerState state)
{
  switch (state)
  {
    case ControllerState::Initialized: return "initialized";
    case ControllerState::Running: return "running";
    case ControllerState::Stopped: return "stopped";
  }
  return "unknown";
}

struct ControllerManager::Entry
{
  std::string name, type;
  ControllerState state = ControllerState::Initialized;
  std::unique_ptr<Controller> controller;
  bool running() const { return state == ControllerState::Running; }
};

ControllerManager::ControllerManager(JointHandles& joints, const Param& params, Log& log, std::string ns)
  : joints_(joints), params_(params), log_(log), ns_(normaliseNamespace(ns))
{
}

ControllerManager::~ControllerManager() = default;

ControllerManager::Entry* ControllerManager::find(const std::string& name)
{
  for (auto& e : entries_)
    if (e->name == name)
      return e.get();
  return nullptr;
}

const ControllerManager::Entry* ControllerManager::find(const std::string& name) const
{
  return const_cast<ControllerManager*>(this)->find(name);
}

Controller* ControllerManager::controller(const std::string& name)
{
  Entry* e = find(name);
  return e ? e->controller.get() : nullptr;
}

bool ControllerManager::anyRunning(const std::function<bool(const Controller&)>& predicate) const
{
  for (const auto& e : entries_)
    if (e->running() && predicate(*e->controller))
      return true;
  return false;
}

std::vector<std::string> ControllerManager::controllerNames() const
{
  std::vector<std::string> names;
  for (const auto& e : entries_)
    names.push_back(e->name);
  return names;
}

bool ControllerManager::loadController(const std::string& name)
{
  if (find(name))
  {
    log_.error("A controller named '" + name + "' was already loaded inside the controller manager");
    return false;
  }
  const std::string controller_ns = ns_ + "/" + name;
  const Param* type = params_.find(joinPath(controller_ns, "type"));
  if (!type || type->type() != Param::Type::String)
  {
    log_.error("Could not load controller '" + name + "' because the type was not specified. Did you load the "
               "controller configuration on the parameter server (namespace: '" + controller_ns + "')?");
    return false;
  }
  std::unique_ptr<Controller> controller = createController(type->asString());
  if (!controller)
  {
    log_.error("Could not load controller '" + name + "' because controller type '" + type->asString() +
               "' does not exist.");
    log_.error("Use 'rosservice call controller_manager/list_controller_types' to get the available types");
    return false;
  }
  ControllerContext context{params_, controller_ns, joints_, log_};
  if (!controller->init(context))
  {
    log_.error("Initializing controller '" + name + "' failed");
    return false;
  }
  std::unique_ptr<Entry> entry(new Entry);
  entry->name = name;
  entry->type = type->asString();
  entry->controller = std::move(controller);
  entries_.push_back(std::move(entry));
  log_.debug("Loaded controller '" + name + "'");
  return true;
}

bool ControllerManager::unloadController(const std::string& name)
{
  for (auto it = entries_.begin(); it != entries_.end(); ++it)
  {
    if ((*it)->name != name)
      continue;
    if ((*it)->running())
    {
      log_.error("Could not unload controller with name '" + name + "' because it is still running");
      return false;
    }
    entries_.erase(it);
    return true;
  }
  log_.error("Could not unload controller with name '" + name + "' because no controller with this name exists");
  return false;
}

bool ControllerManager::switchController(const std::vector<std::string>& start, const std::vector<std::string>& stop,
                                         int strictness, bool start_asap, double timeout)
{
  if (pending_)
  {
    log_.error("Could not switch controllers: the previous switch has not been applied yet");
    return false;
  }
  if (strictness == 0)
  {
    log_.warn("Controller Manager: To switch controllers you need to specify a strictness level of "
              "controller_manager_msgs::SwitchController::STRICT (2) or ::BEST_EFFORT (1). Defaulting to ::BEST_EFFORT.");
    strictness = BEST_EFFORT;
  }
  const bool strict = strictness == STRICT;

  // Names that are not loaded: STRICT fails on the first (stop list first), BEST_EFFORT leaves them out.
  auto requested = [&](const std::vector<std::string>& names, const char* verb, std::vector<const Entry*>& out) {
    for (const std::string& name : names)
    {
      if (const Entry* e = find(name))
      {
        out.push_back(e);
        continue;
      }
      const std::string text = std::string("Could not ") + verb + " controller with name '" + name +
                               "' because no controller with this name exists";
      if (strict)
      {
        log_.error(text);
        return false;
      }
      log_.debug(text);
    }
    return true;
  };
  std::vector<const Entry*> stop_requests, start_requests;
  if (!requested(stop, "stop", stop_requests) || !requested(start, "start", start_requests))
    return false;

  // Each loaded controller in load order, with ros_control 0.20's checks in its order
  // (docs/interfaces.md section 9): a double stop, a double start, then a running controller in both
  // lists, which is refused whatever the strictness.
  std::vector<std::string> to_stop, to_start;
  std::map<std::string, int> claims;  // joint -> controllers that would run after the switch
  for (const auto& e : entries_)
  {
    bool in_stop = std::find(stop_requests.begin(), stop_requests.end(), e.get()) != stop_requests.end();
    bool in_start = std::find(start_requests.begin(), start_requests.end(), e.get()) != start_requests.end();
    const bool running = e->running();
    if (!running && in_stop)
    {
      if (strict)
      {
        log_.error("Could not stop controller '" + e->name + "' since it is not running");
        return false;
      }
      in_stop = false;
    }
    if (running && !in_stop && in_start)
    {
      if (strict)
      {
        log_.error("Controller '" + e->name + "' is already running");
        return false;
      }
      in_start = false;
    }
    if (running && in_stop && in_start)
    {
      // Upstream's wording, "Could no" included.
      log_.error("Could no start or stop controller '" + e->name + "' because of conflicting switching command");
      return false;
    }
    if (in_stop)
      to_stop.push_back(e->name);
    if (in_start)
      to_start.push_back(e->name);
    if ((running && !in_stop) || in_start)
      for (const ClaimedResources& c : e->controller->claimedResources())
        for (const std::string& r : c.resources)
          ++claims[r];
  }

  // No joint may be claimed by two controllers that would run together.
  for (const auto& kv : claims)
    if (kv.second > 1)
    {
      log_.error("Could not switch controllers, due to resource conflict");
      return false;
    }

  if (to_start.empty() && to_stop.empty())
    return true;  // nothing to wait for
  pending_start_ = to_start;
  pending_stop_ = to_stop;
  pending_ = true;
  if (paused_)
    applyPendingSwitch(last_time_ns_);
  return true;
}

void ControllerManager::applyPendingSwitch(int64_t time_ns)
{
  if (!pending_)
    return;
  for (const std::string& name : pending_stop_)
    if (Entry* e = find(name))
    {
      e->controller->stopping(time_ns);
      e->state = ControllerState::Stopped;
    }
  for (const std::string& name : pending_start_)
    if (Entry* e = find(name))
    {
      e->controller->starting(time_ns);
      e->state = ControllerState::Running;
    }
  pending_ = false;
  pending_start_.clear();
  pending_stop_.clear();
}

void ControllerManager::update(int64_t time_ns, double period)
{
  last_time_ns_ = time_ns;
  for (auto& e : entries_)
    if (e->running())
      e->controller->update(time_ns, period);
  applyPendingSwitch(time_ns);
}

void ControllerManager::reset(int64_t time_ns)
{
  last_time_ns_ = time_ns;
  for (auto& e : entries_)
    if (e->running())
    {
      e->controller->stopping(time_ns);
      e->controller->starting(time_ns);
    }
}

std::vector<ControllerInfo> ControllerManager::listControllers() const
{
  std::vector<ControllerInfo> out;
  for (const auto& e : entries_)
    out.push_back({e->name, e->state, e->type, e->controller->claimedResources()});
  return out;
}

std::vector<std::string> ControllerManager::listControllerTypes() const { return controllerTypes(); }

bool ControllerManager::reloadControllerLibraries(bool force_kill)
{
  if (!entries_.empty() && !force_kill)
  {
    log_.error("Controller manager: Cannot reload controller libraries because there are still " +
               std::to_string(entries_.size()) + " controllers loaded. Try again after unloading them, "
               "or call with force_kill true.");
    return false;
  }
  if (!entries_.empty())
    log_.info("Controller manager: Killing all running controllers");
  for (auto& e : entries_)
    if (e->running())
      e->controller->stopping(last_time_ns_);
  entries_.clear();
  pending_ = false;
  pending_start_.clear();
  pending_stop_.clear();
  return true;
}

}  // namespace bullet_plant
