// src/node/frame_messages.h: a camera frame serialized straight from the frame gives the bytes of
// the sensor_msgs message built field by field from it, which is what a subscriber receives.
#include "frame_messages.h"

#include <cmath>
#include <cstring>

#include <gtest/gtest.h>

namespace bullet_plant
{
namespace
{
const float kNaN = std::numeric_limits<float>::quiet_NaN();
const std::string kFrameId = "tianracer/depth_camera_link_optical";

// 4 x 3 pixels: depths inside the cutoff (0.5, 5), nothing hit, too near, too far, on the bounds.
CameraFrame testFrame()
{
  CameraFrame f;
  f.stamp_ns = 12'345'678'901;
  f.width = 4;
  f.height = 3;
  const float depths[12] = {1.0f, kNaN, 0.2f, 6.0f, 0.5f, 5.0f, 2.5f, 4.99f, 0.51f, 3.0f, kNaN, 1.5f};
  for (int p = 0; p < 12; ++p)
  {
    f.depth.push_back(depths[p]);
    for (float c : {0.1f * p, -0.2f * p, depths[p]})
      f.points.push_back(c);
    for (int c = 0; c < 3; ++c)
      f.rgb.push_back(uint8_t(20 * p + 70 * c + 5));
  }
  return f;
}
const DepthCutoff kCutoff{0.5, 5.0};

sensor_msgs::Image builtImage(const CameraFrame& f, const std::string& encoding, uint32_t step)
{
  sensor_msgs::Image image;
  image.header = frameHeader(f, kFrameId);
  image.width = f.width;
  image.height = f.height;
  image.encoding = encoding;
  image.step = step;
  return image;
}

// The messages as the node built them before it serialized frames directly.
sensor_msgs::Image builtRgb(const CameraFrame& f)
{
  sensor_msgs::Image image = builtImage(f, "rgb8", f.width * 3);
  image.data = f.rgb;
  return image;
}

sensor_msgs::Image builtDepth(const CameraFrame& f, DepthCutoff cutoff)
{
  sensor_msgs::Image image = builtImage(f, "32FC1", f.width * 4);
  std::vector<float> depths(f.depth);
  for (float& d : depths)
    if (!cutoff.within(d))
      d = kNaN;
  image.data.resize(depths.size() * 4);
  std::memcpy(image.data.data(), depths.data(), image.data.size());
  return image;
}

sensor_msgs::PointCloud2 builtCloud(const CameraFrame& f, DepthCutoff cutoff)
{
  sensor_msgs::PointCloud2 cloud;
  cloud.header = frameHeader(f, kFrameId);
  cloud.width = f.width;
  cloud.height = f.height;
  cloud.is_dense = true;  // until a point is NaN, as upstream's fill theirs
  cloud.point_step = 16;
  cloud.row_step = 16 * f.width;
  cloud.fields = pointCloudFields();
  cloud.data.resize(size_t(cloud.row_step) * f.height);
  for (size_t p = 0; p < size_t(f.width) * f.height; ++p)
  {
    const float nan3[3] = {kNaN, kNaN, kNaN};
    cloud.is_dense = cloud.is_dense && cutoff.within(f.depth[p]);
    std::memcpy(&cloud.data[16 * p], cutoff.within(f.depth[p]) ? &f.points[3 * p] : nan3, 12);
    const uint32_t rgb = (uint32_t(f.rgb[3 * p]) << 16) | (uint32_t(f.rgb[3 * p + 1]) << 8) | f.rgb[3 * p + 2];
    std::memcpy(&cloud.data[16 * p + 12], &rgb, 4);
  }
  return cloud;
}

template <class M>
std::vector<uint8_t> bytes(const M& message)
{
  ros::SerializedMessage m = ros::serialization::serializeMessage(message);
  return std::vector<uint8_t>(m.buf.get(), m.buf.get() + m.num_bytes);
}

template <class M>
M deserialized(const std::vector<uint8_t>& serialized)
{
  M message;
  ros::serialization::IStream s(const_cast<uint8_t*>(serialized.data()) + 4, serialized.size() - 4);
  ros::serialization::deserialize(s, message);
  return message;
}

float floatAt(const std::vector<uint8_t>& data, size_t offset)
{
  float v;
  std::memcpy(&v, &data[offset], 4);
  return v;
}

TEST(FrameMessages, TraitsAreTheMessagesOwn)
{
  namespace mt = ros::message_traits;
  const CameraFrame f = testFrame();
  const std_msgs::Header header = frameHeader(f, kFrameId);
  EXPECT_STREQ(mt::md5sum(RgbImageOf{f, header}), mt::md5sum<sensor_msgs::Image>());
  EXPECT_STREQ(mt::datatype(DepthImageOf{f, header, kCutoff}), "sensor_msgs/Image");
  EXPECT_STREQ(mt::md5sum(PointCloudOf{f, header, kCutoff}), mt::md5sum<sensor_msgs::PointCloud2>());
  EXPECT_STREQ(mt::datatype(PointCloudOf{f, header, kCutoff}), "sensor_msgs/PointCloud2");
  EXPECT_STREQ(mt::definition<PointCloudOf>(), mt::definition<sensor_msgs::PointCloud2>());
  EXPECT_TRUE(mt::hasHeader<RgbImageOf>());
}

TEST(FrameMessages, RgbImageHasTheBuiltMessagesBytes)
{
  const CameraFrame f = testFrame();
  const std_msgs::Header header = frameHeader(f, kFrameId);
  const std::vector<uint8_t> serialized = bytes(RgbImageOf{f, header});
  EXPECT_EQ(serialized, bytes(builtRgb(f)));
  const sensor_msgs::Image image = deserialized<sensor_msgs::Image>(serialized);
  EXPECT_EQ(image.header.stamp, ros::Time(12, 345'678'901));
  EXPECT_EQ(image.header.frame_id, kFrameId);
  EXPECT_EQ(image.encoding, "rgb8");
  EXPECT_EQ(image.step, 12u);
  EXPECT_EQ(image.data, f.rgb);
}

TEST(FrameMessages, DepthImageIsNaNOutsideTheCutoff)
{
  const CameraFrame f = testFrame();
  const std_msgs::Header header = frameHeader(f, kFrameId);
  const std::vector<uint8_t> serialized = bytes(DepthImageOf{f, header, kCutoff});
  EXPECT_EQ(serialized, bytes(builtDepth(f, kCutoff)));
  const sensor_msgs::Image image = deserialized<sensor_msgs::Image>(serialized);
  EXPECT_EQ(image.encoding, "32FC1");
  EXPECT_EQ(image.step, 16u);
  ASSERT_EQ(image.data.size(), 48u);
  const bool kept[12] = {true, false, false, false, false, false, true, true, true, true, false, true};
  for (int p = 0; p < 12; ++p)
    if (kept[p])
      EXPECT_EQ(floatAt(image.data, 4 * p), f.depth[p]) << "pixel " << p;
    else
      EXPECT_TRUE(std::isnan(floatAt(image.data, 4 * p))) << "pixel " << p;
}

TEST(FrameMessages, PointCloudHasCutoffNaNsAndPackedRgb)
{
  const CameraFrame f = testFrame();
  const std_msgs::Header header = frameHeader(f, kFrameId);
  const std::vector<uint8_t> serialized = bytes(PointCloudOf{f, header, kCutoff});
  EXPECT_EQ(serialized, bytes(builtCloud(f, kCutoff)));
  const sensor_msgs::PointCloud2 cloud = deserialized<sensor_msgs::PointCloud2>(serialized);
  EXPECT_EQ(cloud.header.frame_id, kFrameId);
  EXPECT_EQ(cloud.width, 4u);
  EXPECT_EQ(cloud.height, 3u);
  EXPECT_EQ(cloud.point_step, 16u);
  EXPECT_EQ(cloud.row_step, 64u);
  EXPECT_FALSE(cloud.is_dense) << "NaN points";
  ASSERT_EQ(cloud.fields.size(), 4u);
  EXPECT_EQ(cloud.fields[3].name, "rgb");
  EXPECT_EQ(cloud.fields[3].offset, 12u);
  ASSERT_EQ(cloud.data.size(), 12u * 16);
  EXPECT_EQ(floatAt(cloud.data, 6 * 16), 0.1f * 6);  // pixel 6: within the cutoff
  EXPECT_EQ(floatAt(cloud.data, 6 * 16 + 8), 2.5f);
  for (int p : {1, 2, 3, 4, 5})  // nothing hit, too near, too far, on the bounds
    EXPECT_TRUE(std::isnan(floatAt(cloud.data, 16 * p + 8))) << "pixel " << p;
  uint32_t rgb;
  std::memcpy(&rgb, &cloud.data[6 * 16 + 12], 4);
  EXPECT_EQ(rgb, (125u << 16) | (195u << 8) | 9u);  // pixel 6's colour: 125, 195, 265 wrapped to 9
}

TEST(FrameMessages, APointCloudWithoutNaNPointsIsDense)
{
  CameraFrame f = testFrame();
  for (float& depth : f.depth)
    depth = 1.0f;  // every pixel within the cutoff
  const std::vector<uint8_t> serialized = bytes(PointCloudOf{f, frameHeader(f, kFrameId), kCutoff});
  EXPECT_EQ(serialized, bytes(builtCloud(f, kCutoff)));
  EXPECT_TRUE(deserialized<sensor_msgs::PointCloud2>(serialized).is_dense);
}

}  // namespace
}  // namespace bullet_plant
