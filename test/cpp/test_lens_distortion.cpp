// lens_distortion.cpp and image_encoding.cpp: Gazebo 11's distortion map moves a pixel the way
// Brown's model says (barrel toward the centre, pincushion away from it), the crop's zoom is the
// legacy bound's, no distortion is no remap; the image encodings give upstream's labels and OGRE's
// bytes (luminance = red, 16 bits = 257 x 8 bits, Gazebo's Bayer blocks, unknown = bgr8).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "bullet_plant/image_encoding.h"
#include "rendering/lens_distortion.h"

using namespace bullet_plant;

namespace
{
// Where the remap takes output pixel (u, v) from: the weighted centre of its taps, in pixels.
void sourceOf(const DistortionRemap& remap, int u, int v, double& x, double& y)
{
  const size_t k = size_t(v) * remap.width + u;
  x = y = 0;
  for (int t = 0; t < 4; ++t)
  {
    const uint32_t tap = remap.taps[4 * k + t];
    x += remap.weights[4 * k + t] * double(tap % remap.width);
    y += remap.weights[4 * k + t] * double(tap / remap.width);
  }
}

CameraDistortion radial(double k1)
{
  CameraDistortion d;
  d.given = true;
  d.k1 = k1;
  return d;
}

// Brown's model in pixels of a width x width image of horizontal field `hfov`: the distorted
// position of an undistorted one on the middle row.
double distortedColumn(double k1, int width, double hfov, double column)
{
  const double f = width / (2 * std::tan(hfov / 2)), c = width / 2.0;
  const double x = (column - c) / f;
  return c + f * x * (1 + k1 * x * x);
}
}  // namespace

TEST(LensDistortion, NoCoefficientsNoRemap)
{
  CameraDistortion d;
  d.given = true;
  EXPECT_FALSE(distorts(d));
  EXPECT_TRUE(distortionRemap(d, 64, 48, 1.0, true).empty());
}

TEST(LensDistortion, BarrelPullsTowardTheCentrePincushionPushesAway)
{
  const int width = 101;
  const double hfov = 1.2;
  for (double k1 : {-0.5, 0.5})
  {
    const DistortionRemap remap = distortionRemap(radial(k1), width, width, hfov, false);
    ASSERT_FALSE(remap.empty());
    // An output pixel shows the undistorted point that Brown's model moves onto it: search the
    // undistorted column whose distorted place is the output column.
    for (int u : {15, 25, 76, 86})  // where a barrel lens's source lies inside the frame
    {
      double lo = 0, hi = width;
      for (int i = 0; i < 60; ++i)
      {
        const double mid = (lo + hi) / 2;
        (distortedColumn(k1, width, hfov, mid) < u + 0.5 ? lo : hi) = mid;
      }
      const double expected = lo - 0.5;  // pixel centres at integers
      double x, y;
      sourceOf(remap, u, width / 2, x, y);
      EXPECT_NEAR(x, expected, 1.0) << "k1 " << k1 << " column " << u;
      EXPECT_NEAR(y, width / 2, 1.0);
      // barrel: the output shows what lay farther out; pincushion: nearer the centre
      if (k1 < 0)
        EXPECT_GT(std::abs(x - width / 2), std::abs(u - width / 2) + 0.5) << u;
      else
        EXPECT_LT(std::abs(x - width / 2), std::abs(u - width / 2) - 0.5) << u;
    }
  }
}

TEST(LensDistortion, CropZoomsByTheLegacyBoundsOnlyForBarrel)
{
  double sx, sy;
  lens::cropScale(radial(-0.25), true, sx, sy);
  // legacy form: the corner (0, 0) is 0.5 from the centre on each axis, r^2 = 0.5
  EXPECT_NEAR(sx, 1 - 0.25 * 0.5, 1e-12);
  EXPECT_NEAR(sy, sx, 1e-12);
  lens::cropScale(radial(-0.25), false, sx, sy);
  EXPECT_EQ(sx, 1.0);
  lens::cropScale(radial(0.25), true, sx, sy);
  EXPECT_EQ(sx, 1.0);
  // cropped, the output's edge takes from nearer the middle of the map than uncropped
  const DistortionRemap cropped = distortionRemap(radial(-0.25), 64, 64, 1.0, true);
  const DistortionRemap whole = distortionRemap(radial(-0.25), 64, 64, 1.0, false);
  double xc, yc, xw, yw;
  sourceOf(cropped, 10, 32, xc, yc);
  sourceOf(whole, 10, 32, xw, yw);
  EXPECT_GT(xc, xw + 1);
}

TEST(LensDistortion, RemapCopiesTheColoursItSamples)
{
  // A remap that leaves every pixel where it is (a tiny k1): colours survive the blend.
  const DistortionRemap remap = distortionRemap(radial(-1e-9), 8, 8, 1.0, false);
  std::vector<uint8_t> in(3 * 64, 200), out(3 * 64, 0);
  remapRgb(remap, in.data(), out.data());
  for (uint8_t v : out)
    EXPECT_EQ(v, 200);
}

TEST(ImageEncoding, UpstreamLabelsAndBytesPerPixel)
{
  struct Case { const char* format; const char* encoding; uint32_t bytes; };
  const Case cases[] = {{"L8", "mono8", 1},         {"L_INT8", "mono8", 1},          {"L16", "mono16", 2},
                        {"L_INT16", "mono16", 2},   {"R8G8B8", "rgb8", 3},           {"RGB_INT8", "rgb8", 3},
                        {"B8G8R8", "bgr8", 3},      {"BGR_INT8", "bgr8", 3},         {"R16G16B16", "rgb16", 6},
                        {"RGB_INT16", "rgb16", 6},  {"BAYER_RGGB8", "bayer_rggb8", 1}, {"BAYER_BGGR8", "bayer_bggr8", 1},
                        {"BAYER_GBRG8", "bayer_gbrg8", 1}, {"BAYER_GRBG8", "bayer_grbg8", 1}};
  for (const Case& c : cases)
  {
    const ImageEncoding e = imageEncodingOf(c.format);
    EXPECT_EQ(e.encoding, c.encoding) << c.format;
    EXPECT_EQ(e.bytes_per_pixel, c.bytes) << c.format;
    EXPECT_TRUE(e.known) << c.format;
  }
  for (const char* unknown : {"FLOAT32", "RGBA_INT8", "L_UINT16", ""})
  {
    const ImageEncoding e = imageEncodingOf(unknown);
    EXPECT_FALSE(e.known) << unknown;
    EXPECT_EQ(e.encoding, "bgr8") << unknown;
    EXPECT_EQ(e.bytes_per_pixel, 3u) << unknown;
  }
}

TEST(ImageEncoding, OgresBytes)
{
  // 2 x 2 pixels: red, green / blue, grey
  const uint8_t rgb[] = {200, 10, 20, 30, 180, 40, 50, 60, 170, 128, 128, 128};
  auto encoded = [&](const char* format) {
    const ImageEncoding e = imageEncodingOf(format);
    std::vector<uint8_t> out(4 * e.bytes_per_pixel);
    encodeImage(e, rgb, nullptr, 2, 2, out.data());
    return out;
  };
  EXPECT_EQ(encoded("L8"), (std::vector<uint8_t>{200, 30, 50, 128}));  // the red channel
  EXPECT_EQ(encoded("L16"), (std::vector<uint8_t>{0xC8, 0xC8, 30, 30, 50, 50, 128, 128}));  // x 257, little-endian
  EXPECT_EQ(encoded("B8G8R8"), (std::vector<uint8_t>{20, 10, 200, 40, 180, 30, 170, 60, 50, 128, 128, 128}));
  EXPECT_EQ(encoded("nonsense"), encoded("B8G8R8"));
  const std::vector<uint8_t> rgb16 = encoded("R16G16B16");
  ASSERT_EQ(rgb16.size(), 24u);
  EXPECT_EQ(rgb16[2] | rgb16[3] << 8, 10 * 257);
  // a 16-bit frame's own values, not the 8-bit ones spread
  const uint16_t deep[] = {51400, 2570, 5140, 7710, 46260, 10280, 12850, 15420, 43690, 32896, 32897, 32898};
  const ImageEncoding mono16 = imageEncodingOf("L16");
  std::vector<uint8_t> out(8);
  encodeImage(mono16, rgb, deep, 2, 2, out.data());
  EXPECT_EQ(out, (std::vector<uint8_t>{0xC8, 0xC8, 0x1E, 0x1E, 0x32, 0x32, 0x80, 0x80}));  // the red values
  const uint16_t odd[] = {1, 2, 3, 4, 5, 6, 7, 8, 9, 65535, 0, 256};
  out.resize(24);
  encodeImage(imageEncodingOf("R16G16B16"), rgb, odd, 2, 2, out.data());
  for (int k = 0; k < 12; ++k)
    EXPECT_EQ(out[2 * k] | out[2 * k + 1] << 8, odd[k]) << k;
  // Bayer: top-left, top-right / bottom-left, bottom-right as Camera::ConvertRGBToBAYER fills them
  EXPECT_EQ(encoded("BAYER_RGGB8"), (std::vector<uint8_t>{200, 180, 60, 128}));
  EXPECT_EQ(encoded("BAYER_BGGR8"), (std::vector<uint8_t>{20, 180, 60, 128}));
  EXPECT_EQ(encoded("BAYER_GBRG8"), (std::vector<uint8_t>{10, 30, 170, 128}));
  EXPECT_EQ(encoded("BAYER_GRBG8"), (std::vector<uint8_t>{10, 40, 50, 128}));
}
