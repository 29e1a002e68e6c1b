// rendering::Distortion: a camera's <lens><distortion> (Brown's model: k1, k2, k3, p1, p2 about a
// normalized center) as Camera::LensDistortion() gives it to plugins (gazebo_ros_camera_utils reads
// the coefficients into its CameraInfo and sets the crop from its <borderCrop>). The simulator's
// camera applies it; Crop decides, from the next frame on, whether a barrel distortion's black
// border is cropped away.
#pragma once

#include <ignition/math/Vector2.hh>
#include <sdf/sdf.hh>

#include "gazebo/rendering/RenderTypes.hh"
#include "gazebo/util/system.hh"

namespace gazebo
{
namespace rendering
{
class GZ_RENDERING_VISIBLE Distortion
{
public:
  Distortion();
  virtual ~Distortion();
  // The <distortion> element's coefficients (SDF's defaults: 0, center 0.5 0.5).
  virtual void Load(sdf::ElementPtr _sdf);
  // Gazebo's: a barrel distortion (k1 < 0) is cropped by default.
  void SetCrop(const bool _crop);
  bool Crop() const;
  double K1() const { return k1_; }
  double K2() const { return k2_; }
  double K3() const { return k3_; }
  double P1() const { return p1_; }
  double P2() const { return p2_; }
  ignition::math::Vector2d Center() const { return center_; }

private:
  double k1_ = 0, k2_ = 0, k3_ = 0, p1_ = 0, p2_ = 0;
  ignition::math::Vector2d center_{0.5, 0.5};
  bool crop_ = true;
};
}  // namespace rendering
}  // namespace gazebo
