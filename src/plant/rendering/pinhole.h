// What a camera renders, whoever renders it: a pinhole (image size, focal lengths and centre,
// clip range), one directional light and point and spot lights over an ambient term, the frame it gives (colour bytes and
// depths), and the camera's noise on the colour.
#pragma once

#include <cstddef>
#include <cmath>
#include <cstdint>
#include <vector>

#include <urdf_model/pose.h>

#include "bullet_plant/geometry.h"  // Rgba
#include "bullet_plant/world_description.h"  // LightDescription

namespace bullet_plant
{
// How cameras light what they see: lambert shading by one directional light over an ambient term,
// the background colour where nothing is seen.
struct Lighting
{
  double towards_light[3] = {0.5, -0.1, 0.9};  // unit
  double ambient = 0.35;
  float background[3] = {0.70f, 0.80f, 0.95f};
  bool shadows = true;  // the light's shadows (<scene><shadows>, true by default as in Gazebo)
  // Point and spot lights (world_description.h's LightDescription), lit per pixel; they cast no shadows.
  struct LocalLight
  {
    float position[3];
    float colour[3];
    float direction[3];    // a spot's axis (unit); zero for a point light
    float attenuation[4];  // range, constant, linear, quadratic
    float spot[3];         // cos(inner / 2), cos(outer / 2), falloff
  };
  // OGRE's default limit of lights on one object, as Gazebo renders: the first ones in the file.
  static constexpr size_t kMaxLocalLights = 8;
  std::vector<LocalLight> local;
  static Lighting of(const urdf::Vector3& light_direction, double ambient, const Rgba& background, bool shadows,
                     const std::vector<LightDescription>& lights = {});
};

// A pinhole camera's frame: its pixels (centres at integer coordinates u right, v down from the
// top-left pixel's), what it sees between the clip distances, and its noise.
struct PinholeCamera
{
  int width = 0, height = 0;
  double fx = 0, fy = 0, cx = 0, cy = 0;
  double near = 0, far = 100;  // clip distances along the optical axis
  // Gaussian noise added to each pixel, in whole levels of 1/255 (null: none): the frame's k-th
  // pixel (in image order) takes noise[noise_offset + k] on its red, green and blue alike, as
  // Gazebo's camera noise shader adds one sample to the three. The camera draws the samples once
  // (noiseSamples) and the offset per frame from its own generator, so frames are the same on every
  // run, and each pixel's noise differs from frame to frame.
  static constexpr size_t kNoiseOffsets = 4096;
  const int16_t* noise = nullptr;  // noise_offset + width * height samples at least
  size_t noise_offset = 0;
  // Whether the frame's depths are wanted (a colour camera's are not): a renderer may skip them.
  bool depth = true;
};

struct PinholeImage
{
  std::vector<uint8_t> rgb8;  // lit colour per pixel (plus noise), 0..255, rows from the top; the background where nothing is seen
  std::vector<float> depth;   // along the optical axis, +inf where nothing is seen within the clip range
};

// The samples a camera's noise takes its values from: enough for any offset of a frame of
// `pixels`, each round(255 * draw()) levels, clamped to +-256 (beyond that any value saturates).
template <class Draw>
std::vector<int16_t> noiseSamples(size_t pixels, Draw draw);

// The camera's frame of colours (three bytes a pixel, rows from the top) from its RGBA pixels (as a
// GL reads them back), the noise added: each value v becomes clamp(v + its pixel's sample, 0, 255)
// (after the GL's rounding to bytes, as Gazebo adds its noise to the 8-bit frame).
void noisyRgbFromRgba(const PinholeCamera& camera, const uint8_t* rgba, uint8_t* rgb8);

namespace detail
{
// noisyRgbFromRgba's two ways, for its test: a pixel at a time (the rule, any CPU), and four at a
// time with SSE2 (x86-64's baseline; not built elsewhere), byte for byte the same. `samples` in
// [-256, 256], one per pixel.
void noisyRgbFromRgbaEach(const int16_t* samples, const uint8_t* rgba, uint8_t* rgb8, size_t pixels);
#if defined(__SSE2__)
void noisyRgbFromRgbaSse2(const int16_t* samples, const uint8_t* rgba, uint8_t* rgb8, size_t pixels);
#endif
}  // namespace detail

template <class Draw>
std::vector<int16_t> noiseSamples(size_t pixels, Draw draw)
{
  std::vector<int16_t> samples(pixels + PinholeCamera::kNoiseOffsets);
  for (int16_t& s : samples)
  {
    const double level = 255.0 * draw();
    s = int16_t(level > 256 ? 256 : level < -256 ? -256 : level == level ? std::lround(level) : 0);
  }
  return samples;
}

}  // namespace bullet_plant
