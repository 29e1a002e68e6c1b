// The one place where the plant's types meet geometry_msgs, sensor_msgs, nav_msgs and control_msgs: every node
// file converts through these (the camera's images and points are serialized in frame_messages.h).
#pragma once

#include <cstdint>
#include <string>

#include <control_msgs/FollowJointTrajectoryAction.h>
#include <control_msgs/GripperCommandAction.h>
#include <control_msgs/JointControllerState.h>
#include <control_msgs/JointTrajectoryControllerState.h>
#include <control_msgs/QueryTrajectoryState.h>
#include <gazebo_msgs/ContactState.h>
#include <geometry_msgs/Pose.h>
#include <geometry_msgs/TransformStamped.h>
#include <geometry_msgs/Twist.h>
#include <geometry_msgs/Vector3Stamped.h>
#include <geometry_msgs/WrenchStamped.h>
#include <hector_gazebo_plugins/SetBias.h>
#include <nav_msgs/Odometry.h>
#include <sensor_msgs/Imu.h>
#include <sensor_msgs/JointState.h>
#include <sensor_msgs/LaserScan.h>
#include <sensor_msgs/NavSatFix.h>
#include <std_msgs/Header.h>
#include <std_srvs/Empty.h>
#include <tf2_msgs/TFMessage.h>
#include <trajectory_msgs/JointTrajectory.h>
#include <urdf_model/pose.h>

#include "bullet_plant/controllers.h"
#include "bullet_plant/inertial_sensors.h"
#include "bullet_plant/messages.h"
#include "bullet_plant/robot.h"
#include "bullet_plant/sensors.h"
#include "bullet_plant/action_messages.h"
#include "ros_time.h"

namespace bullet_plant
{
inline std_msgs::Header rosHeader(int64_t stamp_ns, const std::string& frame_id = "")
{
  std_msgs::Header header;
  header.stamp = rosTime(stamp_ns);
  header.frame_id = frame_id;
  return header;
}

inline geometry_msgs::Vector3 toMsg(const urdf::Vector3& v)
{
  geometry_msgs::Vector3 m;
  m.x = v.x;
  m.y = v.y;
  m.z = v.z;
  return m;
}

inline geometry_msgs::Quaternion toMsg(const urdf::Rotation& q)
{
  geometry_msgs::Quaternion m;
  m.x = q.x;
  m.y = q.y;
  m.z = q.z;
  m.w = q.w;
  return m;
}

inline geometry_msgs::Pose toMsg(const urdf::Pose& p)
{
  geometry_msgs::Pose m;
  m.position.x = p.position.x;
  m.position.y = p.position.y;
  m.position.z = p.position.z;
  m.orientation = toMsg(p.rotation);
  return m;
}

inline geometry_msgs::Twist toMsg(const Twist& t)
{
  geometry_msgs::Twist m;
  m.linear = toMsg(urdf::Vector3(t.linear[0], t.linear[1], t.linear[2]));
  m.angular = toMsg(urdf::Vector3(t.angular[0], t.angular[1], t.angular[2]));
  return m;
}

// gazebo_ros normalises a requested orientation, so that an all-zero quaternion means no rotation.
inline urdf::Pose fromMsg(const geometry_msgs::Pose& m)
{
  urdf::Pose p;
  p.position = urdf::Vector3(m.position.x, m.position.y, m.position.z);
  const geometry_msgs::Quaternion& q = m.orientation;
  p.rotation = q.x == 0 && q.y == 0 && q.z == 0 && q.w == 0 ? urdf::Rotation(0, 0, 0, 1)
                                                            : urdf::Rotation(q.x, q.y, q.z, q.w);
  p.rotation.normalize();
  return p;
}

inline Twist fromMsg(const geometry_msgs::Twist& m)
{
  Twist t;
  t.linear = {{m.linear.x, m.linear.y, m.linear.z}};
  t.angular = {{m.angular.x, m.angular.y, m.angular.z}};
  return t;
}

// nav_msgs/Odometry of a pose in `frame` and a twist in `child` (what nav_msgs/Odometry's twist is
// in), covariances `variance` on their diagonals; used by the ground truth (odometry_publisher.cpp,
// gazebo_ros_p3d) and by the drive controllers' odometry (controller_topics.cpp).
inline nav_msgs::Odometry odometryMessage(int64_t stamp_ns, const std::string& frame, const std::string& child,
                                          const urdf::Pose& pose, const urdf::Vector3& linear,
                                          const urdf::Vector3& angular, double variance = 0.0)
{
  nav_msgs::Odometry odom;
  odom.header = rosHeader(stamp_ns, frame);
  odom.child_frame_id = child;
  odom.pose.pose = toMsg(pose);
  odom.twist.twist.linear = toMsg(linear);
  odom.twist.twist.angular = toMsg(angular);
  for (int i : {0, 7, 14, 21, 28, 35})
    odom.pose.covariance[i] = odom.twist.covariance[i] = variance;
  return odom;
}

// The frame -> child transform an odometry message implies, for /tf.
inline geometry_msgs::TransformStamped odometryTransform(const nav_msgs::Odometry& odom)
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

// The sensors' readings carry no names: each plugin stamps its own frame ids (plugin_names.h).
inline sensor_msgs::Imu toMsg(const ImuReading& r, const std::string& frame_id)
{
  sensor_msgs::Imu m;
  m.header = rosHeader(r.stamp_ns, frame_id);
  m.orientation = toMsg(r.orientation);
  m.angular_velocity = toMsg(r.angular_velocity);
  m.linear_acceleration = toMsg(r.linear_acceleration);
  for (int i : {0, 4, 8})
    m.orientation_covariance[i] = m.angular_velocity_covariance[i] = m.linear_acceleration_covariance[i] = r.variance;
  return m;
}

inline nav_msgs::Odometry toMsg(const GroundTruthReading& r, const std::string& frame_id, const std::string& child_frame_id)
{
  return odometryMessage(r.stamp_ns, frame_id, child_frame_id, r.pose, r.linear, r.angular, r.variance);
}

inline sensor_msgs::LaserScan toMsg(const LaserScan& s, const std::string& frame_id)
{
  sensor_msgs::LaserScan m;
  m.header = rosHeader(s.stamp_ns, frame_id);
  m.angle_min = s.angle_min;
  m.angle_max = s.angle_max;
  m.angle_increment = s.angle_increment;
  m.time_increment = s.time_increment;
  m.scan_time = s.scan_time;
  m.range_min = s.range_min;
  m.range_max = s.range_max;
  m.ranges = s.ranges;
  return m;
}

inline sensor_msgs::JointState toMsg(const JointStateSample& s)
{
  sensor_msgs::JointState msg;
  msg.header = rosHeader(s.stamp_ns);
  msg.name = s.name;
  msg.position = s.position;
  msg.velocity = s.velocity;
  msg.effort = s.effort;
  return msg;
}

inline EmptyRequest fromMsg(const std_srvs::Empty::Request&) { return EmptyRequest(); }
inline void toMsg(const EmptyRequest&, std_srvs::Empty::Response&) {}

inline SetBiasRequest fromMsg(const hector_gazebo_plugins::SetBias::Request& m)
{
  return SetBiasRequest{urdf::Vector3(m.bias.x, m.bias.y, m.bias.z)};
}
inline void toMsg(const EmptyRequest&, hector_gazebo_plugins::SetBias::Response&) {}

inline QueryTrajectoryStateRequest fromMsg(const control_msgs::QueryTrajectoryState::Request& m)
{
  return QueryTrajectoryStateRequest{int64_t(m.time.toNSec())};
}

inline void toMsg(const QueryTrajectoryStateResponse& s, control_msgs::QueryTrajectoryState::Response& m)
{
  m.name = s.name;
  m.position = s.position;
  m.velocity = s.velocity;
  m.acceleration = s.acceleration;
}

inline control_msgs::JointControllerState toMsg(const ControllerStateSample& s)
{
  control_msgs::JointControllerState msg;
  msg.header = rosHeader(s.stamp_ns);
  msg.set_point = s.set_point;
  msg.process_value = s.process_value;
  msg.process_value_dot = s.process_value_dot;
  msg.error = s.error;
  msg.time_step = s.time_step;
  msg.command = s.command;
  msg.p = s.p;
  msg.i = s.i;
  msg.d = s.d;
  msg.i_clamp = s.i_clamp;
  msg.antiwindup = s.antiwindup;
  return msg;
}

inline nav_msgs::Odometry toMsg(const OdometrySample& s)
{
  nav_msgs::Odometry odom = odometryMessage(s.stamp_ns, s.frame_id, s.child_frame_id, s.pose, s.linear, s.angular);
  for (int k = 0; k < 6; ++k)
  {
    odom.pose.covariance[7 * k] = s.pose_covariance_diagonal[k];
    odom.twist.covariance[7 * k] = s.twist_covariance_diagonal[k];
  }
  return odom;
}

inline TransformsCommand fromMsg(const tf2_msgs::TFMessage& m)
{
  TransformsCommand out;
  for (const geometry_msgs::TransformStamped& tf : m.transforms)
  {
    TransformSample s;
    s.stamp_ns = int64_t(tf.header.stamp.toNSec());
    s.frame_id = tf.header.frame_id;
    s.child_frame_id = tf.child_frame_id;
    s.pose.position = urdf::Vector3(tf.transform.translation.x, tf.transform.translation.y, tf.transform.translation.z);
    s.pose.rotation = urdf::Rotation(tf.transform.rotation.x, tf.transform.rotation.y, tf.transform.rotation.z,
                                     tf.transform.rotation.w);
    out.transforms.push_back(s);
  }
  return out;
}

inline tf2_msgs::TFMessage toMsg(const TransformSample& s)
{
  geometry_msgs::TransformStamped tf;
  tf.header = rosHeader(s.stamp_ns, s.frame_id);
  tf.child_frame_id = s.child_frame_id;
  tf.transform.translation = toMsg(s.pose.position);
  tf.transform.rotation = toMsg(s.pose.rotation);
  tf2_msgs::TFMessage msg;
  msg.transforms.push_back(tf);
  return msg;
}

inline sensor_msgs::NavSatFix toMsg(const NavSatFixSample& s)
{
  sensor_msgs::NavSatFix m;
  m.header = rosHeader(s.stamp_ns, s.frame_id);
  m.status.status = int8_t(s.status);
  m.status.service = uint16_t(s.service);
  m.latitude = s.latitude;
  m.longitude = s.longitude;
  m.altitude = s.altitude;
  for (int k = 0; k < 3; ++k)
    m.position_covariance[4 * k] = s.position_covariance_diagonal[k];
  m.position_covariance_type = sensor_msgs::NavSatFix::COVARIANCE_TYPE_DIAGONAL_KNOWN;
  return m;
}

inline sensor_msgs::Imu toMsg(const ImuSample& s)
{
  sensor_msgs::Imu m;
  m.header = rosHeader(s.stamp_ns, s.frame_id);
  m.orientation = toMsg(s.orientation);
  m.angular_velocity = toMsg(s.angular_velocity);
  m.linear_acceleration = toMsg(s.linear_acceleration);
  for (int k = 0; k < 3; ++k)
  {
    m.orientation_covariance[4 * k] = s.orientation_covariance_diagonal[k];
    m.angular_velocity_covariance[4 * k] = s.angular_velocity_covariance_diagonal[k];
    m.linear_acceleration_covariance[4 * k] = s.linear_acceleration_covariance_diagonal[k];
  }
  return m;
}

inline geometry_msgs::WrenchStamped toMsg(const WrenchStampedSample& s)
{
  geometry_msgs::WrenchStamped m;
  m.header = rosHeader(s.stamp_ns, s.frame_id);
  m.wrench.force = toMsg(s.force);
  m.wrench.torque = toMsg(s.torque);
  return m;
}

inline geometry_msgs::Vector3Stamped toMsg(const Vector3StampedSample& s)
{
  geometry_msgs::Vector3Stamped m;
  m.header = rosHeader(s.stamp_ns, s.frame_id);
  m.vector = toMsg(s.vector);
  return m;
}

// Trajectories. A stamp is kept as ROS time in ns; stamp 0 stays 0 ("now").
inline TrajectoryPointSample fromMsg(const trajectory_msgs::JointTrajectoryPoint& m)
{
  return TrajectoryPointSample{m.positions, m.velocities, m.accelerations, m.effort, m.time_from_start.toNSec()};
}

inline JointTrajectoryCommand fromMsg(const trajectory_msgs::JointTrajectory& m)
{
  JointTrajectoryCommand t;
  t.stamp_ns = int64_t(m.header.stamp.toNSec());
  t.frame_id = m.header.frame_id;
  t.joint_names = m.joint_names;
  for (const trajectory_msgs::JointTrajectoryPoint& p : m.points)
    t.points.push_back(fromMsg(p));
  return t;
}

inline std::vector<JointToleranceSpec> fromMsg(const std::vector<control_msgs::JointTolerance>& m)
{
  std::vector<JointToleranceSpec> out;
  for (const control_msgs::JointTolerance& t : m)
    out.push_back(JointToleranceSpec{t.name, t.position, t.velocity, t.acceleration});
  return out;
}

inline FollowJointTrajectoryGoal fromMsg(const control_msgs::FollowJointTrajectoryGoal& m)
{
  return FollowJointTrajectoryGoal{fromMsg(m.trajectory), fromMsg(m.path_tolerance), fromMsg(m.goal_tolerance),
                                   m.goal_time_tolerance.toNSec()};
}

inline trajectory_msgs::JointTrajectoryPoint toMsg(const TrajectoryPointSample& s)
{
  trajectory_msgs::JointTrajectoryPoint m;
  m.positions = s.positions;
  m.velocities = s.velocities;
  m.accelerations = s.accelerations;
  m.effort = s.effort;
  m.time_from_start.fromNSec(s.time_from_start_ns);
  return m;
}

template <class RosMsg>  // JointTrajectoryControllerState and FollowJointTrajectoryFeedback
RosMsg trajectoryStateMsg(const TrajectoryStateSample& s)
{
  RosMsg m;
  m.header = rosHeader(s.stamp_ns);
  m.joint_names = s.joint_names;
  m.desired = toMsg(s.desired);
  m.actual = toMsg(s.actual);
  m.error = toMsg(s.error);
  return m;
}

inline control_msgs::JointTrajectoryControllerState toMsg(const TrajectoryStateSample& s)
{
  return trajectoryStateMsg<control_msgs::JointTrajectoryControllerState>(s);
}

// An action's result and feedback, filled into the ROS type actionlib's server wants.
inline void toMsg(const FollowJointTrajectoryResult& r, control_msgs::FollowJointTrajectoryResult& m)
{
  m.error_code = r.error_code;
  m.error_string = r.error_string;
}

inline void toMsg(const TrajectoryStateSample& s, control_msgs::FollowJointTrajectoryFeedback& m)
{
  m = trajectoryStateMsg<control_msgs::FollowJointTrajectoryFeedback>(s);
}

inline GripperCommandGoal fromMsg(const control_msgs::GripperCommandGoal& m)
{
  return GripperCommandGoal{m.command.position, m.command.max_effort};
}

template <class RosMsg>  // GripperCommandResult and GripperCommandFeedback
void toMsg(const GripperCommandResult& r, RosMsg& m)
{
  m.position = r.position;
  m.effort = r.effort;
  m.stalled = r.stalled;
  m.reached_goal = r.reached_goal;
}

// One touching point added to a gazebo_msgs/ContactState: its position, normal, depth and wrench,
// and the wrench to the state's total, as gazebo_ros_bumper fills them.
inline void addContactPoint(gazebo_msgs::ContactState& state, const urdf::Vector3& position,
                            const urdf::Vector3& normal, double depth, const urdf::Vector3& force,
                            const urdf::Vector3& torque)
{
  geometry_msgs::Wrench wrench;
  wrench.force = toMsg(force);
  wrench.torque = toMsg(torque);
  state.wrenches.push_back(wrench);
  state.total_wrench.force.x += wrench.force.x;
  state.total_wrench.force.y += wrench.force.y;
  state.total_wrench.force.z += wrench.force.z;
  state.total_wrench.torque.x += wrench.torque.x;
  state.total_wrench.torque.y += wrench.torque.y;
  state.total_wrench.torque.z += wrench.torque.z;
  state.contact_positions.push_back(toMsg(position));
  state.contact_normals.push_back(toMsg(normal));
  state.depths.push_back(depth);
}

}  // namespace bullet_plant
