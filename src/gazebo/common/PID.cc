// common::PID (gazebo/common/PID.hh).
#include "gazebo/common/PID.hh"

#include <algorithm>
#include <cmath>

namespace gazebo
{
namespace common
{
PID::PID(double p, double i, double d, double imax, double imin, double cmdMax, double cmdMin)
  : p_gain_(p), i_gain_(i), d_gain_(d), i_max_(imax), i_min_(imin), cmd_max_(cmdMax), cmd_min_(cmdMin)
{
}

PID::~PID() = default;

void PID::Init(double p, double i, double d, double imax, double imin, double cmdMax, double cmdMin)
{
  p_gain_ = p;
  i_gain_ = i;
  d_gain_ = d;
  i_max_ = imax;
  i_min_ = imin;
  cmd_max_ = cmdMax;
  cmd_min_ = cmdMin;
  Reset();
}

void PID::SetPGain(double p) { p_gain_ = p; }
void PID::SetIGain(double i) { i_gain_ = i; }
void PID::SetDGain(double d) { d_gain_ = d; }
void PID::SetIMax(double i) { i_max_ = i; }
void PID::SetIMin(double i) { i_min_ = i; }
void PID::SetCmdMax(double c) { cmd_max_ = c; }
void PID::SetCmdMin(double c) { cmd_min_ = c; }
double PID::GetPGain() const { return p_gain_; }
double PID::GetIGain() const { return i_gain_; }
double PID::GetDGain() const { return d_gain_; }
double PID::GetIMax() const { return i_max_; }
double PID::GetIMin() const { return i_min_; }
double PID::GetCmdMax() const { return cmd_max_; }
double PID::GetCmdMin() const { return cmd_min_; }

void PID::Reset()
{
  p_err_last_ = p_err_ = i_err_ = d_err_ = cmd_ = 0.0;
}

double PID::Update(double error, common::Time dt) { return Update(error, dt.Double()); }

double PID::Update(double error, double dt)
{
  p_err_ = error;
  if (dt == 0.0 || !std::isfinite(error) || !std::isfinite(dt))
    return 0.0;
  const double p_term = p_gain_ * p_err_;
  i_err_ += dt * p_err_;
  double i_term = i_gain_ * i_err_;
  // The integral term held within its limits, the integral kept where the limit puts it (an integral
  // gain of 0 has no term to hold).
  if (i_term > i_max_ || i_term < i_min_)
  {
    i_term = i_term > i_max_ ? i_max_ : i_min_;
    if (i_gain_ != 0.0)
      i_err_ = i_term / i_gain_;
  }
  d_err_ = (p_err_ - p_err_last_) / dt;
  p_err_last_ = p_err_;
  cmd_ = -p_term - i_term - d_gain_ * d_err_;
  if (cmd_max_ >= cmd_min_)
    cmd_ = std::min(std::max(cmd_, cmd_min_), cmd_max_);
  return cmd_;
}

void PID::SetCmd(double cmd) { cmd_ = cmd; }

double PID::GetCmd() { return cmd_; }

void PID::GetErrors(double& pe, double& ie, double& de)
{
  pe = p_err_;
  ie = i_err_;
  de = d_err_;
}

PID& PID::operator=(const PID& other)
{
  if (this != &other)
  {
    p_gain_ = other.p_gain_;
    i_gain_ = other.i_gain_;
    d_gain_ = other.d_gain_;
    i_max_ = other.i_max_;
    i_min_ = other.i_min_;
    cmd_max_ = other.cmd_max_;
    cmd_min_ = other.cmd_min_;
    Reset();
  }
  return *this;
}
}  // namespace common
}  // namespace gazebo
