// sensors::CameraSensor (gazebo/sensors/CameraSensor.hh).
#include "gazebo/sensors/CameraSensor.hh"

#include <boost/algorithm/string/replace.hpp>

#include "gazebo/msgs/msgs.hh"
#include "gazebo/rendering/Camera.hh"
#include "gazebo/transport/Node.hh"
#include "gazebo/transport/Publisher.hh"
#include "camera_frames.h"
#include "link_sensor.h"

namespace gazebo
{
namespace sensors
{
CameraSensor::CameraSensor() : Sensor(IMAGE) {}

CameraSensor::~CameraSensor() = default;

rendering::CameraPtr CameraSensor::MakeCamera()
{
  // Gazebo's camera is named PARENT::SENSOR and follows the sensor's pose.
  std::shared_ptr<SensorBridge> simulated = bridge;
  return std::make_shared<rendering::Camera>(ParentName() + "::" + Name(), [simulated] {
    return simulated ? simulated->worldPose() : ignition::math::Pose3d::Zero;
  });
}

std::string CameraSensor::Topic() const
{
  std::string topic = "~/" + ParentName() + "/" + Name() + "/image";
  boost::replace_all(topic, "::", "/");
  return topic;
}

void CameraSensor::Load(const std::string& worldName)
{
  Sensor::Load(worldName);
  if (world)
    image_pub_ = node->Advertise<msgs::ImageStamped>(Topic(), 50);
  // its <camera><noise> as Gazebo's model, for a plugin that reads it; the simulator's camera applies
  // it (one simulation of the sensor), so the model is not applied again here
  detail::loadNoise(noises, CAMERA_NOISE, sdf, "camera");
}

void CameraSensor::Init()
{
  camera = MakeCamera();
  camera->Load(sdf->GetElement("camera"));
  camera->Init();
  if (auto* frames = dynamic_cast<CameraBridge*>(bridge.get()))
    detail::handLensCrop(*camera, *frames);
  Sensor::Init();
}

void CameraSensor::Fini()
{
  image_pub_.reset();
  if (camera)
    camera->Fini();
  Sensor::Fini();
}

unsigned int CameraSensor::ImageWidth() const { return camera ? camera->ImageWidth() : 0; }

unsigned int CameraSensor::ImageHeight() const { return camera ? camera->ImageHeight() : 0; }

const unsigned char* CameraSensor::ImageData() const { return camera ? camera->ImageData() : nullptr; }

bool CameraSensor::IsActive() const { return Sensor::IsActive() || (image_pub_ && image_pub_->HasConnections()); }

bool CameraSensor::UpdateImpl(bool /*force*/)
{
  auto* frames = dynamic_cast<CameraBridge*>(bridge.get());
  if (!frames || !camera)
    return false;
  const unsigned char* image = frames->image();
  if (!image)
    return false;
  lastMeasurementTime = frames->measurementTime();
  detail::handLensCrop(*camera, *frames);
  camera->TakeFrame(image);
  if (image_pub_ && image_pub_->HasConnections())
  {
    msgs::ImageStamped message;
    msgs::Set(message.mutable_time(), lastMeasurementTime);
    msgs::Image& out = *message.mutable_image();
    detail::describeFrames(*camera, out);
    out.set_data(image, camera->ImageByteSize());
    image_pub_->Publish(message);
  }
  return true;
}
}  // namespace sensors
}  // namespace gazebo
