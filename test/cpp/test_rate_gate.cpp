// RateGate and periodNsOfRate: the one update gate of the sensors, the ground-truth odometry and /clock;
// CatchUpRateGate: the `last += period` form of gazebo_plugins' drives and ros_controllers.
#include <gtest/gtest.h>

#include <limits>
#include <vector>

#include "bullet_plant/rate_gate.h"

using bullet_plant::periodNsOfRate;
using bullet_plant::RateGate;

TEST(RateGate, PeriodIsTheRoundedReciprocalAndZeroForNoRate)
{
  EXPECT_EQ(periodNsOfRate(40.0), 25000000);
  EXPECT_EQ(periodNsOfRate(30.0), 33333333);  // 33.33 ms: the camera's period on 1 ms steps
  EXPECT_EQ(periodNsOfRate(0.0), 0);
  EXPECT_EQ(periodNsOfRate(-5.0), 0);
}

TEST(RateGate, OpensFirstThenOncePerPeriod)
{
  RateGate gate(periodNsOfRate(100.0));  // 10 ms
  int opened = 0;
  for (int64_t t = 0; t <= 100000000; t += 1000000)  // 1 ms steps for 100 ms
    opened += gate.due(t);
  EXPECT_EQ(opened, 11);  // at 0, 10, ..., 100 ms
}

TEST(RateGate, ANonDividingPeriodOpensAtTheFirstStepPastIt)
{
  RateGate gate(periodNsOfRate(30.0));
  std::vector<int64_t> opened;
  for (int64_t t = 0; t <= 100000000; t += 1000000)
    if (gate.due(t))
      opened.push_back(t);
  EXPECT_EQ(opened, (std::vector<int64_t>{0, 34000000, 68000000}));
}

// gazebo_ros_triggered_camera sets its sensor's rate to DBL_MIN for "never" (Gazebo's period then
// wraps to some 68 years): the longest period, which never opens, not even first.
TEST(RateGate, ARateOfAlmostNothingNeverOpens)
{
  EXPECT_EQ(periodNsOfRate(2.2250738585072014e-308), std::numeric_limits<int64_t>::max());
  EXPECT_EQ(periodNsOfRate(1e-10), std::numeric_limits<int64_t>::max());
  RateGate gate(periodNsOfRate(2.2250738585072014e-308));
  EXPECT_FALSE(gate.due(0));
  EXPECT_FALSE(gate.due(std::numeric_limits<int64_t>::max() / 2));
  gate.setPeriodNs(0);
  EXPECT_TRUE(gate.due(1));
}

TEST(RateGate, WithoutAPeriodOpensEveryCall)
{
  RateGate gate;
  EXPECT_TRUE(gate.due(5));
  EXPECT_TRUE(gate.due(5));
  EXPECT_TRUE(gate.due(6));
}

TEST(RateGate, OpensAtOnceWhenTimeGoesBackOrAfterReset)
{
  RateGate gate(periodNsOfRate(1.0));
  EXPECT_TRUE(gate.due(5000000000));
  EXPECT_FALSE(gate.due(5500000000));
  EXPECT_TRUE(gate.due(1000000));  // a reset_simulation took time back
  EXPECT_FALSE(gate.due(2000000));
  gate.reset();
  EXPECT_TRUE(gate.due(3000000));
}

TEST(RateGate, WouldOpenForetellsWhetherTheCallsUpToATimeOpenItWithoutOpeningIt)
{
  // The Tianracer's 40 Hz lidar stepped at 1 ms in windows of 10 (CarBatch's question: will this
  // world scan within the step?).
  RateGate gate(periodNsOfRate(40.0));
  int scanning_windows = 0;
  for (int64_t start = 0; start < 200000000; start += 10000000)
  {
    const bool foretold = gate.wouldOpen(start + 10000000);
    EXPECT_EQ(gate.wouldOpen(start + 10000000), foretold) << "asking opened it";
    bool opened = false;
    for (int64_t t = start + 1000000; t <= start + 10000000; t += 1000000)
      opened = gate.due(t) || opened;
    EXPECT_EQ(opened, foretold) << "the window ending at " << (start + 10000000) / 1000000 << " ms";
    scanning_windows += opened;
  }
  EXPECT_EQ(scanning_windows, 8);  // at 1, 26, 51, ..., 176 ms: every second or third window
  EXPECT_TRUE(gate.wouldOpen(1000000)) << "time went back: it opens at once";
}

// CatchUpRateGate: upstream's `if (now - last > period) { ...; last += period; }`.
using bullet_plant::CatchUpRateGate;

TEST(CatchUpRateGate, OpensStrictlyAfterAPeriodFromWhereItWasRestarted)
{
  CatchUpRateGate gate(periodNsOfRate(100.0));  // 10 ms
  gate.restart(0);
  std::vector<int64_t> opened;
  for (int64_t t = 0; t <= 50000000; t += 1000000)  // 1 ms steps for 50 ms
    if (gate.due(t))
      opened.push_back(t);
  EXPECT_EQ(opened, (std::vector<int64_t>{11000000, 21000000, 31000000, 41000000}))
      << "a period having passed is not enough: more than one must";
  EXPECT_EQ(gate.lastNs(), 40000000) << "its clock stays on the period's grid, not at the call";
}

TEST(CatchUpRateGate, ALateCallIsCaughtUpOnTheFollowingCalls)
{
  CatchUpRateGate gate(10);
  gate.restart(0);
  EXPECT_TRUE(gate.due(35));  // three periods late
  EXPECT_EQ(gate.lastNs(), 10);
  EXPECT_TRUE(gate.due(36));
  EXPECT_TRUE(gate.due(37));
  EXPECT_FALSE(gate.due(38)) << "caught up: 38 is within a period of its clock (30)";
  EXPECT_EQ(gate.lastNs(), 30);
}

TEST(CatchUpRateGate, WithoutAPeriodOpensWhenTimeMovesAndTimeGoingBackKeepsItShut)
{
  CatchUpRateGate gate;
  gate.restart(5);
  EXPECT_FALSE(gate.due(5)) << "no time has passed";
  EXPECT_TRUE(gate.due(6));
  CatchUpRateGate slow(100);
  slow.restart(1000);
  EXPECT_FALSE(slow.due(10)) << "unlike RateGate, time going back does not reopen it (upstream's neither)";
  slow.restart(10);
  EXPECT_TRUE(slow.due(111));
}
