// transport::Subscriber, as Gazebo 11's: what Node::Subscribe returns; the subscription ends when it
// is destroyed or Unsubscribe is called (no callback of it runs after that returns, except one that
// calls it from inside itself).
#pragma once

#include <string>

#include <boost/weak_ptr.hpp>

#include "gazebo/transport/TransportTypes.hh"

namespace gazebo
{
namespace transport
{
class GZ_TRANSPORT_VISIBLE Subscriber
{
public:
  Subscriber(const std::string& _topic, NodePtr _node);
  virtual ~Subscriber();
  std::string GetTopic() const;
  void Unsubscribe() const;
  void SetCallbackId(unsigned int _id);
  unsigned int GetCallbackId() const;

private:
  std::string topic;
  boost::weak_ptr<Node> node;
  unsigned int callbackId = 0;
};
}  // namespace transport
}  // namespace gazebo
