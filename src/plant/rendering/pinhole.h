// What a camera renders, whoever renders it: a pinhole (image size, focal lengths and centre,
// clip range), the world's lights over its ambient light, the frame it gives (colour bytes and
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
// How cameras light what they see, as Gazebo 11 does (OGRE's per-pixel lighting, RTShaderSystem):
// a surface of Material m (geometry.h) shows
//   emissive + ambient x m.ambient + shadow x sum over lights of attenuation x spot x
//     (diffuse x m.diffuse x max(0, n . l)), times its texture, + shadow x sum of
//     attenuation x spot x specular x m.specular x max(0, n . h)^m.shininess (where m has specular),
// clamped to [0, 1] per channel; n is the normal on the side the camera sees, h halfway between
// the directions to the light and to the camera, `shadow` 0 in the sun's shadow, 1 out of it (as
// Gazebo's integrated PSSM shadows darken all but the ambient and emissive light). A point or spot
// light's attenuation is 1 / (constant + linear d + quadratic d^2) within its range, nothing beyond;
// a spot's factor is ((rho - cos(outer / 2)) / (cos(inner / 2) - cos(outer / 2)))^falloff clamped
// to [0, 1] inside its outer cone, 0 outside; a directional light is not attenuated.
struct Lighting
{
  struct Light
  {
    enum Kind : int { Directional = 0, Point = 1, Spot = 2 };
    int kind = Point;
    float position[3] = {0, 0, 0};
    float direction[3] = {0, 0, -1};  // the way it shines (unit): directional and spot lights
    float diffuse[3] = {1, 1, 1}, specular[3] = {0.1f, 0.1f, 0.1f};
    float attenuation[4] = {10, 1, 1, 0};  // range, constant, linear, quadratic (not a directional light's)
    float spot[3] = {1, 1, 0};             // cos(inner / 2), cos(outer / 2), falloff
    bool hasSpecular() const { return specular[0] > 0 || specular[1] > 0 || specular[2] > 0; }
    static Light of(const LightDescription& light);
  };
  float ambient[3] = {0.4f, 0.4f, 0.4f};  // <scene><ambient>
  float background[3] = {0.70f, 0.80f, 0.95f};
  // The sun: the directional light that casts the shadows, the first whose <cast_shadows> is true
  // (Gazebo draws one directional light's: its shadow camera setup takes three textures, all it
  // has), else the first directional light; its diffuse share is worked out per vertex (exact on
  // flat faces). None: a world without a directional light.
  bool has_sun = false;
  Light sun;
  double towards_light[3] = {0.5, -0.1, 0.9};  // unit: -sun.direction, for the shadow maps
  bool shadows = false;  // <scene><shadows> and a sun that casts them
  // Every other light, per pixel. Each draw is lit by those whose range reaches its bounds, the
  // nearest first, at most kMaxLights with the sun (OGRE's default of 8 lights on one object, the
  // sun and other directional lights first, as its SceneManager sorts them).
  std::vector<Light> lights;
  static constexpr size_t kMaxLights = 8;
  // The world's lights (world_description.h), in file order.
  static Lighting of(const std::vector<LightDescription>& lights, const Rgba& ambient, const Rgba& background,
                     bool shadows);
  // A frame lit by one directional light (towards `towards`, diffuse `diffuse`, no specular) over a
  // grey `ambient`: what the cameras' tests draw.
  static Lighting sunOnly(const double towards[3], float diffuse, float ambient, bool shadows);
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
  // Bits a colour channel: 8, or 16 for Gazebo's 16-bit image formats (L16, R16G16B16 ...), which
  // OGRE renders into a 16-bit target (PF_L16, PF_SHORT_RGB). A 16-bit frame's noise is noise16,
  // in levels of 1/65535, read as `noise` is.
  int bits = 8;
  const int32_t* noise16 = nullptr;
  // Whether the frame's depths are wanted (a colour camera's are not): a renderer may skip them.
  bool depth = true;
};

struct PinholeImage
{
  std::vector<uint8_t> rgb8;  // lit colour per pixel (plus noise), 0..255, rows from the top; the background where nothing is seen
  std::vector<float> depth;   // along the optical axis, +inf where nothing is seen within the clip range
  // A 16-bit camera's frame (PinholeCamera::bits 16): its colours at 16 bits, 0..65535, the noise
  // added at that depth; rgb8 then holds them rounded to bytes. Empty for an 8-bit camera.
  std::vector<uint16_t> rgb16;
};

// The samples a camera's noise takes its values from: enough for any offset of a frame of
// `pixels`, each round(255 * draw()) levels, clamped to +-256 (beyond that any value saturates).
template <class Draw>
std::vector<int16_t> noiseSamples(size_t pixels, Draw draw);
// The same for a 16-bit camera: round(65535 * draw()) levels, clamped to +-65536.
template <class Draw>
std::vector<int32_t> noiseSamples16(size_t pixels, Draw draw);

// The camera's frame of colours (three bytes a pixel, rows from the top) from its RGBA pixels (as a
// GL reads them back), the noise added: each value v becomes clamp(v + its pixel's sample, 0, 255)
// (after the GL's rounding to bytes, as Gazebo adds its noise to the 8-bit frame).
void noisyRgbFromRgba(const PinholeCamera& camera, const uint8_t* rgba, uint8_t* rgb8);

// The camera's noise added to a frame of colours in place, by noisyRgbFromRgba's rule: for a frame
// that goes through the lens first (Gazebo's noise compositor comes after its distortion's).
void addNoise(const PinholeCamera& camera, uint8_t* rgb8);

// A 16-bit camera's frame (three values a pixel) from its RGBA pixels at 16 bits, its noise16
// added by the same rule (clamped to 0..65535); and that noise added in place, after a lens.
void noisyRgb16FromRgba16(const PinholeCamera& camera, const uint16_t* rgba16, uint16_t* rgb16);
void addNoise(const PinholeCamera& camera, uint16_t* rgb16);

// 16-bit values rounded to bytes (v * 255 / 65535 to the nearest): what an 8-bit reader of a
// 16-bit camera (the viewer, a Python observation) gets.
void rgb8FromRgb16(const uint16_t* rgb16, uint8_t* rgb8, size_t values);

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

namespace detail
{
// Samples in levels of 1/full_scale, clamped to +-(full_scale + 1) (beyond that any value saturates).
template <class Sample, class Draw>
std::vector<Sample> noiseLevels(size_t pixels, double full_scale, Draw draw)
{
  std::vector<Sample> samples(pixels + PinholeCamera::kNoiseOffsets);
  const double limit = full_scale + 1;
  for (Sample& s : samples)
  {
    const double level = full_scale * draw();
    s = Sample(level > limit ? limit : level < -limit ? -limit : level == level ? std::lround(level) : 0);
  }
  return samples;
}
}  // namespace detail

template <class Draw>
std::vector<int16_t> noiseSamples(size_t pixels, Draw draw)
{
  return detail::noiseLevels<int16_t>(pixels, 255.0, draw);
}

template <class Draw>
std::vector<int32_t> noiseSamples16(size_t pixels, Draw draw)
{
  return detail::noiseLevels<int32_t>(pixels, 65535.0, draw);
}

}  // namespace bullet_plant
