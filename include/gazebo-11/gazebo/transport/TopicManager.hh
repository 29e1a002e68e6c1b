// transport::TopicManager: the process's topics, as Gazebo 11's singleton of that name is for a
// node, without the master and the sockets: who advertises and who subscribes to each topic, the
// world namespaces, and the one thread that hands published messages to subscribers in the order
// they were published (as Gazebo's transport thread does, so a callback never runs inside Publish
// on the publisher's thread: a plugin publishing from its world update does not reenter itself).
#pragma once

#include <condition_variable>
#include <cstdint>
#include <deque>
#include <list>
#include <map>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include <boost/weak_ptr.hpp>

// as Gazebo's: every node's user has the messages (gazebo_ros_block_laser converts a msgs::Time
// having included only Node.hh)
#include "gazebo/msgs/msgs.hh"
#include "gazebo/transport/TransportTypes.hh"

namespace gazebo
{
namespace transport
{
class GZ_TRANSPORT_VISIBLE TopicManager
{
public:
  static TopicManager* Instance();
  ~TopicManager();

  // A publisher on a (decoded) topic: a topic has one message type, a second type is refused
  // (common::Exception, as Gazebo's).
  PublisherPtr Advertise(const std::string& _topic, const std::string& _msgType, unsigned int _queueLimit,
                         double _hzRate);
  template <typename M>
  PublisherPtr Advertise(const std::string& _topic, unsigned int _queueLimit, double _hzRate)
  {
    return this->Advertise(_topic, M::descriptor()->full_name(), _queueLimit, _hzRate);
  }
  void Unadvertise(const std::string& _topic, uint32_t _publisherId);

  // The node's callback `_callbackId` on the topic; with `_latching`, the last message of each of
  // the topic's publishers is handed to that callback.
  void Subscribe(const std::string& _topic, const NodePtr& _node, unsigned int _callbackId, bool _latching);
  void Unsubscribe(const std::string& _topic, const NodePtr& _node);

  // Queues the message for the topic's subscribers: the delivery's number, for WaitDelivered.
  uint64_t Publish(const std::string& _topic, MessagePtr _message, const PublisherPtr& _publisher);
  // Returns once the delivery numbered `_sequence` has been handed over (at once from the
  // transport's own thread, which would wait for itself).
  void WaitDelivered(uint64_t _sequence);
  // Waits until every message published so far has been handed over.
  void WaitForAll();

  bool HasSubscribers(const std::string& _topic) const;
  std::string GetMsgType(const std::string& _topic) const;
  void RegisterTopicNamespace(const std::string& _name);
  void GetTopicNamespaces(std::list<std::string>& _namespaces) const;
  // Gazebo's transport loop calls these; here messages go as they are published.
  void ProcessNodes(bool _onlyOut = false);
  void Fini();

private:
  TopicManager();
  struct Delivery
  {
    uint64_t sequence;
    std::string topic;
    MessagePtr message;
    boost::weak_ptr<Publisher> publisher;
    // The topic's subscribers when it was published (one node, for a latched message to one of its
    // callbacks): one that subscribes later does not get it.
    std::vector<boost::weak_ptr<Node>> receivers;
    unsigned int callbackId = 0;
  };
  struct Topic
  {
    std::string msgType;
    std::vector<boost::weak_ptr<Publisher>> publishers;
    std::vector<boost::weak_ptr<Node>> subscribers;
  };
  void run();
  uint64_t enqueue(Delivery delivery);
  // Erases the topic where it has no publisher and no subscriber left (the mutex held).
  void forgetIfUnused(std::map<std::string, Topic>::iterator _topic);

  mutable std::mutex mutex;
  std::condition_variable queued;
  std::condition_variable delivered;
  std::map<std::string, Topic> topics;
  std::list<std::string> namespaces;
  std::deque<Delivery> deliveries;
  uint64_t published = 0;
  uint64_t handedOver = 0;
  bool stopping = false;
  std::thread thread;
};
}  // namespace transport
}  // namespace gazebo
