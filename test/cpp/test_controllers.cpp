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
  EXPECT_EQ(controllerTypes().size(), 10u);
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
    EXPECT_EQ(c->commandTopic(), CommandTopic::Float64);
    EXPECT_FALSE(c->hasState());

    h.setCommand(9.0);
    ASSERT_TRUE(c->setCommand(5.0));
    c->starting(time_ns);
    run(*c, 1);
    EXPECT_EQ(h.command(), 0.0) << k.type << " starts from 0 (the position one from where the joint is, 0 here), not from an earlier command";
    EXPECT_TRUE(c->setCommand(0.25));
    EXPECT_EQ(h.command(), 0.0) << "written by the next update, not by the command itself";
    run(*c, 1);
    EXPECT_EQ(h.command(), 0.25) << k.type;
    for (double bad : {std::nan(""), std::numeric_limits<double>::infinity()})
      EXPECT_FALSE(c->setCommand(bad)) << k.type;
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
  EXPECT_EQ(c->commandTopic(), CommandTopic::None);
  c->starting(time_ns);
  run(*c, 1000);
  std::vector<JointStateSample> samples = c->takeJointStates();
  EXPECT_EQ(samples.size(), 49u) << "every 20 ms after the first 20 ms, strictly later than the period";
  EXPECT_EQ(c->samplesProduced(), samples.size());
  ASSERT_FALSE(samples.empty());
  EXPECT_EQ(samples.front().stamp_ns, 21000000);
  EXPECT_EQ(samples[1].stamp_ns - samples[0].stamp_ns, 20000000);
  EXPECT_EQ(samples.back().name, (std::vector<std::string>{"left_hinge", "left_wheel", "mast", "right_hinge", "right_wheel"}))
      << "every handle, sorted by name";
  EXPECT_EQ(samples.back().position.size(), 5u);
  EXPECT_TRUE(c->takeJointStates().empty()) << "taken once";
  ASSERT_NE(c->latestJointState(), nullptr);
  EXPECT_EQ(c->latestJointState()->stamp_ns, samples.back().stamp_ns);
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
  std::vector<JointStateSample> samples = c->takeJointStates();
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
  EXPECT_EQ(c->samplesProduced(), 0u);
}

TEST_F(ControllerTest, EffortPositionControllerReportsItsStateEveryTenthUpdate)
{
  params.set("/bot/steer/joint", Param::string("left_hinge"));
  params.set("/bot/steer/pid/p", Param::real(4.0));
  params.set("/bot/steer/pid/i", Param::real(2.0));
  params.set("/bot/steer/pid/d", Param::real(1.0));
  params.set("/bot/steer/pid/i_clamp", Param::real(0.5));
  std::unique_ptr<Controller> c = make("effort_controllers/JointPositionController", "steer");
  EXPECT_EQ(c->commandTopic(), CommandTopic::Float64);
  EXPECT_TRUE(c->hasState());
  EXPECT_EQ(c->claimedResources()[0].hardware_interface, "hardware_interface::EffortJointInterface");
  c->starting(time_ns);
  ASSERT_TRUE(c->setCommand(1.0));
  run(*c, 25);
  std::vector<ControllerStateSample> states = c->takeControllerStates();
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
  ASSERT_TRUE(c->setCommand(3.0));
  run(*c, 1);
  std::vector<ControllerStateSample> states = c->takeControllerStates();
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
    EXPECT_EQ(c->commandTopic(), CommandTopic::Float64MultiArray);
    EXPECT_FALSE(c->setCommand(1.0)) << "no Float64";

    std::vector<double> values;
    for (size_t i = 0; i < k.joints.size(); ++i)
      values.push_back(0.1 * double(i + 1));
    ASSERT_TRUE(c->setCommands(values));
    c->starting(time_ns);
    run(*c, 1);
    for (const std::string& j : k.joints)
      EXPECT_EQ(joints.handle(j)->command(), 0.0) << k.type << ": starts from 0 (or the joint's position, 0 here)";
    ASSERT_TRUE(c->setCommands(values));
    run(*c, 1);
    for (size_t i = 0; i < k.joints.size(); ++i)
      EXPECT_EQ(joints.handle(k.joints[i])->command(), values[i]) << k.type << " " << k.joints[i];

    messages.clear();
    std::vector<double> wrong(k.joints.size() + 1, 1.0);
    EXPECT_FALSE(c->setCommands(wrong));
    ASSERT_FALSE(messages.empty());
    EXPECT_EQ(messages.back(), "Dimension of command (" + std::to_string(wrong.size()) +
                                   ") does not match number of joints (" + std::to_string(k.joints.size()) +
                                   ")! Not executing!");
    std::vector<double> bad = values;
    bad.back() = std::nan("");
    EXPECT_FALSE(c->setCommands(bad));
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
  EXPECT_EQ(c->commandTopic(), CommandTopic::Float64MultiArray);
  c->starting(time_ns);
  ASSERT_TRUE(c->setCommands({1.0, -0.2}));
  run(*c, 2);
  EXPECT_EQ(joints.handle("left_hinge")->rejectedCommands(), 0);
}
