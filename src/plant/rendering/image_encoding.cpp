#include "bullet_plant/image_encoding.h"

#include <cstring>
#include <vector>

namespace bullet_plant
{
ImageEncoding imageEncodingOf(const std::string& format)
{
  using Layout = ImageEncoding::Layout;
  ImageEncoding e;
  auto set = [&](Layout layout, const char* encoding, uint32_t bytes) {
    e.layout = layout;
    e.encoding = encoding;
    e.bytes_per_pixel = bytes;
  };
  // Bayer blocks as Camera::ConvertRGBToBAYER fills them from R8G8B8 (top-left, top-right,
  // bottom-left, bottom-right; 0 red, 1 green, 2 blue).
  auto bayer = [&](const char* encoding, int tl, int tr, int bl, int br) {
    set(Layout::Bayer, encoding, 1);
    e.bayer[0] = tl, e.bayer[1] = tr, e.bayer[2] = bl, e.bayer[3] = br;
  };
  if (format == "L8" || format == "L_INT8")
    set(Layout::Mono8, "mono8", 1);
  else if (format == "L16" || format == "L_INT16")
    set(Layout::Mono16, "mono16", 2);
  else if (format == "R8G8B8" || format == "RGB_INT8")
    set(Layout::Rgb8, "rgb8", 3);
  else if (format == "B8G8R8" || format == "BGR_INT8")
    set(Layout::Bgr8, "bgr8", 3);
  else if (format == "R16G16B16" || format == "RGB_INT16")
    set(Layout::Rgb16, "rgb16", 6);
  else if (format == "BAYER_RGGB8")
    bayer("bayer_rggb8", 0, 1, 1, 2);
  else if (format == "BAYER_BGGR8")
    bayer("bayer_bggr8", 2, 1, 1, 0);
  else if (format == "BAYER_GBRG8")
    bayer("bayer_gbrg8", 1, 0, 2, 1);  // Gazebo 11 fills G R / B G
  else if (format == "BAYER_GRBG8")
    bayer("bayer_grbg8", 1, 2, 0, 1);  // Gazebo 11 fills G B / R G
  else
  {
    set(Layout::Bgr8, "bgr8", 3);
    e.known = false;
  }
  return e;
}

namespace
{
// A 16-bit value, little-endian.
inline void put16(uint8_t* out, uint16_t value)
{
  out[0] = uint8_t(value & 0xFF);
  out[1] = uint8_t(value >> 8);
}
}  // namespace

void spreadTo16Bits(const uint8_t* levels8, size_t count, uint16_t* levels16)
{
  for (size_t k = 0; k < count; ++k)
    levels16[k] = uint16_t(levels8[k] * 257u);
}

void encodeImage(const ImageEncoding& e, const uint8_t* rgb, const uint16_t* rgb16, int width, int height,
                 uint8_t* out)
{
  using Layout = ImageEncoding::Layout;
  const size_t pixels = size_t(width) * size_t(height);
  std::vector<uint16_t> spread;
  if (e.sixteenBit() && !rgb16)
  {
    spread.resize(3 * pixels);
    spreadTo16Bits(rgb, spread.size(), spread.data());
    rgb16 = spread.data();
  }
  switch (e.layout)
  {
    case Layout::Rgb8:
      std::memcpy(out, rgb, 3 * pixels);
      return;
    case Layout::Bgr8:
      for (size_t k = 0; k < pixels; ++k, rgb += 3, out += 3)
        out[0] = rgb[2], out[1] = rgb[1], out[2] = rgb[0];
      return;
    case Layout::Mono8:  // OGRE's luminance is the red channel
      for (size_t k = 0; k < pixels; ++k, rgb += 3)
        *out++ = rgb[0];
      return;
    case Layout::Mono16:
      for (size_t k = 0; k < pixels; ++k, rgb16 += 3, out += 2)
        put16(out, rgb16[0]);
      return;
    case Layout::Rgb16:
      for (size_t k = 0; k < pixels; ++k, rgb16 += 3, out += 6)
        put16(out, rgb16[0]), put16(out + 2, rgb16[1]), put16(out + 4, rgb16[2]);
      return;
    case Layout::Bayer:
      for (int v = 0; v < height; ++v)
        for (int u = 0; u < width; ++u, rgb += 3)
          *out++ = rgb[e.bayer[(v % 2) * 2 + u % 2]];
      return;
  }
}

}  // namespace bullet_plant
