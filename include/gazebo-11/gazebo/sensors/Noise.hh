// sensors::Noise and NoiseFactory as Gazebo 11's: a sensor's <noise> element made into a model that
// Apply adds to a value (GaussianNoiseModel.hh for type "gaussian"), "none" passing values through,
// "custom" calling the callback a plugin sets. Which sensors apply theirs here: docs/gazebo_api.md.
#pragma once

#include <functional>
#include <iosfwd>
#include <string>

#include <sdf/sdf.hh>

#include "gazebo/rendering/RenderTypes.hh"
#include "gazebo/sensors/SensorTypes.hh"
#include "gazebo/util/system.hh"

namespace gazebo
{
namespace sensors
{
class GZ_SENSORS_VISIBLE NoiseFactory
{
public:
  // The model of a <noise> element (its `type`: gaussian or gaussian_quantized, none, custom); null,
  // with Gazebo's error, for any other type.
  static NoisePtr NewNoiseModel(sdf::ElementPtr _sdf, const std::string& _sensorType = "");
};

class GZ_SENSORS_VISIBLE Noise
{
public:
  enum NoiseType
  {
    NONE = 0,
    CUSTOM = 1,
    GAUSSIAN = 2
  };
  explicit Noise(NoiseType _type);
  virtual ~Noise();
  virtual void Load(sdf::ElementPtr _sdf);
  // The value with the noise: as it is for NONE, the callback's for CUSTOM (Gazebo's error and the
  // value where none is set), ApplyImpl's otherwise. `_dt`: the time since the last value (for a
  // dynamic bias).
  double Apply(double _in, double _dt = 0.0);
  virtual double ApplyImpl(double _in, double _dt = 0.0);
  virtual void Fini();
  NoiseType GetNoiseType() const;
  // The model becomes CUSTOM: Apply calls the callback.
  virtual void SetCustomNoiseCallback(std::function<double(double)> _cb);
  virtual void SetCustomNoiseCallbackTime(std::function<double(double, double)> _cb);
  // Gazebo's image noise attaches to its camera's shader; the plant's cameras render their own noise.
  virtual void SetCamera(rendering::CameraPtr _camera);
  virtual void Print(std::ostream& _out) const;

protected:
  sdf::ElementPtr sdf;

private:
  NoiseType type_;
  std::function<double(double)> custom_;
  std::function<double(double, double)> custom_time_;
};
}  // namespace sensors
}  // namespace gazebo
