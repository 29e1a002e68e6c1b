// robot_builder.cpp: meshes on a robot fixed in the world collide as their triangles, and a static
// robot (RobotDescription::is_static) keeps its base where it was spawned.
#include <gtest/gtest.h>

#include <string>

#include "log_capture.h"
#include "bullet_plant/world.h"
#include "simulation/internals.h"
#include "mesh_fixtures.h"
#include "simulation/robot_builder.h"

using namespace bullet_plant;

namespace
{
std::string oneLinkUrdf(const std::string& name, const std::string& geometry)
{
  return "<robot name='" + name + "'><link name='base'>"
         "<inertial><mass value='2'/><inertia ixx='0.01' iyy='0.01' izz='0.01' ixy='0' ixz='0' iyz='0'/></inertial>"
         "<collision><geometry>" + geometry + "</geometry></collision></link></robot>";
}
}  // namespace

TEST(BuildRobot, AStaticRobotStaysWhereItIsSpawnedWhileABoxLandsOnItsMesh)
{
  const std::string dir = mesh_fixtures::tempDir();
  const float lo[3] = {-0.5f, -0.5f, -0.1f}, hi[3] = {0.5f, 0.5f, 0.0f};
  const std::string slab_file = mesh_fixtures::binaryBoxStl(dir, "slab.stl", lo, hi);

  World world;
  Robot& box = world.spawn(oneLinkUrdf("box", "<box size='0.2 0.2 0.2'/>"), "box", poseFromXyzRpy(0, 0, 1.0, 0, 0, 0));
  // The slab is built beside World::spawn so that its description can say is_static.
  Robot::Internals slab;
  slab.world = internalsOf(box).world;
  slab.name = "slab";
  slab.description = parseRobotDescription(oneLinkUrdf("slab", "<mesh filename='" + slab_file + "'/>"));
  slab.description.is_static = true;
  buildRobot(slab, poseFromXyzRpy(0, 0, 0.5, 0, 0, 0), {});
  EXPECT_TRUE(slab.multibody.bullet->hasFixedBase());
  ASSERT_EQ(slab.multibody.bodies.size(), 1u);
  ASSERT_EQ(slab.multibody.bodies[0].child_shapes.size(), 1u);
  EXPECT_NE(dynamic_cast<btBvhTriangleMeshShape*>(slab.multibody.bodies[0].child_shapes[0].get()), nullptr)
      << "the mesh of a static robot collides as its triangles";

  world.step(1500);
  EXPECT_NEAR(slab.multibody.rootWorldTransform().getOrigin().z(), 0.5, 1e-9);
  EXPECT_NEAR(box.basePose().position.z, 0.5 + 0.1, 1e-3) << "rests on the slab's top at 0.5 m";
  removeRobot(slab);
}

TEST(BuildRobot, AWheelMeshOnAContinuousJointCollidesAsACylinderAboutItsAxle)
{
  const std::string dir = mesh_fixtures::tempDir();
  const std::string wheel = mesh_fixtures::wheelObj(dir, "wheel.obj", 0.05, 0.03, 24);
  const std::string inertial =
      "<inertial><mass value='0.2'/><inertia ixx='0.0002' iyy='0.0002' izz='0.0002' ixy='0' ixz='0' iyz='0'/></inertial>";
  // A wheel on an axle along y; the hub has no collision.
  const std::string urdf =
      "<robot name='unicycle'><link name='hub'>" + inertial + "</link>"
      "<link name='wheel'>" + inertial + "<collision><geometry><mesh filename='" + wheel + "'/></geometry></collision></link>"
      "<joint name='axle' type='continuous'><parent link='hub'/><child link='wheel'/><axis xyz='0 1 0'/></joint></robot>";
  World world;
  LogCapture info(world.log(), LogLevel::Info);
  const std::vector<std::string>& infos = info.messages;
  Robot& robot = world.spawn(urdf, "unicycle", poseFromXyzRpy(0, 0, 0.05, 0, 0, 0));
  Robot::Internals& r = internalsOf(robot);
  ASSERT_EQ(r.multibody.bodies.size(), 2u);
  auto* cylinder = dynamic_cast<btCylinderShape*>(r.multibody.bodies[1].shape);
  ASSERT_NE(cylinder, nullptr) << "the wheel's collider is the cylinder itself, aligned with its body";
  EXPECT_NEAR(cylinder->getRadius(), 0.05f, 1e-6);
  bool said = false;
  for (const std::string& m : infos)
    said = said || (m.find("'wheel'") != std::string::npos && m.find("cylinder") != std::string::npos &&
                    m.find("wheel.obj") != std::string::npos);
  EXPECT_TRUE(said) << "the log says what the wheel became";
}
