// Gazebo's CameraSensor over the plant's OpenGL camera, as a sensor plugin of the user's own meets
// it: a <sensor type="camera"> whose <plugin> file is found (here Gazebo's own libCameraPlugin.so,
// which sets it active): its rendering::Camera with the <camera> element's size, format, field of
// view and lens distortion, each 10 Hz frame to ConnectNewImageFrame's subscribers in its format's
// bytes, and msgs::ImageStamped on ~/probe/base/eye/image while subscribed.
#include <gtest/gtest.h>

#include <atomic>
#include <mutex>
#include <string>
#include <vector>

#include <gazebo/rendering/rendering.hh>
#include <gazebo/sensors/sensors.hh>
#include <gazebo/transport/transport.hh>

#include "bullet_plant/world.h"

using namespace bullet_plant;

namespace
{
std::string world(const std::string& format, const std::string& lens)
{
  return R"(<sdf version='1.7'><world name='camera_world'>
  <physics type='ode'><max_step_size>0.001</max_step_size></physics>
  <include><uri>model://ground_plane</uri></include>
  <model name='probe'><static>true</static><pose>0 0 0.5 0 0 0</pose><link name='base'>
    <sensor type='camera' name='eye'><update_rate>10</update_rate>
      <camera><horizontal_fov>1.2</horizontal_fov><image><width>16</width><height>12</height><format>)" +
         format + R"(</format></image>)" + lens + R"(</camera>
      <plugin name='frames' filename='libCameraPlugin.so'/>
    </sensor>
  </link></model>
</world></sdf>)";
}

std::shared_ptr<gazebo::sensors::CameraSensor> eye()
{
  return std::dynamic_pointer_cast<gazebo::sensors::CameraSensor>(
      gazebo::sensors::SensorManager::Instance()->GetSensor("eye"));
}
}  // namespace

TEST(GazeboCameraSensor, HandsEachFrameToItsCameraInItsFormat)
{
  World plant(parseWorldDescription(world("L8", "")));
  std::shared_ptr<gazebo::sensors::CameraSensor> sensor = eye();
  ASSERT_TRUE(sensor);
  EXPECT_EQ(sensor->Category(), gazebo::sensors::IMAGE);
  EXPECT_TRUE(sensor->IsActive()) << "CameraPlugin::Load sets its sensor active";
  EXPECT_EQ(sensor->Topic(), "~/probe/base/eye/image");
  gazebo::rendering::CameraPtr camera = sensor->Camera();
  ASSERT_TRUE(camera);
  EXPECT_EQ(camera->Name(), "probe::base::eye");
  EXPECT_EQ(camera->ImageWidth(), 16u);
  EXPECT_EQ(camera->ImageHeight(), 12u);
  EXPECT_EQ(camera->ImageFormat(), "L8");
  EXPECT_EQ(camera->ImageDepth(), 1u);
  EXPECT_DOUBLE_EQ(camera->HFOV().Radian(), 1.2);
  EXPECT_FALSE(camera->LensDistortion()) << "no <distortion>";
  EXPECT_EQ(sensor->ImageData(), nullptr) << "before the first frame";

  std::mutex mutex;
  int frames = 0;
  unsigned int width = 0, height = 0, depth = 0;
  std::string format;
  gazebo::event::ConnectionPtr on_frame = camera->ConnectNewImageFrame(
      [&](const unsigned char* image, unsigned int w, unsigned int h, unsigned int d, const std::string& f) {
        std::lock_guard<std::mutex> lock(mutex);
        ++frames, width = w, height = h, depth = d, format = f;
        ASSERT_TRUE(image);
      });
  plant.step(1000);
  std::lock_guard<std::mutex> lock(mutex);
  // 10 Hz over 1 s; frames render beside the simulation (in lockstep none is skipped) and count once
  // done, so the last one or two may still be rendering when the steps end
  EXPECT_GE(frames, 7);
  EXPECT_LE(frames, 10);
  EXPECT_EQ(width, 16u);
  EXPECT_EQ(height, 12u);
  EXPECT_EQ(depth, 1u);
  EXPECT_EQ(format, "L8");
  EXPECT_NE(sensor->ImageData(), nullptr);
  // frames render beside the simulation and count once done: the latest is a period or two old
  const double age = plant.time() - sensor->LastMeasurementTime().Double();
  EXPECT_GE(age, 0.0);
  EXPECT_LE(age, 0.2 + 1e-9);
}

TEST(GazeboCameraSensor, PublishesImagesWhileSubscribedAndKeepsItsLens)
{
  World plant(parseWorldDescription(
      world("R8G8B8", "<distortion><k1>-0.2</k1><k2>0.05</k2><p1>0.001</p1><center>0.5 0.5</center></distortion>")));
  std::shared_ptr<gazebo::sensors::CameraSensor> sensor = eye();
  ASSERT_TRUE(sensor);
  gazebo::rendering::DistortionPtr lens = sensor->Camera()->LensDistortion();
  ASSERT_TRUE(lens);
  EXPECT_DOUBLE_EQ(lens->K1(), -0.2);
  EXPECT_DOUBLE_EQ(lens->K2(), 0.05);
  EXPECT_DOUBLE_EQ(lens->P1(), 0.001);
  EXPECT_TRUE(lens->Crop()) << "Gazebo's default";
  std::mutex mutex;
  std::vector<gazebo::msgs::ImageStamped> received;
  gazebo::transport::NodePtr node(new gazebo::transport::Node());
  node->Init("camera_world");
  const boost::function<void(ConstImageStampedPtr&)> keep = [&](ConstImageStampedPtr& message) {
    std::lock_guard<std::mutex> lock(mutex);
    received.push_back(*message);
  };
  gazebo::transport::SubscriberPtr subscriber = node->Subscribe(sensor->Topic(), keep);
  plant.step(500);
  gazebo::transport::TopicManager::Instance()->WaitForAll();
  std::lock_guard<std::mutex> lock(mutex);
  ASSERT_GE(received.size(), 3u) << "10 Hz over 0.5 s, the last one or two perhaps still rendering";
  ASSERT_LE(received.size(), 5u);
  const gazebo::msgs::Image& image = received.back().image();
  EXPECT_EQ(image.width(), 16u);
  EXPECT_EQ(image.height(), 12u);
  EXPECT_EQ(image.pixel_format(), 3u) << "common::Image::RGB_INT8";
  EXPECT_EQ(image.step(), 16u * 3);
  EXPECT_EQ(image.data().size(), 16u * 12 * 3);
}

// A <sensor type="depth"> with Gazebo's own libDepthCameraPlugin.so facing a wall 2 m ahead: a
// DepthCameraSensor whose DepthCamera hands each frame over after its image as its
// <depth_camera><output> asks, as Gazebo's reads one render target back: depths by default, RGB
// points (and no depths) for "points". Its <camera> has no <clip>: SDF's 0.1 to 100 m (a near plane
// of 0 left the depths empty).
namespace
{
struct DepthFrames
{
  std::vector<std::string> order;
  std::vector<float> depths, points;
  const float* depth_data = nullptr;
};

DepthFrames depthCameraFrames(const std::string& depth_camera)
{
  std::string text = world("R8G8B8", depth_camera);
  text.replace(text.find("type='camera'"), 13, "type='depth'");
  text.replace(text.find("libCameraPlugin.so"), 18, "libDepthCameraPlugin.so");
  text.replace(text.find("<model name='probe'>"), 0,
               "<model name='wall'><static>true</static><pose>2.1 0 0.5 0 0 0</pose><link name='l'>"
               "<collision name='c'><geometry><box><size>0.2 4 4</size></box></geometry></collision>"
               "<visual name='v'><geometry><box><size>0.2 4 4</size></box></geometry></visual></link></model>");
  World plant(parseWorldDescription(text));
  auto sensor = std::dynamic_pointer_cast<gazebo::sensors::DepthCameraSensor>(
      gazebo::sensors::SensorManager::Instance()->GetSensor("eye"));
  EXPECT_TRUE(sensor);
  if (!sensor)
    return {};
  EXPECT_TRUE(sensor->IsActive()) << "DepthCameraPlugin::Load sets its sensor active";
  gazebo::rendering::DepthCameraPtr camera = sensor->DepthCamera();
  EXPECT_TRUE(camera);
  std::mutex mutex;
  DepthFrames seen;
  gazebo::event::ConnectionPtr on_image = camera->ConnectNewImageFrame(
      [&](const unsigned char*, unsigned int, unsigned int, unsigned int, const std::string&) {
        std::lock_guard<std::mutex> lock(mutex);
        seen.order.push_back("image");
      });
  gazebo::event::ConnectionPtr on_depth = camera->ConnectNewDepthFrame(
      [&](const float* image, unsigned int w, unsigned int h, unsigned int d, const std::string& format) {
        std::lock_guard<std::mutex> lock(mutex);
        seen.order.push_back("depth " + format);
        seen.depths.assign(image, image + w * h * d);
      });
  gazebo::event::ConnectionPtr on_points = camera->ConnectNewRGBPointCloud(
      [&](const float* pcd, unsigned int w, unsigned int h, unsigned int, const std::string& format) {
        std::lock_guard<std::mutex> lock(mutex);
        seen.order.push_back("points " + format);
        seen.points.assign(pcd, pcd + 4 * w * h);
      });
  plant.step(500);
  std::lock_guard<std::mutex> lock(mutex);
  if (sensor->DepthData())
    seen.depth_data = sensor->DepthData() + 6 * 16 + 8;
  if (seen.depth_data)
    seen.depths.push_back(*seen.depth_data);  // the sensor's own copy of the centre, last
  return seen;
}
}  // namespace

TEST(GazeboDepthCameraSensor, HandsDepthsOverAfterTheImageByDefault)
{
  const DepthFrames seen = depthCameraFrames("");
  ASSERT_GE(seen.order.size(), 2u);
  EXPECT_EQ(std::vector<std::string>(seen.order.begin(), seen.order.begin() + 2),
            (std::vector<std::string>{"image", "depth FLOAT32"}));
  EXPECT_TRUE(seen.points.empty()) << "Gazebo's output \"depths\": no points";
  ASSERT_EQ(seen.depths.size(), 16u * 12 + 1);
  const size_t centre = 6 * 16 + 8;
  EXPECT_NEAR(seen.depths[centre], 2.0, 0.02) << "the wall's face, along the optical axis";
  EXPECT_EQ(seen.depths.back(), seen.depths[centre]) << "DepthData: the latest frame's";
}

TEST(GazeboDepthCameraSensor, HandsRGBPointsOverInsteadWhereItsOutputIsPoints)
{
  const DepthFrames seen = depthCameraFrames("<depth_camera><output>points</output></depth_camera>");
  ASSERT_GE(seen.order.size(), 2u);
  EXPECT_EQ(std::vector<std::string>(seen.order.begin(), seen.order.begin() + 2),
            (std::vector<std::string>{"image", "points RGBPOINTS"}));
  EXPECT_TRUE(seen.depths.empty()) << "no depths, nor DepthData, as Gazebo's";
  ASSERT_EQ(seen.points.size(), 4u * 16 * 12);
  const size_t centre = 6 * 16 + 8;
  EXPECT_NEAR(seen.points[4 * centre + 2], 2.0, 0.02) << "z forward in the optical frame: the wall's face";
}
