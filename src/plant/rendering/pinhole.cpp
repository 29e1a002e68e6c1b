#include "rendering/pinhole.h"

#include <cmath>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace bullet_plant
{
Lighting::Light Lighting::Light::of(const LightDescription& light)
{
  Light l;
  l.kind = light.kind == LightDescription::Kind::Directional ? Directional
           : light.kind == LightDescription::Kind::Spot      ? Spot
                                                             : Point;
  const double position[3] = {light.position.x, light.position.y, light.position.z};
  const double direction[3] = {light.direction.x, light.direction.y, light.direction.z};
  const double n = std::sqrt(direction[0] * direction[0] + direction[1] * direction[1] + direction[2] * direction[2]);
  const float diffuse[3] = {light.diffuse.r, light.diffuse.g, light.diffuse.b};
  const float specular[3] = {light.specular.r, light.specular.g, light.specular.b};
  for (int i = 0; i < 3; ++i)
  {
    l.position[i] = float(position[i]);
    l.direction[i] = n > 0 ? float(direction[i] / n) : 0.0f;
    l.diffuse[i] = diffuse[i];
    l.specular[i] = specular[i];
  }
  const double attenuation[4] = {light.range, light.constant, light.linear, light.quadratic};
  for (int i = 0; i < 4; ++i)
    l.attenuation[i] = float(attenuation[i]);
  l.spot[0] = float(std::cos(light.inner_angle / 2));
  l.spot[1] = float(std::cos(light.outer_angle / 2));
  l.spot[2] = float(light.falloff);
  return l;
}

Lighting Lighting::of(const std::vector<LightDescription>& lights, const Rgba& ambient, const Rgba& background,
                      bool shadows)
{
  Lighting l;
  const LightDescription* sun = nullptr;
  for (const LightDescription& light : lights)
    if (light.kind == LightDescription::Kind::Directional && (!sun || (light.cast_shadows && !sun->cast_shadows)))
      sun = &light;
  for (const LightDescription& light : lights)
  {
    if (&light == sun)
    {
      l.has_sun = true;
      l.sun = Light::of(light);
      for (int i = 0; i < 3; ++i)
        l.towards_light[i] = -l.sun.direction[i];
    }
    else if (light.lights())
      l.lights.push_back(Light::of(light));
  }
  l.shadows = shadows && sun && sun->cast_shadows;
  l.ambient[0] = ambient.r;
  l.ambient[1] = ambient.g;
  l.ambient[2] = ambient.b;
  l.background[0] = background.r;
  l.background[1] = background.g;
  l.background[2] = background.b;
  return l;
}

Lighting Lighting::sunOnly(const double towards[3], float diffuse, float ambient, bool shadows)
{
  Lighting l;
  l.has_sun = true;
  const double n = std::sqrt(towards[0] * towards[0] + towards[1] * towards[1] + towards[2] * towards[2]);
  for (int i = 0; i < 3; ++i)
  {
    l.towards_light[i] = towards[i] / n;
    l.sun.direction[i] = float(-towards[i] / n);
    l.sun.diffuse[i] = diffuse;
    l.sun.specular[i] = 0.0f;
    l.ambient[i] = ambient;
  }
  l.sun.kind = Light::Directional;
  l.shadows = shadows;
  return l;
}

namespace
{
// A colour value with its pixel's noise sample, clamped to a byte: the noise's one rule.
inline uint8_t noisy(uint8_t value, int16_t sample)
{
  const int v = value + sample;
  return uint8_t(v < 0 ? 0 : v > 255 ? 255 : v);
}
inline uint16_t noisy(uint16_t value, int32_t sample)
{
  const int32_t v = value + sample;
  return uint16_t(v < 0 ? 0 : v > 65535 ? 65535 : v);
}
}  // namespace

void detail::noisyRgbFromRgbaEach(const int16_t* samples, const uint8_t* rgba, uint8_t* rgb8, size_t pixels)
{
  for (size_t k = 0; k < pixels; ++k, rgb8 += 3, rgba += 4)
    for (int c = 0; c < 3; ++c)
      rgb8[c] = noisy(rgba[c], samples[k]);
}

namespace
{
// Each pixel's sample added to its three values in place (samples null: none).
template <class Value, class Sample>
void addNoiseInPlace(const PinholeCamera& camera, const Sample* noise, Value* rgb)
{
  if (!noise)
    return;
  const Sample* samples = noise + camera.noise_offset;
  const size_t pixels = size_t(camera.width) * size_t(camera.height);
  for (size_t k = 0; k < pixels; ++k, rgb += 3)
    for (int c = 0; c < 3; ++c)
      rgb[c] = noisy(rgb[c], samples[k]);
}
}  // namespace

void addNoise(const PinholeCamera& camera, uint8_t* rgb8)
{
  addNoiseInPlace(camera, camera.noise, rgb8);
}

void noisyRgb16FromRgba16(const PinholeCamera& camera, const uint16_t* rgba16, uint16_t* rgb16)
{
  const size_t pixels = size_t(camera.width) * size_t(camera.height);
  for (size_t k = 0; k < pixels; ++k)
    for (int c = 0; c < 3; ++c)
      rgb16[3 * k + c] = rgba16[4 * k + c];
  addNoiseInPlace(camera, camera.noise16, rgb16);
}

void addNoise(const PinholeCamera& camera, uint16_t* rgb16)
{
  addNoiseInPlace(camera, camera.noise16, rgb16);
}

void rgb8FromRgb16(const uint16_t* rgb16, uint8_t* rgb8, size_t values)
{
  for (size_t k = 0; k < values; ++k)
    rgb8[k] = uint8_t((uint32_t(rgb16[k]) * 255u + 32767u) / 65535u);
}

#if defined(__SSE2__)
void detail::noisyRgbFromRgbaSse2(const int16_t* samples, const uint8_t* rgba, uint8_t* rgb8, size_t pixels)
{
  // v + s clamped to 0..255 is (v + max(s, 0)) - max(-s, 0), each saturating on bytes: four pixels'
  // bytes at once, each pixel's sample spread over its four bytes.
  const __m128i zero = _mm_setzero_si128();
  size_t k = 0;
  for (; k + 4 <= pixels; k += 4)
  {
    const __m128i s = _mm_loadl_epi64(reinterpret_cast<const __m128i*>(samples + k));
    __m128i up = _mm_max_epi16(s, zero), down = _mm_max_epi16(_mm_sub_epi16(zero, s), zero);
    up = _mm_packus_epi16(up, up);
    down = _mm_packus_epi16(down, down);
    up = _mm_unpacklo_epi16(_mm_unpacklo_epi8(up, up), _mm_unpacklo_epi8(up, up));
    down = _mm_unpacklo_epi16(_mm_unpacklo_epi8(down, down), _mm_unpacklo_epi8(down, down));
    const __m128i pixels4 = _mm_loadu_si128(reinterpret_cast<const __m128i*>(rgba + 4 * k));
    alignas(16) uint8_t out[16];
    _mm_store_si128(reinterpret_cast<__m128i*>(out), _mm_subs_epu8(_mm_adds_epu8(pixels4, up), down));
    uint8_t* o = rgb8 + 3 * k;
    for (int p = 0; p < 4; ++p)
      o[3 * p] = out[4 * p], o[3 * p + 1] = out[4 * p + 1], o[3 * p + 2] = out[4 * p + 2];
  }
  noisyRgbFromRgbaEach(samples + k, rgba + 4 * k, rgb8 + 3 * k, pixels - k);
}
#endif

void noisyRgbFromRgba(const PinholeCamera& camera, const uint8_t* rgba, uint8_t* rgb8)
{
  const size_t pixels = size_t(camera.width) * size_t(camera.height);
  if (!camera.noise)
  {
    for (size_t k = 0; k < pixels; ++k, rgb8 += 3, rgba += 4)
      rgb8[0] = rgba[0], rgb8[1] = rgba[1], rgb8[2] = rgba[2];
    return;
  }
  // One pass over the frame, the samples read in order: a frame's noise costs a stream of
  // memory, not a hash and a lookup per value.
#if defined(__SSE2__)
  detail::noisyRgbFromRgbaSse2(camera.noise + camera.noise_offset, rgba, rgb8, pixels);
#else
  detail::noisyRgbFromRgbaEach(camera.noise + camera.noise_offset, rgba, rgb8, pixels);
#endif
}

}  // namespace bullet_plant
