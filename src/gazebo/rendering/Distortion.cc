// rendering::Distortion (gazebo/rendering/Distortion.hh).
#include "gazebo/rendering/Distortion.hh"

namespace gazebo
{
namespace rendering
{
Distortion::Distortion() = default;

Distortion::~Distortion() = default;

void Distortion::Load(sdf::ElementPtr _sdf)
{
  if (!_sdf)
    return;
  k1_ = _sdf->Get<double>("k1");
  k2_ = _sdf->Get<double>("k2");
  k3_ = _sdf->Get<double>("k3");
  p1_ = _sdf->Get<double>("p1");
  p2_ = _sdf->Get<double>("p2");
  center_ = _sdf->Get<ignition::math::Vector2d>("center");
}

void Distortion::SetCrop(const bool _crop) { crop_ = _crop; }

bool Distortion::Crop() const { return crop_; }
}  // namespace rendering
}  // namespace gazebo
