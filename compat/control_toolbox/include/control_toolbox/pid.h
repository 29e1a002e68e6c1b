// control_toolbox::Pid as ros_controls' control_toolbox (noetic) offers it: gains in a Gains struct,
// init from the parameter server (p required; i, d, i_clamp, i_clamp_min, i_clamp_max, antiwindup),
// computeCommand(error, dt) with the derivative from the previous error, or (error, error_dot, dt):
// command = p e + i integral(e) + d e', the integral term held within [i_min, i_max] (antiwindup:
// the integral itself). Differs: no dynamic_reconfigure server and no state publisher
// (initDynamicReconfig is absent); the gains are not shared with a realtime thread.
#pragma once

#include <string>

#include <ros/duration.h>
#include <ros/node_handle.h>

namespace control_toolbox
{
class Pid
{
public:
  struct Gains
  {
    Gains() = default;
    Gains(double p, double i, double d, double i_max, double i_min)
      : p_gain_(p), i_gain_(i), d_gain_(d), i_max_(i_max), i_min_(i_min)
    {
    }
    Gains(double p, double i, double d, double i_max, double i_min, bool antiwindup)
      : p_gain_(p), i_gain_(i), d_gain_(d), i_max_(i_max), i_min_(i_min), antiwindup_(antiwindup)
    {
    }
    double p_gain_ = 0.0;
    double i_gain_ = 0.0;
    double d_gain_ = 0.0;
    double i_max_ = 0.0;
    double i_min_ = 0.0;
    bool antiwindup_ = false;
  };

  Pid(double p = 0.0, double i = 0.0, double d = 0.0, double i_max = 0.0, double i_min = -0.0,
      bool antiwindup = false);
  void initPid(double p, double i, double d, double i_max, double i_min, bool antiwindup = false);
  // The gains under `prefix` (a parameter namespace) or `node`'s namespace; false (and, unless
  // quiet, upstream's error) without a p gain.
  bool initParam(const std::string& prefix, const bool quiet = false);
  bool init(const ros::NodeHandle& node, const bool quiet = false);
  void reset();
  void getGains(double& p, double& i, double& d, double& i_max, double& i_min);
  void getGains(double& p, double& i, double& d, double& i_max, double& i_min, bool& antiwindup);
  Gains getGains() const { return gains_; }
  void setGains(double p, double i, double d, double i_max, double i_min, bool antiwindup = false);
  void setGains(const Gains& gains) { gains_ = gains; }
  // 0 for a zero step or an error that is not finite.
  double computeCommand(double error, ros::Duration dt);
  double computeCommand(double error, double error_dot, ros::Duration dt);
  void setCurrentCmd(double cmd) { cmd_ = cmd; }
  double getCurrentCmd() { return cmd_; }
  void getCurrentPIDErrors(double* pe, double* ie, double* de);
  void printValues();

private:
  Gains gains_;
  bool valid_p_error_last_ = false;
  double p_error_last_ = 0.0, p_error_ = 0.0, i_error_ = 0.0, d_error_ = 0.0, cmd_ = 0.0;
};
}  // namespace control_toolbox
