// gazebo_ros's wrench and effort jobs (apply_body_wrench, apply_joint_effort; Robot::applyLinkWrench
// and applyJointEffort): forces and joint efforts added every step over a span of simulated time.
// Its own unit because the jobs outlive the call that made them: kept here, applied at the start
// of each step (before the controllers and the model plugins, as gazebo_ros's world update begin
// callback runs before any model's), dropped once expired.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <btBulletDynamicsCommon.h>

#include "simulation/robot_multibody.h"

namespace bullet_plant
{
class ExternalEfforts
{
public:
  // From start_ns for duration_ns (negative: until cleared). `body` is the link's body in the
  // multibody, `joint_link` the joint's Bullet link index.
  void addLinkWrench(const std::string& link, int body, const btVector3& force, const btVector3& torque,
                     int64_t start_ns, int64_t duration_ns);
  void clearLinkWrenches(const std::string& link);
  void addJointEffort(const std::string& joint, int joint_link, double effort, int64_t start_ns, int64_t duration_ns);
  void clearJointEfforts(const std::string& joint);

  bool empty() const { return wrenches_.empty() && joint_efforts_.empty(); }
  // The jobs due at time_ns, as forces and torques of the coming step; expired jobs are dropped.
  void apply(RobotMultibody& multibody, int64_t time_ns);

private:
  struct LinkWrench
  {
    std::string link;
    int body;
    btVector3 force, torque;
    int64_t start_ns, end_ns;  // end_ns < 0: no end
  };
  struct JointEffort
  {
    std::string joint;
    int link;
    double effort;
    int64_t start_ns, end_ns;
  };
  std::vector<LinkWrench> wrenches_;
  std::vector<JointEffort> joint_efforts_;
};

}  // namespace bullet_plant
