#include "simulation/external_efforts.h"

#include <algorithm>

#include "physics/dynamics_world.h"

namespace bullet_plant
{
namespace
{
int64_t jobEnd(int64_t start_ns, int64_t duration_ns) { return duration_ns < 0 ? -1 : start_ns + duration_ns; }
}  // namespace

void ExternalEfforts::addLinkWrench(const std::string& link, int body, const btVector3& force, const btVector3& torque,
                                    int64_t start_ns, int64_t duration_ns)
{
  wrenches_.push_back({link, body, force, torque, start_ns, jobEnd(start_ns, duration_ns)});
}

void ExternalEfforts::clearLinkWrenches(const std::string& link)
{
  wrenches_.erase(std::remove_if(wrenches_.begin(), wrenches_.end(), [&](const LinkWrench& x) { return x.link == link; }),
                  wrenches_.end());
}

void ExternalEfforts::addJointEffort(const std::string& joint, int joint_link, double effort, int64_t start_ns,
                                     int64_t duration_ns)
{
  joint_efforts_.push_back({joint, joint_link, effort, start_ns, jobEnd(start_ns, duration_ns)});
}

void ExternalEfforts::clearJointEfforts(const std::string& joint)
{
  joint_efforts_.erase(std::remove_if(joint_efforts_.begin(), joint_efforts_.end(),
                                      [&](const JointEffort& x) { return x.joint == joint; }),
                       joint_efforts_.end());
}

// gazebo_ros's job rule: a job acts while start <= now <= start + duration (always with a negative
// duration) and is dropped once now > start + duration.
void ExternalEfforts::apply(RobotMultibody& multibody, int64_t time_ns)
{
  auto due = [time_ns](int64_t start, int64_t end) { return time_ns >= start && (end < 0 || time_ns <= end); };
  auto expired = [time_ns](int64_t end) { return end >= 0 && time_ns > end; };
  bool acted = false;  // a body asleep wakes to feel it
  for (const LinkWrench& w : wrenches_)
    if (due(w.start_ns, w.end_ns))
    {
      multibody.addBodyWrench(w.body, w.force, w.torque);
      acted = true;
    }
  for (const JointEffort& e : joint_efforts_)
    if (due(e.start_ns, e.end_ns))
    {
      multibody.bullet->addJointTorque(e.link, btScalar(e.effort));
      acted = true;
    }
  if (acted)
    wakeUp(*multibody.bullet);
  wrenches_.erase(std::remove_if(wrenches_.begin(), wrenches_.end(), [&](const LinkWrench& w) { return expired(w.end_ns); }),
                  wrenches_.end());
  joint_efforts_.erase(std::remove_if(joint_efforts_.begin(), joint_efforts_.end(),
                                      [&](const JointEffort& e) { return expired(e.end_ns); }),
                       joint_efforts_.end());
}

}  // namespace bullet_plant
