// sensors::ContactSensor (gazebo/sensors/ContactSensor.hh).
#include "gazebo/sensors/ContactSensor.hh"

#include <boost/algorithm/string/replace.hpp>

#include "gazebo/msgs/msgs.hh"
#include "gazebo/physics/World.hh"
#include "gazebo/transport/Node.hh"
#include "gazebo/transport/Publisher.hh"

namespace gazebo
{
namespace sensors
{
ContactSensor::ContactSensor() : Sensor(OTHER) {}

ContactSensor::~ContactSensor() = default;

void ContactSensor::Load(const std::string& worldName)
{
  Sensor::Load(worldName);
  collisions_.clear();
  const sdf::ElementPtr contact = sdf->GetElement("contact");
  for (sdf::ElementPtr collision = contact->HasElement("collision") ? contact->GetElement("collision") : nullptr;
       collision; collision = collision->GetNextElement("collision"))
    collisions_.push_back(ParentName() + "::" + collision->Get<std::string>());
  if (!world)
    return;
  // its <contact><topic>, else ~/MODEL/LINK/SENSOR (Gazebo's)
  std::string topic = contact->HasElement("topic") ? contact->Get<std::string>("topic") : "__default_topic__";
  if (topic == "__default_topic__")
  {
    topic = "~/" + ParentName() + "/" + Name();
    boost::replace_all(topic, "::", "/");
  }
  contacts_pub_ = node->Advertise<msgs::Contacts>(topic, 100);
}

void ContactSensor::Init() { Sensor::Init(); }

void ContactSensor::Fini()
{
  contacts_pub_.reset();
  Sensor::Fini();
}

unsigned int ContactSensor::GetCollisionCount() const { return static_cast<unsigned int>(collisions_.size()); }

std::string ContactSensor::GetCollisionName(unsigned int index) const
{
  return index < collisions_.size() ? collisions_[index] : std::string();
}

unsigned int ContactSensor::GetCollisionContactCount(const std::string& collisionName) const
{
  std::lock_guard<std::mutex> lock(mutex_);
  unsigned int points = 0;
  for (const msgs::Contact& contact : contacts_msg_.contact())
    if (contact.collision1() == collisionName || contact.collision2() == collisionName)
      points += static_cast<unsigned int>(contact.position_size());
  return points;
}

msgs::Contacts ContactSensor::Contacts() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  return contacts_msg_;
}

std::map<std::string, physics::Contact> ContactSensor::Contacts(const std::string& collisionName) const
{
  std::lock_guard<std::mutex> lock(mutex_);
  std::map<std::string, physics::Contact> result;
  for (const msgs::Contact& contact : contacts_msg_.contact())
  {
    const std::string& other = contact.collision1() == collisionName   ? contact.collision2()
                               : contact.collision2() == collisionName ? contact.collision1()
                                                                        : std::string();
    if (!other.empty())
      result[other] = contact;
  }
  return result;
}

bool ContactSensor::IsActive() const
{
  return Sensor::IsActive() || (contacts_pub_ && contacts_pub_->HasConnections());
}

bool ContactSensor::UpdateImpl(bool /*force*/)
{
  const auto* touching = dynamic_cast<const ContactBridge*>(bridge.get());
  if (!touching)
    return false;
  lastMeasurementTime = touching->measurementTime();
  {
    std::lock_guard<std::mutex> lock(mutex_);
    touching->contacts(*contacts_msg_.mutable_contact());
    for (msgs::Contact& contact : *contacts_msg_.mutable_contact())
    {
      msgs::Set(contact.mutable_time(), lastMeasurementTime);
      contact.set_world(WorldName());
    }
    msgs::Set(contacts_msg_.mutable_time(), lastMeasurementTime);
    if (contacts_pub_ && contacts_pub_->HasConnections())
      contacts_pub_->Publish(contacts_msg_);
  }
  return true;
}
}  // namespace sensors
}  // namespace gazebo
