// A movable URDF joint and the Bullet constraint rows that act on it: what the joint layer
// (hardware/) drives and the simulation builds, steps and restores. Beside them SDF's joints that
// are not one such joint: a ball (a spherical Bullet link) and a coupling of two (a screw's turn and
// slide, a gearbox's two gears).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "bullet_plant/joint_limits.h"
#include "bullet_plant/log.h"
#include "physics/joint_drive.h"

namespace bullet_plant
{
// Bullet clamps every joint rate to this (btMultiBody::setMaxCoordinateVelocity), rad/s or m/s; the
// joint layer holds velocity commands to it too.
constexpr double kMaxJointSpeed = 1e4;

// A movable URDF joint and the Bullet pieces that act on it.
struct MovableJoint
{
  std::string name;
  JointType type = JointType::Revolute;
  int link = -1;                 // Bullet link index (= body index - 1)
  JointLimits limits;
  double damping = 0.0, friction = 0.0;
  std::unique_ptr<JointDrive> drive;           // the joint layer's motor / implicit PID
  std::unique_ptr<JointDrive> damper;          // URDF <dynamics damping> where an explicit torque would be unstable
  // SDF's <dynamics><spring_stiffness>, <spring_reference>: an effort -stiffness * (q - reference).
  double spring_stiffness = 0.0, spring_reference = 0.0;
  std::unique_ptr<JointDrive> spring;          // the spring where an explicit effort would not do (robot_builder.cpp)
  std::unique_ptr<JointDrive> dry_friction;    // URDF <dynamics friction>
  // ODE's joint motor, which Gazebo's <dynamics friction> is (dParamFMax with dParamVel 0): at most
  // `friction` towards this velocity (set_joint_properties' vel; 0: dry friction).
  double friction_velocity = 0.0;
  std::unique_ptr<JointDrive> lower_limit, upper_limit;  // rows only while the joint is at a limit
  double axis_inertia = 0.0;                   // the child body's inertia about the joint axis
  double explicit_effort = 0.0;                // actuator torque applied explicitly this step
  double initial_position = 0.0;
  bool internal = false;                       // the plant's own (a screw's slide): not among the robot's joints
};

// An SDF ball joint: a spherical Bullet link (three velocities, a quaternion position), which no
// joint layer drives. Gazebo 11's ODE ball joint has no position (NaN), velocity (0) or effort.
struct BallJoint
{
  std::string name;
  int link = -1;  // Bullet link index
};

// Two movable joints whose positions are tied, q_follower = multiplier * q_leader, by one rigid
// constraint row on qd_follower - multiplier * qd_leader that also takes back what the positions
// drift apart (holdCoupling). The row is solved with the contacts and the other joint rows, as ODE
// solves its screw and gearbox rows.
struct JointCoupling
{
  std::string name;  // the SDF joint (screw, gearbox)
  size_t leader = 0, follower = 0;  // in RobotMultibody::joints
  double multiplier = 0.0;
  std::unique_ptr<JointDrive> row;  // on the follower's velocity, coupled to the leader's
};

// The coupling's row for the coming step: rigid, its target velocity taking back kCouplingRecovery
// of the positions' mismatch per step (ODE's default erp).
constexpr double kCouplingRecovery = 0.2;
void holdCoupling(JointCoupling& c, const std::vector<MovableJoint>& joints, const btMultiBody& body, double dt);

// q held to the joint's URDF position limits, with a warning naming `what` (initial position,
// position), the joint and the robot when it was outside.
double positionWithinLimits(const MovableJoint& j, double q, Log& log, const std::string& robot, const std::string& what);

}  // namespace bullet_plant
