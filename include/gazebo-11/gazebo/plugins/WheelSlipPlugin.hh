// Gazebo 11's WheelSlipPlugin (libWheelSlipPlugin.so), a model plugin of Gazebo's own that
// gazebo_ros_pkgs' gazebo_ros_wheel_slip derives from. Each <wheel link_name="..."> (one collision,
// one parent joint: its spin axis) gets a slip that grows with its rolling speed: every step, the
// wheel's collision's ODE slips are set to
//   slip1 = r |w| / wheel_normal_force * slip_compliance_lateral        (along fdir1, the spin axis)
//   slip2 = r |w| / wheel_normal_force * slip_compliance_longitudinal   (across it, the rolling way)
// so that at the normal force given, the friction force along a direction is the slip ratio there
// divided by the compliance (until it reaches mu times the normal force). r is <wheel_radius>, or
// the collision's cylinder's or sphere's. The compliances change on ~/<model>/wheel_slip/
// lateral_compliance and longitudinal_compliance (GzString numbers) or by the Set* calls; each
// wheel's slip velocities (longitudinal, lateral, r w) are published on
// ~/<model>/wheel_slip/<link> (msgs::Vector3d) every step.
#pragma once

#include <map>
#include <memory>
#include <string>

#include <ignition/math/Vector2.hh>
#include <ignition/math/Vector3.hh>

#include "gazebo/common/Plugin.hh"
#include "gazebo/msgs/msgs.hh"
#include "gazebo/util/system.hh"

namespace gazebo
{
class WheelSlipPluginPrivate;

class GZ_PLUGIN_VISIBLE WheelSlipPlugin : public ModelPlugin
{
public:
  WheelSlipPlugin();
  ~WheelSlipPlugin() override;
  void Load(physics::ModelPtr _model, sdf::ElementPtr _sdf) override;
  virtual void Fini();
  physics::ModelPtr GetParentModel() const;
  // Each wheel's slip velocities by link name: X the longitudinal slip (m/s), Y the lateral slip
  // (m/s), Z the radius times the spin rate (m/s).
  void GetSlips(std::map<std::string, ignition::math::Vector3d>& _out) const;
  // The unitless compliances, for every wheel or one by its link's name.
  void SetSlipComplianceLateral(const double _compliance);
  void SetSlipComplianceLateral(std::string _wheel_name, const double _compliance);
  void SetSlipComplianceLongitudinal(const double _compliance);
  void SetSlipComplianceLongitudinal(std::string _wheel_name, const double _compliance);
  // Each wheel's friction coefficients (X primary, Y secondary), and one wheel's set; false for a
  // wheel the plugin does not have.
  std::map<std::string, ignition::math::Vector2d> GetFrictionCoefficients();
  bool SetMuPrimary(const std::string& _wheel_name, double _mu);
  bool SetMuSecondary(const std::string& _wheel_name, double _mu);

private:
  void OnLateralCompliance(ConstGzStringPtr& _msg);
  void OnLongitudinalCompliance(ConstGzStringPtr& _msg);
  void Update();

  std::unique_ptr<WheelSlipPluginPrivate> dataPtr;
};
}  // namespace gazebo
