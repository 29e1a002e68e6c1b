// common::Image (gazebo/common/Image.hh).
#include "gazebo/common/Image.hh"

namespace gazebo
{
namespace common
{
namespace
{
const char* const kPixelFormatNames[] = {
    "UNKNOWN_PIXEL_FORMAT", "L_INT8",      "L_INT16",     "RGB_INT8",    "RGBA_INT8",   "BGRA_INT8",  "RGB_INT16",
    "RGB_INT32",            "BGR_INT8",    "BGR_INT16",   "BGR_INT32",   "R_FLOAT16",   "RGB_FLOAT16", "R_FLOAT32",
    "RGB_FLOAT32",          "BAYER_RGGB8", "BAYER_BGGR8", "BAYER_GBRG8", "BAYER_GRBG8"};
static_assert(sizeof(kPixelFormatNames) / sizeof(kPixelFormatNames[0]) == Image::PIXEL_FORMAT_COUNT,
              "a name for each pixel format");
}  // namespace

Image::PixelFormat Image::ConvertPixelFormat(const std::string& _format)
{
  if (_format == "L8" || _format == "L_INT8")
    return L_INT8;
  if (_format == "L16" || _format == "L_INT16" || _format == "L_UINT16")
    return L_INT16;
  if (_format == "R8G8B8" || _format == "RGB_INT8")
    return RGB_INT8;
  if (_format == "R16G16B16" || _format == "RGB_INT16" || _format == "RGB_UINT16")
    return RGB_INT16;
  if (_format == "FLOAT32")
    return R_FLOAT32;
  if (_format == "FLOAT16")
    return R_FLOAT16;
  for (unsigned int i = 0; i < PIXEL_FORMAT_COUNT; ++i)
    if (_format == kPixelFormatNames[i])
      return static_cast<PixelFormat>(i);
  return UNKNOWN_PIXEL_FORMAT;
}
}  // namespace common
}  // namespace gazebo
