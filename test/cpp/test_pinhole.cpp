// pinhole.cpp: the camera noise's two ways (a pixel at a time, four at a time with SSE2) give the
// same bytes, the samples' extremes and a pixel count that is not a multiple of four included; the
// noise-free copy keeps every colour.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

#include "rendering/pinhole.h"

using namespace bullet_plant;

TEST(CameraNoise, FourPixelsAtATimeGiveThePixelAtATimeRulesBytes)
{
#if defined(__SSE2__)
  std::mt19937 rng(11);
  for (size_t pixels : {size_t(1), size_t(3), size_t(4), size_t(1027), size_t(640 * 480)})
  {
    std::vector<uint8_t> rgba(4 * pixels), each(3 * pixels), four(3 * pixels);
    std::vector<int16_t> samples(pixels);
    for (uint8_t& v : rgba)
      v = uint8_t(rng());
    const int16_t extremes[] = {-256, 256, -255, 255, -1, 1, 0};
    for (size_t k = 0; k < pixels; ++k)  // the extremes first, then any level
      samples[k] = k < 7 ? extremes[k] : int16_t(int(rng() % 513) - 256);
    detail::noisyRgbFromRgbaEach(samples.data(), rgba.data(), each.data(), pixels);
    detail::noisyRgbFromRgbaSse2(samples.data(), rgba.data(), four.data(), pixels);
    ASSERT_EQ(each, four) << pixels << " pixels";
    for (size_t k = 0; k < pixels; ++k)
      for (int c = 0; c < 3; ++c)
        ASSERT_EQ(each[3 * k + c], std::min(255, std::max(0, rgba[4 * k + c] + samples[k]))) << k;
  }
#else
  GTEST_SKIP() << "no SSE2 on this CPU: the pixel at a time rule is the only one built";
#endif
}

TEST(CameraNoise, WithoutNoiseTheColoursAreCopied)
{
  PinholeCamera camera;
  camera.width = 5;
  camera.height = 3;
  std::vector<uint8_t> rgba(4 * 15), rgb(3 * 15);
  for (size_t k = 0; k < rgba.size(); ++k)
    rgba[k] = uint8_t(17 * k);
  noisyRgbFromRgba(camera, rgba.data(), rgb.data());
  for (size_t k = 0; k < 15; ++k)
    for (int c = 0; c < 3; ++c)
      EXPECT_EQ(rgb[3 * k + c], rgba[4 * k + c]);
}
