// inertial_sensors.cpp: the IMU and gazebo_ros_p3d models (their names: test_plugin_names.cpp), and
// the plugin parameters robot_description.cpp reads for them.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "bullet_plant/geometry.h"
#include "bullet_plant/inertial_sensors.h"
#include "bullet_plant/robot_description.h"

using namespace bullet_plant;

namespace
{
const urdf::Vector3 kGravity(0, 0, -9.8);

SensorDescription imuSensor(std::map<std::string, std::string> plugin, bool model_plugin = false)
{
  SensorDescription d;
  d.name = "imu";
  d.type = "imu";
  d.link = "imu_link";
  d.model_plugin = model_plugin;
  d.plugin_file = findPluginFile(model_plugin ? "libgazebo_ros_imu.so" : "libgazebo_ros_imu_sensor.so");
  d.plugin = std::move(plugin);
  return d;
}

LinkMotion at(const urdf::Pose& pose, urdf::Vector3 velocity = urdf::Vector3(), urdf::Vector3 omega = urdf::Vector3())
{
  LinkMotion m;
  m.pose = pose;
  m.velocity = velocity;
  m.angular_velocity = omega;
  return m;
}
}  // namespace

TEST(Imu, AtRestReadsTheReactionToGravityInItsOwnFrame)
{
  Imu imu(imuSensor({{"frameName", "imu_link"}, {"updateRateHZ", "100"}}), 1);
  imu.sample(at(urdf::Pose()), kGravity, 0);
  imu.sample(at(urdf::Pose()), kGravity, 10000000);
  EXPECT_NEAR(imu.latest().linear_acceleration.z, 9.8, 1e-12);
  EXPECT_NEAR(imu.latest().linear_acceleration.x, 0.0, 1e-12);
  // Rolled 90 degrees about x, the IMU's y axis points up: the reaction reads along +y.
  Imu rolled(imuSensor({{"frameName", "imu_link"}}), 1);
  rolled.sample(at(poseFromXyzRpy(0, 0, 0, M_PI / 2, 0, 0)), kGravity, 0);
  EXPECT_NEAR(rolled.latest().linear_acceleration.y, 9.8, 1e-9);
  EXPECT_NEAR(rolled.latest().linear_acceleration.z, 0.0, 1e-9);
}

TEST(Imu, DifferentiatesVelocityBetweenConsecutiveSamplesOnly)
{
  Imu imu(imuSensor({{"frameName", "imu_link"}, {"updateRateHZ", "100"}}), 1);
  imu.sample(at(urdf::Pose(), urdf::Vector3(1.0, 0, 0)), kGravity, 0);
  EXPECT_NEAR(imu.latest().linear_acceleration.x, 0.0, 1e-12) << "no previous sample: gravity only";
  imu.sample(at(urdf::Pose(), urdf::Vector3(1.02, 0, 0)), kGravity, 10000000);
  EXPECT_NEAR(imu.latest().linear_acceleration.x, 2.0, 1e-9);
  imu.sample(at(urdf::Pose(), urdf::Vector3(5.0, 0, 0)), kGravity, 1000000000);
  EXPECT_NEAR(imu.latest().linear_acceleration.x, 0.0, 1e-12) << "after a pause in sampling: a fresh start";
}

TEST(Imu, RatesInTheImuFrameAndOrientationInTheWorldOrRelativeToSpawnWhereAsked)
{
  const urdf::Pose spawn = poseFromXyzRpy(0, 0, 0, 0, 0, 0.3);
  Imu imu(imuSensor({{"frameName", "/car1/imu_link"}}), 1);
  imu.setReference(spawn.rotation);
  imu.sample(at(poseFromXyzRpy(0, 0, 0, 0, 0, 0.8), urdf::Vector3(), urdf::Vector3(0, 0, 1.5)), kGravity, 0);
  const ImuReading& r = imu.latest();
  EXPECT_NEAR(r.angular_velocity.z, 1.5, 1e-12);
  EXPECT_NEAR(2 * std::atan2(r.orientation.z, r.orientation.w), 0.8, 1e-9) << "gazebo_ros_imu_sensor: REP 145's world";
  Imu since_spawn(imuSensor({{"frameName", "imu_link"}, {"initialOrientationAsReference", "true"}}), 1);
  since_spawn.setReference(spawn.rotation);
  since_spawn.sample(at(poseFromXyzRpy(0, 0, 0, 0, 0, 0.8)), kGravity, 0);
  EXPECT_NEAR(2 * std::atan2(since_spawn.latest().orientation.z, since_spawn.latest().orientation.w), 0.5, 1e-9)
      << "initialOrientationAsReference: since spawn";

  Imu model(imuSensor({{"bodyName", "imu_link"}}, true), 1);
  model.sample(at(poseFromXyzRpy(0, 0, 0, 0, 0, 0.8)), kGravity, 0);
  EXPECT_NEAR(2 * std::atan2(model.latest().orientation.z, model.latest().orientation.w), 0.8, 1e-9) << "gazebo_ros_imu: world";
}

TEST(Imu, NoiseIsSeededAndHasTheGivenSpread)
{
  auto run = [](uint32_t seed) {
    Imu imu(imuSensor({{"frameName", "f"}, {"gaussianNoise", "0.1"}}), seed);
    double sum = 0, sum2 = 0;
    for (int i = 0; i < 2000; ++i)
    {
      imu.sample(at(urdf::Pose()), kGravity, int64_t(i) * 1000000000);
      const double e = imu.latest().angular_velocity.x;
      sum += e;
      sum2 += e * e;
    }
    return std::make_pair(sum / 2000, std::sqrt(sum2 / 2000));
  };
  EXPECT_EQ(run(7), run(7));
  EXPECT_NEAR(run(7).first, 0.0, 0.01);
  EXPECT_NEAR(run(7).second, 0.1, 0.01);
}

TEST(GroundTruthOdometry, PoseAndWorldTwistOfItsBodyInTheResolvedFrame)
{
  SensorDescription d;
  d.name = "p3d";
  d.type = "p3d";
  d.link = "base_footprint";
  d.model_plugin = true;
  d.plugin_file = findPluginFile("libgazebo_ros_p3d.so");
  d.plugin = {{"bodyName", "base_footprint"}, {"topicName", "ground_truth"}, {"updateRate", "50"}};
  GroundTruthOdometry p3d(d, 1);
  EXPECT_EQ(p3d.periodNs(), 20000000);
  p3d.sample(at(poseFromXyzRpy(1, 2, 0, 0, 0, 0.5), urdf::Vector3(0.3, 0.4, 0), urdf::Vector3(0, 0, 0.7)), nullptr, 5);
  const GroundTruthReading& r = p3d.latest();
  EXPECT_DOUBLE_EQ(r.pose.position.y, 2.0);
  EXPECT_DOUBLE_EQ(r.linear.y, 0.4) << "world frame, as gazebo_ros_p3d";
  EXPECT_DOUBLE_EQ(r.angular.z, 0.7);
}

TEST(RobotDescriptionPlugins, ModelPluginsUnknownPluginsAndRobotSimType)
{
  const std::string urdf =
      "<robot name=\"r\"><link name=\"base\"/>"
      "<gazebo><plugin name=\"truth\" filename=\"libgazebo_ros_p3d.so\"><bodyName>base</bodyName>"
      "<topicName>odom_truth</topicName></plugin>"
      "<plugin name=\"drive\" filename=\"libgazebo_ros_diff_drive.so\"><leftJoint>l</leftJoint></plugin>"
      "<plugin name=\"grip\" filename=\"libgazebo_ros_vacuum_gripper.so\"/>"
      "<plugin name=\"gazebo_ros_control\" filename=\"libgazebo_ros_control.so\"><robotSimType>my/Hw</robotSimType>"
      "</plugin></gazebo></robot>";
  RobotDescription d = parseRobotDescription(urdf);
  ASSERT_EQ(d.sensors.size(), 1u);
  EXPECT_EQ(d.sensors[0].type, "p3d");
  EXPECT_EQ(d.sensors[0].link, "base");
  ASSERT_EQ(d.warnings.size(), 1u);
  EXPECT_NE(d.warnings[0].find("'grip' (libgazebo_ros_vacuum_gripper.so)"), std::string::npos) << d.warnings[0];
  EXPECT_NE(d.warnings[0].find(", gazebo_ros_diff_drive,"), std::string::npos) << "the simulated ones listed";
  ASSERT_EQ(d.model_plugins.size(), 1u) << "a model plugin the plant simulates is kept for the robot to load";
  EXPECT_EQ(d.model_plugins[0].filename, "libgazebo_ros_diff_drive.so");
  EXPECT_EQ(d.model_plugins[0].text("leftJoint", ""), "l");
  ASSERT_EQ(d.errors.size(), 1u);
  EXPECT_NE(d.errors[0].find("robotSimType 'my/Hw'"), std::string::npos);
  EXPECT_FALSE(d.control.present) << "no controller manager, as when gazebo_ros_control cannot load the class";
  EXPECT_TRUE(d.control.legacy_mode_ns) << "legacyModeNS defaults to true";
}
