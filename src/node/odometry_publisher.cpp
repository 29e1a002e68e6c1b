#include "odometry_publisher.h"

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

nav_msgs::Odometry odometryMessage(int64_t stamp_ns, const std::string& frame, const std::string& child,
                                   const urdf::Pose& pose, const urdf::Vector3& linear, const urdf::Vector3& angular)
{
  nav_msgs::Odometry odom;
  odom.header.stamp = rosTime(stamp_ns);
  odom.header.frame_id = frame;
  odom.child_frame_id = child;
  odom.pose.pose.position.x = pose.position.x;
  odom.pose.pose.position.y = pose.position.y;
  odom.pose.pose.position.z = pose.position.z;
  odom.pose.pose.orientation.x = pose.rotation.x;
  odom.pose.pose.orientation.y = pose.rotation.y;
  odom.pose.pose.orientation.z = pose.rotation.z;
  odom.pose.pose.orientation.w = pose.rotation.w;
  odom.twist.twist.linear.x = linear.x;
  odom.twist.twist.linear.y = linear.y;
  odom.twist.twist.linear.z = linear.z;
  odom.twist.twist.angular.x = angular.x;
  odom.twist.twist.angular.y = angular.y;
  odom.twist.twist.angular.z = angular.z;
  return odom;
}

geometry_msgs::TransformStamped odometryTransform(const nav_msgs::Odometry& odom)
{
  geometry_msgs::TransformStamped tf;
  tf.header = odom.header;
  tf.child_frame_id = odom.child_frame_id;
  tf.transform.translation.x = odom.pose.pose.position.x;
  tf.transform.translation.y = odom.pose.pose.position.y;
  tf.transform.translation.z = odom.pose.pose.position.z;
  tf.transform.rotation = odom.pose.pose.orientation;
  return tf;
}

void OdometryPublisher::publish(int64_t time_ns, bool tf)
{
  if (last_ns_ >= 0 && time_ns - last_ns_ < period_ns_ && time_ns >= last_ns_)
    return;
  last_ns_ = time_ns;
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
