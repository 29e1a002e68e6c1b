// Joints made at run time (WorldPluginContext::attach: what Gazebo's Joint::Attach asks of the
// plant): a fixed, prismatic, revolute or ball joint between a box and the world or another box,
// checked against the motion they must allow: a slide down a tilted axis at g's part along it, a
// pendulum's swing at the speed its energy gives, the limits, an effort that holds the box up, and
// what a bad joint gets (nothing attached, the world runs).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "bullet_plant/robot.h"
#include "bullet_plant/world.h"
#include "simulation/internals.h"
#include "simulation/world_plugin_context.h"

using namespace bullet_plant;

namespace
{
constexpr double kMass = 2.0, kSide = 0.2;

// A free box of our own, 0.2 m a side and 2 kg, its link `box`.
std::string boxModel(const std::string& name)
{
  const double i = kMass * kSide * kSide / 6;
  return "<sdf version='1.6'><model name='" + name + "'><link name='box'><inertial><mass>" + std::to_string(kMass) +
         "</mass><inertia><ixx>" + std::to_string(i) + "</ixx><iyy>" + std::to_string(i) + "</iyy><izz>" +
         std::to_string(i) + "</izz></inertia></inertial><collision name='c'><geometry><box><size>0.2 0.2 0.2</size>"
         "</box></geometry></collision></link></model></sdf>";
}

// Boxes box0, box1 ... at `at`, no ground under them, and the world's side of Gazebo's physics.
struct Scene
{
  World world;
  PlantWorldPluginContext context;
  explicit Scene(std::vector<urdf::Vector3> at) : context(world, *internalsOf(spawnBoxes(at)).world) {}
  Robot& spawnBoxes(const std::vector<urdf::Vector3>& at)
  {
    for (size_t b = 0; b < at.size(); ++b)
    {
      urdf::Pose pose;
      pose.position = at[b];
      world.spawn(boxModel("box" + std::to_string(b)), "box" + std::to_string(b), pose);
    }
    return *world.robot("box0");
  }
  urdf::Pose pose(int box = 0) { return world.robot("box" + std::to_string(box))->linkPose("box"); }
  double g() const { return -context.gravity().z; }
  void run(double seconds) { world.step(static_cast<int>(std::lround(seconds / world.timeStep()))); }
};

RunTimeJoint toWorld(RunTimeJoint::Type type, const urdf::Vector3& anchor, const urdf::Vector3& axis)
{
  RunTimeJoint joint;
  joint.type = type;
  joint.child_model = "box0";
  joint.child_link = "box";
  joint.anchor = anchor;
  joint.axis = axis;
  return joint;
}

double angleOf(const urdf::Rotation& r)
{
  double x, y, z, w;
  r.getQuaternion(x, y, z, w);
  return 2 * std::acos(std::min(1.0, std::fabs(w)));
}
}  // namespace

TEST(RunTimeJoints, APrismaticJointToTheWorldSlidesAlongItsTiltedAxisAtGsPartAndStopsAtItsLimit)
{
  Scene s({urdf::Vector3(0, 0, 10)});
  const double c = 1 / std::sqrt(2.0);
  RunTimeJoint joint = toWorld(RunTimeJoint::Type::Prismatic, urdf::Vector3(0, 0, 10), urdf::Vector3(c, 0, c));
  joint.lower = -0.5;
  const int id = s.context.attach(joint);
  ASSERT_GE(id, 0);
  const double t = 0.2, a = -s.g() * c;  // along the axis: g's part, no friction
  s.run(t);
  const urdf::Pose p = s.pose();
  const double along = (p.position.x + (p.position.z - 10)) * c;
  EXPECT_NEAR(s.context.jointPosition(id), along, 1e-6);
  EXPECT_NEAR(along, 0.5 * a * t * t, 0.02 * 0.5 * s.g() * c * t * t);
  EXPECT_NEAR(s.context.jointVelocity(id), a * t, 0.02 * s.g() * c * t);
  // On the line, not turned.
  EXPECT_NEAR(p.position.x - (p.position.z - 10), 0.0, 1e-3);
  EXPECT_NEAR(p.position.y, 0.0, 1e-6);
  EXPECT_LT(angleOf(p.rotation), 1e-3);
  s.run(1.0);
  EXPECT_NEAR(s.context.jointPosition(id), -0.5, 0.005);
  EXPECT_NEAR(s.context.jointVelocity(id), 0.0, 0.01);
}

TEST(RunTimeJoints, AnEffortOfItsWeightHoldsABoxOnAVerticalSlideAndItsDampingSlowsItsFall)
{
  Scene s({urdf::Vector3(0, 0, 10), urdf::Vector3(3, 0, 10)});
  const int held = s.context.attach(toWorld(RunTimeJoint::Type::Prismatic, urdf::Vector3(0, 0, 10), urdf::Vector3(0, 0, 1)));
  RunTimeJoint damped = toWorld(RunTimeJoint::Type::Prismatic, urdf::Vector3(3, 0, 10), urdf::Vector3(0, 0, 1));
  damped.child_model = "box1";
  damped.damping = 20.0;  // N s/m: terminal speed m g / d = 0.98 m/s
  const int falling = s.context.attach(damped);
  ASSERT_GE(held, 0);
  ASSERT_GE(falling, 0);
  for (int i = 0; i < 1000; ++i)
  {
    s.context.addJointEffort(held, kMass * s.g());
    s.world.step();
  }
  EXPECT_NEAR(s.context.jointPosition(held), 0.0, 1e-3);
  EXPECT_NEAR(s.context.jointVelocity(falling), -kMass * s.g() / 20.0, 0.02);
}

TEST(RunTimeJoints, ARevoluteJointSwingsAPendulumAboutItsAxisAtTheSpeedItsEnergyGivesAndStopsAtItsLimit)
{
  Scene s({urdf::Vector3(0, 0, 10), urdf::Vector3(3, 0, 10)});
  // 1 m from the anchor, level: the box swings down about y, a positive turn.
  const int id = s.context.attach(toWorld(RunTimeJoint::Type::Revolute, urdf::Vector3(-1, 0, 10), urdf::Vector3(0, 1, 0)));
  RunTimeJoint limited = toWorld(RunTimeJoint::Type::Revolute, urdf::Vector3(2, 0, 10), urdf::Vector3(0, 1, 0));
  limited.child_model = "box1";
  limited.upper = 0.5;
  limited.damping = 20.0;  // N m s/rad: it comes to its limit slowly (a hard stop can rebound: docs)
  const int stopped = s.context.attach(limited);
  ASSERT_GE(id, 0);
  ASSERT_GE(stopped, 0);
  double lowest = 10, speed_there = 0;
  for (int i = 0; i < 800; ++i)
  {
    s.world.step();
    const urdf::Pose p = s.pose();
    const double dx = p.position.x + 1, dz = p.position.z - 10;
    ASSERT_NEAR(std::hypot(dx, dz), 1.0, 2e-3) << "step " << i;
    ASSERT_NEAR(p.position.y, 0.0, 1e-6);
    ASSERT_NEAR(s.context.jointPosition(id), std::atan2(-dz, dx), 2e-3) << "step " << i;
    if (p.position.z < lowest)
    {
      lowest = p.position.z;
      speed_there = std::fabs(s.context.jointVelocity(id));
    }
  }
  // At the bottom: m g r = (m r^2 + I) w^2 / 2.
  const double inertia = kMass * 1.0 + kMass * kSide * kSide / 6;
  EXPECT_NEAR(lowest, 9.0, 2e-3);
  EXPECT_NEAR(speed_there, std::sqrt(2 * kMass * s.g() * 1.0 / inertia), 0.03 * std::sqrt(2 * s.g()));
  EXPECT_NEAR(s.context.jointPosition(stopped), 0.5, 0.01);
}

TEST(RunTimeJoints, ABallJointKeepsTheAnchorAndAFixedOneHoldsTheBoxUntilReleased)
{
  Scene s({urdf::Vector3(0, 0, 10), urdf::Vector3(3, 0, 10)});
  const int ball = s.context.attach(toWorld(RunTimeJoint::Type::Ball, urdf::Vector3(-0.6, 0.8, 10), urdf::Vector3()));
  RunTimeJoint fixed = toWorld(RunTimeJoint::Type::Fixed, urdf::Vector3(3, 0, 10), urdf::Vector3());
  fixed.child_model = "box1";
  const int held = s.context.attach(fixed);
  ASSERT_GE(ball, 0);
  ASSERT_GE(held, 0);
  s.run(0.5);
  const urdf::Pose p = s.pose();
  EXPECT_NEAR(std::hypot(p.position.x + 0.6, p.position.y - 0.8, p.position.z - 10), 1.0, 2e-3);
  EXPECT_LT(p.position.z, 9.3);  // it swung down
  EXPECT_EQ(s.context.jointPosition(ball), 0.0);  // neither slides nor turns about one axis
  EXPECT_NEAR(s.pose(1).position.z, 10.0, 1e-3);
  EXPECT_LT(angleOf(s.pose(1).rotation), 1e-3);
  s.context.detach(held);
  s.run(0.5);
  EXPECT_NEAR(s.pose(1).position.z, 10.0 - 0.5 * s.g() * 0.25, 0.02);
}

TEST(RunTimeJoints, AnEffortOnAJointBetweenTwoModelsPushesThemApartAlongItsAxisAsTheyFall)
{
  Scene s({urdf::Vector3(0, 0, 10), urdf::Vector3(0.5, 0, 10)});
  RunTimeJoint slide;
  slide.type = RunTimeJoint::Type::Prismatic;
  slide.parent_model = "box0";
  slide.parent_link = "box";
  slide.child_model = "box1";
  slide.child_link = "box";
  slide.anchor = urdf::Vector3(0.5, 0, 10);
  slide.axis = urdf::Vector3(1, 0, 0);
  const int id = s.context.attach(slide);
  ASSERT_GE(id, 0);
  for (int i = 0; i < 500; ++i)
  {
    s.context.addJointEffort(id, 1.0);  // 1 N on box1 along x, its reaction on box0
    s.world.step();
  }
  // Each box 0.5 m/s^2 its way: they part at 1 m/s^2, and fall together.
  EXPECT_NEAR(s.context.jointPosition(id), 0.5 * 1.0 * 0.25, 0.003);
  EXPECT_NEAR(s.pose(1).position.x - 0.5, 0.5 * 0.5 * 0.25, 0.002);
  EXPECT_NEAR(s.pose(0).position.x, -0.5 * 0.5 * 0.25, 0.002);
  EXPECT_NEAR(s.pose(1).position.z, s.pose(0).position.z, 1e-3);
  EXPECT_NEAR(s.pose(0).position.z, 10.0 - 0.5 * s.g() * 0.25, 0.01);
}

TEST(RunTimeJoints, ABadJointIsRefusedWithWhyAndTheWorldRuns)
{
  Scene s({urdf::Vector3(0, 0, 10)});
  const double nan = std::numeric_limits<double>::quiet_NaN();
  RunTimeJoint unknown = toWorld(RunTimeJoint::Type::Fixed, urdf::Vector3(), urdf::Vector3());
  unknown.child_model = "nobody";
  EXPECT_EQ(s.context.attach(unknown), -1);
  RunTimeJoint no_link = toWorld(RunTimeJoint::Type::Fixed, urdf::Vector3(), urdf::Vector3());
  no_link.child_link = "wheel";
  EXPECT_EQ(s.context.attach(no_link), -1);
  EXPECT_EQ(s.context.attach(toWorld(RunTimeJoint::Type::Ball, urdf::Vector3(nan, 0, 0), urdf::Vector3())), -1);
  EXPECT_EQ(s.context.attach(toWorld(RunTimeJoint::Type::Prismatic, urdf::Vector3(), urdf::Vector3(0, 0, 0))), -1);
  RunTimeJoint inverted = toWorld(RunTimeJoint::Type::Revolute, urdf::Vector3(), urdf::Vector3(0, 0, 1));
  inverted.lower = 1;
  inverted.upper = -1;
  EXPECT_EQ(s.context.attach(inverted), -1);
  RunTimeJoint same_body = toWorld(RunTimeJoint::Type::Fixed, urdf::Vector3(), urdf::Vector3());
  same_body.parent_model = "box0";
  same_body.parent_link = "box";
  EXPECT_EQ(s.context.attach(same_body), -1);
  // A good one: a NaN effort is dropped; a released id answers 0 and takes nothing.
  const int id = s.context.attach(toWorld(RunTimeJoint::Type::Prismatic, urdf::Vector3(0, 0, 10), urdf::Vector3(0, 0, 1)));
  ASSERT_GE(id, 0);
  s.context.addJointEffort(id, nan);
  s.run(0.1);
  EXPECT_TRUE(std::isfinite(s.pose().position.z));
  EXPECT_NEAR(s.context.jointVelocity(id), -s.g() * 0.1, 0.02);
  s.context.detach(id);
  s.context.addJointEffort(id, 5.0);
  EXPECT_EQ(s.context.jointPosition(id), 0.0);
  s.run(0.1);
  EXPECT_NEAR(s.pose().position.z, 10.0 - 0.5 * s.g() * 0.04, 0.01);
}
