// How a camera's <image><format> becomes a sensor_msgs/Image, as Gazebo 11 renders it and
// gazebo_ros_camera_utils (Init) labels it: the encoding, the bytes a pixel (upstream's skip_) and
// the bytes themselves, from the plant's rendered colours.
//
// Where Gazebo's pixels come from (gazebo/rendering/Camera.cc, OgrePixelFormat and ReadPixelBuffer):
// the render target is created in the format's OGRE pixel format and read back into it, so OGRE
// converts the rendered colour: a luminance format (PF_L8, PF_L16) keeps the red channel alone
// (OgrePixelFormat.cpp's descriptor: rbits 8 or 16, no green or blue bits; packColour writes red),
// not a weighted luminance. 16-bit formats are rendered at 16 bits (OGRE's GL picks a 16-bit target,
// PF_SHORT_RGB or its RGBA alternative), and so does the plant (a 16-bit normalized target,
// GL_EXT_texture_norm16; on a GL without it, 257 x the 8-bit value). Bayer formats render
// PF_BYTE_RGB and Camera::ConvertRGBToBAYER samples it, its GBRG8 and GRBG8 patterns swapped as
// Gazebo 11 has them (GBRG8 gives G R / B G rows, GRBG8 G B / R G). A format Gazebo does not know
// renders PF_R8G8B8, which is B G R bytes in memory, and the plugin labels it bgr8.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace bullet_plant
{
struct ImageEncoding
{
  enum class Layout { Rgb8, Bgr8, Mono8, Mono16, Rgb16, Bayer };
  Layout layout = Layout::Rgb8;
  std::string encoding = "rgb8";  // sensor_msgs/image_encodings
  uint32_t bytes_per_pixel = 3;   // upstream's skip_: the message's step is width x this
  // Bayer: which channel (0 red, 1 green, 2 blue) each pixel of a 2 x 2 block takes, by
  // (row % 2) * 2 + column % 2.
  int bayer[4] = {0, 1, 1, 2};
  bool known = true;  // false: upstream's "Unsupported Gazebo ImageFormat", bgr8
  bool sixteenBit() const { return layout == Layout::Mono16 || layout == Layout::Rgb16; }
};

// The encoding of an SDF <image><format>, as gazebo_ros_camera_utils' Init maps it: L8 / L_INT8
// mono8, L16 / L_INT16 mono16, R8G8B8 / RGB_INT8 rgb8, B8G8R8 / BGR_INT8 bgr8, R16G16B16 / RGB_INT16
// rgb16, BAYER_RGGB8 / BGGR8 / GBRG8 / GRBG8 bayer_*8; anything else bgr8, not known.
ImageEncoding imageEncodingOf(const std::string& format);

// 8-bit levels spread over 16 bits (x 257: 255 -> 65535), what a 16-bit camera gives where the GL has
// no 16-bit colour targets.
void spreadTo16Bits(const uint8_t* levels8, size_t count, uint16_t* levels16);

// The message's data for the frame's pixels (3 values a pixel, rows from the top, the image `width`
// wide): pixels x bytes_per_pixel bytes into `out`, 16-bit values little-endian. A 16-bit encoding
// takes the frame's 16-bit colours `rgb16` (null: spreadTo16Bits of the 8-bit ones), the others `rgb8`.
void encodeImage(const ImageEncoding& encoding, const uint8_t* rgb8, const uint16_t* rgb16, int width, int height,
                 uint8_t* out);

}  // namespace bullet_plant
