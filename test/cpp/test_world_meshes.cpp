// world.cpp's static mesh collisions: a box lands on a mesh floor and rests on it, rays see the
// floor, and a mesh that cannot be loaded is left out with a warning naming it.
#include <gtest/gtest.h>

#include <string>

#include "bullet_plant/world.h"
#include "mesh_fixtures.h"

using namespace bullet_plant;

namespace
{
StaticCollision meshCollision(const std::string& name, const std::string& file)
{
  StaticCollision c;
  c.name = name;
  c.shape.kind = Shape::Kind::Mesh;
  c.shape.mesh_uri = "model://scenery/" + name;
  c.shape.mesh_file = file;
  c.pose = poseFromXyzRpy(0, 0, 0.2, 0, 0, 0);
  return c;
}
}  // namespace

TEST(WorldMeshes, ABoxRestsOnAStaticMeshFloorThatRaysSee)
{
  const std::string dir = mesh_fixtures::tempDir();
  const float lo[3] = {-2, -2, -0.1f}, hi[3] = {2, 2, 0};
  WorldDescription description = emptyWorldDescription();
  description.collisions.clear();  // no ground plane: the mesh is the floor, its top at z = 0.2
  description.collisions.push_back(meshCollision("floor", mesh_fixtures::binaryBoxStl(dir, "floor.stl", lo, hi)));
  description.collisions.push_back(meshCollision("broken", mesh_fixtures::write(dir, "broken.stl", "not a mesh")));
  testing::internal::CaptureStderr();  // the world's log until a sink is set
  World world(description);
  const std::string built = testing::internal::GetCapturedStderr();
  EXPECT_NE(built.find("'broken'"), std::string::npos) << built;
  EXPECT_NE(built.find("model://scenery/broken"), std::string::npos) << built;
  EXPECT_NE(built.find("left out"), std::string::npos) << built;
  world.log().setSink([](LogLevel, const std::string&) {});

  const std::string box = "<robot name='box'><link name='box'><inertial><mass value='1'/>"
                          "<inertia ixx='0.01' iyy='0.01' izz='0.01' ixy='0' ixz='0' iyz='0'/></inertial>"
                          "<collision><geometry><box size='0.2 0.2 0.2'/></geometry></collision></link></robot>";
  Robot& robot = world.spawn(box, "box", poseFromXyzRpy(0.3, -0.4, 0.6, 0, 0, 0));
  world.step(1500);
  EXPECT_NEAR(robot.basePose().position.z, 0.2 + 0.1, 1e-3) << "rests on the mesh's top";
  EXPECT_NEAR(world.castRay(urdf::Vector3(1, 1, 1), urdf::Vector3(0, 0, -1), 5.0, nullptr), 0.8, 1e-6);
}
