// Every plugin file and controller type registers itself from its own file (registry.h); a file
// the linker leaves out of the static plant takes its names with it. These are the names the plant
// offers (docs/interfaces.md section 11, section 4): each must be registered once linked.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "bullet_plant/controllers.h"
#include "bullet_plant/model_plugin.h"
#include "bullet_plant/robot_description.h"

using namespace bullet_plant;

namespace
{
const std::vector<std::string> kSensorPluginFiles = {
    "libgazebo_ros_laser.so",          "libgazebo_ros_gpu_laser.so",         "libgazebo_ros_camera.so",
    "libgazebo_ros_openni_kinect.so",  "libgazebo_ros_depth_camera.so",      "libgazebo_ros_multicamera.so",
    "libgazebo_ros_imu_sensor.so",     "libgazebo_ros_range.so",             "libgazebo_ros_velodyne_laser.so",
    "libgazebo_ros_velodyne_gpu_laser.so", "libgazebo_ros_block_laser.so",   "libhector_gazebo_ros_sonar.so",
    "libgazebo_ros_bumper.so"};
const std::vector<std::string> kLinkSensorPluginFiles = {"libgazebo_ros_imu.so", "libgazebo_ros_p3d.so"};
const std::vector<std::string> kModelPluginFiles = {
    "libgazebo_ros_diff_drive.so",           "libgazebo_ros_skid_steer_drive.so",
    "libgazebo_ros_tricycle_drive.so",       "libgazebo_ros_planar_move.so",
    "libgazebo_ros_joint_state_publisher.so", "libroboticsgroup_upatras_gazebo_mimic_joint_plugin.so",
    "libroboticsgroup_gazebo_mimic_joint_plugin.so", "libhector_gazebo_ros_gps.so",
    "libhector_gazebo_ros_imu.so",           "libhector_gazebo_ros_magnetic.so",
    "libgazebo_ros_force_based_move.so",     "libgazebo_ros_force.so",
    "libgazebo_ros_f3d.so",                  "libgazebo_ros_ft_sensor.so",
    "libgazebo_ros_joint_pose_trajectory.so", "libgazebo_ros_hand_of_god.so"};
const std::vector<std::string> kControllerTypes = {
    "ackermann_steering_controller/AckermannSteeringController",
    "diff_drive_controller/DiffDriveController",
    "effort_controllers/GripperActionController",
    "effort_controllers/JointEffortController",
    "effort_controllers/JointGroupEffortController",
    "effort_controllers/JointGroupPositionController",
    "effort_controllers/JointPositionController",
    "effort_controllers/JointTrajectoryController",
    "effort_controllers/JointVelocityController",
    "joint_state_controller/JointStateController",
    "mecanum_drive_controller/MecanumDriveController",
    "position_controllers/GripperActionController",
    "position_controllers/JointGroupPositionController",
    "position_controllers/JointPositionController",
    "position_controllers/JointTrajectoryController",
    "velocity_controllers/JointGroupVelocityController",
    "velocity_controllers/JointTrajectoryController",
    "velocity_controllers/JointVelocityController"};
}  // namespace

TEST(Registries, EverySensorPluginFileIsRegisteredAsOne)
{
  for (const std::string& file : kSensorPluginFiles)
  {
    const PluginFile* registered = findPluginFile(file);
    ASSERT_NE(registered, nullptr) << file;
    EXPECT_EQ(registered->role, PluginRole::Sensor) << file;
  }
  for (const std::string& file : kLinkSensorPluginFiles)
  {
    const PluginFile* registered = findPluginFile(file);
    ASSERT_NE(registered, nullptr) << file;
    EXPECT_EQ(registered->role, PluginRole::LinkSensor) << file;
  }
}

TEST(Registries, EveryModelPluginIsRegisteredWithItsFile)
{
  for (const std::string& file : kModelPluginFiles)
  {
    const PluginFile* registered = findPluginFile(file);
    ASSERT_NE(registered, nullptr) << file;
    EXPECT_EQ(registered->role, PluginRole::Model) << file;
    EXPECT_NE(createModelPlugin(file), nullptr) << file;
  }
  EXPECT_EQ(createModelPlugin("libgazebo_ros_laser.so"), nullptr) << "a sensor plugin's file makes no model plugin";
  EXPECT_EQ(findPluginFile("libgazebo_ros_vacuum_gripper.so"), nullptr);
}

TEST(Registries, EveryControllerTypeIsRegistered)
{
  for (const std::string& type : kControllerTypes)
    EXPECT_NE(createController(type), nullptr) << type;
  EXPECT_EQ(createController("velocity_controllers/JointPositionController"), nullptr);
}

TEST(Registries, EveryModelPluginFactoryHasItsFilesFacts)
{
  // GAZEBO_ROS_MODEL_PLUGIN registers both; a file with a factory but no facts would never be read.
  for (const std::string& file : Registry<ModelPluginFactory>::instance().names())
  {
    const PluginFile* registered = findPluginFile(file);
    ASSERT_NE(registered, nullptr) << file;
    EXPECT_EQ(registered->role, PluginRole::Model) << file;
  }
}
