// Gazebo's MultiCameraSensor over the plant's cameras, as a sensor plugin of the user's own meets it
// (gazebo_ros_pkgs' MultiCameraPlugin, gazebo_ros_multicamera): a <sensor type="multicamera"> of two
// <camera>s whose <plugin> file is found (the tests' own libtest_activate_sensor.so, which sets it
// active: Gazebo ships no multicamera plugin library): a rendering::Camera for each, named by its
// element, with its own size and format and its pose; each 10 Hz moment's frames to each camera's
// subscribers, and one msgs::ImagesStamped of both on ~/probe/base/stereo/images while subscribed.
// Then the render events: a camera that a PreRender callback activates for one frame at a time, as
// gazebo_ros_triggered_camera does, gives one frame for each activation.
#include <gtest/gtest.h>

#include <cfloat>
#include <cstdlib>
#include <mutex>
#include <string>
#include <vector>

#include <gazebo/common/Events.hh>
#include <gazebo/rendering/rendering.hh>
#include <gazebo/sensors/sensors.hh>
#include <gazebo/transport/transport.hh>

#include "bullet_plant/world.h"

using namespace bullet_plant;

namespace
{
// A red post 2 m ahead of the probe's link, which stands 0.5 m up.
const char* const kPost =
    "<model name='post'><static>true</static><pose>2 0 0.5 0 0 0</pose><link name='l'>"
    "<visual name='v'><geometry><box><size>0.1 0.6 1</size></box></geometry>"
    "<material><ambient>1 0 0 1</ambient><diffuse>1 0 0 1</diffuse></material></visual></link></model>";

std::string world(const std::string& sensor)
{
  return std::string(R"(<sdf version='1.7'><world name='multicamera_world'>
  <physics type='ode'><max_step_size>0.001</max_step_size></physics>
  <include><uri>model://ground_plane</uri></include>)") +
         kPost + R"(
  <model name='probe'><static>true</static><pose>0 0 0.5 0 0 0</pose><link name='base'>)" +
         sensor + R"(</link></model>
</world></sdf>)";
}

const char* const kStereo = R"(<sensor type='multicamera' name='stereo'><update_rate>10</update_rate>
      <pose>0 0 0.1 0 0 0</pose>
      <camera name='left'><pose>0 0.05 0 0 0 0</pose><horizontal_fov>1.0</horizontal_fov>
        <image><width>16</width><height>12</height><format>L8</format></image></camera>
      <camera name='right'><pose>0 -0.05 0 0 0 0</pose><horizontal_fov>1.0</horizontal_fov>
        <image><width>8</width><height>6</height><format>R8G8B8</format></image></camera>
      <plugin name='activate' filename='libtest_activate_sensor.so'/>
    </sensor>)";

class GazeboMultiCameraSensor : public testing::Test
{
protected:
  void SetUp() override
  {
    const char* path = std::getenv("GAZEBO_PLUGIN_PATH");
    setenv("GAZEBO_PLUGIN_PATH", (std::string(TEST_PLUGIN_DIR) + ":" + (path ? path : "")).c_str(), 1);
  }
};

std::shared_ptr<gazebo::sensors::MultiCameraSensor> stereo()
{
  return std::dynamic_pointer_cast<gazebo::sensors::MultiCameraSensor>(
      gazebo::sensors::SensorManager::Instance()->GetSensor("stereo"));
}
}  // namespace

TEST_F(GazeboMultiCameraSensor, HasACameraForEachCameraElement)
{
  World plant(parseWorldDescription(world(kStereo)));
  std::shared_ptr<gazebo::sensors::MultiCameraSensor> sensor = stereo();
  ASSERT_TRUE(sensor) << "a MultiCameraSensor named stereo in SensorManager";
  EXPECT_EQ(sensor->Category(), gazebo::sensors::IMAGE);
  EXPECT_TRUE(sensor->IsActive()) << "its plugin set it active";
  EXPECT_EQ(sensor->Topic(), "~/probe/base/stereo/images");
  ASSERT_EQ(sensor->CameraCount(), 2u);
  EXPECT_FALSE(sensor->Camera(2)) << "past the last: null, with Gazebo's error";
  gazebo::rendering::CameraPtr left = sensor->Camera(0), right = sensor->Camera(1);
  EXPECT_EQ(left->Name(), "left");
  EXPECT_EQ(right->Name(), "right");
  EXPECT_EQ(sensor->ImageWidth(0), 16u);
  EXPECT_EQ(sensor->ImageHeight(0), 12u);
  EXPECT_EQ(sensor->ImageWidth(1), 8u);
  EXPECT_EQ(sensor->ImageHeight(1), 6u);
  EXPECT_EQ(left->ImageFormat(), "L8");
  EXPECT_EQ(right->ImageDepth(), 3u);
  EXPECT_DOUBLE_EQ(left->HFOV().Radian(), 1.0);
  // link 0.5 up, the sensor 0.1 above it, each camera 5 cm to its side
  EXPECT_EQ(left->WorldPose().Pos(), ignition::math::Vector3d(0, 0.05, 0.6));
  EXPECT_EQ(right->WorldPose().Pos(), ignition::math::Vector3d(0, -0.05, 0.6));
  EXPECT_EQ(sensor->ImageData(0), nullptr) << "before the first frame";
}

TEST_F(GazeboMultiCameraSensor, HandsEachMomentsFramesToEachCameraAndPublishesThemTogether)
{
  World plant(parseWorldDescription(world(kStereo)));
  std::shared_ptr<gazebo::sensors::MultiCameraSensor> sensor = stereo();
  ASSERT_TRUE(sensor);
  std::mutex mutex;
  std::vector<int> frames(2, 0);
  std::vector<std::string> formats(2);
  std::vector<std::vector<unsigned char>> latest(2);
  std::vector<gazebo::event::ConnectionPtr> connections;
  for (unsigned int i = 0; i < 2; ++i)
    connections.push_back(sensor->Camera(i)->ConnectNewImageFrame(
        [&, i](const unsigned char* image, unsigned int w, unsigned int h, unsigned int d, const std::string& f) {
          std::lock_guard<std::mutex> lock(mutex);
          ++frames[i];
          formats[i] = f;
          latest[i].assign(image, image + w * h * d);
        }));
  std::vector<gazebo::msgs::ImagesStamped> received;
  gazebo::transport::NodePtr node(new gazebo::transport::Node());
  node->Init("multicamera_world");
  const boost::function<void(ConstImagesStampedPtr&)> keep = [&](ConstImagesStampedPtr& message) {
    std::lock_guard<std::mutex> lock(mutex);
    received.push_back(*message);
  };
  gazebo::transport::SubscriberPtr subscriber = node->Subscribe(sensor->Topic(), keep);
  // One step a call: each call returns with its frames done, so the sensor hands each moment's
  // frames over at the next step whatever the machine's load (with step(1000) a frame came when the
  // render thread finished it, and the count moved with the load).
  for (int i = 0; i < 1000; ++i)
    plant.step(1);
  gazebo::transport::TopicManager::Instance()->WaitForAll();
  std::lock_guard<std::mutex> lock(mutex);
  // 10 Hz over 1 s: ten moments, both cameras at each
  EXPECT_EQ(frames[0], 10);
  EXPECT_EQ(frames[1], frames[0]);
  EXPECT_EQ(formats[0], "L8");
  EXPECT_EQ(formats[1], "R8G8B8");
  ASSERT_EQ(latest[0].size(), 16u * 12);
  // the red post, straight ahead, in both: L8 is the red channel
  EXPECT_GT(latest[0][6 * 16 + 8], 100);
  const unsigned char* centre = &latest[1][3 * (3 * 8 + 4)];
  EXPECT_GT(centre[0], 100);
  EXPECT_LT(centre[1], 60);
  ASSERT_EQ(received.size(), size_t(frames[0]));
  const gazebo::msgs::ImagesStamped& message = received.back();
  ASSERT_EQ(message.image_size(), 2);
  EXPECT_EQ(message.image(0).width(), 16u);
  EXPECT_EQ(message.image(0).pixel_format(), 1u) << "common::Image::L_INT8";
  EXPECT_EQ(message.image(1).step(), 8u * 3);
  EXPECT_EQ(message.image(1).data().size(), 8u * 6 * 3);
  EXPECT_EQ(gazebo::msgs::Convert(message.time()), sensor->LastMeasurementTime());
  EXPECT_EQ(std::string(message.image(0).data()), std::string(latest[0].begin(), latest[0].end()));
}

// gazebo_ros_triggered_camera's way: the camera inactive at a rate of DBL_MIN ("never"); a trigger
// activates it at rate 0 in the next PreRender, and each frame deactivates it. Three triggers, one of
// them while a frame is being made for another, give three frames, and none comes untriggered.
TEST_F(GazeboMultiCameraSensor, ACameraActivatedInPreRenderGivesOneFrameForEachActivation)
{
  World plant(parseWorldDescription(world(R"(<sensor type='camera' name='eye'><update_rate>1</update_rate>
      <camera><horizontal_fov>1.0</horizontal_fov><image><width>8</width><height>6</height></image></camera>
      <plugin name='frames' filename='libCameraPlugin.so'/></sensor>)")));
  auto sensor = std::dynamic_pointer_cast<gazebo::sensors::CameraSensor>(
      gazebo::sensors::SensorManager::Instance()->GetSensor("eye"));
  ASSERT_TRUE(sensor);
  std::mutex mutex;
  int triggered = 0, frames = 0, pre_renders = 0;
  auto enable = [&](bool on) {
    sensor->SetActive(on);
    sensor->SetUpdateRate(on ? 0.0 : DBL_MIN);
  };
  enable(false);
  gazebo::event::ConnectionPtr pre_render = gazebo::event::Events::ConnectPreRender([&] {
    std::lock_guard<std::mutex> lock(mutex);
    ++pre_renders;
    if (triggered > 0)
      enable(true);
  });
  gazebo::event::ConnectionPtr on_frame = sensor->Camera()->ConnectNewImageFrame(
      [&](const unsigned char*, unsigned int, unsigned int, unsigned int, const std::string&) {
        std::lock_guard<std::mutex> lock(mutex);
        ++frames;
        enable(false);
        triggered = std::max(triggered - 1, 0);
      });
  // one step at a time, each step's frames collected at its end (as a node steps in lockstep)
  auto step = [&](int steps) {
    for (int i = 0; i < steps; ++i)
      plant.step(1);
  };
  step(300);
  int untriggered = 0;
  {
    std::lock_guard<std::mutex> lock(mutex);
    EXPECT_EQ(pre_renders, 300) << "once a step, in a world with a camera";
    // CameraPlugin::Load activated it, so the plant rendered at the first step, before the test
    // deactivated it; none after
    EXPECT_LE(frames, 1);
    untriggered = frames;
  }
  step(300);
  {
    std::lock_guard<std::mutex> lock(mutex);
    EXPECT_EQ(frames, untriggered) << "never triggered";
    triggered = 1;
  }
  step(300);
  {
    std::lock_guard<std::mutex> lock(mutex);
    EXPECT_EQ(frames, untriggered + 1);
    triggered = 2;
  }
  step(300);
  std::lock_guard<std::mutex> lock(mutex);
  EXPECT_EQ(frames, untriggered + 3);
  EXPECT_EQ(triggered, 0);
}
