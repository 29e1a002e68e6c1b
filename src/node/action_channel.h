// An action an owner in the plant serves (action_messages.h's four ports), served over ROS by
// actionlib's own ActionServer: goals and cancels arrive on ROS threads and are posted to the
// simulation thread, where the owner's goal port says accepted or not; the owner's result and
// feedback ports, drained after each step, end and inform the goals by id.
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <string>

#include <actionlib/server/action_server.h>

#include "bullet_plant/message_ports.h"
#include "bullet_plant/action_messages.h"
#include "msg_conversions.h"

namespace bullet_plant
{
class ActionChannel
{
public:
  // `Post` runs work on the simulation thread; `FindPort` finds the owner's port there by its topic
  // under the action ("goal", "cancel"), null when the owner is gone.
  using Post = std::function<void(std::function<void()>)>;
  using FindPort = std::function<Port*(const std::string& topic)>;

  virtual ~ActionChannel() = default;
  // Ends or informs goals from what the owner's result or feedback port holds.
  virtual void drain(Port& port) = 0;
};

// Serves RosAction on `name`; Goal, Result and Feedback are the plant's types for its goal, result
// and feedback (converted by msg_conversions.h's fromMsg(goal) and toMsg(plant, ros&)).
template <class RosAction, class Goal, class Result, class Feedback>
class ActionChannelOf : public ActionChannel
{
  using RosResult = typename RosAction::_action_result_type::_result_type;
  using RosFeedback = typename RosAction::_action_feedback_type::_feedback_type;
  using Server = actionlib::ActionServer<RosAction>;
  using GoalHandle = typename Server::GoalHandle;

public:
  ActionChannelOf(ros::NodeHandle& nh, const std::string& name, Post post, FindPort find_port)
    : post_(std::move(post)), find_port_(std::move(find_port)), alive_(std::make_shared<bool>(true))
  {
    server_.reset(new Server(nh, name, [this](GoalHandle gh) { onGoal(gh); }, [this](GoalHandle gh) { onCancel(gh); },
                             false));
    server_->start();
  }

  ~ActionChannelOf() override
  {
    *alive_ = false;
    std::lock_guard<std::mutex> lock(mutex_);
    for (auto& kept : goals_)  // the owner is gone (controller unloaded): its goals end with it
      kept.second.setAborted(RosResult(), "the controller serving this action was stopped or unloaded");
  }

  void drain(Port& port) override
  {
    if (auto* results = dynamic_cast<OutputPort<ActionResult<Result>>*>(&port))
      for (const ActionResult<Result>& r : results->take())
        finish(r);
    else if (auto* feedback = dynamic_cast<OutputPort<ActionFeedback<Feedback>>*>(&port))
      for (const ActionFeedback<Feedback>& f : feedback->take())
      {
        std::lock_guard<std::mutex> lock(mutex_);
        auto it = goals_.find(f.id);
        if (it != goals_.end())
        {
          RosFeedback m;
          toMsg(f.feedback, m);
          it->second.publishFeedback(m);
        }
      }
  }

private:
  void onGoal(GoalHandle gh)
  {
    const std::string id = gh.getGoalID().id;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      goals_[id] = gh;
    }
    ActionGoal<Goal> goal{id, fromMsg(*gh.getGoal())};
    std::weak_ptr<bool> alive = alive_;
    post_([this, alive, goal] {
      std::shared_ptr<bool> still = alive.lock();
      if (!still || !*still)
        return;
      auto* port = dynamic_cast<InputPort<ActionGoal<Goal>>*>(find_port_("goal"));
      if (!port)
        return finish(ActionResult<Result>{goal.id, GoalOutcome::Rejected, Result(), "the controller is gone"});
      if (port->deliver(goal))
      {
        std::lock_guard<std::mutex> lock(mutex_);
        auto it = goals_.find(goal.id);
        if (it != goals_.end())
          it->second.setAccepted();
      }  // a refused goal comes back as a Rejected result, with its reason
    });
  }

  void onCancel(GoalHandle gh)
  {
    const std::string id = gh.getGoalID().id;
    std::weak_ptr<bool> alive = alive_;
    post_([this, alive, id] {
      std::shared_ptr<bool> still = alive.lock();
      if (!still || !*still)
        return;
      if (auto* port = dynamic_cast<InputPort<ActionCancel>*>(find_port_("cancel")))
        port->deliver(ActionCancel{id});
    });
  }

  void finish(const ActionResult<Result>& r)
  {
    std::lock_guard<std::mutex> lock(mutex_);
    auto it = goals_.find(r.id);
    if (it == goals_.end())
      return;
    RosResult result;
    toMsg(r.result, result);
    switch (r.outcome)
    {
      case GoalOutcome::Rejected: it->second.setRejected(result, r.text); break;
      case GoalOutcome::Succeeded: it->second.setSucceeded(result, r.text); break;
      case GoalOutcome::Aborted: it->second.setAborted(result, r.text); break;
      case GoalOutcome::Canceled: it->second.setCanceled(result, r.text); break;
    }
    goals_.erase(it);
  }

  Post post_;
  FindPort find_port_;
  std::shared_ptr<bool> alive_;  // posted work finds it false once this is gone
  std::mutex mutex_;             // goals_: ROS threads add, the simulation thread ends
  std::map<std::string, GoalHandle> goals_;
  std::unique_ptr<Server> server_;
};

}  // namespace bullet_plant
