// robot_description.cpp and sdf_model.cpp: the robot-level Gazebo extensions read from URDF
// (<static>), and a joint's feedback (<provideFeedback>, <provide_feedback>) from URDF and SDF.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "bullet_plant/robot_description.h"
#include "bullet_plant/sdf_model.h"

using namespace bullet_plant;

namespace
{
std::string urdfWith(const std::string& gazebo_blocks)
{
  return "<robot name=\"post\"><link name=\"base\"><collision><geometry><box size=\"1 1 1\"/></geometry>"
         "</collision></link>" + gazebo_blocks + "</robot>";
}
}  // namespace

TEST(RobotDescription, RobotLevelGazeboStaticMakesTheRobotStatic)
{
  EXPECT_TRUE(parseRobotDescription(urdfWith("<gazebo><static>true</static></gazebo>")).is_static);
  EXPECT_TRUE(parseRobotDescription(urdfWith("<gazebo><static>1</static></gazebo>")).is_static);
  EXPECT_FALSE(parseRobotDescription(urdfWith("<gazebo><static>false</static></gazebo>")).is_static);
  EXPECT_FALSE(parseRobotDescription(urdfWith("")).is_static);
}

TEST(RobotDescription, StaticInsideALinksGazeboBlockIsNotTheRobots)
{
  EXPECT_FALSE(parseRobotDescription(urdfWith("<gazebo reference=\"base\"><static>true</static></gazebo>")).is_static);
}

TEST(RobotDescription, KeepsTheDirectoryItsFileCameFrom)
{
  EXPECT_EQ(parseRobotDescription(urdfWith(""), "/robots/post").base_dir, "/robots/post");
  EXPECT_EQ(parseRobotDescription(urdfWith("")).base_dir, "");
}

TEST(RobotDescription, AJointThatProvidesFeedbackIsMeasuredFromTheStartInUrdfAndSdf)
{
  const std::string arm = "<robot name=\"arm\"><link name=\"base\"/><link name=\"arm\"><inertial><mass value=\"1\"/>"
                          "<inertia ixx=\"0.1\" iyy=\"0.1\" izz=\"0.1\" ixy=\"0\" ixz=\"0\" iyz=\"0\"/></inertial></link>"
                          "<joint name=\"elbow\" type=\"continuous\"><parent link=\"base\"/><child link=\"arm\"/></joint>";
  EXPECT_EQ(parseRobotDescription(arm + "<gazebo reference=\"elbow\"><provideFeedback>true</provideFeedback>"
                                        "</gazebo></robot>").joint_feedback,
            std::set<std::string>{"elbow"});
  EXPECT_TRUE(parseRobotDescription(arm + "</robot>").joint_feedback.empty());
  const std::string sdf = "<sdf version='1.6'><model name='arm'><link name='base'/><link name='arm'><inertial>"
                          "<mass>1</mass></inertial></link><joint name='elbow' type='revolute'><parent>base</parent>"
                          "<child>arm</child><axis><xyz>0 0 1</xyz></axis><physics><provide_feedback>true"
                          "</provide_feedback></physics></joint></model></sdf>";
  EXPECT_EQ(parseSdfModel(sdf).robot.joint_feedback, std::set<std::string>{"elbow"});
}
