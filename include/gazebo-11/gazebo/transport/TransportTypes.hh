// Gazebo transport's class names and handle types, as Gazebo 11 declares them (boost::shared_ptr
// handles): what plugins that include this header only to name them need (gazebo_plugins' p3d,
// f3d, force, ft_sensor ... include it and use none). Gazebo's transport itself is not offered yet:
// the classes are declared, not defined.
#pragma once

#include <boost/shared_ptr.hpp>

namespace gazebo
{
namespace transport
{
class Connection;
class Node;
class Publication;
class PublicationTransport;
class Publisher;
class SubscribeOptions;
class Subscriber;
class SubscriptionTransport;

typedef boost::shared_ptr<Connection> ConnectionPtr;
typedef boost::shared_ptr<Node> NodePtr;
typedef boost::shared_ptr<Publication> PublicationPtr;
typedef boost::shared_ptr<PublicationTransport> PublicationTransportPtr;
typedef boost::shared_ptr<Publisher> PublisherPtr;
typedef boost::shared_ptr<Subscriber> SubscriberPtr;
typedef boost::shared_ptr<SubscriptionTransport> SubscriptionTransportPtr;
}  // namespace transport
}  // namespace gazebo
