// Ground-truth odometry of one robot: nav_msgs/Odometry on `odom` and the odom -> root link
// transform on /tf, every 20 ms of simulated time; neither built while nobody subscribes to it.
// Runs on the simulation thread.
#pragma once

#include <cstdint>

#include <ros/ros.h>

#include "bullet_plant/rate_gate.h"
#include "counted_publisher.h"

namespace bullet_plant
{
class Outbox;
class Robot;

class OdometryPublisher
{
public:
  OdometryPublisher(Robot& robot, ros::NodeHandle& nh, Outbox& outbox);
  // After a step: publishes when the period has passed (or time went back, after a reset); the
  // transform only with `tf` (false while a controller of the robot publishes its odometry's).
  void publish(int64_t time_ns, bool tf = true);

private:
  void publishNow(int64_t time_ns, bool tf);

  Robot& robot_;
  Outbox& outbox_;
  CountedPublisher odom_pub_, tf_pub_;
  RateGate gate_{periodNsOfRate(50.0)};
};

}  // namespace bullet_plant
