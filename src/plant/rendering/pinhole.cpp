#include "rendering/pinhole.h"

#include <cmath>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace bullet_plant
{
Lighting Lighting::of(const urdf::Vector3& light_direction, double ambient, const Rgba& background, bool shadows,
                      const std::vector<LightDescription>& lights)
{
  Lighting l;
  for (const LightDescription& light : lights)
  {
    if (light.range <= 0 || l.local.size() == kMaxLocalLights)
      continue;
    LocalLight local;
    const double position[3] = {light.position.x, light.position.y, light.position.z};
    const double direction[3] = {light.direction.x, light.direction.y, light.direction.z};
    const float colour[3] = {light.diffuse.r, light.diffuse.g, light.diffuse.b};
    for (int i = 0; i < 3; ++i)
    {
      local.position[i] = float(position[i]);
      local.colour[i] = colour[i];
      local.direction[i] = light.spot ? float(direction[i]) : 0.0f;
    }
    const double attenuation[4] = {light.range, light.constant, light.linear, light.quadratic};
    for (int i = 0; i < 4; ++i)
      local.attenuation[i] = float(attenuation[i]);
    local.spot[0] = float(std::cos(light.inner_angle / 2));
    local.spot[1] = float(std::cos(light.outer_angle / 2));
    local.spot[2] = float(light.falloff);
    l.local.push_back(local);
  }
  l.shadows = shadows;
  const double towards[3] = {-light_direction.x, -light_direction.y, -light_direction.z};
  const double n = std::sqrt(towards[0] * towards[0] + towards[1] * towards[1] + towards[2] * towards[2]);
  for (int i = 0; i < 3; ++i)
    l.towards_light[i] = n > 0 ? towards[i] / n : 0.0;
  l.ambient = ambient;
  l.background[0] = float(background.r);
  l.background[1] = float(background.g);
  l.background[2] = float(background.b);
  return l;
}

void detail::noisyRgbFromRgbaEach(const int16_t* samples, const uint8_t* rgba, uint8_t* rgb8, size_t pixels)
{
  for (size_t k = 0; k < pixels; ++k, rgb8 += 3, rgba += 4)
    for (int c = 0; c < 3; ++c)
    {
      const int value = rgba[c] + samples[k];
      rgb8[c] = uint8_t(value < 0 ? 0 : value > 255 ? 255 : value);
    }
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
