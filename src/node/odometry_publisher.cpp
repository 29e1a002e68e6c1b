#include "odometry_publisher.h"

#include <tf2_msgs/TFMessage.h>

#include "bullet_plant/geometry.h"
#include "bullet_plant/robot.h"
#include "msg_conversions.h"

namespace bullet_plant
{
OdometryPublisher::OdometryPublisher(Robot& robot, ros::NodeHandle& nh) : robot_(robot)
{
  odom_pub_ = nh.advertise<nav_msgs::Odometry>("odom", 10);
  tf_pub_ = nh.advertise<tf2_msgs::TFMessage>("/tf", 100);
}

void OdometryPublisher::publish(int64_t time_ns, bool tf)
{
  if (gate_.due(time_ns))
    publishNow(time_ns, tf);
}

void OdometryPublisher::publishNow(int64_t time_ns, bool tf)
{
  urdf::Pose pose = robot_.basePose();
  Twist twist = robot_.baseTwist();
  // nav_msgs/Odometry's twist is in the child frame.
  urdf::Rotation to_body = pose.rotation.GetInverse();
  nav_msgs::Odometry odom = odometryMessage(
      time_ns, "odom", robot_.description().model->getRoot()->name, pose,
      rotate(to_body, urdf::Vector3(twist.linear[0], twist.linear[1], twist.linear[2])),
      rotate(to_body, urdf::Vector3(twist.angular[0], twist.angular[1], twist.angular[2])));
  odom_pub_.publish(odom);
  if (!tf)
    return;
  tf2_msgs::TFMessage msg;
  msg.transforms.push_back(odometryTransform(odom));
  tf_pub_.publish(msg);
}

}  // namespace bullet_plant
