// Gazebo 11's common library over the plant (include/gazebo-11/gazebo/common/): common::Time's
// arithmetic as plugins use it on simulated time, event::EventT's connections as plugins hold
// them, the console's prefixes, PluginT::Create's errors for a library that is not a plugin,
// common::Animation's key frames and interpolation, and sensors::Sensor's base as a sensor plugin
// reads it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>

#include <gazebo/common/common.hh>
#include <gazebo/sensors/Sensor.hh>

#include "mesh_fixtures.h"

using gazebo::common::Time;

TEST(GazeboTime, KeepsSecondsAndNanosecondsOfOneSign)
{
  EXPECT_EQ(Time(1, 1500000000), Time(2, 500000000));
  const Time negative(-0.25);
  EXPECT_EQ(negative.sec, 0);
  EXPECT_EQ(negative.nsec, -250000000);
  const Time borrow = Time(2, 0) - Time(0, 1);
  EXPECT_EQ(borrow.sec, 1);
  EXPECT_EQ(borrow.nsec, 999999999);
  EXPECT_DOUBLE_EQ((Time(1.5) - Time(2.0)).Double(), -0.5);
}

TEST(GazeboTime, ArithmeticAndComparisonsAsAPluginUsesThemOnSimulatedTime)
{
  const Time last(10, 990000000), now(11, 10000000);
  const Time elapsed = now - last;
  EXPECT_EQ(elapsed, Time(0, 20000000));
  EXPECT_NEAR(elapsed.Double(), 0.02, 1e-12);
  EXPECT_TRUE(elapsed >= 0.02 && elapsed < 0.021 && elapsed > Time::Zero);
  EXPECT_NEAR((Time(3.0) * Time(0.5)).Double(), 1.5, 1e-9);
  EXPECT_NEAR((Time(3.0) / Time(2.0)).Double(), 1.5, 1e-9);
  EXPECT_EQ(Time(3.0) / Time::Zero, Time(3.0));  // Gazebo's: an error, and the time as it was
  Time accumulated;
  for (int i = 0; i < 1000; ++i)
    accumulated += Time(0.001);
  EXPECT_EQ(accumulated, Time(1, 0));
  std::stringstream text;
  text << Time(4, 5);
  EXPECT_EQ(text.str(), "4 5");
  Time read;
  text >> read;
  EXPECT_EQ(read, Time(4, 5));
}

TEST(GazeboTime, NonFiniteSecondsAreZeroAndTheWallClockMoves)
{
  EXPECT_EQ(Time(std::numeric_limits<double>::quiet_NaN()), Time::Zero);
  EXPECT_EQ(Time(std::numeric_limits<double>::infinity()), Time::Zero);
  const Time before = Time::GetWallTime();
  Time::MSleep(2);
  EXPECT_GE((Time::GetWallTime() - before).Double(), 0.002);
  EXPECT_EQ(Time::GetWallTimeAsISOString().size(), 19u);  // YYYY-MM-DDTHH:MM:SS
}

TEST(GazeboEvents, ACallbackRunsWhileItsConnectionIsHeld)
{
  gazebo::event::EventT<void(const gazebo::common::UpdateInfo&)> update;
  int calls = 0;
  double seen = 0.0;
  gazebo::event::ConnectionPtr connection = update.Connect([&](const gazebo::common::UpdateInfo& info) {
    ++calls;
    seen = info.simTime.Double();
  });
  gazebo::common::UpdateInfo info;
  info.simTime = Time(1.25);
  update(info);
  EXPECT_EQ(calls, 1);
  EXPECT_DOUBLE_EQ(seen, 1.25);
  EXPECT_EQ(update.ConnectionCount(), 1u);
  connection.reset();  // as a plugin disconnects: its member reset
  update(info);
  EXPECT_EQ(calls, 1);
  EXPECT_EQ(update.ConnectionCount(), 0u);
}

TEST(GazeboEvents, ABoundMemberWithoutArgumentsConnectsToWorldUpdateBegin)
{
  struct Plugin
  {
    int updates = 0;
    void OnUpdate() { ++updates; }
  } plugin;
  // Gazebo's tutorials connect std::bind(&Plugin::OnUpdate, this), which takes no UpdateInfo.
  auto connection = gazebo::event::Events::ConnectWorldUpdateBegin(std::bind(&Plugin::OnUpdate, &plugin));
  gazebo::event::Events::worldUpdateBegin(gazebo::common::UpdateInfo());
  EXPECT_EQ(plugin.updates, 1);
}

TEST(GazeboEvents, ASubscriberMayDisconnectAnotherDuringTheCall)
{
  gazebo::event::EventT<void()> step;
  int first = 0, second = 0;
  gazebo::event::ConnectionPtr b;
  auto a = step.Connect([&] {
    ++first;
    b.reset();
  });
  b = step.Connect([&] { ++second; });
  step();
  EXPECT_EQ(first, 1);
  EXPECT_EQ(second, 0);  // disconnected before its turn came
}

TEST(GazeboConsole, LinesCarryGazebosPrefixes)
{
  const std::string path = mesh_fixtures::tempDir("gazebo_console") + "/err.txt";
  FILE* saved = std::freopen(path.c_str(), "w", stderr);
  ASSERT_NE(saved, nullptr);
  gzerr << "joint [" << "wheel" << "] not found" << std::endl;
  gzwarn << "slow" << std::endl;
  std::fflush(stderr);
  std::ifstream written(path);
  std::string error_line, warning_line;
  std::getline(written, error_line);
  std::getline(written, warning_line);
  EXPECT_EQ(error_line.rfind("[Err] [test_gazebo_common.cpp:", 0), 0u) << error_line;
  EXPECT_NE(error_line.find("] joint [wheel] not found"), std::string::npos) << error_line;
  EXPECT_EQ(warning_line.rfind("[Wrn] [test_gazebo_common.cpp:", 0), 0u) << warning_line;
}

TEST(GazeboPlugin, ALibraryThatIsNotFoundOrNotAPluginGivesNoPluginAndSaysWhy)
{
  EXPECT_FALSE(gazebo::ModelPlugin::Create("libno_such_plugin_here.so", "missing"));
  // A shared library without RegisterPlugin: the C library itself.
  EXPECT_FALSE(gazebo::WorldPlugin::Create("libm.so.6", "not_a_plugin"));
}

// common::PID drives a unit mass to a target as Gazebo's joint controllers use it: the command is
// the force for error = position - target.
TEST(GazeboPid, DrivesAMassToItsTargetAndHoldsItsLimits)
{
  gazebo::common::PID pid(40.0, 20.0, 12.0, 2.0, -2.0, 10.0, -10.0);
  double x = 0.0, v = 0.0;
  const double dt = 0.001, target = 1.0;
  double largest = 0.0;
  for (int i = 0; i < 20000; ++i)  // 20 s: the integral's wind-up unwinds in a few seconds
  {
    const double force = pid.Update(x - target, dt);
    largest = std::max(largest, std::abs(force));
    v += force * dt;
    x += v * dt;
  }
  EXPECT_NEAR(x, target, 1e-3);
  EXPECT_LE(largest, 10.0);  // clamped to [cmdMin, cmdMax]
  double pe, ie, de;
  pid.GetErrors(pe, ie, de);
  EXPECT_LE(std::abs(20.0 * ie), 2.0);  // the integral term within [imin, imax]
}

TEST(GazeboPid, AZeroStepOrANonFiniteErrorCommandsNothingAndUnclampedByDefault)
{
  gazebo::common::PID pid(2.0, 0.0, 0.0);
  EXPECT_EQ(pid.Update(1.0, gazebo::common::Time(0, 0)), 0.0);
  EXPECT_EQ(pid.Update(std::numeric_limits<double>::quiet_NaN(), 0.01), 0.0);
  EXPECT_EQ(pid.Update(-100.0, 0.01), 200.0);  // cmdMax -1 < cmdMin 0: no clamp
  gazebo::common::PID copy;
  copy = pid;
  EXPECT_EQ(copy.GetPGain(), 2.0);
  EXPECT_EQ(copy.GetCmd(), 0.0);  // assignment starts the errors and the command again, as Gazebo's
}

// sensors::Sensor, the base every Gazebo sensor type derives from: what its <sensor> element gives,
// over sensor.sdf's defaults, and its names as gazebo_ros_utils.h reads them (GetModelName splits
// ScopedName at "::").
class CountingSensor : public gazebo::sensors::Sensor
{
public:
  CountingSensor() : Sensor(gazebo::sensors::OTHER) {}
  int updates = 0;

protected:
  bool UpdateImpl(bool) override { return ++updates > 0; }
};

sdf::ElementPtr sensorElement(const std::string& xml)
{
  sdf::SDFPtr document(new sdf::SDF);
  sdf::init(document);
  sdf::readString("<sdf version='1.6'><model name='m'><link name='l'>" + xml + "</link></model></sdf>", document);
  return document->Root()->GetElement("model")->GetElement("link")->GetElement("sensor");
}

// Gazebo's animate_joints example's key frames, on a loop of 5 s.
TEST(GazeboAnimation, ANumericAnimationInterpolatesBetweenItsKeyFramesAndWrapsWhereItLoops)
{
  gazebo::common::NumericAnimationPtr anim(new gazebo::common::NumericAnimation("swing", 5.0, true));
  anim->CreateKeyFrame(0.0)->SetValue(0.1);
  anim->CreateKeyFrame(5.0)->SetValue(0.1);
  anim->CreateKeyFrame(2.5)->SetValue(2.0);  // created out of order, kept in time order
  ASSERT_EQ(anim->GetKeyFrameCount(), 3u);
  EXPECT_DOUBLE_EQ(anim->GetKeyFrame(1)->GetTime(), 2.5);
  EXPECT_EQ(anim->GetKeyFrame(3), nullptr);

  gazebo::common::NumericKeyFrame value(0);
  anim->GetInterpolatedKeyFrame(value);
  EXPECT_DOUBLE_EQ(value.GetValue(), 0.1);
  anim->AddTime(1.25);
  anim->GetInterpolatedKeyFrame(value);
  EXPECT_NEAR(value.GetValue(), 1.05, 1e-12);
  anim->AddTime(2.5);  // 3.75 s: half way back
  anim->GetInterpolatedKeyFrame(value);
  EXPECT_NEAR(value.GetValue(), 1.05, 1e-12);
  anim->AddTime(1.75);  // 5.5 s: 0.5 s into the next loop
  EXPECT_NEAR(anim->GetTime(), 0.5, 1e-12);
  anim->GetInterpolatedKeyFrame(value);
  EXPECT_NEAR(value.GetValue(), 0.1 + 1.9 * 0.2, 1e-12);
}

TEST(GazeboAnimation, WithoutALoopTheTimeStaysWithinTheLengthAndBadInputChangesNothing)
{
  gazebo::common::NumericAnimation anim("once", 2.0, false);
  anim.CreateKeyFrame(0.0)->SetValue(0.0);
  anim.CreateKeyFrame(2.0)->SetValue(4.0);
  anim.AddTime(3.0);
  EXPECT_DOUBLE_EQ(anim.GetTime(), 2.0);
  gazebo::common::NumericKeyFrame value(0);
  anim.GetInterpolatedKeyFrame(value);
  EXPECT_DOUBLE_EQ(value.GetValue(), 4.0);
  anim.AddTime(-5.0);
  EXPECT_DOUBLE_EQ(anim.GetTime(), 0.0);
  anim.AddTime(std::numeric_limits<double>::quiet_NaN());
  EXPECT_DOUBLE_EQ(anim.GetTime(), 0.0);

  // no key frames: the value asked for is left as it was; a loop of no length stays at 0
  gazebo::common::NumericAnimation empty("empty", 0.0, true);
  empty.AddTime(1.0);
  gazebo::common::NumericKeyFrame untouched(0);
  untouched.SetValue(7.0);
  empty.GetInterpolatedKeyFrame(untouched);
  EXPECT_DOUBLE_EQ(untouched.GetValue(), 7.0);
}

TEST(GazeboAnimation, APoseAnimationPassesThroughItsKeyFramesAlongSplines)
{
  gazebo::common::PoseAnimation anim("slide", 2.0, false);
  for (int second = 0; second <= 2; ++second)
  {
    gazebo::common::PoseKeyFrame* key = anim.CreateKeyFrame(second);
    key->Translation(ignition::math::Vector3d(second, 0, 0));
    key->Rotation(ignition::math::Quaterniond(0, 0, 0.5 * second));
  }
  gazebo::common::PoseKeyFrame pose(0);
  anim.SetTime(1.0);  // on a key frame: that key frame
  anim.GetInterpolatedKeyFrame(pose);
  EXPECT_NEAR(pose.Translation().X(), 1.0, 1e-9);
  EXPECT_NEAR(pose.Rotation().Yaw(), 0.5, 1e-9);
  // between key frames: along ignition-math's splines through them (Catmull-Rom through the
  // translations, squad through the rotations, their tangents made once), as Gazebo's
  anim.SetTime(0.5);
  anim.GetInterpolatedKeyFrame(pose);
  ignition::math::Spline translations;
  ignition::math::RotationSpline rotations;
  translations.AutoCalculate(false);
  rotations.AutoCalculate(false);
  for (int second = 0; second <= 2; ++second)
  {
    translations.AddPoint(ignition::math::Vector3d(second, 0, 0));
    rotations.AddPoint(ignition::math::Quaterniond(0, 0, 0.5 * second));
  }
  translations.RecalcTangents();
  rotations.RecalcTangents();
  EXPECT_NEAR(pose.Translation().X(), translations.Interpolate(0, 0.5).X(), 1e-12);
  EXPECT_NEAR(pose.Rotation().Yaw(), rotations.Interpolate(0, 0.5).Yaw(), 1e-12);
  EXPECT_GT(pose.Translation().X(), 0.4);  // on its way from the first key frame to the second
  EXPECT_LT(pose.Translation().X(), 0.5);
  anim.SetTime(1.5);  // the second segment: from index 1
  anim.GetInterpolatedKeyFrame(pose);
  EXPECT_NEAR(pose.Translation().X(), translations.Interpolate(1, 0.5).X(), 1e-12);
  EXPECT_GT(pose.Translation().X(), 1.0);
  EXPECT_LT(pose.Translation().X(), 2.0);
}

TEST(GazeboSensor, ReadsItsElementOverTheSpecsDefaultsAndNamesItselfByItsParent)
{
  CountingSensor sonar, quiet;
  sonar.Load("default", sensorElement("<sensor name='front_sonar' type='sonar'><always_on>1</always_on>"
                                      "<update_rate>20</update_rate><topic>range</topic><pose>0.1 0 0.2 0 0 0</pose>"
                                      "</sensor>"));
  sonar.SetParent("bot::chassis", 7);
  EXPECT_EQ(sonar.Name(), "front_sonar");
  EXPECT_EQ(sonar.Type(), "sonar");
  EXPECT_TRUE(sonar.IsActive());
  EXPECT_DOUBLE_EQ(sonar.UpdateRate(), 20.0);
  EXPECT_EQ(sonar.Topic(), "range");
  EXPECT_EQ(sonar.Pose(), ignition::math::Pose3d(0.1, 0, 0.2, 0, 0, 0));
  EXPECT_EQ(sonar.ParentName(), "bot::chassis");
  EXPECT_EQ(sonar.ParentId(), 7u);
  EXPECT_EQ(sonar.ScopedName(), "default::bot::chassis::front_sonar");
  EXPECT_EQ(sonar.Category(), gazebo::sensors::OTHER);

  quiet.Load("default", sensorElement("<sensor name='q' type='imu'/>"));
  EXPECT_FALSE(quiet.IsActive());  // always_on's default
  EXPECT_DOUBLE_EQ(quiet.UpdateRate(), 0.0);
  EXPECT_EQ(quiet.Topic(), "");
  EXPECT_FALSE(quiet.Visualize());
  EXPECT_NE(quiet.Id(), sonar.Id());
}

TEST(GazeboSensor, InNoWorldItSaysSoOnceAndNeverUpdates)
{
  CountingSensor lost;
  testing::internal::CaptureStderr();
  lost.Load("no_such_world", sensorElement("<sensor name='lost' type='imu'><always_on>1</always_on></sensor>"));
  lost.Update(true);
  lost.Update(true);
  const std::string said = testing::internal::GetCapturedStderr();
  EXPECT_EQ(lost.updates, 0);
  EXPECT_NE(said.find("Unable to find world by name in physics::get_world[no_such_world]"), std::string::npos) << said;
  EXPECT_EQ(said.find("is in no world"), said.rfind("is in no world")) << said;
  EXPECT_NE(said.find("Sensor [lost] is in no world"), std::string::npos) << said;
}
