// A camera frame's sensor_msgs/Image (rgb8 or the <image><format>'s encoding, 32FC1 depth) and sensor_msgs/PointCloud2 as roscpp
// publishes them, serialized straight from the frame into roscpp's buffer: a subscriber receives
// the same bytes, md5 and type as from a message built first, without the copy (a point cloud is
// 4.9 MB at 640 x 480). Publish one of these views on a publisher advertised with the message type.
#pragma once

#include <cstring>
#include <limits>
#include <vector>

#include <ros/serialization.h>
#include <sensor_msgs/Image.h>
#include <sensor_msgs/PointCloud2.h>
#include <std_msgs/Header.h>

#include "bullet_plant/image_encoding.h"
#include "bullet_plant/sensors.h"
#include "ros_time.h"

namespace bullet_plant
{
// gazebo_ros_openni_kinect's pointCloudCutoff(Max): depths outside (near, far) are published as NaN.
struct DepthCutoff
{
  double near = 0, far = 0;
  bool within(float depth) const { return depth > near && depth < far; }
};

// Each view carries the header its plugin stamps (frameHeader) with the frame's pixels.
struct RgbImageOf  // sensor_msgs/Image, rgb8
{
  const CameraFrame& frame;
  const std_msgs::Header& header;
};
struct EncodedImageOf  // sensor_msgs/Image in the camera's <image><format> (image_encoding.h)
{
  const CameraFrame& frame;
  const std_msgs::Header& header;
  const ImageEncoding& encoding;
};
struct DepthImageOf  // sensor_msgs/Image, 32FC1 metres, NaN outside the cutoff
{
  const CameraFrame& frame;
  const std_msgs::Header& header;
  DepthCutoff cutoff;
};
struct PointCloudOf  // sensor_msgs/PointCloud2: x y z float32 (NaN outside the cutoff), rgb packed in a float32
{
  const CameraFrame& frame;
  const std_msgs::Header& header;
  DepthCutoff cutoff;
  bool organized = true;  // height x width as the image; else one row of every pixel
  // The image's encoding, whose bytes colour the points as upstream's FillPointCloudHelper takes
  // them (null: rgb8)
  const ImageEncoding* encoding = nullptr;
};

// The header the frame's messages carry (seq is filled in by roscpp as it publishes); the frame id
// is the plugin's (plugin_names.h).
inline std_msgs::Header frameHeader(const CameraFrame& f, const std::string& frame_id)
{
  std_msgs::Header header;
  header.stamp = rosTime(f.stamp_ns);
  header.frame_id = frame_id;
  return header;
}

// The fields of the point cloud, as gazebo_ros_openni_kinect publishes them.
inline const std::vector<sensor_msgs::PointField>& pointCloudFields()
{
  static const std::vector<sensor_msgs::PointField> fields = [] {
    std::vector<sensor_msgs::PointField> out(4);
    const char* names[] = {"x", "y", "z", "rgb"};
    for (int i = 0; i < 4; ++i)
    {
      out[i].name = names[i];
      out[i].offset = 4 * i;
      out[i].datatype = sensor_msgs::PointField::FLOAT32;
      out[i].count = 1;
    }
    return out;
  }();
  return fields;
}
constexpr uint32_t kPointStep = 16;

namespace frame_messages
{
// The traits of a view are its message's: same type name, md5 and definition.
template <class Trait>
struct Of : Trait
{
  using Trait::value;
  template <class View>
  static const char* value(const View&) { return Trait::value(); }
};

// sensor_msgs/Image of `size` data bytes, which write_data(pointer) writes.
template <class Stream, class WriteData>
void writeImage(Stream& s, const std_msgs::Header& header, const CameraFrame& f, const std::string& encoding, uint32_t bytes_per_pixel, uint32_t size,
                WriteData write_data)
{
  s.next(header);
  s.next(uint32_t(f.height));
  s.next(uint32_t(f.width));
  s.next(encoding);
  s.next(uint8_t(0));  // is_bigendian
  s.next(uint32_t(f.width * bytes_per_pixel));  // step
  s.next(size);
  write_data(s.advance(size));
}

inline uint32_t imageLength(const std_msgs::Header& header, const std::string& encoding, uint32_t size)
{
  return ros::serialization::serializationLength(header) + 4 + 4 + 4 + encoding.size() + 1 + 4 + 4 + size;
}

inline const std::string& rgb8() { static const std::string s = "rgb8"; return s; }
inline const std::string& depth32FC1() { static const std::string s = "32FC1"; return s; }

// A point's colour packed as the cloud's rgb field (r << 16 | g << 8 | b) from the image pixel's
// bytes, as upstream's FillPointCloudHelper reads the published image: three bytes a pixel give
// their three in order, one byte (mono8, bayer) a grey of it, anything else (16-bit) black.
inline uint32_t cloudColour(const ImageEncoding* e, const uint8_t* rgb, size_t pixel, int width)
{
  using Layout = ImageEncoding::Layout;
  const uint8_t* c = rgb + 3 * pixel;
  if (!e || e->layout == Layout::Rgb8)
    return (uint32_t(c[0]) << 16) | (uint32_t(c[1]) << 8) | c[2];
  switch (e->layout)
  {
    case Layout::Bgr8:
      return (uint32_t(c[2]) << 16) | (uint32_t(c[1]) << 8) | c[0];
    case Layout::Mono8:
      return (uint32_t(c[0]) << 16) | (uint32_t(c[0]) << 8) | c[0];
    case Layout::Bayer:
    {
      const int u = int(pixel % size_t(width)), v = int(pixel / size_t(width));
      const uint32_t g = c[e->bayer[(v % 2) * 2 + u % 2]];
      return (g << 16) | (g << 8) | g;
    }
    default:
      return 0;
  }
}

inline void writeCutDepth(uint8_t* out, float depth, DepthCutoff cutoff)
{
  const float value = cutoff.within(depth) ? depth : std::numeric_limits<float>::quiet_NaN();
  std::memcpy(out, &value, 4);
}
}  // namespace frame_messages
}  // namespace bullet_plant

namespace ros
{
namespace message_traits
{
using bullet_plant::frame_messages::Of;
template <> struct MD5Sum<bullet_plant::RgbImageOf> : Of<MD5Sum<sensor_msgs::Image>> {};
template <> struct DataType<bullet_plant::RgbImageOf> : Of<DataType<sensor_msgs::Image>> {};
template <> struct Definition<bullet_plant::RgbImageOf> : Of<Definition<sensor_msgs::Image>> {};
template <> struct HasHeader<bullet_plant::RgbImageOf> : TrueType {};
template <> struct MD5Sum<bullet_plant::EncodedImageOf> : Of<MD5Sum<sensor_msgs::Image>> {};
template <> struct DataType<bullet_plant::EncodedImageOf> : Of<DataType<sensor_msgs::Image>> {};
template <> struct Definition<bullet_plant::EncodedImageOf> : Of<Definition<sensor_msgs::Image>> {};
template <> struct HasHeader<bullet_plant::EncodedImageOf> : TrueType {};
template <> struct MD5Sum<bullet_plant::DepthImageOf> : Of<MD5Sum<sensor_msgs::Image>> {};
template <> struct DataType<bullet_plant::DepthImageOf> : Of<DataType<sensor_msgs::Image>> {};
template <> struct Definition<bullet_plant::DepthImageOf> : Of<Definition<sensor_msgs::Image>> {};
template <> struct HasHeader<bullet_plant::DepthImageOf> : TrueType {};
template <> struct MD5Sum<bullet_plant::PointCloudOf> : Of<MD5Sum<sensor_msgs::PointCloud2>> {};
template <> struct DataType<bullet_plant::PointCloudOf> : Of<DataType<sensor_msgs::PointCloud2>> {};
template <> struct Definition<bullet_plant::PointCloudOf> : Of<Definition<sensor_msgs::PointCloud2>> {};
template <> struct HasHeader<bullet_plant::PointCloudOf> : TrueType {};
}  // namespace message_traits

namespace serialization
{
template <>
struct Serializer<bullet_plant::RgbImageOf>
{
  template <typename Stream>
  static void write(Stream& s, const bullet_plant::RgbImageOf& m)
  {
    namespace fm = bullet_plant::frame_messages;
    const std::vector<uint8_t>& rgb = m.frame.rgb;
    fm::writeImage(s, m.header, m.frame, fm::rgb8(), 3, rgb.size(), [&](uint8_t* out) { std::memcpy(out, rgb.data(), rgb.size()); });
  }
  static uint32_t serializedLength(const bullet_plant::RgbImageOf& m)
  {
    return bullet_plant::frame_messages::imageLength(m.header, bullet_plant::frame_messages::rgb8(), m.frame.rgb.size());
  }
};

template <>
struct Serializer<bullet_plant::EncodedImageOf>
{
  template <typename Stream>
  static void write(Stream& s, const bullet_plant::EncodedImageOf& m)
  {
    namespace fm = bullet_plant::frame_messages;
    const bullet_plant::CameraFrame& f = m.frame;
    const uint16_t* rgb16 = f.rgb16.empty() ? nullptr : f.rgb16.data();
    fm::writeImage(s, m.header, f, m.encoding.encoding, m.encoding.bytes_per_pixel, length(m), [&](uint8_t* out) {
      bullet_plant::encodeImage(m.encoding, f.rgb.data(), rgb16, f.width, f.height, out);
    });
  }
  static uint32_t serializedLength(const bullet_plant::EncodedImageOf& m)
  {
    return bullet_plant::frame_messages::imageLength(m.header, m.encoding.encoding, length(m));
  }
  static uint32_t length(const bullet_plant::EncodedImageOf& m)
  {
    return uint32_t(m.frame.width) * uint32_t(m.frame.height) * m.encoding.bytes_per_pixel;
  }
};

template <>
struct Serializer<bullet_plant::DepthImageOf>
{
  template <typename Stream>
  static void write(Stream& s, const bullet_plant::DepthImageOf& m)
  {
    namespace fm = bullet_plant::frame_messages;
    fm::writeImage(s, m.header, m.frame, fm::depth32FC1(), 4, 4 * m.frame.depth.size(), [&](uint8_t* out) {
      for (float depth : m.frame.depth)
        fm::writeCutDepth(out, depth, m.cutoff), out += 4;
    });
  }
  static uint32_t serializedLength(const bullet_plant::DepthImageOf& m)
  {
    return bullet_plant::frame_messages::imageLength(m.header, bullet_plant::frame_messages::depth32FC1(),
                                                     4 * m.frame.depth.size());
  }
};

template <>
struct Serializer<bullet_plant::PointCloudOf>
{
  template <typename Stream>
  static void write(Stream& s, const bullet_plant::PointCloudOf& m)
  {
    const bullet_plant::CameraFrame& f = m.frame;
    const size_t pixels = size_t(f.width) * f.height;
    const uint32_t height = m.organized ? uint32_t(f.height) : 1, width = uint32_t(pixels / height);
    s.next(m.header);
    s.next(height);
    s.next(width);
    s.next(bullet_plant::pointCloudFields());
    s.next(uint8_t(0));  // is_bigendian
    s.next(bullet_plant::kPointStep);
    s.next(uint32_t(bullet_plant::kPointStep * width));  // row_step
    s.next(uint32_t(bullet_plant::kPointStep * pixels));
    uint8_t* out = s.advance(uint32_t(bullet_plant::kPointStep * pixels));
    static const float kNaN[3] = {std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::quiet_NaN(),
                                  std::numeric_limits<float>::quiet_NaN()};
    bool dense = true;  // upstream's: until a point is NaN (beyond the cutoffs, nothing seen)
    for (size_t p = 0; p < pixels; ++p, out += bullet_plant::kPointStep)
    {
      const bool seen = m.cutoff.within(f.depth[p]);
      dense = dense && seen;
      std::memcpy(out, seen ? &f.points[3 * p] : kNaN, 12);
      const uint32_t rgb = bullet_plant::frame_messages::cloudColour(m.encoding, f.rgb.data(), p, f.width);
      std::memcpy(out + 12, &rgb, 4);
    }
    s.next(uint8_t(dense));  // is_dense
  }
  static uint32_t serializedLength(const bullet_plant::PointCloudOf& m)
  {
    return serializationLength(m.header) + 4 + 4 +
           serializationLength(bullet_plant::pointCloudFields()) + 1 + 4 + 4 + 4 +
           bullet_plant::kPointStep * uint32_t(m.frame.width) * m.frame.height + 1;
  }
};
}  // namespace serialization
}  // namespace ros
