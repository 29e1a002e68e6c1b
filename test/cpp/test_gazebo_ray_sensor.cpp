// Gazebo's RaySensor over the plant's lidar, as a sensor plugin of the user's own meets it: a
// <sensor type="ray"> whose <plugin> file is found (here Gazebo's own libRayPlugin.so) is a
// sensors::RaySensor in SensorManager, named in its link as Gazebo names it; its <ray> element's
// counts, angles and ranges; each scan the plant makes is its laser shape's ranges and a
// LaserScanStamped on ~/MODEL/LINK/SENSOR/scan (only while subscribed, which keeps it measuring);
// the model's removal takes it out of SensorManager. A wall's face stands 1.4 m before the lidar,
// which rests on the ground (its visual too: a gpu_ray lidar sees visuals, as Gazebo's renders them).
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <mutex>
#include <string>
#include <vector>

#include <gazebo/sensors/sensors.hh>
#include <gazebo/transport/transport.hh>

#include "bullet_plant/robot.h"
#include "bullet_plant/world.h"

using namespace bullet_plant;

namespace
{
const char* const kWorld = R"(<sdf version='1.7'><world name='ray_world'>
  <physics type='ode'><max_step_size>0.001</max_step_size></physics>
  <include><uri>model://ground_plane</uri></include>
  <model name='wall'><static>true</static><pose>1.6 0 0.5 0 0 0</pose>
    <link name='body'><collision name='c'><geometry><box><size>0.2 3 1</size></box></geometry></collision>
      <visual name='v'><geometry><box><size>0.2 3 1</size></box></geometry></visual></link></model>
  <model name='probe'><pose>0 0 0.1 0 0 0</pose><link name='base'>
    <inertial><mass>2</mass><inertia><ixx>0.01</ixx><iyy>0.01</iyy><izz>0.01</izz></inertia></inertial>
    <collision name='c'><geometry><box><size>0.2 0.2 0.2</size></box></geometry></collision>
    <sensor type='ray' name='lidar'><pose>0.1 0 0.05 0 0 0</pose><update_rate>10</update_rate>
      <ray><scan><horizontal><samples>5</samples><min_angle>-0.3</min_angle><max_angle>0.3</max_angle></horizontal>
        </scan><range><min>0.1</min><max>5</max><resolution>0.01</resolution></range></ray>
      <plugin name='rays' filename='libRayPlugin.so'/>
    </sensor>
  </link></model>
</world></sdf>)";

std::shared_ptr<gazebo::sensors::RaySensor> lidar()
{
  return std::dynamic_pointer_cast<gazebo::sensors::RaySensor>(
      gazebo::sensors::SensorManager::Instance()->GetSensor("lidar"));
}
}  // namespace

TEST(GazeboRaySensor, IsThePlantsLidarNamedAsGazebosWithItsRayElement)
{
  World world(parseWorldDescription(kWorld));
  std::shared_ptr<gazebo::sensors::RaySensor> ray = lidar();
  ASSERT_TRUE(ray);
  EXPECT_EQ(ray->ScopedName(), "ray_world::probe::base::lidar");
  EXPECT_EQ(gazebo::sensors::get_sensor("ray_world::probe::base::lidar"), ray);
  EXPECT_EQ(ray->ParentName(), "probe::base");
  EXPECT_EQ(ray->Topic(), "~/probe/base/lidar/scan");
  EXPECT_EQ(ray->Type(), "ray");
  EXPECT_EQ(ray->RayCount(), 5);
  EXPECT_EQ(ray->RangeCount(), 5);
  EXPECT_EQ(ray->VerticalRayCount(), 1);
  EXPECT_DOUBLE_EQ(ray->AngleMin().Radian(), -0.3);
  EXPECT_DOUBLE_EQ(ray->AngleMax().Radian(), 0.3);
  EXPECT_DOUBLE_EQ(ray->AngleResolution(), 0.15);
  EXPECT_DOUBLE_EQ(ray->RangeMin(), 0.1);
  EXPECT_DOUBLE_EQ(ray->RangeMax(), 5.0);
  EXPECT_DOUBLE_EQ(ray->RangeResolution(), 0.01);
  EXPECT_DOUBLE_EQ(ray->UpdateRate(), 10.0);
  EXPECT_FALSE(ray->IsActive()) << "not always_on, nobody subscribed";
  EXPECT_DOUBLE_EQ(ray->Pose().Pos().X(), 0.1);
}

TEST(GazeboRaySensor, ScansWhileItsTopicIsSubscribedAndPublishesEachOnce)
{
  World world(parseWorldDescription(kWorld));
  std::shared_ptr<gazebo::sensors::RaySensor> ray = lidar();
  ASSERT_TRUE(ray);
  std::atomic<int> shape_scans{0};
  gazebo::event::ConnectionPtr on_scans = ray->LaserShape()->ConnectNewLaserScans([&] { ++shape_scans; });
  world.step(500);  // nobody subscribed: nothing measured
  EXPECT_EQ(shape_scans, 0);

  std::mutex mutex;
  std::vector<gazebo::msgs::LaserScanStamped> received;
  gazebo::transport::NodePtr node(new gazebo::transport::Node());
  node->Init("ray_world");
  const boost::function<void(ConstLaserScanStampedPtr&)> keep = [&](ConstLaserScanStampedPtr& scan) {
    std::lock_guard<std::mutex> lock(mutex);
    received.push_back(*scan);
  };
  gazebo::transport::SubscriberPtr subscriber = node->Subscribe(ray->Topic(), keep);
  EXPECT_TRUE(ray->IsActive()) << "Gazebo's rule: active while its topic has a subscriber";
  world.step(1000);  // 1 s at 10 Hz
  gazebo::transport::TopicManager::Instance()->WaitForAll();
  std::lock_guard<std::mutex> lock(mutex);
  EXPECT_NEAR(shape_scans, 10, 1);
  ASSERT_EQ(static_cast<int>(received.size()), shape_scans.load()) << "each scan once";
  const gazebo::msgs::LaserScanStamped& last = received.back();
  EXPECT_EQ(last.scan().frame(), "probe::base");
  EXPECT_EQ(last.scan().count(), 5u);
  EXPECT_DOUBLE_EQ(last.scan().angle_step(), 0.15);
  ASSERT_EQ(last.scan().ranges_size(), 5);
  ASSERT_EQ(last.scan().intensities_size(), 5);
  // the middle ray meets the wall's face 1.4 m ahead; the outer ones at 1.4 / cos(0.3)
  EXPECT_NEAR(last.scan().ranges(2), 1.4, 5e-3);
  EXPECT_NEAR(last.scan().ranges(0), 1.4 / std::cos(0.3), 5e-3);
  EXPECT_NEAR(ray->Range(2), last.scan().ranges(2), 1e-12);
  EXPECT_NEAR(ray->LaserShape()->GetRange(2), last.scan().ranges(2), 1e-6);
  EXPECT_NEAR(last.scan().world_pose().position().x(), 0.1, 1e-3);
  EXPECT_NEAR(last.scan().world_pose().position().z(), 0.15, 2e-3);
  // stamped with the simulated time of its measurement, 0.1 s apart (from the step after the
  // subscription was seen: the period runs from the sensor's first scan, as Gazebo's)
  const double stamp = last.time().sec() + last.time().nsec() * 1e-9;
  EXPECT_NEAR(ray->LastMeasurementTime().Double(), stamp, 1e-9);
  EXPECT_GT(received.front().time().sec() + received.front().time().nsec() * 1e-9, 0.5);
  for (int i = 1; i < static_cast<int>(received.size()); ++i)
  {
    const double before = received[i - 1].time().sec() + received[i - 1].time().nsec() * 1e-9;
    const double now = received[i].time().sec() + received[i].time().nsec() * 1e-9;
    EXPECT_NEAR(now - before, 0.1, 1e-9);
  }
}

TEST(GazeboRaySensor, NothingWithinRangeIsInfinityAndTheShapesMaximum)
{
  World world(parseWorldDescription(std::string(kWorld).replace(std::string(kWorld).find("1.6 0 0.5"), 9, "9.6 0 0.5")));
  std::shared_ptr<gazebo::sensors::RaySensor> ray = lidar();
  ASSERT_TRUE(ray);
  ray->SetActive(true);
  world.step(200);
  std::vector<double> ranges;
  ray->Ranges(ranges);
  ASSERT_EQ(ranges.size(), 5u);
  for (double range : ranges)
    EXPECT_TRUE(std::isinf(range) && range > 0) << range;
  EXPECT_DOUBLE_EQ(ray->LaserShape()->GetRange(0), 5.0);
  EXPECT_DOUBLE_EQ(ray->LaserShape()->GetRetro(0), 0.0);
  EXPECT_EQ(ray->LaserShape()->GetFiducial(0), -1);
}

TEST(GazeboRaySensor, LeavesSensorManagerWithItsModel)
{
  World world(parseWorldDescription(kWorld));
  ASSERT_TRUE(lidar());
  EXPECT_TRUE(world.remove("probe"));
  EXPECT_FALSE(gazebo::sensors::SensorManager::Instance()->GetSensor("ray_world::probe::base::lidar"));
  world.step(10);
}

// The same lidar as type gpu_ray, with Gazebo's own libGpuRayPlugin.so: a GpuRaySensor (no
// RaySensor), active once its plugin loaded (GpuRayPlugin sets it), each scan a laser frame of 3
// floats a ray and the same message; the camera geometry as Gazebo's Init derives it.
TEST(GazeboGpuRaySensor, IsThePlantsLidarWithGazebosLaserFrames)
{
  std::string world_text(kWorld);
  world_text.replace(world_text.find("type='ray'"), 10, "type='gpu_ray'");
  world_text.replace(world_text.find("libRayPlugin.so"), 15, "libGpuRayPlugin.so");
  World world(parseWorldDescription(world_text));
  gazebo::sensors::SensorPtr sensor = gazebo::sensors::SensorManager::Instance()->GetSensor("lidar");
  auto gpu = std::dynamic_pointer_cast<gazebo::sensors::GpuRaySensor>(sensor);
  ASSERT_TRUE(gpu);
  EXPECT_FALSE(std::dynamic_pointer_cast<gazebo::sensors::RaySensor>(sensor)) << "Gazebo's two are apart";
  EXPECT_EQ(gpu->Category(), gazebo::sensors::IMAGE);
  EXPECT_EQ(gpu->Topic(), "~/probe/base/lidar/scan");
  EXPECT_TRUE(gpu->IsActive()) << "GpuRayPlugin::Load sets its sensor active";
  EXPECT_EQ(gpu->CameraCount(), 1u);
  EXPECT_DOUBLE_EQ(gpu->HorzFOV(), 0.6);
  EXPECT_DOUBLE_EQ(gpu->HorzHalfAngle(), 0.0);
  EXPECT_DOUBLE_EQ(gpu->RayCountRatio(), 2048.0) << "one vertical ray: the camera's width";
  EXPECT_DOUBLE_EQ(gpu->Retro(0), 0.0);
  EXPECT_EQ(gpu->Fiducial(0), -1);

  std::mutex mutex;
  std::vector<std::vector<float>> frames;
  unsigned int width = 0, height = 0, depth = 0;
  gazebo::event::ConnectionPtr on_frame = gpu->ConnectNewLaserFrame(
      [&](const float* image, unsigned int w, unsigned int h, unsigned int d, const std::string&) {
        std::lock_guard<std::mutex> lock(mutex);
        width = w, height = h, depth = d;
        frames.emplace_back(image, image + w * h * d);
      });
  world.step(1000);
  std::lock_guard<std::mutex> lock(mutex);
  EXPECT_NEAR(static_cast<int>(frames.size()), 10, 1);
  ASSERT_FALSE(frames.empty());
  EXPECT_EQ(width, 5u);
  EXPECT_EQ(height, 1u);
  EXPECT_EQ(depth, 3u);
  EXPECT_NEAR(frames.back()[2 * 3], 1.4, 5e-3) << "the middle ray's range";
  EXPECT_EQ(frames.back()[2 * 3 + 1], 0.0f) << "its intensity";
  EXPECT_NEAR(gpu->Range(2), 1.4, 5e-3);
  EXPECT_NEAR(gpu->Range(0), 1.4 / std::cos(0.3), 5e-3);
}

// Its <ray><noise> is Gazebo's model for a plugin to read (Sensor::Noise(RAY_NOISE)); the plant's
// lidar applies it (one simulation of the sensor).
TEST(GazeboRaySensor, ItsNoiseModelIsItsRayElementsNoise)
{
  std::string noisy = kWorld;
  const std::string range = "<range><min>0.1</min>";
  noisy.replace(noisy.find(range), 0, "<noise><type>gaussian</type><mean>0.0</mean><stddev>0.01</stddev></noise>");
  World world(parseWorldDescription(noisy));
  std::shared_ptr<gazebo::sensors::RaySensor> ray = lidar();
  ASSERT_TRUE(ray);
  auto noise = std::dynamic_pointer_cast<gazebo::sensors::GaussianNoiseModel>(ray->Noise(gazebo::sensors::RAY_NOISE));
  ASSERT_TRUE(noise);
  EXPECT_DOUBLE_EQ(noise->GetStdDev(), 0.01);
  EXPECT_DOUBLE_EQ(noise->GetMean(), 0.0);
}
