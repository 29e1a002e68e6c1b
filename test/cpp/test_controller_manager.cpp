// The controller manager's rules (controller_manager.cpp, docs/interfaces.md section 2) on real joint
// handles behind the JointHandles interface: load errors, switch strictness, resource conflicts, when
// a switch takes effect, unload and reload, and what list_controllers reports. Error texts are the
// real manager's, read from the log.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include "bullet_plant/controller_manager.h"
#include "bullet_plant/hardware_interface.h"
#include "bullet_plant/log.h"
#include "bullet_plant/params.h"
#include "controller_commands.h"
#include "two_axle_joints.h"

using namespace bullet_plant;

namespace
{
const std::string kVelocity = "velocity_controllers/JointVelocityController";
const std::string kEffortPosition = "effort_controllers/JointPositionController";
const std::string kJointState = "joint_state_controller/JointStateController";

class ControllerManagerTest : public ::testing::Test
{
protected:
  ControllerManagerTest() : manager(joints, params, log, "/bot")
  {
    log.setSink([this](LogLevel level, const std::string& m) { messages.emplace_back(level, m); });
    controller("joint_state_controller", kJointState);
    params.set("/bot/joint_state_controller/publish_rate", Param::integer(50));
    controller("left_vel", kVelocity, "left_wheel");
    controller("right_vel", kVelocity, "right_wheel");
    controller("second_right_vel", kVelocity, "right_wheel");
    controller("left_steer", kEffortPosition, "left_hinge");
    params.set("/bot/left_steer/pid/p", Param::real(4.0));
    params.set("/bot/left_steer/pid/d", Param::real(1.0));
    // broken configurations
    params.set("/bot/no_type/joint", Param::string("left_wheel"));
    controller("bad_type", "foo_controllers/Bar", "left_wheel");
    controller("no_joint", kVelocity);
    controller("ghost_joint", kVelocity, "nowhere");
    controller("wrong_interface", kVelocity, "left_hinge");
    controller("no_p", kEffortPosition, "right_hinge");
    params.set("/bot/no_p/pid/i", Param::real(1.0));
    controller("no_rate", kJointState);
  }

  void controller(const std::string& name, const std::string& type, const std::string& joint = "")
  {
    params.set("/bot/" + name + "/type", Param::string(type));
    if (!joint.empty())
      params.set("/bot/" + name + "/joint", Param::string(joint));
  }

  bool logged(LogLevel level, const std::string& text) const
  {
    return std::find(messages.begin(), messages.end(), std::make_pair(level, text)) != messages.end();
  }
  bool loggedError(const std::string& text) const { return logged(LogLevel::Error, text); }
  int errorCount() const
  {
    return int(std::count_if(messages.begin(), messages.end(), [](const auto& m) { return m.first == LogLevel::Error; }));
  }

  ControllerState state(const std::string& name) const
  {
    for (const ControllerInfo& info : manager.listControllers())
      if (info.name == name)
        return info.state;
    ADD_FAILURE() << name << " is not loaded";
    return ControllerState::Initialized;
  }

  void loadAndStart(const std::vector<std::string>& names)
  {
    for (const std::string& name : names)
      ASSERT_TRUE(manager.loadController(name)) << name;
    ASSERT_TRUE(manager.switchController(names, {}, ControllerManager::STRICT));
    manager.update(time_ns += 1000000, 0.001);
    for (const std::string& name : names)
      ASSERT_EQ(state(name), ControllerState::Running) << name;
    messages.clear();
  }

  TwoAxleJoints joints;
  Param params = Param::map();
  Log log;
  std::vector<std::pair<LogLevel, std::string>> messages;
  ControllerManager manager;
  int64_t time_ns = 0;
};
}  // namespace

TEST(ControllerState, NamesAreTheServiceStrings)
{
  EXPECT_STREQ(controllerStateName(ControllerState::Initialized), "initialized");
  EXPECT_STREQ(controllerStateName(ControllerState::Running), "running");
  EXPECT_STREQ(controllerStateName(ControllerState::Stopped), "stopped");
}

TEST_F(ControllerManagerTest, LoadGivesInitializedControllersInLoadOrderWithTheirClaims)
{
  for (const char* name : {"left_steer", "joint_state_controller", "left_vel"})
    ASSERT_TRUE(manager.loadController(name)) << name;
  std::vector<ControllerInfo> infos = manager.listControllers();
  ASSERT_EQ(infos.size(), 3u);
  EXPECT_EQ(infos[0].name, "left_steer");
  EXPECT_EQ(infos[1].name, "joint_state_controller");
  EXPECT_EQ(infos[2].name, "left_vel");
  for (const ControllerInfo& info : infos)
    EXPECT_EQ(info.state, ControllerState::Initialized) << info.name;
  EXPECT_EQ(infos[0].type, kEffortPosition);
  ASSERT_EQ(infos[0].claimed_resources.size(), 1u);
  EXPECT_EQ(infos[0].claimed_resources[0].hardware_interface, "hardware_interface::EffortJointInterface");
  EXPECT_EQ(infos[0].claimed_resources[0].resources, std::vector<std::string>{"left_hinge"});
  ASSERT_EQ(infos[1].claimed_resources.size(), 1u);
  EXPECT_EQ(infos[1].claimed_resources[0].hardware_interface, "hardware_interface::JointStateInterface");
  EXPECT_TRUE(infos[1].claimed_resources[0].resources.empty()) << "the joint state controller claims nothing";
  EXPECT_EQ(infos[2].claimed_resources[0].hardware_interface, "hardware_interface::VelocityJointInterface");
  EXPECT_EQ(infos[2].claimed_resources[0].resources, std::vector<std::string>{"left_wheel"});
  EXPECT_EQ(errorCount(), 0);
}

TEST_F(ControllerManagerTest, LoadErrorsHaveTheRealManagersTexts)
{
  ASSERT_TRUE(manager.loadController("left_vel"));
  EXPECT_FALSE(manager.loadController("left_vel"));
  EXPECT_TRUE(loggedError("A controller named 'left_vel' was already loaded inside the controller manager"));

  EXPECT_FALSE(manager.loadController("no_type"));
  EXPECT_TRUE(loggedError("Could not load controller 'no_type' because the type was not specified. Did you load "
                          "the controller configuration on the parameter server (namespace: '/bot/no_type')?"));
  EXPECT_FALSE(manager.loadController("bad_type"));
  EXPECT_TRUE(loggedError("Could not load controller 'bad_type' because controller type 'foo_controllers/Bar' does "
                          "not exist."));
  EXPECT_TRUE(loggedError("Use 'rosservice call controller_manager/list_controller_types' to get the available types"));

  const std::vector<std::pair<std::string, std::string>> init_failures = {
      {"no_joint", "No joint given (namespace: /bot/no_joint)"},
      {"ghost_joint", "Could not find resource 'nowhere' in 'hardware_interface::VelocityJointInterface'."},
      {"wrong_interface", "Could not find resource 'left_hinge' in 'hardware_interface::VelocityJointInterface'."},
      {"no_p", "No p gain specified for pid.  Namespace: /bot/no_p/pid"},
      {"no_rate", "Parameter 'publish_rate' not set"},
  };
  for (const auto& failure : init_failures)
  {
    messages.clear();
    EXPECT_FALSE(manager.loadController(failure.first)) << failure.first;
    EXPECT_TRUE(loggedError(failure.second)) << failure.first;
    EXPECT_TRUE(loggedError("Initializing controller '" + failure.first + "' failed")) << failure.first;
  }
  EXPECT_EQ(manager.controllerNames(), std::vector<std::string>{"left_vel"}) << "failed loads leave nothing behind";
}

TEST_F(ControllerManagerTest, StrictRefusesWhatBestEffortSkips)
{
  loadAndStart({"left_vel"});
  ASSERT_TRUE(manager.loadController("right_vel"));

  EXPECT_FALSE(manager.switchController({"ghost"}, {}, ControllerManager::STRICT));
  EXPECT_TRUE(loggedError("Could not start controller with name 'ghost' because no controller with this name exists"));
  EXPECT_FALSE(manager.switchController({"left_vel"}, {}, ControllerManager::STRICT));
  EXPECT_TRUE(loggedError("Controller 'left_vel' is already running"));
  EXPECT_FALSE(manager.switchController({}, {"ghost"}, ControllerManager::STRICT));
  EXPECT_TRUE(loggedError("Could not stop controller with name 'ghost' because no controller with this name exists"));
  EXPECT_FALSE(manager.switchController({}, {"right_vel"}, ControllerManager::STRICT));
  EXPECT_TRUE(loggedError("Could not stop controller 'right_vel' since it is not running"));
  EXPECT_FALSE(manager.switchPending());

  messages.clear();
  EXPECT_TRUE(manager.switchController({"ghost"}, {}, ControllerManager::BEST_EFFORT));
  EXPECT_TRUE(logged(LogLevel::Debug, "Could not start controller with name 'ghost' because no controller with this name exists"));
  EXPECT_TRUE(manager.switchController({"left_vel"}, {}, ControllerManager::BEST_EFFORT));
  EXPECT_TRUE(manager.switchController({}, {"ghost", "right_vel"}, ControllerManager::BEST_EFFORT));
  EXPECT_EQ(errorCount(), 0);
  EXPECT_FALSE(manager.switchPending()) << "nothing to do: no switch waits";
  EXPECT_EQ(state("left_vel"), ControllerState::Running);
  EXPECT_EQ(state("right_vel"), ControllerState::Initialized);

  // what is valid in a best-effort request still happens
  EXPECT_TRUE(manager.switchController({"ghost", "right_vel"}, {"left_vel"}, ControllerManager::BEST_EFFORT));
  manager.update(time_ns += 1000000, 0.001);
  EXPECT_EQ(state("right_vel"), ControllerState::Running);
  EXPECT_EQ(state("left_vel"), ControllerState::Stopped);
}

TEST_F(ControllerManagerTest, StrictnessZeroIsBestEffortWithAWarning)
{
  ASSERT_TRUE(manager.loadController("left_vel"));
  EXPECT_TRUE(manager.switchController({"ghost", "left_vel"}, {}, 0));
  EXPECT_TRUE(logged(LogLevel::Warn,
                     "Controller Manager: To switch controllers you need to specify a strictness level of "
                     "controller_manager_msgs::SwitchController::STRICT (2) or ::BEST_EFFORT (1). Defaulting to "
                     "::BEST_EFFORT."));
  EXPECT_EQ(errorCount(), 0);
  manager.update(time_ns += 1000000, 0.001);
  EXPECT_EQ(state("left_vel"), ControllerState::Running);
}

// ros_control 0.20 (docs/interfaces.md section 9): a running controller in both lists is refused
// whatever the strictness; a stopped one is started by BEST_EFFORT and refused by STRICT (as a double
// stop); an unknown name in both is ignored by BEST_EFFORT.
TEST_F(ControllerManagerTest, NameInBothListsAsRosControl020)
{
  loadAndStart({"left_vel"});
  for (int strictness : {int(ControllerManager::BEST_EFFORT), int(ControllerManager::STRICT)})
  {
    messages.clear();
    EXPECT_FALSE(manager.switchController({"left_vel"}, {"left_vel"}, strictness));
    EXPECT_TRUE(loggedError("Could no start or stop controller 'left_vel' because of conflicting switching command"));
    EXPECT_FALSE(manager.switchPending());
    EXPECT_EQ(state("left_vel"), ControllerState::Running);
  }

  ASSERT_TRUE(manager.switchController({}, {"left_vel"}, ControllerManager::STRICT));
  manager.update(time_ns += 1000000, 0.001);
  ASSERT_EQ(state("left_vel"), ControllerState::Stopped);
  messages.clear();
  EXPECT_FALSE(manager.switchController({"left_vel"}, {"left_vel"}, ControllerManager::STRICT));
  EXPECT_TRUE(loggedError("Could not stop controller 'left_vel' since it is not running"));
  EXPECT_EQ(errorCount(), 1);
  EXPECT_FALSE(manager.switchPending());

  EXPECT_TRUE(manager.switchController({"left_vel"}, {"left_vel"}, ControllerManager::BEST_EFFORT));
  manager.update(time_ns += 1000000, 0.001);
  EXPECT_EQ(state("left_vel"), ControllerState::Running);

  messages.clear();
  EXPECT_TRUE(manager.switchController({"ghost"}, {"ghost"}, ControllerManager::BEST_EFFORT));
  EXPECT_FALSE(manager.switchPending());
  EXPECT_EQ(errorCount(), 0);
  EXPECT_FALSE(manager.switchController({"ghost"}, {"ghost"}, ControllerManager::STRICT));
  EXPECT_TRUE(loggedError("Could not stop controller with name 'ghost' because no controller with this name exists"));
}

TEST_F(ControllerManagerTest, TwoRunningControllersMayNotClaimOneJoint)
{
  loadAndStart({"right_vel"});
  ASSERT_TRUE(manager.loadController("second_right_vel"));
  EXPECT_FALSE(manager.switchController({"second_right_vel"}, {}, ControllerManager::STRICT));
  EXPECT_TRUE(loggedError("Could not switch controllers, due to resource conflict"));
  EXPECT_FALSE(manager.switchController({"second_right_vel"}, {}, ControllerManager::BEST_EFFORT));

  // stopping the holder in the same switch frees the joint
  EXPECT_TRUE(manager.switchController({"second_right_vel"}, {"right_vel"}, ControllerManager::STRICT));
  manager.update(time_ns += 1000000, 0.001);
  EXPECT_EQ(state("second_right_vel"), ControllerState::Running);
  EXPECT_EQ(state("right_vel"), ControllerState::Stopped);

  // and two that would start together conflict as well
  ASSERT_TRUE(manager.switchController({}, {"second_right_vel"}, ControllerManager::STRICT));
  manager.update(time_ns += 1000000, 0.001);
  messages.clear();
  EXPECT_FALSE(manager.switchController({"right_vel", "second_right_vel"}, {}, ControllerManager::STRICT));
  EXPECT_TRUE(loggedError("Could not switch controllers, due to resource conflict"));

  // claiming nothing, the joint state controller runs beside anything
  ASSERT_TRUE(manager.loadController("joint_state_controller"));
  EXPECT_TRUE(manager.switchController({"joint_state_controller", "right_vel"}, {}, ControllerManager::STRICT));
}

TEST_F(ControllerManagerTest, SwitchTakesEffectAfterTheNextUpdatesControllerUpdates)
{
  loadAndStart({"left_vel"});
  ASSERT_TRUE(manager.loadController("right_vel"));
  JointHandle& left = *joints.handle("left_wheel");
  JointHandle& right = *joints.handle("right_wheel");
  ASSERT_TRUE(command(*manager.controller("left_vel"), 3.0));
  right.setCommand(7.0);

  ASSERT_TRUE(manager.switchController({"right_vel"}, {"left_vel"}, ControllerManager::STRICT));
  EXPECT_TRUE(manager.switchPending());
  EXPECT_EQ(state("left_vel"), ControllerState::Running) << "nothing changes before the control update";
  EXPECT_EQ(state("right_vel"), ControllerState::Initialized);
  EXPECT_FALSE(manager.switchController({}, {"right_vel"}, ControllerManager::STRICT));
  EXPECT_TRUE(loggedError("Could not switch controllers: the previous switch has not been applied yet"));

  manager.update(time_ns += 1000000, 0.001);
  EXPECT_FALSE(manager.switchPending());
  EXPECT_EQ(state("left_vel"), ControllerState::Stopped);
  EXPECT_EQ(state("right_vel"), ControllerState::Running);
  EXPECT_EQ(left.command(), 3.0) << "the stopping controller still ran in that update";
  EXPECT_EQ(right.command(), 7.0) << "the starting controller did not run yet";

  ASSERT_TRUE(command(*manager.controller("right_vel"), -2.0));
  ASSERT_TRUE(command(*manager.controller("left_vel"), 5.0));
  manager.update(time_ns += 1000000, 0.001);
  EXPECT_EQ(right.command(), -2.0);
  EXPECT_EQ(left.command(), 3.0) << "a stopped controller writes nothing";
}

TEST_F(ControllerManagerTest, SwitchWhilePausedAppliesAtOnce)
{
  loadAndStart({"left_vel"});
  ASSERT_TRUE(manager.loadController("right_vel"));
  manager.setPaused(true);
  ASSERT_TRUE(manager.switchController({"right_vel"}, {"left_vel"}, ControllerManager::STRICT));
  EXPECT_FALSE(manager.switchPending());
  EXPECT_EQ(state("left_vel"), ControllerState::Stopped);
  EXPECT_EQ(state("right_vel"), ControllerState::Running);
}

TEST_F(ControllerManagerTest, UnloadRefusesRunningAndUnknownControllers)
{
  loadAndStart({"left_vel", "right_vel"});
  EXPECT_FALSE(manager.unloadController("left_vel"));
  EXPECT_TRUE(loggedError("Could not unload controller with name 'left_vel' because it is still running"));
  EXPECT_FALSE(manager.unloadController("ghost"));
  EXPECT_TRUE(loggedError("Could not unload controller with name 'ghost' because no controller with this name exists"));

  ASSERT_TRUE(manager.switchController({}, {"left_vel"}, ControllerManager::STRICT));
  manager.update(time_ns += 1000000, 0.001);
  EXPECT_TRUE(manager.unloadController("left_vel"));
  EXPECT_EQ(manager.controllerNames(), std::vector<std::string>{"right_vel"});
  EXPECT_EQ(manager.controller("left_vel"), nullptr);
  ASSERT_TRUE(manager.loadController("left_steer"));
  EXPECT_TRUE(manager.unloadController("left_steer")) << "an initialized controller unloads";
  EXPECT_TRUE(manager.loadController("left_vel")) << "and can be loaded again";
}

TEST_F(ControllerManagerTest, ReloadLibrariesNeedsForceKillWhileControllersAreLoaded)
{
  EXPECT_TRUE(manager.reloadControllerLibraries(false)) << "nothing loaded";
  loadAndStart({"left_vel"});
  ASSERT_TRUE(manager.loadController("right_vel"));
  EXPECT_FALSE(manager.reloadControllerLibraries(false));
  EXPECT_TRUE(loggedError("Controller manager: Cannot reload controller libraries because there are still 2 "
                          "controllers loaded. Try again after unloading them, or call with force_kill true."));
  EXPECT_EQ(manager.controllerNames().size(), 2u);

  ASSERT_TRUE(manager.switchController({"right_vel"}, {}, ControllerManager::STRICT));
  EXPECT_TRUE(manager.reloadControllerLibraries(true));
  EXPECT_TRUE(logged(LogLevel::Info, "Controller manager: Killing all running controllers"));
  EXPECT_TRUE(manager.listControllers().empty());
  EXPECT_FALSE(manager.switchPending()) << "a pending switch dies with its controllers";
  EXPECT_TRUE(manager.loadController("left_vel"));
}

TEST_F(ControllerManagerTest, ListsTheTypesItOffers)
{
  const std::vector<std::string> types = manager.listControllerTypes();
  for (const std::string& type : {kVelocity, kEffortPosition, kJointState, std::string("effort_controllers/JointEffortController"),
                                  std::string("effort_controllers/JointVelocityController"),
                                  std::string("position_controllers/JointPositionController"),
                                  std::string("position_controllers/JointGroupPositionController"),
                                  std::string("velocity_controllers/JointGroupVelocityController"),
                                  std::string("effort_controllers/JointGroupEffortController"),
                                  std::string("effort_controllers/JointGroupPositionController"),
                                  std::string("ackermann_steering_controller/AckermannSteeringController"),
                                  std::string("diff_drive_controller/DiffDriveController"),
                                  std::string("mecanum_drive_controller/MecanumDriveController"),
                                  std::string("position_controllers/JointTrajectoryController"),
                                  std::string("velocity_controllers/JointTrajectoryController"),
                                  std::string("effort_controllers/JointTrajectoryController"),
                                  std::string("position_controllers/GripperActionController"),
                                  std::string("effort_controllers/GripperActionController")})
    EXPECT_NE(std::find(types.begin(), types.end(), type), types.end()) << type;
  EXPECT_EQ(types.size(), 18u);
}
