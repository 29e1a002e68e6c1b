// sensors::Noise, NoiseFactory (gazebo/sensors/Noise.hh) and GaussianNoiseModel
// (gazebo/sensors/GaussianNoiseModel.hh).
#include "gazebo/sensors/Noise.hh"

#include <cmath>
#include <ostream>

#include <ignition/math/Helpers.hh>
#include <ignition/math/Rand.hh>

#include "gazebo/common/Console.hh"
#include "gazebo/sensors/GaussianNoiseModel.hh"

namespace gazebo
{
namespace sensors
{
NoisePtr NoiseFactory::NewNoiseModel(sdf::ElementPtr _sdf, const std::string& /*_sensorType*/)
{
  if (!_sdf || _sdf->GetName() != "noise")
  {
    gzerr << "Not a noise SDF element\n";
    return NoisePtr();
  }
  const std::string type = _sdf->Get<std::string>("type");
  NoisePtr noise;
  // (Gazebo's cameras take an ImageGaussianNoiseModel, which adds the noise in their shader; the
  // plant's cameras render theirs: a camera's model here adds it to values, as any other's.)
  if (type == "gaussian" || type == "gaussian_quantized")
    noise = std::make_shared<GaussianNoiseModel>();
  else if (type == "none" || type == "custom")
    noise = std::make_shared<Noise>(Noise::NONE);
  else
  {
    gzerr << "Unrecognized noise type\n";
    return NoisePtr();
  }
  noise->Load(_sdf);
  return noise;
}

Noise::Noise(NoiseType _type) : type_(_type) {}

Noise::~Noise() = default;

void Noise::Load(sdf::ElementPtr _sdf) { sdf = _sdf; }

double Noise::Apply(double _in, double _dt)
{
  if (type_ == NONE)
    return _in;
  if (type_ == CUSTOM)
  {
    if (custom_time_)
      return custom_time_(_in, _dt);
    if (custom_)
      return custom_(_in);
    gzerr << "Custom noise callback function not set! Please call SetCustomNoiseCallback within a sensor plugin.\n";
    return _in;
  }
  return ApplyImpl(_in, _dt);
}

double Noise::ApplyImpl(double _in, double /*_dt*/) { return _in; }

void Noise::Fini() {}

Noise::NoiseType Noise::GetNoiseType() const { return type_; }

void Noise::SetCustomNoiseCallback(std::function<double(double)> _cb)
{
  type_ = CUSTOM;
  custom_ = std::move(_cb);
}

void Noise::SetCustomNoiseCallbackTime(std::function<double(double, double)> _cb)
{
  type_ = CUSTOM;
  custom_time_ = std::move(_cb);
}

void Noise::SetCamera(rendering::CameraPtr /*_camera*/) {}

void Noise::Print(std::ostream& _out) const { _out << "Noise with type[" << type_ << "] does not have an overloaded Print function. No more information is available."; }

GaussianNoiseModel::GaussianNoiseModel() : Noise(Noise::GAUSSIAN) {}

GaussianNoiseModel::~GaussianNoiseModel() = default;

void GaussianNoiseModel::Load(sdf::ElementPtr _sdf)
{
  Noise::Load(_sdf);
  mean = _sdf->Get<double>("mean");
  stdDev = _sdf->Get<double>("stddev");
  if (_sdf->HasElement("bias_mean"))
    biasMean_ = _sdf->Get<double>("bias_mean");
  if (_sdf->HasElement("bias_stddev"))
    biasStdDev_ = _sdf->Get<double>("bias_stddev");
  if (_sdf->HasElement("dynamic_bias_stddev"))
    dynamicBiasStdDev_ = _sdf->Get<double>("dynamic_bias_stddev");
  if (_sdf->HasElement("dynamic_bias_correlation_time"))
    dynamicBiasCorrTime_ = _sdf->Get<double>("dynamic_bias_correlation_time");
  SampleBias();
  if (_sdf->HasElement("precision"))
  {
    precision = _sdf->Get<double>("precision");
    if (precision < 0)
      gzerr << "Noise precision cannot be less than 0\n";
    else if (!ignition::math::equal(precision, 0.0, 1e-6))
      quantized = true;
  }
}

void GaussianNoiseModel::SampleBias()
{
  bias = ignition::math::Rand::DblNormal(biasMean_, biasStdDev_);
  // the mean's sign at random, as Gazebo's: a bias as likely below as above
  if (ignition::math::Rand::DblUniform() < 0.5)
    bias = -bias;
}

void GaussianNoiseModel::Fini() { Noise::Fini(); }

double GaussianNoiseModel::ApplyImpl(double _in, double _dt)
{
  const double white = ignition::math::Rand::DblNormal(mean, stdDev);
  if (dynamicBiasStdDev_ > 0 && dynamicBiasCorrTime_ > 0)
  {
    // a first-order Gauss-Markov bias, discretised over dt (Gazebo's, after RotorS's IMU)
    const double sigma = dynamicBiasStdDev_, tau = dynamicBiasCorrTime_;
    const double sigma_d = std::sqrt(-sigma * sigma * tau / 2 * std::expm1(-2 * _dt / tau));
    bias = std::exp(-_dt / tau) * bias + ignition::math::Rand::DblNormal(0, sigma_d);
  }
  double output = _in + bias + white;
  if (quantized)
    output = std::round(output / precision) * precision;
  return output;
}

double GaussianNoiseModel::GetMean() const { return mean; }

double GaussianNoiseModel::GetStdDev() const { return stdDev; }

double GaussianNoiseModel::GetBias() const { return bias; }

void GaussianNoiseModel::Print(std::ostream& _out) const
{
  _out << "Gaussian noise, mean[" << mean << "], stdDev[" << stdDev << "] bias[" << bias << "] precision["
       << precision << "] quantized[" << quantized << "]";
}
}  // namespace sensors
}  // namespace gazebo
