#include "odometry_publisher.h"

#include <tf2_msgs/TFMessage.h>

#include "bullet_plant/geometry.h"
#include "bullet_plant/robot.h"
#include "msg_conversions.h"
#include "outbox.h"

namespace bullet_plant
{
OdometryPublisher::OdometryPublisher(Robot& robot, ros::NodeHandle& nh, Outbox& outbox) : robot_(robot), outbox_(outbox)
{
  odom_pub_ = CountedPublisher::advertise<nav_msgs::Odometry>(nh, "odom", 10);
  tf_pub_ = CountedPublisher::advertise<tf2_msgs::TFMessage>(nh, "/tf", 100);
}

void OdometryPublisher::publish(int64_t time_ns, bool tf)
{
  if (gate_.due(time_ns))
    publishNow(time_ns, tf);
}

void OdometryPublisher::publishNow(int64_t time_ns, bool tf)
{
  tf = tf && tf_pub_.subscribed();
  if (!tf && !odom_pub_.subscribed())
    return;
  urdf::Pose pose = robot_.basePose();
  Twist twist = robot_.baseTwist();
  // nav_msgs/Odometry's twist is in the child frame.
  urdf::Rotation to_body = pose.rotation.GetInverse();
  nav_msgs::Odometry odom = odometryMessage(
      time_ns, "odom", robot_.description().model->getRoot()->name, pose,
      rotate(to_body, urdf::Vector3(twist.linear[0], twist.linear[1], twist.linear[2])),
      rotate(to_body, urdf::Vector3(twist.angular[0], twist.angular[1], twist.angular[2])));
  tf2_msgs::TFMessage transform;
  if (tf)
    transform.transforms.push_back(odometryTransform(odom));
  if (odom_pub_.subscribed())
    outbox_.publish(odom_pub_.publisher(), std::move(odom));
  if (tf)
    outbox_.publish(tf_pub_.publisher(), std::move(transform));
}

}  // namespace bullet_plant
