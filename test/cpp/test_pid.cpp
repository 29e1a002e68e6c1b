// control_toolbox's PID as pid.cpp implements it (docs/interfaces.md section 4): the three terms,
// i_clamp and antiwindup, the guards, the gains from parameters, and the implicit laws the joints use.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "bullet_plant/params.h"
#include "bullet_plant/pid.h"

using bullet_plant::EffortLaw;
using bullet_plant::Param;
using bullet_plant::Pid;
using bullet_plant::PidGains;
using bullet_plant::readPidGains;

namespace
{
PidGains gains(double p, double i, double d, double i_clamp, bool antiwindup = false)
{
  return PidGains::withIClamp(p, i, d, i_clamp, antiwindup);
}

// What the law asks for when the joint ends the step at (q_end, qd_end).
double effortAt(const EffortLaw& law, double q_end, double qd_end)
{
  return law.feedforward + law.stiffness * (law.position_target - q_end) + law.damping * (law.velocity_target - qd_end);
}

const double kNaN = std::numeric_limits<double>::quiet_NaN();
const double kInf = std::numeric_limits<double>::infinity();
}  // namespace

TEST(Pid, ProportionalIntegralAndDerivativeTerms)
{
  Pid pid(gains(2.0, 3.0, 0.1, 100.0));
  // first call: the derivative is taken from a previous error of 0; the integral is dt * error
  EXPECT_DOUBLE_EQ(pid.computeCommand(1.0, 0.1), 2.0 * 1.0 + 3.0 * 0.1 + 0.1 * (1.0 - 0.0) / 0.1);
  EXPECT_DOUBLE_EQ(pid.computeCommand(0.5, 0.1), 2.0 * 0.5 + 3.0 * (0.1 + 0.05) + 0.1 * (0.5 - 1.0) / 0.1);
  EXPECT_DOUBLE_EQ(pid.pError(), 0.5);
  EXPECT_DOUBLE_EQ(pid.iError(), 0.15);
  EXPECT_DOUBLE_EQ(pid.dError(), -5.0);
  // the explicit error_dot form
  EXPECT_DOUBLE_EQ(pid.computeCommand(0.5, 2.0, 0.1), 2.0 * 0.5 + 3.0 * (0.15 + 0.05) + 0.1 * 2.0);
  EXPECT_DOUBLE_EQ(pid.command(), 2.0 * 0.5 + 3.0 * 0.2 + 0.1 * 2.0);
}

TEST(Pid, IClampBoundsTheIntegralTermNotTheIntegral)
{
  Pid pid(gains(0.0, 2.0, 0.0, 1.0));
  EXPECT_DOUBLE_EQ(pid.computeCommand(1.0, 0.4), 0.8);
  EXPECT_DOUBLE_EQ(pid.computeCommand(1.0, 0.4), 1.0) << "2 * 0.8 clamped to i_max";
  EXPECT_DOUBLE_EQ(pid.iError(), 0.8) << "the integral itself keeps growing";
  EXPECT_DOUBLE_EQ(pid.computeCommand(-1.0, 0.4), 0.8) << "2 * 0.4: still wound up";
  EXPECT_DOUBLE_EQ(pid.computeCommand(-5.0, 0.4), -1.0) << "2 * -1.6 clamped to i_min";

  Pid zero_clamp(gains(0.0, 2.0, 0.0, 0.0));
  for (int k = 0; k < 10; ++k)
    EXPECT_EQ(zero_clamp.computeCommand(1.0, 0.1), 0.0) << "i_clamp 0 disables the integral term";
  EXPECT_NEAR(zero_clamp.iError(), 1.0, 1e-12);
}

TEST(Pid, AntiwindupClampsTheIntegralItself)
{
  Pid windup(gains(0.0, 2.0, 0.0, 1.0, false));
  Pid antiwindup(gains(0.0, 2.0, 0.0, 1.0, true));
  for (int k = 0; k < 5; ++k)
  {
    windup.computeCommand(1.0, 0.1);
    antiwindup.computeCommand(1.0, 0.1);
  }
  EXPECT_DOUBLE_EQ(windup.computeCommand(1.0, 0.1), 1.0);      // 2 * 0.6 clamped to 1
  EXPECT_DOUBLE_EQ(antiwindup.computeCommand(1.0, 0.1), 1.0);  // integral held at i_max / i = 0.5
  EXPECT_DOUBLE_EQ(antiwindup.iError(), 0.5);
  EXPECT_DOUBLE_EQ(windup.computeCommand(-1.0, 0.1), 1.0);      // 2 * 0.6: still wound up
  EXPECT_DOUBLE_EQ(antiwindup.computeCommand(-1.0, 0.1), 0.8);  // 2 * (0.5 - 0.1)
}

TEST(Pid, AntiwindupBoundsAreDividedByTheMagnitudeOfI)
{
  PidGains g = gains(0.0, -4.0, 0.0, 0.0, true);
  g.i_max = 2.0;
  g.i_min = -1.0;
  Pid pid(g);
  pid.computeCommand(10.0, 1.0);
  EXPECT_DOUBLE_EQ(pid.iError(), 0.5) << "i_max / |i|";
  EXPECT_DOUBLE_EQ(pid.command(), -2.0);
  pid.computeCommand(-10.0, 1.0);
  EXPECT_DOUBLE_EQ(pid.iError(), -0.25) << "i_min / |i|";
}

TEST(Pid, ZeroStepAndNonFiniteErrorsGiveZero)
{
  for (double bad : {kNaN, kInf, -kInf})
  {
    Pid pid(gains(2.0, 1.0, 0.5, 10.0));
    EXPECT_EQ(pid.computeCommand(bad, 0.01), 0.0) << bad;
    EXPECT_EQ(pid.computeCommand(1.0, bad, 0.01), 0.0) << "error_dot " << bad;
    EXPECT_EQ(pid.iError(), 0.0) << "nothing integrated";
  }
  Pid pid(gains(2.0, 1.0, 0.5, 10.0));
  EXPECT_EQ(pid.computeCommand(1.0, 0.0), 0.0) << "dt 0";
  EXPECT_EQ(pid.pError(), 0.0) << "the derivative form returns before recording the error";
  EXPECT_EQ(pid.computeCommand(1.0, 3.0, 0.0), 0.0) << "dt 0";
  EXPECT_EQ(pid.pError(), 1.0) << "the error_dot form records the errors first";
  EXPECT_EQ(pid.dError(), 3.0);
  EXPECT_EQ(pid.iError(), 0.0);
}

TEST(Pid, ResetClearsTheHistory)
{
  Pid pid(gains(0.0, 0.0, 0.1, 0.0));
  pid.computeCommand(1.0, 0.01);
  EXPECT_EQ(pid.computeCommand(1.0, 0.01), 0.0) << "steady error: no derivative";
  pid.reset();
  EXPECT_DOUBLE_EQ(pid.computeCommand(1.0, 0.01), 0.1 * 1.0 / 0.01) << "the derivative kick from 0";
}

TEST(PidGains, IClampBoundsBothWays)
{
  PidGains g = PidGains::withIClamp(1.0, 2.0, 3.0, -0.7, true);
  EXPECT_EQ(g.p, 1.0);
  EXPECT_EQ(g.i, 2.0);
  EXPECT_EQ(g.d, 3.0);
  EXPECT_EQ(g.i_max, 0.7);
  EXPECT_EQ(g.i_min, -0.7);
  EXPECT_TRUE(g.antiwindup);
}

TEST(PidGains, ReadFromParameters)
{
  Param root = Param::map();
  root.set("/bot/ctrl/pid/p", Param::real(4.0));
  root.set("/bot/ctrl/pid/i", Param::integer(2));
  root.set("/bot/ctrl/pid/d", Param::real(1.0));
  root.set("/bot/ctrl/pid/i_clamp", Param::real(-3.0));
  root.set("/bot/ctrl/pid/antiwindup", Param::boolean(true));
  PidGains g = readPidGains(root, "/bot/ctrl/pid");
  EXPECT_EQ(g.p, 4.0);
  EXPECT_EQ(g.i, 2.0);
  EXPECT_EQ(g.d, 1.0);
  EXPECT_EQ(g.i_max, 3.0) << "i_max = |i_clamp|";
  EXPECT_EQ(g.i_min, -3.0) << "i_min = -|i_clamp|";
  EXPECT_TRUE(g.antiwindup);

  root.set("/bot/ctrl/pid/i_clamp_max", Param::real(5.0));
  root.set("/bot/ctrl/pid/i_clamp_min", Param::real(-0.5));
  root.set("/bot/ctrl/pid/antiwindup", Param::integer(1));
  g = readPidGains(root, "/bot/ctrl/pid");
  EXPECT_EQ(g.i_max, 5.0) << "i_clamp_max overrides";
  EXPECT_EQ(g.i_min, -0.5) << "i_clamp_min overrides";
  EXPECT_FALSE(g.antiwindup) << "only a boolean turns antiwindup on";

  Param only_p = Param::map();
  only_p.set("ns/pid/p", Param::real(1.0));
  g = readPidGains(only_p, "ns/pid");
  EXPECT_EQ(g.i, 0.0);
  EXPECT_EQ(g.d, 0.0);
  EXPECT_EQ(g.i_max, 0.0);
  EXPECT_EQ(g.i_min, 0.0);
  EXPECT_FALSE(g.antiwindup);
}

TEST(PidGains, MissingPNamesTheNamespace)
{
  Param root = Param::map();
  root.set("/bot/ctrl/pid/i", Param::real(1.0));
  root.set("/bot/other/pid/p", Param::string("four"));
  for (const char* ns : {"bot/ctrl/pid", "bot/other/pid"})
  {
    try
    {
      readPidGains(root, ns);
      FAIL() << "no error for " << ns;
    }
    catch (const std::runtime_error& e)
    {
      EXPECT_EQ(std::string(e.what()), std::string("No p gain specified for pid.  Namespace: /") + ns);
    }
  }
}

// The velocity law: effort = p*e' + d*(e' - e_last)/dt + i_term with e' = v* - qd' at the step's end.
TEST(PidImplicit, VelocityLawByHand)
{
  Pid pid(gains(100.0, 0.5, 10.0, 1.0));
  const double dt = 0.001;
  EffortLaw law = pid.implicitVelocityLaw(31.25, 30.0, dt);
  EXPECT_TRUE(law.implicit());
  EXPECT_DOUBLE_EQ(law.damping, 100.0 + 10.0 / dt);
  EXPECT_DOUBLE_EQ(law.velocity_target, 31.25);
  EXPECT_EQ(law.stiffness, 0.0);
  EXPECT_DOUBLE_EQ(law.feedforward, 0.5 * (dt * 1.25) - 10.0 / dt * 0.0);
  EXPECT_DOUBLE_EQ(pid.pError(), 1.25);

  pid.endImplicitStep(0.75, 7.0, dt);
  EXPECT_DOUBLE_EQ(pid.dError(), 0.75 / dt);
  EXPECT_DOUBLE_EQ(pid.pError(), 0.75);
  EXPECT_DOUBLE_EQ(pid.command(), 7.0);

  law = pid.implicitVelocityLaw(31.25, 30.5, dt);
  EXPECT_DOUBLE_EQ(law.feedforward, 0.5 * (dt * 1.25 + dt * 0.75) - 10.0 / dt * 0.75);
}

TEST(PidImplicit, PositionLawByHand)
{
  Pid pid(gains(4.0, 2.0, 1.0, 10.0));
  const double dt = 0.001;
  EffortLaw law = pid.implicitPositionLaw(0.3, 0.1, dt);
  EXPECT_DOUBLE_EQ(law.stiffness, 4.0);
  EXPECT_DOUBLE_EQ(law.position_target, 0.4);
  EXPECT_DOUBLE_EQ(law.damping, 1.0);
  EXPECT_EQ(law.velocity_target, 0.0);
  EXPECT_DOUBLE_EQ(law.feedforward, 2.0 * (dt * 0.3) + 1.0 / dt * (0.3 - 0.0));

  pid.endImplicitStep(0.25, -1.5, dt);
  EXPECT_DOUBLE_EQ(pid.dError(), 0.25 / dt);
  law = pid.implicitPositionLaw(0.2, 0.2, dt);
  EXPECT_DOUBLE_EQ(law.position_target, 0.4);
  EXPECT_DOUBLE_EQ(law.feedforward, 2.0 * (dt * 0.3 + dt * 0.2) + 1.0 / dt * (0.2 - 0.25));
}

// Without an integral, both laws evaluated at the state the step ends in are computeCommand of the
// error the step ends with: the same controller, taken at the end of the step.
TEST(PidImplicit, LawsAreComputeCommandAtTheEndOfTheStep)
{
  const double dt = 0.002;
  Pid implicit_pid(gains(4.0, 0.0, 1.0, 0.0)), explicit_pid(gains(4.0, 0.0, 1.0, 0.0));
  const double q = 0.1, error = 0.3, qd_end = 2.0, q_end = q + dt * qd_end;
  EffortLaw law = implicit_pid.implicitPositionLaw(error, q, dt);
  const double error_end = (q + error) - q_end;
  EXPECT_NEAR(effortAt(law, q_end, qd_end), explicit_pid.computeCommand(error_end, dt), 1e-9);

  Pid implicit_vel(gains(100.0, 0.0, 10.0, 0.0)), explicit_vel(gains(100.0, 0.0, 10.0, 0.0));
  implicit_vel.endImplicitStep(0.4, 0.0, dt);
  explicit_vel.computeCommand(0.4, dt);
  law = implicit_vel.implicitVelocityLaw(5.0, 4.0, dt);
  EXPECT_NEAR(effortAt(law, 0.0, 4.7), explicit_vel.computeCommand(5.0 - 4.7, dt), 1e-9);
}

TEST(PidImplicit, ZeroStepOrNonFiniteErrorGivesNoLaw)
{
  Pid pid(gains(4.0, 2.0, 1.0, 10.0));
  EXPECT_FALSE(pid.implicitPositionLaw(0.3, 0.0, 0.0).implicit());
  EXPECT_FALSE(pid.implicitPositionLaw(kNaN, 0.0, 0.001).implicit());
  EXPECT_FALSE(pid.implicitVelocityLaw(1.0, 0.0, 0.0).implicit());
  EXPECT_FALSE(pid.implicitVelocityLaw(kInf, 0.0, 0.001).implicit());
  EXPECT_EQ(pid.iError(), 0.0);
  pid.endImplicitStep(0.5, 1.0, 0.001);
  pid.endImplicitStep(kNaN, 2.0, 0.001);
  EXPECT_EQ(pid.pError(), 0.5) << "a non-finite end error is ignored";
  EXPECT_EQ(pid.command(), 1.0);
}
