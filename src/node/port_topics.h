// The ROS side of ports (bullet_plant/message_ports.h): for a set of port owners (a robot's
// controllers, a model plugin), a subscriber per input and a publisher per output topic, each
// port's message type mapped to its ROS message once (port_topics.cpp). Messages that arrive are
// posted to the simulation thread and handed to the port found again there (its owner may be gone
// by then); outputs are drained after each step into the plant's outbox (outbox.h), or let go unbuilt
// while nobody subscribes; a service call waits for its answer from the simulation thread.
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <ros/ros.h>

#include "action_channel.h"
#include "bullet_plant/message_ports.h"
#include "counted_publisher.h"

namespace bullet_plant
{
class RosPlant;
struct PortTransport;

class PortTopics
{
public:
  // The ports' owners by name, on the simulation thread: null when one is gone.
  using FindOwner = std::function<const MessagePorts*(const std::string& name)>;

  PortTopics(RosPlant& plant, const ros::NodeHandle& nh, FindOwner find_owner);
  ~PortTopics();
  // Subscribers and publishers for exactly these owners (name -> ports; a Controller-scoped topic
  // resolves to "<name>/<topic>" under the node handle, "" for none), kept where unchanged.
  void refresh(const std::vector<std::pair<std::string, const MessagePorts*>>& owners);
  // After a step: what the outputs hold.
  void publish();

private:
  struct Output
  {
    Port* port;
    const PortTransport* transport;
    CountedPublisher publisher;
    uint64_t drained = ~uint64_t(0);  // the port's published() when last drained
  };
  std::string topicOf(const std::string& owner, const Port& port) const;
  ros::Subscriber subscribe(const std::string& owner, const Port& port, const PortTransport& transport);
  ros::ServiceServer advertiseService(const std::string& owner, const Port& port, const PortTransport& transport);
  std::shared_ptr<ActionChannel> serve(const std::string& owner, const Port& goal_port, const std::string& action,
                                       const PortTransport& transport);

  RosPlant& plant_;
  ros::NodeHandle nh_;
  FindOwner find_owner_;
  std::shared_ptr<bool> alive_;  // posted work finds it false once this is gone
  std::map<std::string, ros::Subscriber> subscribers_;  // by owner and topic
  std::map<std::string, CountedPublisher> publishers_;  // by topic, shared by the owners on it
  std::vector<Output> outputs_;                         // owners' order, ports' order
  std::map<std::string, std::shared_ptr<ActionChannel>> actions_;       // by action name (topic)
  std::map<std::string, ros::ServiceServer> services_;                  // by service name
  std::vector<std::pair<Port*, std::shared_ptr<ActionChannel>>> action_outputs_;  // result, feedback
};

}  // namespace bullet_plant
