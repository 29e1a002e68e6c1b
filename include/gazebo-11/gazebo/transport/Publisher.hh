// transport::Publisher, as Gazebo 11's: made by Node::Advertise, publishes messages of its topic's
// type. Here every subscriber is in the process (Gazebo's transport without its master and sockets):
// a message goes to the subscribers' callbacks on the transport's own thread, in the order published.
#pragma once

#include <cstdint>
#include <mutex>
#include <string>

#include <boost/enable_shared_from_this.hpp>
#include <boost/weak_ptr.hpp>
#include <google/protobuf/message.h>

#include "gazebo/common/Time.hh"
#include "gazebo/transport/TransportTypes.hh"

namespace gazebo
{
namespace transport
{
class GZ_TRANSPORT_VISIBLE Publisher : public boost::enable_shared_from_this<Publisher>
{
public:
  Publisher(const std::string& _topic, const std::string& _msgType, unsigned int _limit, double _hzRate);
  virtual ~Publisher();

  // Whether the topic has a subscriber.
  bool HasConnections() const;
  // Blocks until the topic has a subscriber; a negative timeout waits for ever. True once it has.
  void WaitForConnection() const;
  bool WaitForConnection(const common::Time& _timeout) const;

  void SetPublication(PublicationPtr _publication);

  // Publishes a copy of the message (of the topic's type, else a common::Exception as Gazebo's);
  // _block: returns once every subscriber's callback has had it (except from inside a callback).
  void Publish(const google::protobuf::Message& _message, bool _block = false) { this->PublishImpl(_message, _block); }
  template <typename M>
  void Publish(const M& _message, bool _block = false)
  {
    this->PublishImpl(_message, _block);
  }

  // Messages published and not yet handed to every subscriber.
  unsigned int GetOutgoingCount() const;
  std::string GetTopic() const;
  std::string GetMsgType() const;
  // Gazebo sends the queue on the wire here; in the process there is nothing left to send.
  void SendMessage();
  // Gazebo's publisher keeps its node; here the node owns its publishers and nothing is kept.
  void SetNode(NodePtr _node);
  // The last message published (for latching subscribers): serialized, and as a message.
  std::string GetPrevMsg() const;
  MessagePtr GetPrevMsgPtr() const;
  uint32_t Id() const;
  void Fini();

  // The transport's own: a message of this publisher's has reached its subscribers.
  void OnDelivered();

  // Not Gazebo's: publishes `_message` itself, which the caller gives up (it must not change it
  // after): the simulator's sensors publish each measurement so, without Publish's copy.
  void PublishOwned(MessagePtr _message);

private:
  void PublishImpl(const google::protobuf::Message& _message, bool _block);
  void Send(MessagePtr _message, bool _block);

  std::string topic;
  std::string msgType;
  unsigned int queueLimit;
  double updatePeriod;
  uint32_t id;

  mutable std::mutex mutex;
  MessagePtr prevMsg;
  common::Time prevPublishTime;
  unsigned int outgoing = 0;
  bool queueLimitWarned = false;
};
}  // namespace transport
}  // namespace gazebo
