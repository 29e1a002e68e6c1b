// Gazebo's ForceTorqueSensor, as a sensor plugin of the user's own meets it (here Gazebo's own
// libForceTorquePlugin.so): a <sensor type="force_torque"> in a <joint> is a
// sensors::ForceTorqueSensor in SensorManager, its parent the joint (MODEL::JOINT). A 2 kg load whose
// centre is 0.5 m out along x hangs on a hinge about z (gravity cannot turn it) under a base fixed to
// the world: with Gazebo's signs, the load passes its weight (0, 0, -19.6) N to the joint and its
// moment about the joint (0.5, 0, 0) x (0, 0, -19.6) = (0, 9.8, 0) N m, in the child's frame
// (frame child, measure_direction child_to_parent: the defaults); in the parent's frame measured
// parent to child both are negated; in a sensor frame yawed a quarter turn the moment is along its x.
// Each measurement at the sensor's <update_rate> is a msgs::WrenchStamped on ~/MODEL/JOINT/SENSOR/wrench
// and a call of ConnectUpdate's subscribers. The same sensor under a URDF's
// <gazebo reference="JOINT"> is the joint's too.
#include <gtest/gtest.h>

#include <atomic>
#include <mutex>
#include <string>
#include <vector>

#include <gazebo/physics/Joint.hh>
#include <gazebo/physics/Link.hh>
#include <gazebo/sensors/sensors.hh>
#include <gazebo/transport/transport.hh>

#include "bullet_plant/world.h"

using namespace bullet_plant;

namespace
{
const char* const kWorld = R"(<sdf version='1.7'><world name='ft_world'>
  <physics type='ode'><max_step_size>0.001</max_step_size></physics>
  <model name='arm'>
    <link name='base'><pose>0 0 1 0 0 0</pose>
      <inertial><mass>5</mass><inertia><ixx>0.1</ixx><iyy>0.1</iyy><izz>0.1</izz></inertia></inertial>
    </link>
    <joint name='mount' type='fixed'><parent>world</parent><child>base</child></joint>
    <link name='load'><pose>0 0 0.8 0 0 0</pose>
      <inertial><pose>0.5 0 0 0 0 0</pose><mass>2</mass>
        <inertia><ixx>0.01</ixx><iyy>0.01</iyy><izz>0.01</izz></inertia></inertial>
    </link>
    <joint name='hinge' type='revolute'><parent>base</parent><child>load</child>
      <axis><xyz>0 0 1</xyz></axis>
      <sensor name='ft_child' type='force_torque'><always_on>1</always_on><update_rate>100</update_rate>
        <plugin name='ft' filename='libForceTorquePlugin.so'/></sensor>
      <sensor name='ft_parent' type='force_torque'><always_on>1</always_on>
        <force_torque><frame>parent</frame><measure_direction>parent_to_child</measure_direction></force_torque>
        <plugin name='ft' filename='libForceTorquePlugin.so'/></sensor>
      <sensor name='ft_sensor' type='force_torque'><always_on>1</always_on><pose>0 0 0 0 0 1.5707963267948966</pose>
        <force_torque><frame>sensor</frame></force_torque>
        <plugin name='ft' filename='libForceTorquePlugin.so'/></sensor>
    </joint>
  </model>
  <model name='offset_arm'><pose>3 0 0 0 0 0</pose>
    <link name='base'><pose>0 0 1 0 0 0</pose>
      <inertial><mass>5</mass><inertia><ixx>0.1</ixx><iyy>0.1</iyy><izz>0.1</izz></inertia></inertial>
    </link>
    <joint name='mount' type='fixed'><parent>world</parent><child>base</child></joint>
    <link name='load'><pose>0 0 0.8 0 0 0</pose>
      <inertial><pose>1 0 0 0 0 0</pose><mass>2</mass>
        <inertia><ixx>0.01</ixx><iyy>0.01</iyy><izz>0.01</izz></inertia></inertial>
    </link>
    <joint name='hinge' type='revolute'><parent>base</parent><child>load</child>
      <pose>0.5 0 0 0 0 1.5707963267948966</pose><axis><xyz>0 0 1</xyz></axis>
      <sensor name='ft_offset_child' type='force_torque'><always_on>1</always_on>
        <plugin name='ft' filename='libForceTorquePlugin.so'/></sensor>
      <sensor name='ft_offset_sensor' type='force_torque'><always_on>1</always_on>
        <force_torque><frame>sensor</frame></force_torque>
        <plugin name='ft' filename='libForceTorquePlugin.so'/></sensor>
    </joint>
  </model>
</world></sdf>)";

std::shared_ptr<gazebo::sensors::ForceTorqueSensor> forceTorque(const std::string& name)
{
  return std::dynamic_pointer_cast<gazebo::sensors::ForceTorqueSensor>(
      gazebo::sensors::SensorManager::Instance()->GetSensor(name));
}

void expectNear(const ignition::math::Vector3d& measured, const ignition::math::Vector3d& expected, double tolerance,
                const std::string& what)
{
  EXPECT_NEAR(measured.X(), expected.X(), tolerance) << what << ": " << measured;
  EXPECT_NEAR(measured.Y(), expected.Y(), tolerance) << what << ": " << measured;
  EXPECT_NEAR(measured.Z(), expected.Z(), tolerance) << what << ": " << measured;
}
}  // namespace

TEST(GazeboForceTorqueSensor, MeasuresItsJointsWrenchInTheFrameAndDirectionItNames)
{
  World world(parseWorldDescription(kWorld));
  auto child = forceTorque("ft_child"), parent = forceTorque("ft_parent"), sensor = forceTorque("ft_sensor");
  ASSERT_TRUE(child && parent && sensor);
  EXPECT_EQ(child->ParentName(), "arm::hinge");
  EXPECT_EQ(child->ScopedName(), "ft_world::arm::hinge::ft_child");
  EXPECT_EQ(child->Type(), "force_torque");
  EXPECT_EQ(child->Category(), gazebo::sensors::OTHER);
  EXPECT_EQ(child->Topic(), "~/arm/hinge/ft_child/wrench");
  ASSERT_TRUE(child->Joint());
  EXPECT_EQ(child->Joint()->GetName(), "hinge");
  EXPECT_EQ(child->Joint()->InitialAnchorPose(), ignition::math::Pose3d::Zero) << "the joint at its child's origin";

  std::mutex mutex;
  std::vector<gazebo::msgs::WrenchStamped> published, delivered;
  gazebo::event::ConnectionPtr on_update =
      child->ConnectUpdate([&](gazebo::msgs::WrenchStamped message) {
        std::lock_guard<std::mutex> lock(mutex);
        delivered.push_back(message);
      });
  gazebo::transport::NodePtr node(new gazebo::transport::Node());
  node->Init("ft_world");
  const boost::function<void(ConstWrenchStampedPtr&)> keep = [&](ConstWrenchStampedPtr& message) {
    std::lock_guard<std::mutex> lock(mutex);
    published.push_back(*message);
  };
  gazebo::transport::SubscriberPtr subscriber = node->Subscribe(child->Topic(), keep);
  world.step(500);
  gazebo::transport::TopicManager::Instance()->WaitForAll();

  const double weight = 2 * 9.8, moment = 0.5 * weight;
  expectNear(child->Force(), {0, 0, -weight}, 0.02, "child frame, child to parent: the load's weight");
  expectNear(child->Torque(), {0, moment, 0}, 0.02, "child frame: the weight's moment about the joint");
  expectNear(parent->Force(), {0, 0, weight}, 0.02, "parent frame, parent to child: the joint holds it up");
  expectNear(parent->Torque(), {0, -moment, 0}, 0.02, "parent frame, parent to child");
  expectNear(sensor->Force(), {0, 0, -weight}, 0.02, "a frame yawed about z keeps z");
  expectNear(sensor->Torque(), {moment, 0, 0}, 0.02, "the child's y is the yawed sensor's x");

  std::lock_guard<std::mutex> lock(mutex);
  EXPECT_NEAR(double(delivered.size()), 50.0, 1.0) << "100 Hz for 0.5 s";
  EXPECT_EQ(published.size(), delivered.size());
  ASSERT_FALSE(published.empty());
  EXPECT_DOUBLE_EQ(published.back().wrench().force().z(), child->Force().Z());
  EXPECT_NEAR(published.back().time().sec() + published.back().time().nsec() * 1e-9, 0.5, 0.0105);
}

// The joint's frame apart from its child's: 0.5 m out along x, yawed a quarter turn. The torque is
// about the joint's origin (the load's centre, 1 m out, is 0.5 m from it) in the child link's axes;
// a sensor at the joint's frame (frame sensor, no pose of its own) has it along its x.
TEST(GazeboForceTorqueSensor, AJointFrameApartFromItsChildsMovesTheTorquesOriginNotItsAxes)
{
  World world(parseWorldDescription(kWorld));
  auto child = forceTorque("ft_offset_child"), sensor = forceTorque("ft_offset_sensor");
  ASSERT_TRUE(child && sensor && child->Joint());
  EXPECT_EQ(child->Joint()->GetChild() ? child->Joint()->GetChild()->GetName() : "", "load");
  const ignition::math::Pose3d anchor = child->Joint()->InitialAnchorPose();
  EXPECT_NEAR(anchor.Pos().X(), 0.5, 1e-9);
  EXPECT_NEAR(anchor.Rot().Yaw(), 1.5707963267948966, 1e-9);
  world.step(300);
  const double weight = 2 * 9.8, moment = 0.5 * weight;
  expectNear(child->Force(), {0, 0, -weight}, 0.02, "child frame");
  expectNear(child->Torque(), {0, moment, 0}, 0.02, "about the joint, in the child's axes");
  expectNear(sensor->Torque(), {moment, 0, 0}, 0.02, "the joint frame's axes");
}

TEST(GazeboForceTorqueSensor, ASensorInAUrdfJointsGazeboBlockIsThatJoints)
{
  const std::string urdf = R"(<robot name='lift'>
  <link name='world'/>
  <joint name='mount' type='fixed'><parent link='world'/><child link='base'/><origin xyz='0 0 1'/></joint>
  <link name='base'><inertial><mass value='5'/><inertia ixx='0.1' iyy='0.1' izz='0.1' ixy='0' ixz='0' iyz='0'/></inertial></link>
  <joint name='slide' type='prismatic'><parent link='base'/><child link='carriage'/><axis xyz='1 0 0'/>
    <limit lower='-1' upper='1' effort='100' velocity='1'/></joint>
  <link name='carriage'><inertial><mass value='3'/><inertia ixx='0.01' iyy='0.01' izz='0.01' ixy='0' ixz='0' iyz='0'/></inertial></link>
  <gazebo reference='slide'>
    <sensor name='ft' type='force_torque'><always_on>true</always_on>
      <plugin name='ft' filename='libForceTorquePlugin.so'/></sensor>
  </gazebo>
</robot>)";
  World world;
  world.spawn(urdf, "lift", urdf::Pose());
  auto ft = forceTorque("ft");
  ASSERT_TRUE(ft);
  EXPECT_EQ(ft->ParentName(), "lift::slide");
  world.step(200);
  expectNear(ft->Force(), {0, 0, -3 * 9.8}, 0.02, "the carriage's weight");
}
