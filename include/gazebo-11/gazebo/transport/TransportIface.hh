// Gazebo 11's transport functions for programs and plugins: here the transport is the process's own
// (no master to connect to), so init and run succeed at once and fini ends it.
#pragma once

#include <list>
#include <string>

#include "gazebo/transport/TransportTypes.hh"

namespace gazebo
{
namespace transport
{
GZ_TRANSPORT_VISIBLE bool init(const std::string& _masterHost = "", unsigned int _masterPort = 0,
                               uint32_t _timeoutIterations = 30);
GZ_TRANSPORT_VISIBLE void run();
GZ_TRANSPORT_VISIBLE bool is_stopped();
GZ_TRANSPORT_VISIBLE void stop();
GZ_TRANSPORT_VISIBLE void fini();
GZ_TRANSPORT_VISIBLE void clear_buffers();
GZ_TRANSPORT_VISIBLE bool get_topic_namespaces(std::list<std::string>& _namespaces);
}  // namespace transport
}  // namespace gazebo
