// sensors::MultiCameraSensor (gazebo/sensors/MultiCameraSensor.hh).
#include "gazebo/sensors/MultiCameraSensor.hh"

#include <boost/algorithm/string/replace.hpp>

#include "gazebo/common/Console.hh"
#include "gazebo/msgs/msgs.hh"
#include "gazebo/rendering/Camera.hh"
#include "gazebo/transport/Node.hh"
#include "gazebo/transport/Publisher.hh"
#include "camera_frames.h"

namespace gazebo
{
namespace sensors
{
MultiCameraSensor::MultiCameraSensor() : Sensor(IMAGE) {}

MultiCameraSensor::~MultiCameraSensor() = default;

std::string MultiCameraSensor::Topic() const
{
  std::string topic = Sensor::Topic();
  if (topic.empty())
  {
    topic = "~/" + ParentName() + "/" + Name() + "/images";
    boost::replace_all(topic, "::", "/");
  }
  return topic;
}

void MultiCameraSensor::Load(const std::string& worldName)
{
  Sensor::Load(worldName);
  if (world)
    images_pub_ = node->Advertise<msgs::ImagesStamped>(Topic(), 50);
}

void MultiCameraSensor::Init()
{
  auto* simulated = dynamic_cast<MultiCameraBridge*>(bridge.get());
  // (each camera holds the bridge, whose camera `frames` points into, for as long as a plugin holds it)
  std::shared_ptr<SensorBridge> keep = bridge;
  unsigned int index = 0;
  for (sdf::ElementPtr element = sdf->HasElement("camera") ? sdf->GetElement("camera") : nullptr; element;
       element = element->GetNextElement("camera"), ++index)
  {
    // Gazebo's scene names each camera by its element; it follows the sensor's pose composed with
    // the camera's, which the simulator's camera of that element has.
    CameraBridge* frames = simulated && index < simulated->cameraCount() ? &simulated->camera(index) : nullptr;
    auto camera = std::make_shared<rendering::Camera>(element->Get<std::string>("name"), [keep, frames] {
      return frames ? frames->worldPose() : ignition::math::Pose3d::Zero;
    });
    camera->Load(element);
    camera->Init();
    if (frames)
      detail::handLensCrop(*camera, *frames);
    detail::describeFrames(*camera, *message_.add_image());
    cameras_.push_back(std::move(camera));
  }
  Sensor::Init();
}

void MultiCameraSensor::Fini()
{
  images_pub_.reset();
  for (const rendering::CameraPtr& camera : cameras_)
    camera->Fini();
  cameras_.clear();
  Sensor::Fini();
}

unsigned int MultiCameraSensor::CameraCount() const { return static_cast<unsigned int>(cameras_.size()); }

rendering::CameraPtr MultiCameraSensor::Camera(unsigned int _index) const
{
  if (_index < cameras_.size())
    return cameras_[_index];
  gzerr << "camera index out of range. Valid range[0.." << static_cast<int>(cameras_.size()) - 1 << "]\n";
  return rendering::CameraPtr();
}

unsigned int MultiCameraSensor::ImageWidth(unsigned int _index) const
{
  const rendering::CameraPtr camera = Camera(_index);
  return camera ? camera->ImageWidth() : 0;
}

unsigned int MultiCameraSensor::ImageHeight(unsigned int _index) const
{
  const rendering::CameraPtr camera = Camera(_index);
  return camera ? camera->ImageHeight() : 0;
}

const unsigned char* MultiCameraSensor::ImageData(unsigned int _index)
{
  const rendering::CameraPtr camera = Camera(_index);
  return camera ? camera->ImageData(0) : nullptr;
}

bool MultiCameraSensor::IsActive() const { return Sensor::IsActive() || (images_pub_ && images_pub_->HasConnections()); }

bool MultiCameraSensor::UpdateImpl(bool /*force*/)
{
  auto* simulated = dynamic_cast<MultiCameraBridge*>(bridge.get());
  if (!simulated || cameras_.empty() || simulated->cameraCount() < cameras_.size())
    return false;
  std::vector<const unsigned char*> images(cameras_.size());
  for (size_t i = 0; i < cameras_.size(); ++i)
    if (!(images[i] = simulated->camera(static_cast<unsigned int>(i)).image()))
      return false;
  lastMeasurementTime = simulated->camera(0).measurementTime();
  const bool publish = images_pub_ && images_pub_->HasConnections();
  if (publish)
    msgs::Set(message_.mutable_time(), lastMeasurementTime);
  for (size_t i = 0; i < cameras_.size(); ++i)
  {
    rendering::Camera& camera = *cameras_[i];
    detail::handLensCrop(camera, simulated->camera(static_cast<unsigned int>(i)));
    camera.TakeFrame(images[i]);
    if (publish)
      message_.mutable_image(static_cast<int>(i))->set_data(images[i], camera.ImageByteSize());
  }
  if (publish)
    images_pub_->Publish(message_);
  return true;
}
}  // namespace sensors
}  // namespace gazebo
