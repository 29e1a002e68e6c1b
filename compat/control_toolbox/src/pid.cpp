#include "control_toolbox/pid.h"

#include <algorithm>
#include <cmath>

#include <ros/console.h>

namespace control_toolbox
{
namespace
{
bool finite(double v) { return std::isfinite(v); }
}  // namespace

Pid::Pid(double p, double i, double d, double i_max, double i_min, bool antiwindup)
{
  initPid(p, i, d, i_max, i_min, antiwindup);
}

void Pid::initPid(double p, double i, double d, double i_max, double i_min, bool antiwindup)
{
  setGains(p, i, d, i_max, i_min, antiwindup);
  reset();
}

bool Pid::initParam(const std::string& prefix, const bool quiet) { return init(ros::NodeHandle(prefix), quiet); }

bool Pid::init(const ros::NodeHandle& node, const bool quiet)
{
  ros::NodeHandle nh(node);
  Gains gains;
  if (!nh.getParam("p", gains.p_gain_))
  {
    if (!quiet)
      ROS_ERROR("No p gain specified for pid.  Namespace: %s", nh.getNamespace().c_str());
    return false;
  }
  nh.param("i", gains.i_gain_, 0.0);
  nh.param("d", gains.d_gain_, 0.0);
  double i_clamp = 0.0;
  nh.param("i_clamp", i_clamp, 0.0);
  gains.i_max_ = std::abs(i_clamp);
  gains.i_min_ = -std::abs(i_clamp);
  if (nh.hasParam("i_clamp_min"))
  {
    nh.param("i_clamp_min", gains.i_min_, gains.i_min_);
    gains.i_min_ = -std::abs(gains.i_min_);
  }
  if (nh.hasParam("i_clamp_max"))
  {
    nh.param("i_clamp_max", gains.i_max_, gains.i_max_);
    gains.i_max_ = std::abs(gains.i_max_);
  }
  nh.param("antiwindup", gains.antiwindup_, false);
  setGains(gains);
  reset();
  return true;
}

void Pid::reset()
{
  valid_p_error_last_ = false;
  p_error_last_ = p_error_ = i_error_ = d_error_ = cmd_ = 0.0;
}

void Pid::getGains(double& p, double& i, double& d, double& i_max, double& i_min)
{
  bool antiwindup;
  getGains(p, i, d, i_max, i_min, antiwindup);
}

void Pid::getGains(double& p, double& i, double& d, double& i_max, double& i_min, bool& antiwindup)
{
  p = gains_.p_gain_;
  i = gains_.i_gain_;
  d = gains_.d_gain_;
  i_max = gains_.i_max_;
  i_min = gains_.i_min_;
  antiwindup = gains_.antiwindup_;
}

void Pid::setGains(double p, double i, double d, double i_max, double i_min, bool antiwindup)
{
  setGains(Gains(p, i, d, i_max, i_min, antiwindup));
}

double Pid::computeCommand(double error, ros::Duration dt)
{
  if (dt == ros::Duration(0.0) || !finite(error))
    return 0.0;
  double error_dot = d_error_;
  if (dt.toSec() > 0.0)
  {
    if (valid_p_error_last_)
      error_dot = (error - p_error_last_) / dt.toSec();
    p_error_last_ = error;
    valid_p_error_last_ = true;
  }
  return computeCommand(error, error_dot, dt);
}

double Pid::computeCommand(double error, double error_dot, ros::Duration dt)
{
  p_error_ = error;
  d_error_ = error_dot;
  if (dt == ros::Duration(0.0) || !finite(error) || !finite(error_dot))
    return 0.0;
  i_error_ += dt.toSec() * p_error_;
  if (gains_.antiwindup_ && gains_.i_gain_ != 0)
  {
    const double a = gains_.i_min_ / gains_.i_gain_, b = gains_.i_max_ / gains_.i_gain_;
    i_error_ = std::max(std::min(a, b), std::min(i_error_, std::max(a, b)));
  }
  double i_term = gains_.i_gain_ * i_error_;
  if (!gains_.antiwindup_)
    i_term = std::max(gains_.i_min_, std::min(i_term, gains_.i_max_));
  cmd_ = gains_.p_gain_ * p_error_ + i_term + gains_.d_gain_ * d_error_;
  return cmd_;
}

void Pid::getCurrentPIDErrors(double* pe, double* ie, double* de)
{
  *pe = p_error_;
  *ie = i_error_;
  *de = d_error_;
}

void Pid::printValues()
{
  ROS_INFO_STREAM_NAMED("pid", "Current Values of PID Class:\n"
                                   << "  P Gain:       " << gains_.p_gain_ << "\n"
                                   << "  I Gain:       " << gains_.i_gain_ << "\n"
                                   << "  D Gain:       " << gains_.d_gain_ << "\n"
                                   << "  I_Max:        " << gains_.i_max_ << "\n"
                                   << "  I_Min:        " << gains_.i_min_ << "\n"
                                   << "  Antiwindup:   " << gains_.antiwindup_ << "\n"
                                   << "  P_Error_Last: " << p_error_last_ << "\n"
                                   << "  P_Error:      " << p_error_ << "\n"
                                   << "  I_Error:      " << i_error_ << "\n"
                                   << "  D_Error:      " << d_error_ << "\n"
                                   << "  Command:      " << cmd_);
}
}  // namespace control_toolbox
