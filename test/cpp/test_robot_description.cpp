// robot_description.cpp: the robot-level Gazebo extensions read from URDF (here: <static>).
#include <gtest/gtest.h>

#include <string>

#include "bullet_plant/robot_description.h"

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
