// sensors::GaussianNoiseModel as Gazebo 11's: a <noise type="gaussian"> element's white noise
// (mean, stddev), its constant bias (drawn once from bias_mean and bias_stddev, its sign at random),
// its dynamic bias (dynamic_bias_stddev, dynamic_bias_correlation_time: a first-order Gauss-Markov
// process over each Apply's dt) and its precision (rounding, where not 0). Draws come from
// ignition-math's generator, as Gazebo's (ignition::math::Rand::Seed makes them repeat).
#pragma once

#include <iosfwd>

#include "gazebo/sensors/Noise.hh"

namespace gazebo
{
namespace sensors
{
class GZ_SENSORS_VISIBLE GaussianNoiseModel : public Noise
{
public:
  GaussianNoiseModel();
  ~GaussianNoiseModel() override;
  void Load(sdf::ElementPtr _sdf) override;
  void Fini() override;
  double ApplyImpl(double _in, double _dt) override;
  double GetMean() const;
  double GetStdDev() const;
  double GetBias() const;
  void Print(std::ostream& _out) const override;

protected:
  double mean = 0.0, stdDev = 0.0, bias = 0.0, precision = 0.0;
  bool quantized = false;

private:
  void SampleBias();
  double biasMean_ = 0.0, biasStdDev_ = 0.0, dynamicBiasStdDev_ = 0.0, dynamicBiasCorrTime_ = 0.0;
};
}  // namespace sensors
}  // namespace gazebo
