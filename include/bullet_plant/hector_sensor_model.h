// hector_gazebo_plugins' SensorModel3 (sensor_model.h), the error model every hector sensor plugin
// shares: per axis, output = value * scaleError + offset + drift + white noise, the drift a
// first-order Gauss-Markov process of stationary deviation `drift` and bandwidth `driftFrequency`:
//   drift <- exp(-dt f) drift + dt N(0, sqrt(2 f) drift_sigma)
// drawn anew at load and reset as N(0, drift_sigma). Its parameters are <prefix>Offset,
// <prefix>Drift, <prefix>DriftFrequency, <prefix>GaussianNoise, <prefix>ScaleError, or offset, drift,
// ... without a prefix (docs/model_plugins.md).
#pragma once

#include <cctype>
#include <cmath>
#include <random>
#include <string>

#include <urdf_model/pose.h>

#include "bullet_plant/log.h"
#include "bullet_plant/model_plugin.h"
#include "bullet_plant/robot_description.h"

namespace bullet_plant
{
// <bodyName>, the link every hector model plugin measures (default: the model's root link); false,
// with the error logged naming the plugin, for a name that is no link of the model.
inline bool readHectorBodyName(const ModelPluginDescription& d, ModelPluginContext& context, std::string& link)
{
  link = d.text("bodyName", context.rootLink());
  return requireLink(d, context, "bodyName", link);
}

class HectorSensorModel
{
public:
  void load(const ModelPluginDescription& d, const std::string& prefix)
  {
    auto key = [&](const std::string& name) {
      return prefix.empty() ? std::string(1, char(std::tolower(name[0]))) + name.substr(1) : prefix + name;
    };
    offset_ = d.vector(key("Offset"), urdf::Vector3(0, 0, 0));
    drift_ = d.vector(key("Drift"), urdf::Vector3(0, 0, 0));
    drift_frequency_ = d.vector(key("DriftFrequency"), urdf::Vector3(1.0 / 3600, 1.0 / 3600, 1.0 / 3600));
    gaussian_noise_ = d.vector(key("GaussianNoise"), urdf::Vector3(0, 0, 0));
    scale_error_ = d.vector(key("ScaleError"), urdf::Vector3(1, 1, 1));
  }

  void reset(std::mt19937& rng)
  {
    for (int i = 0; i < 3; ++i)
      at(current_drift_, i) = normal(rng, at(drift_, i));
  }

  urdf::Vector3 operator()(const urdf::Vector3& value, double dt, std::mt19937& rng)
  {
    urdf::Vector3 out;
    for (int i = 0; i < 3; ++i)
      at(out, i) = axis(i, at(value, i), dt, rng);
    return out;
  }

  // hector's scalar SensorModel (the sonar's): the x parameters alone, one drift.
  double operator()(double value, double dt, std::mt19937& rng) { return axis(0, value, dt, rng); }

  void setGaussianNoise(const urdf::Vector3& noise) { gaussian_noise_ = noise; }
  // getCurrentBias: the drift now plus the offset.
  urdf::Vector3 currentBias() const
  {
    return urdf::Vector3(current_drift_.x + offset_.x, current_drift_.y + offset_.y, current_drift_.z + offset_.z);
  }
  const urdf::Vector3& drift() const { return drift_; }
  const urdf::Vector3& gaussianNoise() const { return gaussian_noise_; }
  const urdf::Vector3& currentDrift() const { return current_drift_; }
  void setCurrentDrift(const urdf::Vector3& drift) { current_drift_ = drift; }

private:
  double axis(int i, double value, double dt, std::mt19937& rng)
  {
    const double f = at(drift_frequency_, i);
    at(current_drift_, i) = std::exp(-dt * f) * at(current_drift_, i) + dt * normal(rng, std::sqrt(2 * f) * at(drift_, i));
    const double error = at(offset_, i) + at(current_drift_, i) + normal(rng, at(gaussian_noise_, i));
    return value * at(scale_error_, i) + error;
  }

  static double& at(urdf::Vector3& v, int i) { return i == 0 ? v.x : i == 1 ? v.y : v.z; }
  static double at(const urdf::Vector3& v, int i) { return i == 0 ? v.x : i == 1 ? v.y : v.z; }
  // Zero deviation draws nothing: a noiseless model keeps the generator where it was.
  static double normal(std::mt19937& rng, double stddev)
  {
    return stddev > 0 ? std::normal_distribution<double>(0.0, stddev)(rng) : 0.0;
  }

  urdf::Vector3 offset_, drift_, drift_frequency_, gaussian_noise_, scale_error_, current_drift_;
};

// hector's UpdateTimer: <updateRate> (Hz) or <updatePeriod> (s, over the rate) and <updateOffset>
// (s). A period of 0 fires every step; otherwise it fires on the step whose time, less the offset,
// lies within half a step of a multiple of the period (phase-locked, not counted from the last
// update). dt is the time since the last update, 0 on the first one after load or reset.
class HectorUpdateTimer
{
public:
  void load(const ModelPluginDescription& d, double default_rate, const ModelPluginContext& context)
  {
    load(d, default_rate, context.stepSize());
  }

  void load(const ModelPluginDescription& d, double default_rate, double step_size)
  {
    const double rate = d.number("updateRate", default_rate);
    double period = rate > 0 ? 1.0 / rate : 0.0;
    period = d.number("updatePeriod", period);
    period_ns_ = std::llround(period * 1e9);
    offset_ns_ = std::llround(d.number("updateOffset", 0.0) * 1e9);
    step_ns_ = std::llround(step_size * 1e9);
  }

  bool due(int64_t time_ns) const
  {
    if (period_ns_ <= 0)
      return true;
    int64_t fraction = (time_ns - offset_ns_ + step_ns_ / 2) % period_ns_;
    if (fraction < 0)
      fraction += period_ns_;
    return fraction < step_ns_;
  }

  // Marks the update at time_ns and returns the time since the last one (s).
  double update(int64_t time_ns)
  {
    const double dt = last_update_ns_ == 0 ? 0.0 : (time_ns - last_update_ns_) * 1e-9;
    last_update_ns_ = time_ns;
    return dt;
  }

  void reset() { last_update_ns_ = 0; }
  // Whether time_ns lies before the last update: the world was reset since.
  bool wentBack(int64_t time_ns) const { return time_ns < last_update_ns_; }

private:
  int64_t period_ns_ = 0, offset_ns_ = 0, step_ns_ = 1000000, last_update_ns_ = 0;
};

}  // namespace bullet_plant
