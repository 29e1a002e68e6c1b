// Gazebo transport's class names and handle types, as Gazebo 11 declares them (boost::shared_ptr
// handles, and MessagePtr over protobuf's Message).
#pragma once

#include <boost/shared_ptr.hpp>
#include <google/protobuf/message.h>

#include "gazebo/util/system.hh"

namespace gazebo
{
namespace transport
{
class CallbackHelper;
class Connection;
class Node;
class Publication;
class PublicationTransport;
class Publisher;
class SubscribeOptions;
class Subscriber;
class SubscriptionTransport;

typedef boost::shared_ptr<google::protobuf::Message> MessagePtr;
typedef boost::shared_ptr<CallbackHelper> CallbackHelperPtr;
typedef boost::shared_ptr<Connection> ConnectionPtr;
typedef boost::shared_ptr<Node> NodePtr;
typedef boost::shared_ptr<Publication> PublicationPtr;
typedef boost::shared_ptr<PublicationTransport> PublicationTransportPtr;
typedef boost::shared_ptr<Publisher> PublisherPtr;
typedef boost::shared_ptr<Subscriber> SubscriberPtr;
typedef boost::shared_ptr<SubscriptionTransport> SubscriptionTransportPtr;
}  // namespace transport
}  // namespace gazebo
