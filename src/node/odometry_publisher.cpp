#include "odometry_publisher.h"

#include <nav_msgs/Odometry.h>
#include <tf2_msgs/TFMessage.h>

#include "bullet_plant/geometry.h"
#include "bullet_plant/robot.h"
#include "ros_time.h"

namespace bullet_plant
{
OdometryPublisher::OdometryPublisher(Robot& robot, ros::NodeHandle& nh) : robot_(robot)
{
  odom_pub_ = nh.advertise<nav_msgs::Odometry>("odom", 10);
  tf_pub_ = nh.advertise<tf2_msgs::TFMessage>("/tf", 100);
}

void OdometryPublisher::publish(int64_t time_ns)
{
  if (last_ns_ >= 0 && time_ns - last_ns_ < period_ns_ && time_ns >= last_ns_)
    return;
  last_ns_ = time_ns;
  publishNow(time_ns);
}

void OdometryPublisher::publishNow(int64_t time_ns)
{
  urdf::Pose pose = robot_.basePose();
  Twist twist = robot_.baseTwist();
  const std::string child = robot_.description().model->getRoot()->name;
  nav_msgs::Odometry odom;
  odom.header.stamp = rosTime(time_ns);
  odom.header.frame_id = "odom";
  odom.child_frame_id = child;
  odom.pose.pose.position.x = pose.position.x;
  odom.pose.pose.position.y = pose.position.y;
  odom.pose.pose.position.z = pose.position.z;
  odom.pose.pose.orientation.x = pose.rotation.x;
  odom.pose.pose.orientation.y = pose.rotation.y;
  odom.pose.pose.orientation.z = pose.rotation.z;
  odom.pose.pose.orientation.w = pose.rotation.w;
  // nav_msgs/Odometry's twist is in the child frame.
  urdf::Rotation to_body = pose.rotation.GetInverse();
  urdf::Vector3 v = rotate(to_body, urdf::Vector3(twist.linear[0], twist.linear[1], twist.linear[2]));
  urdf::Vector3 w = rotate(to_body, urdf::Vector3(twist.angular[0], twist.angular[1], twist.angular[2]));
  odom.twist.twist.linear.x = v.x;
  odom.twist.twist.linear.y = v.y;
  odom.twist.twist.linear.z = v.z;
  odom.twist.twist.angular.x = w.x;
  odom.twist.twist.angular.y = w.y;
  odom.twist.twist.angular.z = w.z;
  odom_pub_.publish(odom);

  geometry_msgs::TransformStamped tf;
  tf.header = odom.header;
  tf.child_frame_id = child;
  tf.transform.translation.x = pose.position.x;
  tf.transform.translation.y = pose.position.y;
  tf.transform.translation.z = pose.position.z;
  tf.transform.rotation = odom.pose.pose.orientation;
  tf2_msgs::TFMessage msg;
  msg.transforms.push_back(tf);
  tf_pub_.publish(msg);
}

}  // namespace bullet_plant
