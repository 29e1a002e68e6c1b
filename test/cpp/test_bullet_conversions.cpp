// physics/bullet_conversions: urdf's vectors and poses to Bullet's and back, a rotation of zero
// length as the identity, any other normalised.
#include <gtest/gtest.h>

#include <cmath>

#include "physics/bullet_conversions.h"

using namespace bullet_plant;

TEST(BulletConversions, VectorsAndPosesGoThereAndBackUnchanged)
{
  const urdf::Vector3 v(1.5, -2.25, 3.125);
  const urdf::Vector3 back = fromBullet(toBullet(v));
  EXPECT_EQ(back.x, v.x);
  EXPECT_EQ(back.y, v.y);
  EXPECT_EQ(back.z, v.z);

  urdf::Pose pose;
  pose.position = urdf::Vector3(0.1, 0.2, 0.3);
  pose.rotation.setFromRPY(0.3, -0.2, 1.1);
  const urdf::Pose round = fromBullet(toBullet(pose));
  EXPECT_NEAR(round.position.x, 0.1, 1e-6);
  EXPECT_NEAR(round.position.z, 0.3, 1e-6);
  double roll, pitch, yaw;
  round.rotation.getRPY(roll, pitch, yaw);
  EXPECT_NEAR(roll, 0.3, 1e-6);
  EXPECT_NEAR(pitch, -0.2, 1e-6);
  EXPECT_NEAR(yaw, 1.1, 1e-6);
}

TEST(BulletConversions, ARotationOfZeroLengthIsTheIdentityAndAnyOtherIsNormalised)
{
  urdf::Pose zero;
  zero.rotation = urdf::Rotation(0, 0, 0, 0);
  const btTransform t = toBullet(zero);
  EXPECT_EQ(t.getRotation(), btQuaternion::getIdentity());

  urdf::Pose scaled;
  scaled.rotation = urdf::Rotation(0, 0, 2, 2);  // 90 degrees about z, length 2 * sqrt(2)
  const btQuaternion q = toBullet(scaled).getRotation();
  EXPECT_NEAR(q.length(), 1.0, 1e-6);
  EXPECT_NEAR(q.z(), std::sqrt(0.5), 1e-6);
  EXPECT_NEAR(q.w(), std::sqrt(0.5), 1e-6);
}
