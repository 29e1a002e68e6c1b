// sensors::ContactSensor: a <sensor type="contact"> as Gazebo 11's: its <contact><collision>s (in its
// link), and after each measurement the contacts between them and anything else (msgs::Contacts:
// points and normals in the world, depths, wrenches), published on ~/MODEL/LINK/SENSOR (or its
// <contact><topic>) while someone subscribes. Its measurements are the simulator's (ContactBridge:
// the plant's contact sensor, one simulation of each sensor); what differs: docs/gazebo_api.md.
#pragma once

#include <map>
#include <mutex>
#include <string>
#include <vector>

#include "gazebo/msgs/MessageTypes.hh"
#include "gazebo/physics/Contact.hh"
#include "gazebo/sensors/Sensor.hh"
#include "gazebo/transport/TransportTypes.hh"

namespace gazebo
{
namespace sensors
{
class GZ_SENSORS_VISIBLE ContactSensor : public Sensor
{
public:
  ContactSensor();
  ~ContactSensor() override;

  // Its collisions (MODEL::LINK::COLLISION) and its topic.
  void Load(const std::string& worldName) override;
  using Sensor::Load;
  void Init() override;
  void Fini() override;

  unsigned int GetCollisionCount() const;
  // Collision `index`'s scoped name; "" past the end.
  std::string GetCollisionName(unsigned int index) const;
  // The latest measurement's points of the contacts `collisionName` is in.
  unsigned int GetCollisionContactCount(const std::string& collisionName) const;
  // The latest measurement.
  msgs::Contacts Contacts() const;
  // The latest measurement's contacts of `collisionName`, by the other collision's name.
  std::map<std::string, physics::Contact> Contacts(const std::string& collisionName) const;

  // Active as set, or while its topic has a subscriber (Gazebo's rule).
  bool IsActive() const override;

protected:
  bool UpdateImpl(bool force) override;

private:
  std::vector<std::string> collisions_;
  transport::PublisherPtr contacts_pub_;
  mutable std::mutex mutex_;
  msgs::Contacts contacts_msg_;
};
}  // namespace sensors
}  // namespace gazebo
