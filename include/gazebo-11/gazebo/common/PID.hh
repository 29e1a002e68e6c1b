// common::PID as Gazebo 11's: command = -(p e + i integral(e) + d de/dt) for the error
// e = state - target, the integral term held within [imin, imax], the command within
// [cmdMin, cmdMax] where cmdMax >= cmdMin (by default it is not clamped).
#pragma once

#include "gazebo/common/Time.hh"
#include "gazebo/util/system.hh"

namespace gazebo
{
namespace common
{
class GZ_COMMON_VISIBLE PID
{
public:
  PID(double p = 0.0, double i = 0.0, double d = 0.0, double imax = 0.0, double imin = 0.0, double cmdMax = -1.0,
      double cmdMin = 0.0);
  virtual ~PID();
  void Init(double p = 0.0, double i = 0.0, double d = 0.0, double imax = 0.0, double imin = 0.0, double cmdMax = -1.0,
            double cmdMin = 0.0);
  void SetPGain(double p);
  void SetIGain(double i);
  void SetDGain(double d);
  void SetIMax(double i);
  void SetIMin(double i);
  void SetCmdMax(double c);
  void SetCmdMin(double c);
  double GetPGain() const;
  double GetIGain() const;
  double GetDGain() const;
  double GetIMax() const;
  double GetIMin() const;
  double GetCmdMax() const;
  double GetCmdMin() const;
  // One step of `dt`: the command. A zero step or a non-finite error is 0 and changes nothing but
  // the error kept.
  double Update(double error, common::Time dt);
  double Update(double error, double dt);
  void SetCmd(double cmd);
  double GetCmd();
  void GetErrors(double& pe, double& ie, double& de);
  // The gains and limits of `other`; the errors and the command start again (Gazebo's).
  PID& operator=(const PID& other);
  void Reset();

private:
  double p_gain_, i_gain_, d_gain_, i_max_, i_min_, cmd_max_, cmd_min_;
  double p_err_last_ = 0.0, p_err_ = 0.0, i_err_ = 0.0, d_err_ = 0.0, cmd_ = 0.0;
};
}  // namespace common
}  // namespace gazebo
