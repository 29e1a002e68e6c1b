// gazebo_ros_bumper: a contact sensor's contacts as gazebo_msgs/ContactsState on <bumperTopicName>
// (default "bumper_states", in <robotNamespace>), frame tf::resolve(tf_prefix, <frameName>)
// (default "world"), at each update of the sensor while subscribed. A ContactState per pair of
// collisions (collision1 the sensor's), with upstream's info text; positions and normals in the
// world (upstream never transforms them into frameName), each point's wrench on the sensor's body
// in its link frame and their sum. Upstream's rules (docs/interfaces.md section 11).
#include <sstream>

#include <gazebo_msgs/ContactsState.h>

#include "msg_conversions.h"
#include "ros_names.h"
#include "sensor_plugin.h"

namespace bullet_plant
{
class GazeboRosBumper : public SensorPlugin
{
public:
  void Load(Sensor& sensor) override
  {
    contact_sensor_ = &sensorAs<ContactSensor>(sensor, "gazebo_ros_bumper");
    const SensorDescription& d = sensor.description();
    ros::NodeHandle nh = nodeHandle(sensor);
    std::string prefix;
    nh.getParam("tf_prefix", prefix);  // its own namespace only, no search
    contacts_.header.frame_id = pluginFrameId(d, prefix);
    contact_pub_ = CountedPublisher::advertise<gazebo_msgs::ContactsState>(
        nh, requireValidRosName(pluginTopic(d), "sensor '" + sensor.name() + "' bumperTopicName"), 1);
  }

  bool subscribed() const override { return contact_pub_.subscribed(); }

  void OnUpdate() override
  {
    if (!takeUpdate(*contact_sensor_))
      return;
    const ContactReading& reading = contact_sensor_->latest();
    const ros::Time stamp = rosTime(reading.stamp_ns);
    contacts_.header.stamp = stamp;
    contacts_.states.clear();
    const size_t count = reading.states.size();
    for (size_t i = 0; i < count; ++i)
    {
      const ContactState& contact = reading.states[i];
      gazebo_msgs::ContactState state;
      state.collision1_name = contact.collision1;
      state.collision2_name = contact.collision2;
      std::ostringstream info;
      info << "Debug:  i:(" << i << "/" << count << ")     my geom:" << contact.collision1
           << "   other geom:" << contact.collision2 << "         time:" << stamp << std::endl;
      state.info = info.str();
      for (const ContactPoint& point : contact.points)
        addContactPoint(state, point.position, point.normal, point.depth, point.force, point.torque);
      contacts_.states.push_back(std::move(state));
    }
    outbox().publish(contact_pub_.publisher(), contacts_);
  }

private:
  ContactSensor* contact_sensor_ = nullptr;
  gazebo_msgs::ContactsState contacts_;
  CountedPublisher contact_pub_;
};

GAZEBO_ROS_SENSOR_PLUGIN(GazeboRosBumper, "libgazebo_ros_bumper.so");

}  // namespace bullet_plant
