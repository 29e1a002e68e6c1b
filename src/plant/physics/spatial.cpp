#include "physics/spatial.h"

namespace bullet_plant
{
Frame Frame::fromPose(const urdf::Pose& p)
{
  Frame f;
  double x = p.rotation.x, y = p.rotation.y, z = p.rotation.z, w = p.rotation.w;
  double n = std::sqrt(x * x + y * y + z * z + w * w);
  if (n > 0)
  {
    x /= n; y /= n; z /= n; w /= n;
  }
  f.R[0] = 1 - 2 * (y * y + z * z); f.R[1] = 2 * (x * y - z * w);     f.R[2] = 2 * (x * z + y * w);
  f.R[3] = 2 * (x * y + z * w);     f.R[4] = 1 - 2 * (x * x + z * z); f.R[5] = 2 * (y * z - x * w);
  f.R[6] = 2 * (x * z - y * w);     f.R[7] = 2 * (y * z + x * w);     f.R[8] = 1 - 2 * (x * x + y * y);
  f.t[0] = p.position.x; f.t[1] = p.position.y; f.t[2] = p.position.z;
  return f;
}

Frame Frame::operator*(const Frame& b) const
{
  Frame out;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      out.R[3 * i + j] = R[3 * i] * b.R[j] + R[3 * i + 1] * b.R[3 + j] + R[3 * i + 2] * b.R[6 + j];
  apply(b.t, out.t);
  return out;
}

}  // namespace bullet_plant
