// Ground-truth odometry of one robot: nav_msgs/Odometry on `odom` and the odom -> root link
// transform on /tf, every 20 ms of simulated time. Runs on the simulation thread.
#pragma once

#include <cstdint>

#include <geometry_msgs/TransformStamped.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>
#include <urdf_model/pose.h>

namespace bullet_plant
{
class Robot;

// nav_msgs/Odometry of a pose in `frame` and a twist in `child` (what nav_msgs/Odometry's twist is
// in), covariances 0; and the frame -> child transform it implies, for /tf. One place for both, used
// by the ground truth here and by the drive controllers' odometry (controller_topics.cpp).
nav_msgs::Odometry odometryMessage(int64_t stamp_ns, const std::string& frame, const std::string& child,
                                   const urdf::Pose& pose, const urdf::Vector3& linear, const urdf::Vector3& angular);
geometry_msgs::TransformStamped odometryTransform(const nav_msgs::Odometry& odom);

class OdometryPublisher
{
public:
  OdometryPublisher(Robot& robot, ros::NodeHandle& nh);
  // After a step: publishes when the period has passed (or time went back, after a reset); the
  // transform only with `tf` (false while a controller of the robot publishes its odometry's).
  void publish(int64_t time_ns, bool tf = true);

private:
  void publishNow(int64_t time_ns, bool tf);

  Robot& robot_;
  ros::Publisher odom_pub_, tf_pub_;
  int64_t period_ns_ = 20000000, last_ns_ = -1;
};

}  // namespace bullet_plant
