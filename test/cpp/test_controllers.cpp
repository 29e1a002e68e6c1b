// The controller types (controllers.cpp, docs/interfaces.md section 4) on real joint handles: what
// the forward command controllers write, the joint state controller's rate and joints, the effort
// PID controllers' state reports.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "bullet_plant/controllers.h"
#include "bullet_plant/log.h"
#include "bullet_plant/params.h"
#include "controller_commands.h"
#include "two_axle_joints.h"

using namespace bullet_plant;

namespace
{
class ControllerTest : public ::testing::Test
{
protected:
  ControllerTest() { log.setSink([this](LogLevel, const std::string& m) { messages.push_back(m); }); }

  // A controller of `type` named `name` under /bot, initialised with what params holds for it.
  std::unique_ptr<Controller> make(const std::string& type, const std::string& name)
  {
    std::unique_ptr<Controller> c = createController(type);
    EXPECT_NE(c, nullptr) << type;
    ControllerContext context{params, "/bot/" + name, joints, log};
    EXPECT_TRUE(c->init(context)) << name << ": " << (messages.empty() ? "" : messages.back());
    return c;
  }

  // Runs the controller's control loop for `steps` updates of 1 ms.
  void run(Controller& c, int steps)
  {
    for (int k = 0; k < steps; ++k)
    {
      time_ns += 1000000;
      c.update(time_ns, 0.001);
    }
  }

  TwoAxleJoints joints;
  Param params = Param::map();
  Log log;
  std::vector<std::string> messages;
  int64_t time_ns = 0;
};
}  // namespace

TEST(ControllerTypes, UnknownTypeMakesNothing)
{
  EXPECT_EQ(createController("velocity_controllers/JointPositionController"), nullptr);
  EXPECT_EQ(controllerTypes().size(), 18u);  // each one listed in ControllerManagerTest.ListsTheTypesItOffers
  for (const std::string& type : controllerTypes())
    EXPECT_NE(createController(type), nullptr) << type;
}

TEST_F(ControllerTest, ForwardCommandControllersWriteTheirCommandEachUpdate)
{
  struct Case { const char* type; const char* joint; };
  for (const Case& k : {Case{"velocity_controllers/JointVelocityController", "left_wheel"},
                        Case{"effort_controllers/JointEffortController", "right_hinge"},
                        Case{"position_controllers/JointPositionController", "mast"}})
  {
    params.set(std::string("/bot/fwd/type"), Param::string(k.type));
    params.set(std::string("/bot/fwd/joint"), Param::string(k.joint));
    std::unique_ptr<Controller> c = make(k.type, "fwd");
    JointHandle& h = *joints.handle(k.joint);
    ASSERT_EQ(c->claimedResources().size(), 1u);
    EXPECT_EQ(c->claimedResources()[0].hardware_interface, interfaceName(h.interface())) << k.type;
    EXPECT_EQ(c->claimedResources()[0].resources, std::vector<std::string>{k.joint});
    EXPECT_EQ(commandTopic<double>(*c), "command");
    EXPECT_EQ(c->output<ControllerStateSample>(), nullptr);

    h.setCommand(9.0);
    ASSERT_TRUE(command(*c, 5.0));
    c->starting(time_ns);
    run(*c, 1);
    EXPECT_EQ(h.command(), 0.0) << k.type << " starts from 0 (the position one from where the joint is, 0 here), not from an earlier command";
    EXPECT_TRUE(command(*c, 0.25));
    EXPECT_EQ(h.command(), 0.0) << "written by the next update, not by the command itself";
    run(*c, 1);
    EXPECT_EQ(h.command(), 0.25) << k.type;
    for (double bad : {std::nan(""), std::numeric_limits<double>::infinity()})
      EXPECT_FALSE(command(*c, bad)) << k.type;
    run(*c, 1);
    EXPECT_EQ(h.command(), 0.25) << "a refused command leaves the last one";
    EXPECT_EQ(h.rejectedCommands(), 0) << "refused by the controller, never reaching the joint";
  }
}

TEST_F(ControllerTest, JointStateControllerSamplesAtItsPublishRate)
{
  params.set("/bot/jsc/publish_rate", Param::real(50.0));
  std::unique_ptr<Controller> c = make("joint_state_controller/JointStateController", "jsc");
  ASSERT_EQ(c->claimedResources().size(), 1u);
  EXPECT_EQ(c->claimedResources()[0].hardware_interface, std::string(kJointStateInterface));
  EXPECT_EQ(c->ports().size(), 1u) << "joint_states only, no command";
  c->starting(time_ns);
  run(*c, 1000);
  std::vector<JointStateSample> samples = take<JointStateSample>(*c);
  EXPECT_EQ(samples.size(), 49u) << "every 20 ms after the first 20 ms, strictly later than the period";
  EXPECT_EQ(c->messagesPublished(), samples.size());
  ASSERT_FALSE(samples.empty());
  EXPECT_EQ(samples.front().stamp_ns, 21000000);
  EXPECT_EQ(samples[1].stamp_ns - samples[0].stamp_ns, 20000000);
  EXPECT_EQ(samples.back().name, (std::vector<std::string>{"left_hinge", "left_wheel", "mast", "right_hinge", "right_wheel"}))
      << "every handle, sorted by name";
  EXPECT_EQ(samples.back().position.size(), 5u);
  EXPECT_TRUE(take<JointStateSample>(*c).empty()) << "taken once";
  ASSERT_NE(c->output<JointStateSample>()->latest(), nullptr);
  EXPECT_EQ(c->output<JointStateSample>()->latest()->stamp_ns, samples.back().stamp_ns);
}

TEST_F(ControllerTest, JointStateControllerJointsAndExtraJoints)
{
  params.set("/bot/jsc/publish_rate", Param::integer(1000));
  params.set("/bot/jsc/joints", Param::list({Param::string("right_wheel"), Param::string("mast")}));
  Param extra = Param::map();
  extra.set("name", Param::string("virtual"));
  extra.set("position", Param::real(1.5));
  params.set("/bot/jsc/extra_joints", Param::list({extra}));
  std::unique_ptr<Controller> c = make("joint_state_controller/JointStateController", "jsc");
  c->starting(time_ns);
  run(*c, 3);
  std::vector<JointStateSample> samples = take<JointStateSample>(*c);
  ASSERT_FALSE(samples.empty());
  EXPECT_EQ(samples.back().name, (std::vector<std::string>{"right_wheel", "mast", "virtual"}));
  EXPECT_EQ(samples.back().position.back(), 1.5);
  EXPECT_EQ(samples.back().velocity.back(), 0.0);

  params.set("/bot/bad/publish_rate", Param::integer(10));
  params.set("/bot/bad/joints", Param::list({Param::string("nowhere")}));
  std::unique_ptr<Controller> bad = createController("joint_state_controller/JointStateController");
  ControllerContext context{params, "/bot/bad", joints, log};
  EXPECT_FALSE(bad->init(context));
  EXPECT_EQ(messages.back(), "Joint 'nowhere' given in /bot/bad/joints has no state handle");
}

TEST_F(ControllerTest, JointStateControllerWithRateZeroNeverSamples)
{
  params.set("/bot/jsc/publish_rate", Param::integer(0));
  std::unique_ptr<Controller> c = make("joint_state_controller/JointStateController", "jsc");
  c->starting(time_ns);
  run(*c, 100);
  EXPECT_EQ(c->messagesPublished(), 0u);
}

TEST_F(ControllerTest, EffortPositionControllerReportsItsStateEveryTenthUpdate)
{
  params.set("/bot/steer/joint", Param::string("left_hinge"));
  params.set("/bot/steer/pid/p", Param::real(4.0));
  params.set("/bot/steer/pid/i", Param::real(2.0));
  params.set("/bot/steer/pid/d", Param::real(1.0));
  params.set("/bot/steer/pid/i_clamp", Param::real(0.5));
  std::unique_ptr<Controller> c = make("effort_controllers/JointPositionController", "steer");
  EXPECT_EQ(commandTopic<double>(*c), "command");
  ASSERT_NE(c->output<ControllerStateSample>(), nullptr);
  EXPECT_EQ(c->output<ControllerStateSample>()->topic(), "state");
  EXPECT_EQ(c->claimedResources()[0].hardware_interface, "hardware_interface::EffortJointInterface");
  c->starting(time_ns);
  ASSERT_TRUE(command(*c, 1.0));
  run(*c, 25);
  std::vector<ControllerStateSample> states = take<ControllerStateSample>(*c);
  ASSERT_EQ(states.size(), 3u) << "updates 0, 10 and 20";
  EXPECT_EQ(states[1].stamp_ns - states[0].stamp_ns, 10000000);
  const ControllerStateSample& s = states.back();
  EXPECT_EQ(s.set_point, 0.6) << "the command limited to the joint's range";
  EXPECT_EQ(s.process_value, 0.0);
  EXPECT_DOUBLE_EQ(s.error, 0.6);
  EXPECT_EQ(s.time_step, 0.001);
  EXPECT_EQ(s.p, 4.0);
  EXPECT_EQ(s.i, 2.0);
  EXPECT_EQ(s.d, 1.0);
  EXPECT_EQ(s.i_clamp, 0.5);
  EXPECT_FALSE(s.antiwindup);
  EXPECT_EQ(joints.handle("left_hinge")->rejectedCommands(), 0);
}

TEST_F(ControllerTest, EffortVelocityControllerTracksTheWheelSpeed)
{
  params.set("/bot/wheel/joint", Param::string("right_hinge"));
  params.set("/bot/wheel/pid/p", Param::real(2.0));
  std::unique_ptr<Controller> c = make("effort_controllers/JointVelocityController", "wheel");
  c->starting(time_ns);
  ASSERT_TRUE(command(*c, 3.0));
  run(*c, 1);
  std::vector<ControllerStateSample> states = take<ControllerStateSample>(*c);
  ASSERT_EQ(states.size(), 1u);
  EXPECT_EQ(states[0].set_point, 3.0) << "a velocity set point is not limited by the position range";
  EXPECT_EQ(states[0].process_value, 0.0);
  EXPECT_EQ(states[0].process_value_dot, 0.0);
  EXPECT_EQ(states[0].error, 3.0);
}

TEST_F(ControllerTest, JointGroupControllersForwardOneValuePerJoint)
{
  struct Case { const char* type; std::vector<std::string> joints; };
  for (const Case& k : {Case{"velocity_controllers/JointGroupVelocityController", {"right_wheel", "left_wheel"}},
                        Case{"effort_controllers/JointGroupEffortController", {"left_hinge", "right_hinge"}},
                        Case{"position_controllers/JointGroupPositionController", {"mast"}}})
  {
    std::vector<Param> names;
    for (const std::string& j : k.joints)
      names.push_back(Param::string(j));
    params.set("/bot/group/joints", Param::list(names));
    std::unique_ptr<Controller> c = make(k.type, "group");
    ASSERT_EQ(c->claimedResources().size(), 1u);
    EXPECT_EQ(c->claimedResources()[0].hardware_interface, interfaceName(joints.handle(k.joints[0])->interface()));
    EXPECT_EQ(c->claimedResources()[0].resources, k.joints) << "in the parameter's order";
    EXPECT_EQ(commandTopic<std::vector<double>>(*c), "command");
    EXPECT_FALSE(command(*c, 1.0)) << "no Float64";

    std::vector<double> values;
    for (size_t i = 0; i < k.joints.size(); ++i)
      values.push_back(0.1 * double(i + 1));
    ASSERT_TRUE(command(*c, values));
    c->starting(time_ns);
    run(*c, 1);
    for (const std::string& j : k.joints)
      EXPECT_EQ(joints.handle(j)->command(), 0.0) << k.type << ": starts from 0 (or the joint's position, 0 here)";
    ASSERT_TRUE(command(*c, values));
    run(*c, 1);
    for (size_t i = 0; i < k.joints.size(); ++i)
      EXPECT_EQ(joints.handle(k.joints[i])->command(), values[i]) << k.type << " " << k.joints[i];

    messages.clear();
    std::vector<double> wrong(k.joints.size() + 1, 1.0);
    EXPECT_FALSE(command(*c, wrong));
    ASSERT_FALSE(messages.empty());
    EXPECT_EQ(messages.back(), "Dimension of command (" + std::to_string(wrong.size()) +
                                   ") does not match number of joints (" + std::to_string(k.joints.size()) +
                                   ")! Not executing!");
    std::vector<double> bad = values;
    bad.back() = std::nan("");
    EXPECT_FALSE(command(*c, bad));
    run(*c, 1);
    EXPECT_EQ(joints.handle(k.joints.back())->command(), values.back()) << "a refused command leaves the last one";
  }
}

TEST_F(ControllerTest, JointGroupControllersRefuseBadJointLists)
{
  auto init = [&](const std::string& type) {
    std::unique_ptr<Controller> c = createController(type);
    ControllerContext context{params, "/bot/group", joints, log};
    return c->init(context);
  };
  EXPECT_FALSE(init("velocity_controllers/JointGroupVelocityController"));
  EXPECT_EQ(messages.back(), "Failed to getParam 'joints' (namespace: /bot/group).");
  params.set("/bot/group/joints", Param::list({}));
  EXPECT_FALSE(init("velocity_controllers/JointGroupVelocityController"));
  EXPECT_EQ(messages.back(), "List of joint names is empty.");
  params.set("/bot/group/joints", Param::list({Param::string("left_wheel"), Param::string("left_hinge")}));
  EXPECT_FALSE(init("velocity_controllers/JointGroupVelocityController"));
  EXPECT_EQ(messages.back(),
            "Exception thrown: Could not find resource 'left_hinge' in 'hardware_interface::VelocityJointInterface'.");
}

TEST_F(ControllerTest, EffortJointGroupPositionControllerNeedsAPidPerJoint)
{
  params.set("/bot/group/joints", Param::list({Param::string("left_hinge"), Param::string("right_hinge")}));
  params.set("/bot/group/left_hinge/pid/p", Param::real(4.0));
  std::unique_ptr<Controller> c = createController("effort_controllers/JointGroupPositionController");
  ControllerContext context{params, "/bot/group", joints, log};
  EXPECT_FALSE(c->init(context));
  ASSERT_GE(messages.size(), 2u);
  EXPECT_EQ(messages[messages.size() - 2], "No p gain specified for pid.  Namespace: /bot/group/right_hinge/pid");
  EXPECT_EQ(messages.back(), "Failed to load PID parameters from right_hinge/pid");

  params.set("/bot/group/right_hinge/pid/p", Param::real(4.0));
  c = make("effort_controllers/JointGroupPositionController", "group");
  EXPECT_EQ(c->claimedResources()[0].hardware_interface, "hardware_interface::EffortJointInterface");
  EXPECT_EQ(commandTopic<std::vector<double>>(*c), "command");
  c->starting(time_ns);
  ASSERT_TRUE(command(*c, std::vector<double>{1.0, -0.2}));
  run(*c, 2);
  EXPECT_EQ(joints.handle("left_hinge")->rejectedCommands(), 0);
}

namespace
{
const char* kBicycleUrdf = R"(<robot name="bicycle">
  <link name="base_link"/>
  <link name="rear_wheel"><collision><geometry><cylinder radius="0.05" length="0.02"/></geometry></collision></link>
  <link name="steer"/>
  <link name="box_wheel"><collision><geometry><box size="0.1 0.1 0.1"/></geometry></collision></link>
  <joint name="rear_wheel_joint" type="continuous"><parent link="base_link"/><child link="rear_wheel"/>
    <origin xyz="-0.1 0 0"/><axis xyz="0 1 0"/></joint>
  <joint name="front_steer_joint" type="revolute"><parent link="base_link"/><child link="steer"/>
    <origin xyz="0.3 0 0"/><axis xyz="0 0 1"/><limit lower="-0.6" upper="0.6" effort="1" velocity="8"/></joint>
  <joint name="box_wheel_joint" type="continuous"><parent link="base_link"/><child link="box_wheel"/>
    <origin xyz="-0.1 0.2 0"/><axis xyz="0 1 0"/></joint>
</robot>)";

class AckermannTest : public ControllerTest
{
protected:
  AckermannTest()
  {
    params.set("/bot/robot_description", Param::string(kBicycleUrdf));
    params.set("/bot/ack/rear_wheel", Param::string("rear_wheel_joint"));
    params.set("/bot/ack/front_steer", Param::string("front_steer_joint"));
    std::vector<Param> diagonal;
    for (double v : {0.001, 0.001, 1e6, 1e6, 1e6, 1000.0})
      diagonal.push_back(Param::real(v));
    params.set("/bot/ack/pose_covariance_diagonal", Param::list(diagonal));
    params.set("/bot/ack/twist_covariance_diagonal", Param::list(diagonal));
  }

  std::unique_ptr<Controller> init(bool expect_ok = true)
  {
    std::unique_ptr<Controller> c = createController("ackermann_steering_controller/AckermannSteeringController");
    ControllerContext context{params, "/bot/ack", bicycle, log};
    EXPECT_EQ(c->init(context), expect_ok) << (messages.empty() ? "" : messages.back());
    return c;
  }

  double wheelCommand() { return bicycle.handle("rear_wheel_joint")->command(); }
  double steerCommand() { return bicycle.handle("front_steer_joint")->command(); }

  // ros_controllers' bicycle test robot: one rear wheel (velocity) and one front steering joint (position).
  JointList bicycle = std::move(JointList()
                                    .add("rear_wheel_joint", JointType::Continuous, JointInterface::Velocity, wheelLimits())
                                    .add("front_steer_joint", JointType::Revolute, JointInterface::Position, hingeLimits())
                                    .add("effort_steer", JointType::Revolute, JointInterface::Effort, hingeLimits()));
};
}  // namespace

TEST_F(AckermannTest, TwistDrivesTheRearWheelAndSteersWithGeometryFromTheUrdf)
{
  std::unique_ptr<Controller> c = init();
  EXPECT_EQ(commandTopic<TwistCommand>(*c), "cmd_vel");
  ASSERT_EQ(c->claimedResources().size(), 2u);
  EXPECT_EQ(c->claimedResources()[0].hardware_interface, "hardware_interface::PositionJointInterface");
  EXPECT_EQ(c->claimedResources()[0].resources, std::vector<std::string>{"front_steer_joint"});
  EXPECT_EQ(c->claimedResources()[1].resources, std::vector<std::string>{"rear_wheel_joint"});
  ASSERT_NE(c->output<OdometrySample>(), nullptr);
  EXPECT_EQ(c->output<OdometrySample>()->topic(), "odom");
  ASSERT_NE(c->output<TransformSample>(), nullptr) << "enable_odom_tf defaults to true";
  EXPECT_EQ(c->output<TransformSample>()->topic(), "/tf");

  EXPECT_FALSE(twist(*c, 1.0, 0.2)) << "not running yet";
  EXPECT_EQ(messages.back(), "Can't accept new commands. Controller is not running.");
  c->starting(time_ns);
  run(*c, 1);
  ASSERT_TRUE(twist(*c, 1.0, 0.2));
  run(*c, 1);
  EXPECT_DOUBLE_EQ(wheelCommand(), 1.0 / 0.05) << "speed / the wheel link's cylinder radius";
  EXPECT_EQ(steerCommand(), 0.2) << "angular.z is the steering angle";
  EXPECT_FALSE(twist(*c, std::nan(""), 0.0));
  run(*c, 1);
  EXPECT_DOUBLE_EQ(wheelCommand(), 20.0) << "a NaN command is ignored";

  run(*c, 497);
  EXPECT_DOUBLE_EQ(wheelCommand(), 20.0) << "within cmd_vel_timeout (0.5 s)";
  run(*c, 2);
  EXPECT_EQ(wheelCommand(), 0.0) << "older than cmd_vel_timeout: brake";
  EXPECT_EQ(steerCommand(), 0.0);
  c->stopping(time_ns);
  EXPECT_FALSE(twist(*c, 1.0, 0.0));

  std::vector<OdometrySample> odometry = take<OdometrySample>(*c);
  ASSERT_FALSE(odometry.empty());
  EXPECT_EQ(odometry.back().frame_id, "odom");
  EXPECT_EQ(odometry.back().child_frame_id, "base_link");
  EXPECT_EQ(odometry.back().pose_covariance_diagonal[2], 1e6);
  std::vector<TransformSample> transforms = take<TransformSample>(*c);
  ASSERT_EQ(transforms.size(), odometry.size()) << "a transform with each odometry message";
  EXPECT_EQ(transforms.back().pose.position.x, odometry.back().pose.position.x);
  EXPECT_EQ(transforms.back().child_frame_id, "base_link");
}

TEST_F(AckermannTest, ParametersOverrideTheUrdfAndLimitTheCommands)
{
  params.erase("/bot/robot_description");
  params.set("/bot/ack/wheel_radius", Param::real(0.1));
  params.set("/bot/ack/wheel_separation_h", Param::real(0.4));
  params.set("/bot/ack/linear/x/has_acceleration_limits", Param::boolean(true));
  params.set("/bot/ack/linear/x/max_acceleration", Param::real(2.0));
  params.set("/bot/ack/angular/z/has_velocity_limits", Param::boolean(true));
  params.set("/bot/ack/angular/z/max_velocity", Param::real(0.3));
  std::unique_ptr<Controller> c = init();
  c->starting(time_ns);
  ASSERT_TRUE(twist(*c, 1.0, -0.5));
  run(*c, 100);
  EXPECT_NEAR(wheelCommand(), 0.2 / 0.1, 1e-9) << "2 m/s^2 for 0.1 s: 0.2 m/s, through the radius parameter";
  EXPECT_EQ(steerCommand(), -0.3) << "min_velocity defaults to -max_velocity";
  run(*c, 400);
  EXPECT_NEAR(wheelCommand(), 1.0 / 0.1, 1e-9);
}

TEST_F(AckermannTest, OpenLoopOdometryIntegratesTheCommandsAndPublishesAtItsRate)
{
  params.set("/bot/ack/open_loop", Param::boolean(true));
  params.set("/bot/ack/publish_rate", Param::real(10.0));
  std::unique_ptr<Controller> c = init();
  c->starting(time_ns);
  ASSERT_TRUE(twist(*c, 1.0, 0.0));
  run(*c, 400);
  std::vector<OdometrySample> odometry = take<OdometrySample>(*c);
  ASSERT_EQ(odometry.size(), 3u) << "every 100 ms, strictly later than the period";
  EXPECT_EQ(odometry.back().stamp_ns, 301000000);
  EXPECT_NEAR(odometry.back().pose.position.x, 0.3, 1e-9) << "the command reaches odometry one update later: 300 ms of 1 m/s";
  EXPECT_EQ(odometry.back().pose.position.y, 0.0);
  EXPECT_EQ(odometry.back().linear.x, 1.0);
}

TEST_F(AckermannTest, InitErrorsNameWhatIsMissing)
{
  params.set("/bot/ack/front_steer", Param::string("effort_steer"));
  init(false);
  EXPECT_EQ(messages.back(), "effort_steer couldn't be retrieved from model description")
      << "the URDF is read first, for wheel_separation_h";
  params.set("/bot/ack/wheel_separation_h", Param::real(0.4));
  init(false);
  EXPECT_EQ(messages.back(), "Exception thrown while initializing controller 'ack'.\nCould not find resource "
                             "'effort_steer' in 'hardware_interface::PositionJointInterface'.");
  params.set("/bot/ack/front_steer", Param::string("front_steer_joint"));
  params.set("/bot/ack/rear_wheel", Param::string("box_wheel_joint"));
  init(false);
  EXPECT_EQ(messages.back(), "Couldn't retrieve box_wheel_joint wheel radius");
  EXPECT_EQ(messages[messages.size() - 2], "Wheel link box_wheel is NOT modeled as a cylinder!");
  params.set("/bot/ack/rear_wheel", Param::string("rear_wheel_joint"));
  params.erase("/bot/ack/wheel_separation_h");
  params.erase("/bot/ack/twist_covariance_diagonal");
  init(false);
  EXPECT_EQ(messages.back().rfind("Parameter 'twist_covariance_diagonal' of /bot/ack must be a list of 6 numbers", 0), 0u);
  params.erase("/bot/robot_description");
  init(false);
  EXPECT_EQ(messages.back(), "Robot descripion couldn't be retrieved from param server.");
}

TEST_F(ControllerTest, DiffDriveControllerTurnsTwistIntoWheelSpeedsAndIntegratesOpenLoop)
{
  params.set("/bot/diff/left_wheel", Param::string("left_wheel"));
  params.set("/bot/diff/right_wheel", Param::list({Param::string("right_wheel")}));
  params.set("/bot/diff/wheel_separation", Param::real(0.4));
  params.set("/bot/diff/wheel_radius", Param::real(0.1));
  params.set("/bot/diff/open_loop", Param::boolean(true));
  params.set("/bot/diff/publish_rate", Param::real(10.0));
  std::vector<Param> diagonal;
  for (double v : {0.001, 0.001, 1e6, 1e6, 1e6, 1000.0})
    diagonal.push_back(Param::real(v));
  params.set("/bot/diff/pose_covariance_diagonal", Param::list(diagonal));
  params.set("/bot/diff/twist_covariance_diagonal", Param::list(diagonal));
  std::unique_ptr<Controller> c = make("diff_drive_controller/DiffDriveController", "diff");
  EXPECT_EQ(commandTopic<TwistCommand>(*c), "cmd_vel");
  ASSERT_EQ(c->claimedResources().size(), 1u);
  EXPECT_EQ(c->claimedResources()[0].resources, (std::vector<std::string>{"left_wheel", "right_wheel"}));
  EXPECT_FALSE(twist(*c, 1.0, 0.0)) << "not running yet";
  c->starting(time_ns);
  ASSERT_TRUE(twist(*c, 1.0, 0.5));
  run(*c, 1);
  EXPECT_DOUBLE_EQ(joints.handle("left_wheel")->command(), (1.0 - 0.5 * 0.2) / 0.1);
  EXPECT_DOUBLE_EQ(joints.handle("right_wheel")->command(), (1.0 + 0.5 * 0.2) / 0.1);
  run(*c, 399);
  std::vector<OdometrySample> odometry = take<OdometrySample>(*c);
  ASSERT_EQ(odometry.size(), 3u) << "every 100 ms, strictly later than the period";
  // Open loop: the commands integrated on the arc of radius 2 m, the first update with none yet.
  const double heading = 0.5 * 0.300;
  EXPECT_NEAR(odometry.back().pose.position.x, 2.0 * std::sin(heading), 1e-9);
  EXPECT_EQ(odometry.back().linear.x, 1.0);
  EXPECT_EQ(odometry.back().twist_covariance_diagonal[5], 1000.0);
  EXPECT_EQ(take<TransformSample>(*c).size(), 3u);
  run(*c, 200);
  EXPECT_EQ(joints.handle("left_wheel")->command(), 0.0) << "older than cmd_vel_timeout: brake";
  EXPECT_FALSE(twist(*c, std::nan(""), 0.0));
}

TEST_F(ControllerTest, DiffDriveControllerInitErrorsAreUpstreams)
{
  auto init = [&] {
    std::unique_ptr<Controller> c = createController("diff_drive_controller/DiffDriveController");
    ControllerContext context{params, "/bot/diff", joints, log};
    return c->init(context);
  };
  EXPECT_FALSE(init());
  EXPECT_EQ(messages.back(), "Couldn't retrieve wheel param 'left_wheel'.");
  params.set("/bot/diff/left_wheel", Param::list({}));
  EXPECT_FALSE(init());
  EXPECT_EQ(messages.back(), "Wheel param 'left_wheel' is an empty list");
  params.set("/bot/diff/left_wheel", Param::list({Param::string("left_wheel"), Param::real(2)}));
  EXPECT_FALSE(init());
  EXPECT_EQ(messages.back(), "Wheel param 'left_wheel' #1 isn't a string.");
  params.set("/bot/diff/left_wheel", Param::list({Param::string("left_wheel"), Param::string("mast")}));
  params.set("/bot/diff/right_wheel", Param::string("right_wheel"));
  EXPECT_FALSE(init());
  EXPECT_EQ(messages.back(), "#left wheels (2) != #right wheels (1).");
  params.set("/bot/diff/left_wheel", Param::string("left_hinge"));
  params.set("/bot/diff/wheel_separation", Param::real(0.4));
  params.set("/bot/diff/wheel_radius", Param::real(0.1));
  EXPECT_FALSE(init());
  EXPECT_EQ(messages.back(), "Parameter 'pose_covariance_diagonal' of /bot/diff must be a list of 6 numbers (the "
                             "odometry's covariance diagonal, e.g. [0.001, 0.001, 1000000.0, 1000000.0, 1000000.0, 1000.0])");
  std::vector<Param> diagonal(6, Param::real(0.1));
  params.set("/bot/diff/pose_covariance_diagonal", Param::list(diagonal));
  params.set("/bot/diff/twist_covariance_diagonal", Param::list(diagonal));
  EXPECT_FALSE(init());
  EXPECT_EQ(messages.back(), "Exception thrown while initializing controller 'diff'.\nCould not find resource "
                             "'left_hinge' in 'hardware_interface::VelocityJointInterface'.");
}
