// joint_state_controller/JointStateController: every joint handle's state as sensor_msgs/JointState
// on joint_states at publish_rate, plus extra_joints (docs/interfaces.md section 4).
#include "control/controller_support.h"

#include <map>

namespace bullet_plant
{
namespace
{
class JointStateController : public Controller
{
public:
  bool init(ControllerContext& c) override
  {
    const Param* rate = param(c, "publish_rate");
    if (!rate || !rate->isNumber())
    {
      c.log.error("Parameter 'publish_rate' not set");
      return false;
    }
    publish_gate_.setPeriodNs(periodNsOfRate(rate->asDouble()));  // 0: never publishes
    // Default: every joint with a state handle, sorted by name as the hardware interface lists them.
    std::map<std::string, JointHandle*> by_name;
    for (JointHandle& h : c.joints.handles())
      by_name[h.name()] = &h;
    if (const Param* joints = param(c, "joints"))
    {
      if (joints->type() != Param::Type::List)
      {
        c.log.error("Parameter 'joints' of " + c.ns + " is not a list of joint names");
        return false;
      }
      for (const Param& j : joints->asList())
      {
        if (j.type() != Param::Type::String || !by_name.count(j.asString()))
        {
          c.log.error("Joint " + j.describe() + " given in " + c.ns + "/joints has no state handle");
          return false;
        }
        joints_.push_back(by_name[j.asString()]);
      }
    }
    else
      for (auto& kv : by_name)
        joints_.push_back(kv.second);
    if (const Param* extra = param(c, "extra_joints"))
      for (const Param& e : extra->type() == Param::Type::List ? extra->asList() : std::vector<Param>())
      {
        const Param* name = e.find("name");
        if (!name || name->type() != Param::Type::String)
        {
          c.log.error("Extra joint specification in " + c.ns + " has no name");
          return false;
        }
        auto number = [&](const char* key) { const Param* v = e.find(key); return v && v->isNumber() ? v->asDouble() : 0.0; };
        extra_.push_back({name->asString(), number("position"), number("velocity"), number("effort")});
      }
    claimed_.assign(1, ClaimedResources{kJointStateInterface, {}});
    joint_states_ = &advertise<JointStateSample>("joint_states", TopicScope::Robot);
    return true;
  }

  void starting(int64_t time_ns) override { publish_gate_.restart(time_ns); }

  void update(int64_t time_ns, double) override
  {
    if (publish_gate_.periodNs() <= 0 || !publish_gate_.due(time_ns))
      return;
    JointStateSample s;
    s.stamp_ns = time_ns;
    for (JointHandle* h : joints_)
    {
      s.name.push_back(h->name());
      s.position.push_back(h->position());
      s.velocity.push_back(h->velocity());
      s.effort.push_back(h->effort());
    }
    for (const Extra& e : extra_)
    {
      s.name.push_back(e.name);
      s.position.push_back(e.position);
      s.velocity.push_back(e.velocity);
      s.effort.push_back(e.effort);
    }
    joint_states_->publish(s);
  }

private:
  struct Extra { std::string name; double position, velocity, effort; };
  std::vector<JointHandle*> joints_;
  std::vector<Extra> extra_;
  OutputPort<JointStateSample>* joint_states_ = nullptr;
  CatchUpRateGate publish_gate_;  // publish_rate
};
}  // namespace

ROS_CONTROLLER_TYPE(joint_state, "joint_state_controller/JointStateController",
                    controllerFactory<JointStateController>());

}  // namespace bullet_plant
