// The parameter tree (params.cpp): what the plant reads of the ROS parameter server.
#include <gtest/gtest.h>

#include <stdexcept>

#include "bullet_plant/params.h"

using bullet_plant::Param;

TEST(Param, FindsNestedValuesByPathAndIgnoresLeadingSlash)
{
  Param root = Param::map();
  root.set("/tianracer/gazebo_ros_control/pid_gains/left_rear_wheel_joint/p", Param::real(100.0));
  const Param* p = root.find("tianracer/gazebo_ros_control/pid_gains/left_rear_wheel_joint/p");
  ASSERT_NE(p, nullptr);
  EXPECT_DOUBLE_EQ(p->asDouble(), 100.0);
  EXPECT_EQ(root.find("tianracer/missing"), nullptr);
  EXPECT_EQ(root.find("tianracer/gazebo_ros_control/pid_gains/left_rear_wheel_joint/p/deeper"), nullptr);
}

TEST(Param, MergeReplacesLeavesAndKeepsSiblings)
{
  Param root = Param::map();
  root.set("ns/a", Param::integer(1));
  root.set("ns/b", Param::string("kept"));
  Param update = Param::map();
  update.set("ns/a", Param::integer(2));
  root.merge(update);
  EXPECT_EQ(root.find("ns/a")->asInt(), 2);
  EXPECT_EQ(root.find("ns/b")->asString(), "kept");
  EXPECT_TRUE(root.erase("ns/b"));
  EXPECT_EQ(root.find("ns/b"), nullptr);
}

TEST(Param, WrongTypeNamesWhatItGot)
{
  const Param text = Param::string("abc");
  try
  {
    text.asDouble();
    FAIL() << "a string read as a number must throw";
  }
  catch (const std::runtime_error& e)
  {
    EXPECT_NE(std::string(e.what()).find("'abc'"), std::string::npos) << e.what();
  }
  EXPECT_DOUBLE_EQ(Param::integer(3).asDouble(), 3.0);
}

TEST(Namespaces, NormaliseAndJoin)
{
  EXPECT_EQ(bullet_plant::normaliseNamespace(""), "");
  EXPECT_EQ(bullet_plant::normaliseNamespace("/"), "");
  EXPECT_EQ(bullet_plant::normaliseNamespace("tianracer/"), "/tianracer");
  EXPECT_EQ(bullet_plant::joinPath("/tianracer", "x/p"), "tianracer/x/p");
}
