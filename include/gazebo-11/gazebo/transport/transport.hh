// Gazebo's transport header, as plugins include it: nodes, publishers and subscribers inside the
// process (gazebo/transport/TopicManager.hh says how messages go).
#pragma once

#include "gazebo/transport/CallbackHelper.hh"
#include "gazebo/transport/Node.hh"
#include "gazebo/transport/Publisher.hh"
#include "gazebo/transport/Subscriber.hh"
#include "gazebo/transport/TopicManager.hh"
#include "gazebo/transport/TransportIface.hh"
#include "gazebo/transport/TransportTypes.hh"
