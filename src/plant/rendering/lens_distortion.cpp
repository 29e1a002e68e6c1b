#include "rendering/lens_distortion.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace bullet_plant
{
bool distorts(const CameraDistortion& d)
{
  return d.k1 != 0 || d.k2 != 0 || d.k3 != 0 || d.p1 != 0 || d.p2 != 0;
}

void lens::distortPoint(const CameraDistortion& d, double width_over_focal, double in_x, double in_y, double& out_x,
                        double& out_y)
{
  // Brown's model in normalized camera coordinates: Gazebo scales the offset from the centre by
  // the texture's width over the focal length, distorts, and scales back.
  const double x = (in_x - d.center_x) * width_over_focal, y = (in_y - d.center_y) * width_over_focal;
  const double r2 = x * x + y * y;
  const double radial = 1.0 + d.k1 * r2 + d.k2 * r2 * r2 + d.k3 * r2 * r2 * r2;
  const double dx = x * radial + d.p2 * (r2 + 2 * x * x) + 2 * d.p1 * x * y;
  const double dy = y * radial + d.p1 * (r2 + 2 * y * y) + 2 * d.p2 * x * y;
  out_x = d.center_x + dx / width_over_focal;
  out_y = d.center_y + dy / width_over_focal;
}

namespace
{
// A texel index as Gazebo computes it, an unsigned int from a double: truncated toward zero, so
// a point less than one texel left of (or above) the texture still lands on its first texel;
// -1 where it lands nowhere.
long texelOf(double position, unsigned texels)
{
  const double t = position * texels;
  if (!(t > -1.0) || t >= double(texels))
    return -1;
  return long(t);  // truncation toward zero
}
}  // namespace

std::vector<double> lens::distortionMap(const CameraDistortion& d, int width, int height, double hfov, int& side)
{
  // Gazebo's square texture, one texel less than the image's larger side (at least one here,
  // where Gazebo would divide by zero), its focal length from the field of view along that side.
  const int larger = std::max(width, height);
  const unsigned tex = unsigned(std::max(larger - 1, 1));
  side = int(tex);
  const double vfov = 2.0 * std::atan(std::tan(hfov / 2.0) * height / std::max(width, 1));
  const double fov = height > width ? vfov : hfov;
  const double focal = larger / (2.0 * std::tan(fov / 2.0));
  const double width_over_focal = tex / focal;

  std::vector<double> map(2 * size_t(tex) * tex, -1.0);
  const double centre_x = d.center_x * tex, centre_y = d.center_y * tex;
  for (unsigned row = 0; row < tex; ++row)
    for (unsigned col = 0; col < tex; ++col)
    {
      const double u = double(col) / tex, v = double(row) / tex;
      double dx, dy;
      distortPoint(d, width_over_focal, u, v, dx, dy);
      const long dc = texelOf(dx, tex), dr = texelOf(dy, tex);
      if (dc < 0 || dr < 0)
        continue;  // lands outside the image: expected, so that no border stays unmapped
      double* texel = &map[2 * (size_t(dr) * tex + size_t(dc))];
      // Where several undistorted texels land on one, the one nearer the centre wins: a strong
      // distortion does not fold the image over itself.
      if (texel[0] != -1.0 || texel[1] != -1.0)
      {
        const double held = std::hypot(texel[0] * tex - centre_x, texel[1] * tex - centre_y);
        if (!(std::hypot(col - centre_x, row - centre_y) < held))
          continue;
      }
      texel[0] = u;
      texel[1] = v;
    }

  // Holes (texels nothing landed on) take the mean of their set neighbours, read from the map as
  // it was before any hole was filled.
  std::vector<double> filled(map);
  auto at = [&](long c, long r, double& x, double& y) {
    if (c < 0 || r < 0 || c >= long(tex) || r >= long(tex))
      return false;
    x = map[2 * (size_t(r) * tex + size_t(c))];
    y = map[2 * (size_t(r) * tex + size_t(c)) + 1];
    return x > -0.5;
  };
  for (long r = 0; r < long(tex); ++r)
    for (long c = 0; c < long(tex); ++c)
    {
      double* texel = &filled[2 * (size_t(r) * tex + size_t(c))];
      if (!(texel[0] < -0.5 && texel[1] < -0.5))
        continue;
      static const int kNeighbours[8][2] = {{1, 0}, {-1, 0}, {0, -1}, {0, 1}, {1, 1}, {-1, 1}, {1, -1}, {-1, -1}};
      double sum_x = 0, sum_y = 0, divisor = 0;
      for (int k = 0; k < 8; ++k)
      {
        double x, y;
        if (!at(c + kNeighbours[k][0], r + kNeighbours[k][1], x, y))
          continue;
        const double w = k < 4 ? 1.0 : 0.707;
        sum_x += w * x;
        sum_y += w * y;
        divisor += w;
      }
      if (divisor > 0.5)
        sum_x /= divisor, sum_y /= divisor;
      texel[0] = std::min(1.0, std::max(0.0, sum_x));
      texel[1] = std::min(1.0, std::max(0.0, sum_y));
    }
  return filled;
}

void lens::cropScale(const CameraDistortion& d, bool crop, double& sx, double& sy)
{
  sx = sy = 1.0;
  if (!crop || !(d.k1 < 0))
    return;
  double ax, ay, bx, by;
  distortPoint(d, 1.0, 0.0, 0.0, ax, ay);  // the legacy form: no focal length
  distortPoint(d, 1.0, 1.0, 1.0, bx, by);
  if (bx - ax < 1e-7 || by - ay < 1e-7 || !std::isfinite(bx - ax) || !std::isfinite(by - ay))
    return;  // Gazebo refuses so small a scale and does not crop
  sx = bx - ax;
  sy = by - ay;
}

namespace
{
// Bilinear taps of the point (x, y) in pixel coordinates (centres at integers) of a width x height
// image, clamped at its edges.
void bilinearTaps(double x, double y, int width, int height, uint32_t* taps, float* weights)
{
  x = std::min(double(width - 1), std::max(0.0, x));
  y = std::min(double(height - 1), std::max(0.0, y));
  const int x0 = std::min(int(x), width - 1), y0 = std::min(int(y), height - 1);
  const int x1 = std::min(x0 + 1, width - 1), y1 = std::min(y0 + 1, height - 1);
  const double fx = x - x0, fy = y - y0;
  taps[0] = uint32_t(y0 * width + x0);
  taps[1] = uint32_t(y0 * width + x1);
  taps[2] = uint32_t(y1 * width + x0);
  taps[3] = uint32_t(y1 * width + x1);
  weights[0] = float((1 - fx) * (1 - fy));
  weights[1] = float(fx * (1 - fy));
  weights[2] = float((1 - fx) * fy);
  weights[3] = float(fx * fy);
}
}  // namespace

DistortionRemap distortionRemap(const CameraDistortion& d, int width, int height, double hfov, bool crop)
{
  DistortionRemap remap;
  if (!distorts(d) || width <= 0 || height <= 0)
    return remap;
  int tex = 0;
  const std::vector<double> map = lens::distortionMap(d, width, height, hfov, tex);
  double scale_x, scale_y;
  lens::cropScale(d, crop, scale_x, scale_y);
  remap.width = width;
  remap.height = height;
  const size_t pixels = size_t(width) * height;
  remap.taps.resize(4 * pixels);
  remap.weights.resize(4 * pixels);
  for (int py = 0; py < height; ++py)
    for (int px = 0; px < width; ++px)
    {
      const size_t k = size_t(py) * width + px;
      // The shader's texture coordinate at the pixel's centre, zoomed about the middle to crop.
      const double u = ((px + 0.5) / width - 0.5) * scale_x + 0.5;
      const double v = ((py + 0.5) / height - 0.5) * scale_y + 0.5;
      // The map read bilinearly (texel centres at (i + 0.5) / tex), clamped at its edges.
      uint32_t map_taps[4];
      float map_weights[4];
      bilinearTaps(u * tex - 0.5, v * tex - 0.5, tex, tex, map_taps, map_weights);
      double mx = 0, my = 0;
      bool black = false;
      for (int t = 0; t < 4; ++t)
      {
        const double x = map[2 * map_taps[t]], y = map[2 * map_taps[t] + 1];
        black = black || (map_weights[t] > 0 && (x < 0 || y < 0));
        mx += map_weights[t] * x;
        my += map_weights[t] * y;
      }
      if (black)
      {
        for (int t = 0; t < 4; ++t)
          remap.taps[4 * k + t] = DistortionRemap::kBlack, remap.weights[4 * k + t] = 0;
        continue;
      }
      // The rendered frame at the undistorted point, bilinearly.
      bilinearTaps(mx * width - 0.5, my * height - 0.5, width, height, &remap.taps[4 * k], &remap.weights[4 * k]);
    }
  return remap;
}

namespace
{
template <class Value>
void remapValues(const DistortionRemap& remap, const Value* in, Value* out)
{
  constexpr float kMax = float(std::numeric_limits<Value>::max());
  const size_t pixels = size_t(remap.width) * remap.height;
  for (size_t k = 0; k < pixels; ++k, out += 3)
  {
    const uint32_t* taps = &remap.taps[4 * k];
    const float* w = &remap.weights[4 * k];
    if (taps[0] == DistortionRemap::kBlack)
    {
      out[0] = out[1] = out[2] = 0;
      continue;
    }
    for (int c = 0; c < 3; ++c)
    {
      const float value = w[0] * in[3 * taps[0] + c] + w[1] * in[3 * taps[1] + c] + w[2] * in[3 * taps[2] + c] +
                          w[3] * in[3 * taps[3] + c];
      out[c] = Value(std::min(kMax, value + 0.5f));
    }
  }
}
}  // namespace

void remapRgb(const DistortionRemap& remap, const uint8_t* in, uint8_t* out)
{
  remapValues(remap, in, out);
}

void remapRgb(const DistortionRemap& remap, const uint16_t* in, uint16_t* out)
{
  remapValues(remap, in, out);
}

}  // namespace bullet_plant
