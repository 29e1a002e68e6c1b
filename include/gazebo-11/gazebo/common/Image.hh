// common::Image as camera sensors and plugins use it: the pixel formats (common::Image::PixelFormat,
// the number a msgs::Image carries) and ConvertPixelFormat from an <image><format> name. Loading,
// saving and converting images: absent (docs/gazebo_api.md).
#pragma once

#include <string>

#include "gazebo/util/system.hh"

namespace gazebo
{
namespace common
{
class GZ_COMMON_VISIBLE Image
{
public:
  enum PixelFormat
  {
    UNKNOWN_PIXEL_FORMAT = 0,
    L_INT8,
    L_INT16,
    RGB_INT8,
    RGBA_INT8,
    BGRA_INT8,
    RGB_INT16,
    RGB_INT32,
    BGR_INT8,
    BGR_INT16,
    BGR_INT32,
    R_FLOAT16,
    RGB_FLOAT16,
    R_FLOAT32,
    RGB_FLOAT32,
    BAYER_RGGB8,
    BAYER_BGGR8,
    BAYER_GBRG8,
    BAYER_GRBG8,
    PIXEL_FORMAT_COUNT
  };
  // Gazebo's: the old names L8, L16, R8G8B8, R16G16B16, FLOAT32, FLOAT16, then the enum's own names
  // (RGB_INT8 ...); UNKNOWN_PIXEL_FORMAT for any other (B8G8R8 among them, as in Gazebo 11).
  static PixelFormat ConvertPixelFormat(const std::string& _format);
};
}  // namespace common
}  // namespace gazebo
