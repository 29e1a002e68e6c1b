#include "rendering/pinhole.h"

#include <cmath>

namespace bullet_plant
{
Lighting Lighting::of(const urdf::Vector3& light_direction, double ambient, const Rgba& background, bool shadows)
{
  Lighting l;
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
  const int16_t* samples = camera.noise + camera.noise_offset;
  for (size_t k = 0; k < pixels; ++k, rgb8 += 3, rgba += 4)
    for (int c = 0; c < 3; ++c)
    {
      const int value = rgba[c] + samples[k];
      rgb8[c] = uint8_t(value < 0 ? 0 : value > 255 ? 255 : value);
    }
}

}  // namespace bullet_plant
