// A camera's <distortion> as Gazebo 11 applies it (gazebo/rendering/Distortion.cc and its compositor
// shader camera_distortion_map_fs.glsl), reimplemented as a remap of the frame after it is read
// back: Brown's model (k1 k2 k3 radial, p1 p2 tangential, about <center>) builds a map once per
// camera from each distorted pixel to the undistorted one it shows, and every frame samples the
// rendered image through it.
#pragma once

#include <cstdint>
#include <vector>

#include "bullet_plant/robot_description.h"  // CameraDistortion

namespace bullet_plant
{
// What the remap of one camera's frames needs, worked out once (distortionRemap).
struct DistortionRemap
{
  int width = 0, height = 0;
  // Per output pixel, in image order: the four rendered pixels it blends (kBlack: none, the pixel
  // is black) and their weights (bilinear, summing to 1).
  static constexpr uint32_t kBlack = 0xFFFFFFFFu;
  std::vector<uint32_t> taps;    // 4 per pixel
  std::vector<float> weights;    // 4 per pixel
  bool empty() const { return taps.empty(); }
};

namespace lens
{
// Gazebo's Distortion::Distort with a focal length (the map's): the normalized image point `in`
// (0..1 across the texture) moved by Brown's model about `center`, in normalized camera
// coordinates (the offset from the centre times width / focal).
void distortPoint(const CameraDistortion& d, double width_over_focal, double in_x, double in_y, double& out_x,
                  double& out_y);

// Gazebo's distortion map: a square texture of (max(width, height) - 1)^2 texels over the image,
// each holding the normalized undistorted point a distorted texel shows, -1 where nothing landed
// before the hole filling, which then averages the eight neighbours that have one (diagonals
// weighted 0.707) and clamps to [0, 1] (a texel with none gets (0, 0)). x, y per texel.
std::vector<double> distortionMap(const CameraDistortion& d, int width, int height, double hfov, int& side);

// The scale Gazebo's shader zooms the map by to crop a barrel lens's black border: Distort(1, 1) -
// Distort(0, 0) in the legacy (focal-free) form when cropping and k1 < 0, else 1 (and 1 when that
// difference is not positive, where Gazebo refuses it).
void cropScale(const CameraDistortion& d, bool crop, double& sx, double& sy);
}  // namespace lens

// Whether the distortion changes anything: Gazebo applies none when all five are 0.
bool distorts(const CameraDistortion& d);

// The remap of a width x height camera of horizontal field `hfov` (rad): for each output pixel its
// texel of the map (nearest, the shader's lookup at the pixel's centre after the crop's zoom) and
// the undistorted point there sampled bilinearly from the rendered frame, clamped at its edges.
DistortionRemap distortionRemap(const CameraDistortion& d, int width, int height, double hfov, bool crop);

// out = the frame `in` (3 values a pixel, rows from the top; 8 or 16 bits) through the remap.
void remapRgb(const DistortionRemap& remap, const uint8_t* in, uint8_t* out);
void remapRgb(const DistortionRemap& remap, const uint16_t* in, uint16_t* out);

}  // namespace bullet_plant
