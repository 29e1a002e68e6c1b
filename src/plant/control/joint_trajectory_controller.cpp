// joint_trajectory_controller (ros_controllers, ROS 1 Noetic): {position,velocity,effort}_controllers/
// JointTrajectoryController. A trajectory_msgs/JointTrajectory on <ctrl>/command or a
// control_msgs/FollowJointTrajectory goal on <ctrl>/follow_joint_trajectory is merged into the
// trajectory being followed at the next update (points already past dropped, a bridge from the
// current desired state to the first kept point), each joint interpolated by spline_segment.h; the
// position variant commands the desired position, the velocity and effort ones
// velocity_ff * desired velocity + PID(position error, velocity error) with gains/<joint>. Goals are
// checked against path tolerances on the way and goal tolerances at the end (constraints/...,
// overridden per goal). Parameters, defaults, texts and error codes are upstream's
// (docs/interfaces.md section 12b has them and what differs).
#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include "bullet_plant/action_messages.h"
#include "control/controller_support.h"
#include "control/spline_segment.h"

namespace bullet_plant
{
namespace
{
constexpr double kNs = 1e-9;

double shortestAngularDistance(double from, double to)
{
  const double d = std::fmod(to - from + M_PI, 2.0 * M_PI);
  return (d < 0 ? d + 2.0 * M_PI : d) - M_PI;
}

// A bound per quantity; 0 is "not checked".
struct StateTolerance
{
  double position = 0, velocity = 0, acceleration = 0;
};

// One joint's tolerances on the segments of a goal (tolerances.h's SegmentTolerancesPerJoint).
struct JointTolerances
{
  StateTolerance path, goal;
  double goal_time = 0;
};

// A segment as the controller keeps it: the goal it serves ("" for none) and that goal's tolerances.
struct Segment
{
  SplineSegment spline;
  std::string goal_id;
  JointTolerances tolerances;
};
using JointTrajectory = std::vector<Segment>;

// The segment in force at `time`: the last one started by then (the first before any starts).
size_t findSegment(const JointTrajectory& t, double time)
{
  size_t k = 0;
  while (k + 1 < t.size() && t[k + 1].spline.startTime() <= time)
    ++k;
  return k;
}

bool exceeds(const StateTolerance& tol, double position_error, double velocity_error, double acceleration_error)
{
  return (tol.position > 0 && std::fabs(position_error) > tol.position) ||
         (tol.velocity > 0 && std::fabs(velocity_error) > tol.velocity) ||
         (tol.acceleration > 0 && std::fabs(acceleration_error) > tol.acceleration);
}

// A goal's JointTolerance over a default: > 0 replaces, < 0 (-1) removes the bound, 0 keeps it.
void override(double given, double& value)
{
  if (given > 0)
    value = given;
  else if (given < 0)
    value = 0;
}

class JointTrajectoryController : public Controller
{
public:
  explicit JointTrajectoryController(JointInterface iface) : interface_(iface)
  {
    subscribe<JointTrajectoryCommand>("command", [this](const JointTrajectoryCommand& t) { return onCommand(t); });
    subscribe<ActionGoal<FollowJointTrajectoryGoal>>(
        "follow_joint_trajectory/goal", [this](const ActionGoal<FollowJointTrajectoryGoal>& g) { return onGoal(g); });
    subscribe<ActionCancel>("follow_joint_trajectory/cancel", [this](const ActionCancel& c) { return onCancel(c); });
    state_port_ = &advertise<TrajectoryStateSample>("state");
    result_port_ = &advertise<ActionResult<FollowJointTrajectoryResult>>("follow_joint_trajectory/result");
    feedback_port_ = &advertise<ActionFeedback<TrajectoryStateSample>>("follow_joint_trajectory/feedback");
    serve<QueryTrajectoryStateRequest, QueryTrajectoryStateResponse>(
        "query_state", [this](const QueryTrajectoryStateRequest& q, QueryTrajectoryStateResponse& r) {
          return queryState(q, r);
        });
  }

  bool init(ControllerContext& c) override
  {
    log_ = &c.log;
    ns_ = c.ns;
    state_gate_.setPeriodNs(periodNsOfRate(paramNumber(c, "state_publish_rate", 50.0)));
    feedback_gate_.setPeriodNs(periodNsOfRate(paramNumber(c, "action_monitor_rate", 20.0)));
    stop_trajectory_duration_ = paramNumber(c, "stop_trajectory_duration", 0.0);
    allow_partial_joints_goal_ = paramFlag(c, "allow_partial_joints_goal", false);
    if (!readJoints(c))
      return false;
    for (const std::string& joint : joint_names_)
    {
      JointTolerances t;
      t.goal.velocity = paramNumber(c, "constraints/stopped_velocity_tolerance", 0.01);
      t.path.position = paramNumber(c, "constraints/" + joint + "/trajectory", 0.0);
      t.goal.position = paramNumber(c, "constraints/" + joint + "/goal", 0.0);
      t.goal_time = paramNumber(c, "constraints/goal_time", 0.0);
      default_tolerances_.push_back(t);
      if (interface_ != JointInterface::Position)
      {
        const std::string gains = joinPath(c.ns, "gains/" + joint);
        try
        {
          pids_.emplace_back(readPidGains(c.params, gains));
        }
        catch (const std::exception& e)
        {
          // upstream loads anyway and then runs on null PIDs: the plant refuses the controller instead
          c.log.error(std::string(e.what()) + "\nFailed to initialize PID gains from ROS parameter server. Set " +
                      gains + "/p (and i, d) for joint '" + joint + "'.");
          return false;
        }
        velocity_ff_.push_back(paramNumber(c, "velocity_ff/" + joint, 0.0));
      }
    }
    state_.joint_names = joint_names_;
    return true;
  }

  void starting(int64_t time_ns) override
  {
    running_ = true;
    last_update_ns_ = time_ns;
    desired_.assign(handles_.size(), SplineState());
    for (size_t j = 0; j < handles_.size(); ++j)
    {
      desired_[j].position = handles_[j]->position();
      desired_[j].velocity = handles_[j]->velocity();
    }
    trajectory_.assign(handles_.size(), JointTrajectory());
    setHoldPosition(time_ns * kNs, "");
    state_gate_.reset();
    feedback_gate_.reset();
    for (size_t j = 0; j < pids_.size(); ++j)
      pids_[j].reset();
    for (size_t j = 0; j < handles_.size(); ++j)
      handles_[j]->setCommand(interface_ == JointInterface::Position ? handles_[j]->position() : 0.0);
  }

  void stopping(int64_t) override
  {
    running_ = false;
    preemptActiveGoal();
  }

  void update(int64_t time_ns, double period) override
  {
    last_update_ns_ = time_ns;
    period_ = period;
    const double now = time_ns * kNs;
    std::vector<double> position_error(handles_.size()), velocity_error(handles_.size());
    for (size_t j = 0; j < handles_.size(); ++j)
    {
      const JointTrajectory& t = trajectory_[j];
      desired_[j] = t[findSegment(t, now)].spline.sample(now);
      const double actual = handles_[j]->position();
      position_error[j] = handles_[j]->type() == JointType::Prismatic ? desired_[j].position - actual
                                                                       : shortestAngularDistance(actual, desired_[j].position);
      velocity_error[j] = desired_[j].velocity - handles_[j]->velocity();
    }
    checkTolerances(now, position_error, velocity_error);
    for (size_t j = 0; j < handles_.size(); ++j)
    {
      if (interface_ == JointInterface::Position)
        handles_[j]->setCommand(desired_[j].position);
      else
        handles_[j]->setCommand(velocity_ff_[j] * desired_[j].velocity +
                                pids_[j].computeCommand(position_error[j], velocity_error[j], period));
    }
    fillState(time_ns, position_error, velocity_error);
    if (!active_goal_.empty() && feedback_gate_.due(time_ns))
      feedback_port_->publish(ActionFeedback<TrajectoryStateSample>{active_goal_, state_});
    if (state_gate_.due(time_ns))
      state_port_->publish(state_);
  }

private:
  // The query_state service: the trajectory in force sampled at the request's time (sim time, which
  // upstream's uptime mapping reduces to), as upstream's queryStateService.
  bool queryState(const QueryTrajectoryStateRequest& q, QueryTrajectoryStateResponse& r)
  {
    if (!running_)
    {
      log_->error("Can't sample trajectory. Controller is not running.");
      return false;
    }
    const double time = q.time_ns * kNs;
    r = QueryTrajectoryStateResponse{joint_names_, {}, {}, {}};
    for (const JointTrajectory& t : trajectory_)
    {
      if (t.empty() || time < t.front().spline.startTime())
      {
        log_->error("Requested sample time precedes trajectory start time.");
        return false;
      }
      const SplineState s = t[findSegment(t, time)].spline.sample(time);
      r.position.push_back(s.position);
      r.velocity.push_back(s.velocity);
      r.acceleration.push_back(s.acceleration);
    }
    return true;
  }

  bool readJoints(ControllerContext& c)
  {
    const Param* names = param(c, "joints");
    if (!names)
    {
      c.log.error("Could not find 'joints' parameter (namespace: " + c.ns + ").");
      return false;
    }
    if (names->type() != Param::Type::List)
    {
      c.log.error("The 'joints' parameter is not an array (namespace: " + c.ns + ").");
      return false;
    }
    for (const Param& name : names->asList())
    {
      if (name.type() != Param::Type::String)
      {
        c.log.error("The 'joints' parameter contains a non-string element (namespace: " + c.ns + ").");
        return false;
      }
      joint_names_.push_back(name.asString());
    }
    if (joint_names_.empty())
    {
      // upstream returns false without a word; the plant says why
      c.log.error("The 'joints' parameter of " + c.ns + " is an empty list: name the joints to control.");
      return false;
    }
    std::vector<std::string> claimed;
    for (const std::string& joint : joint_names_)
    {
      JointHandle* h = c.joints.handle(joint);
      if (!h || h->interface() != interface_)
      {
        c.log.error("Could not find joint '" + joint + "' in '" + interfaceName(interface_) + "'.");
        return false;
      }
      handles_.push_back(h);
      claimed.push_back(joint);
    }
    claimed_.assign(1, ClaimedResources{interfaceName(interface_), claimed});
    return true;
  }

  // The joint index of each of the message's joints; empty when one is unknown or repeated, or (without
  // allow_partial_joints_goal) when the message does not name them all.
  std::vector<size_t> mapping(const std::vector<std::string>& names) const
  {
    if (!allow_partial_joints_goal_ && names.size() != joint_names_.size())
      return {};
    std::vector<size_t> out;
    for (const std::string& name : names)
    {
      auto it = std::find(joint_names_.begin(), joint_names_.end(), name);
      if (it == joint_names_.end() || std::count(names.begin(), names.end(), name) > 1)
        return {};
      out.push_back(size_t(it - joint_names_.begin()));
    }
    return out;
  }

  bool onCommand(const JointTrajectoryCommand& t)
  {
    std::string error;
    if (!updateTrajectoryCommand(t, "", nullptr, error))
    {
      log_->error(error);
      return false;
    }
    preemptActiveGoal();
    return true;
  }

  bool onGoal(const ActionGoal<FollowJointTrajectoryGoal>& g)
  {
    auto reject = [&](int32_t code, const std::string& text) {
      log_->error(text);
      result_port_->publish(ActionResult<FollowJointTrajectoryResult>{
          g.id, GoalOutcome::Rejected, FollowJointTrajectoryResult{code, text}, text});
      return false;
    };
    if (!running_)
      return reject(FollowJointTrajectoryResult::INVALID_GOAL, "Can't accept new action goals. Controller is not running.");
    if (mapping(g.goal.trajectory.joint_names).empty())
      return reject(FollowJointTrajectoryResult::INVALID_JOINTS, "Joints on incoming goal don't match the controller joints.");
    std::string error;
    if (!updateTrajectoryCommand(g.goal.trajectory, g.id, &g.goal, error))
      return reject(FollowJointTrajectoryResult::INVALID_GOAL, error);
    preemptActiveGoal();
    active_goal_ = g.id;
    return true;
  }

  bool onCancel(const ActionCancel& c)
  {
    if (c.id.empty() || c.id != active_goal_)
      return true;  // not the goal in force: nothing to stop
    setHoldPosition(last_update_ns_ * kNs, "");
    finishActiveGoal(GoalOutcome::Canceled, FollowJointTrajectoryResult(), "canceled");
    return true;
  }

  // upstream's preemptActiveGoal: the client sees PREEMPTED, error_code 0.
  void preemptActiveGoal()
  {
    if (!active_goal_.empty())
      finishActiveGoal(GoalOutcome::Canceled, FollowJointTrajectoryResult(), "preempted by a new trajectory");
  }

  void finishActiveGoal(GoalOutcome outcome, const FollowJointTrajectoryResult& result, const std::string& text)
  {
    result_port_->publish(ActionResult<FollowJointTrajectoryResult>{active_goal_, outcome, result, text});
    active_goal_.clear();
  }

  // The hold trajectory (stop_trajectory_duration 0: stay at the actual position) or the stop ramp
  // (> 0: from the last desired state to rest within that time), serving `goal_id`.
  void setHoldPosition(double time, const std::string& goal_id)
  {
    const double d = stop_trajectory_duration_;
    for (size_t j = 0; j < handles_.size(); ++j)
    {
      Segment hold;
      hold.goal_id = goal_id;
      SplineState start;
      start.has_velocity = start.has_acceleration = true;
      if (d <= 0.0)
      {
        start.position = handles_[j]->position();
        hold.spline = SplineSegment(time, start, time, start);
      }
      else
      {
        start.position = desired_[j].position;
        start.velocity = desired_[j].velocity;
        SplineState mirrored = start;
        mirrored.velocity = -start.velocity;
        const SplineState end = SplineSegment(time, start, time + 2.0 * d, mirrored).sample(time + d);
        hold.spline = SplineSegment(time, start, time + d, end);
      }
      trajectory_[j].assign(1, hold);
    }
  }

  // init_joint_trajectory.h's rules, from the next update on; false with the reason in `error`.
  bool updateTrajectoryCommand(const JointTrajectoryCommand& msg, const std::string& goal_id,
                               const FollowJointTrajectoryGoal* goal, std::string& error)
  {
    if (!running_)
    {
      error = "Can't accept new commands. Controller is not running.";
      return false;
    }
    const double next_update = (last_update_ns_ + int64_t(std::llround(period_ * 1e9))) * kNs;
    if (msg.points.empty())
    {
      setHoldPosition(last_update_ns_ * kNs, goal_id);  // "Empty trajectory command, stopping."
      return true;
    }
    const double start = msg.stamp_ns == 0 ? next_update : msg.stamp_ns * kNs;
    for (size_t k = 0; k + 1 < msg.points.size(); ++k)
      if (msg.points[k].time_from_start_ns >= msg.points[k + 1].time_from_start_ns)
      {
        error = "Trajectory message contains waypoints that are not strictly increasing in time.";
        return false;
      }
    const std::vector<size_t> joints = mapping(msg.joint_names);
    if (joints.empty())
    {
      error = "Cannot create trajectory from message. It does not contain the expected joints.";
      return false;
    }
    // the points not yet reached at the next update
    size_t first = 0;
    while (first < msg.points.size() && start + msg.points[first].time_from_start_ns * kNs <= next_update)
      ++first;
    if (first == msg.points.size())
    {
      std::ostringstream text;
      text << "Dropping all " << msg.points.size() << " trajectory point(s), as they occur before the current time.\n"
           << "Last point is " << std::to_string(next_update - (start + msg.points.back().time_from_start_ns * kNs))
           << "s in the past.";
      error = text.str();
      return false;
    }
    for (size_t k = first; k < msg.points.size(); ++k)
    {
      const TrajectoryPointSample& p = msg.points[k];
      if (p.positions.size() != joints.size() || (!p.velocities.empty() && p.velocities.size() != joints.size()) ||
          (!p.accelerations.empty() && p.accelerations.size() != joints.size()))
      {
        // upstream checks velocities and accelerations against the positions only, then reads
        // positions past their end when there are fewer than joints
        error = "Size mismatch in trajectory point position, velocity or acceleration data.";
        return false;
      }
      for (const std::vector<double>* v : {&p.positions, &p.velocities, &p.accelerations})
        for (double x : *v)
          if (!std::isfinite(x))
          {
            error = "Trajectory point " + std::to_string(k) + " has a non-finite value: every position, velocity "
                    "and acceleration must be a number.";
            return false;
          }
    }
    if (first > 0 && !(first == 1 && msg.points[0].time_from_start_ns == 0 && msg.stamp_ns == 0))
      log_->warn("Dropping first " + std::to_string(first) + " trajectory point(s) out of " +
                 std::to_string(msg.points.size()) + ", as they occur before the current time.\nFirst valid point will "
                 "be reached in " + std::to_string(start + msg.points[first].time_from_start_ns * kNs - next_update) +
                 "s.");

    std::vector<JointTolerances> tolerances = default_tolerances_;
    if (goal)
      applyGoalTolerances(*goal, tolerances);
    std::vector<JointTrajectory> merged = trajectory_;
    for (JointTrajectory& t : merged)  // what is left of the old trajectory now serves this goal
      for (size_t k = findSegment(t, next_update); k < t.size(); ++k)
        t[k].goal_id = goal_id;
    for (size_t m = 0; m < joints.size(); ++m)
    {
      const size_t j = joints[m];
      JointTrajectory& t = merged[j];
      const double bridge_start = std::max(start, next_update);
      const size_t from = findSegment(t, next_update), to = findSegment(t, bridge_start);
      SplineState current = t[to].spline.sample(bridge_start);
      JointTrajectory kept(t.begin() + from, t.begin() + to + 1);
      auto waypoint = [&](size_t k) {
        const TrajectoryPointSample& p = msg.points[k];
        SplineState s;
        s.position = p.positions[m];
        s.has_velocity = !p.velocities.empty();
        s.velocity = s.has_velocity ? p.velocities[m] : 0.0;
        s.has_acceleration = !p.accelerations.empty();
        s.acceleration = s.has_acceleration ? p.accelerations[m] : 0.0;
        return s;
      };
      double offset = 0.0;  // continuous joints take the short way round to the first point
      if (handles_[j]->type() == JointType::Continuous)
      {
        const double target = waypoint(first).position;
        offset = current.position + shortestAngularDistance(current.position, target) - target;
      }
      auto shifted = [&](size_t k) {
        SplineState s = waypoint(k);
        s.position += offset;
        return s;
      };
      auto segment = [&](double t0, const SplineState& s0, double t1, const SplineState& s1) {
        Segment s;
        s.spline = SplineSegment(t0, s0, t1, s1);
        s.goal_id = goal_id;
        s.tolerances = tolerances[j];
        return s;
      };
      kept.push_back(segment(bridge_start, current, start + msg.points[first].time_from_start_ns * kNs, shifted(first)));
      for (size_t k = first; k + 1 < msg.points.size(); ++k)
        kept.push_back(segment(start + msg.points[k].time_from_start_ns * kNs, shifted(k),
                               start + msg.points[k + 1].time_from_start_ns * kNs, shifted(k + 1)));
      t.swap(kept);
    }
    trajectory_.swap(merged);
    return true;
  }

  void applyGoalTolerances(const FollowJointTrajectoryGoal& goal, std::vector<JointTolerances>& tolerances) const
  {
    for (size_t j = 0; j < joint_names_.size(); ++j)
    {
      for (const JointToleranceSpec& t : goal.path_tolerance)
        if (t.name == joint_names_[j])
        {
          override(t.position, tolerances[j].path.position);
          override(t.velocity, tolerances[j].path.velocity);
          override(t.acceleration, tolerances[j].path.acceleration);
        }
      for (const JointToleranceSpec& t : goal.goal_tolerance)
        if (t.name == joint_names_[j])
        {
          override(t.position, tolerances[j].goal.position);
          override(t.velocity, tolerances[j].goal.velocity);
          override(t.acceleration, tolerances[j].goal.acceleration);
        }
      override(goal.goal_time_tolerance_ns * kNs, tolerances[j].goal_time);
    }
  }

  // Path tolerances while a goal's segment runs, goal tolerances from its last segment's end: a
  // violation aborts the goal (the trajectory goes on, as upstream's does).
  void checkTolerances(double now, const std::vector<double>& position_error, const std::vector<double>& velocity_error)
  {
    if (active_goal_.empty())
      return;
    bool all_reached = true;
    for (size_t j = 0; j < handles_.size(); ++j)
    {
      const JointTrajectory& t = trajectory_[j];
      const size_t k = findSegment(t, now);
      const Segment& s = t[k];
      if (s.goal_id != active_goal_)
      {
        all_reached = false;
        continue;
      }
      const JointTolerances& tol = s.tolerances;
      if (now < s.spline.endTime())
      {
        all_reached = false;
        if (exceeds(tol.path, position_error[j], velocity_error[j], 0.0))
          return abortActiveGoal(FollowJointTrajectoryResult::PATH_TOLERANCE_VIOLATED, j, "path", tol.path,
                                 position_error[j], velocity_error[j]);
      }
      else if (k + 1 == t.size() && exceeds(tol.goal, position_error[j], velocity_error[j], 0.0))
      {
        all_reached = false;
        if (now >= s.spline.endTime() + tol.goal_time)
          return abortActiveGoal(FollowJointTrajectoryResult::GOAL_TOLERANCE_VIOLATED, j, "goal", tol.goal,
                                 position_error[j], velocity_error[j]);
      }
      else if (k + 1 != t.size())
        all_reached = false;
    }
    if (all_reached)
      finishActiveGoal(GoalOutcome::Succeeded, FollowJointTrajectoryResult(), "");
  }

  void abortActiveGoal(int32_t code, size_t joint, const char* which, const StateTolerance& tol, double position_error,
                       double velocity_error)
  {
    std::ostringstream text;
    text << "joint '" << joint_names_[joint] << "' is off its trajectory by " << position_error << " (position), "
         << velocity_error << " (velocity), beyond its " << which << " tolerance " << tol.position << ", "
         << tol.velocity << " (0: unchecked)";
    finishActiveGoal(GoalOutcome::Aborted, FollowJointTrajectoryResult{code, text.str()}, text.str());
  }

  void fillState(int64_t time_ns, const std::vector<double>& position_error, const std::vector<double>& velocity_error)
  {
    const size_t n = handles_.size();
    state_.stamp_ns = time_ns;
    state_.desired.positions.resize(n);
    state_.desired.velocities.resize(n);
    state_.desired.accelerations.resize(n);
    state_.actual.positions.resize(n);
    state_.actual.velocities.resize(n);
    state_.error.positions = position_error;
    state_.error.velocities = velocity_error;
    for (size_t j = 0; j < n; ++j)
    {
      state_.desired.positions[j] = desired_[j].position;
      state_.desired.velocities[j] = desired_[j].velocity;
      state_.desired.accelerations[j] = desired_[j].acceleration;
      state_.actual.positions[j] = handles_[j]->position();
      state_.actual.velocities[j] = handles_[j]->velocity();
    }
  }

  JointInterface interface_;
  Log* log_ = nullptr;
  std::string ns_;
  std::vector<std::string> joint_names_;
  std::vector<JointHandle*> handles_;
  std::vector<Pid> pids_;
  std::vector<double> velocity_ff_;
  std::vector<JointTolerances> default_tolerances_;
  double stop_trajectory_duration_ = 0.0;
  bool allow_partial_joints_goal_ = false;
  bool running_ = false;
  int64_t last_update_ns_ = 0;
  double period_ = 0.001;
  std::vector<JointTrajectory> trajectory_;  // per joint
  std::vector<SplineState> desired_;
  std::string active_goal_;  // "" when no goal is in force
  TrajectoryStateSample state_;
  RateGate state_gate_, feedback_gate_;
  OutputPort<TrajectoryStateSample>* state_port_ = nullptr;
  OutputPort<ActionResult<FollowJointTrajectoryResult>>* result_port_ = nullptr;
  OutputPort<ActionFeedback<TrajectoryStateSample>>* feedback_port_ = nullptr;
};
}  // namespace

ROS_CONTROLLER_TYPE(effort_trajectory, "effort_controllers/JointTrajectoryController",
                    controllerFactory<JointTrajectoryController>(JointInterface::Effort));
ROS_CONTROLLER_TYPE(position_trajectory, "position_controllers/JointTrajectoryController",
                    controllerFactory<JointTrajectoryController>(JointInterface::Position));
ROS_CONTROLLER_TYPE(velocity_trajectory, "velocity_controllers/JointTrajectoryController",
                    controllerFactory<JointTrajectoryController>(JointInterface::Velocity));

}  // namespace bullet_plant
