// The topics of what the plant hosts in place of ROS code: controllers and Gazebo model plugins.
// ros_controllers' controllers and gazebo_plugins' plugins subscribe to their commands and advertise
// what they publish on their own node handles; the plant has no ROS, so they declare typed ports
// instead (MessagePorts), and each transport maps a message type to its wire once: the ROS node
// (src/node/port_topics.cpp) and the Python module (src/python/port_bindings.cpp). A new
// controller or plugin that speaks known messages touches only its own file and its registry.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <typeindex>
#include <typeinfo>
#include <utility>
#include <vector>

namespace bullet_plant
{
// Where a port's topic name resolves, as a ros_controllers controller's two node handles do: its own
// (<robot ns>/<controller>/<topic>) or the robot's (<robot ns>/<topic>); a model plugin's resolve
// against its namespace either way. A topic starting with '/' is global.
enum class TopicScope { Controller, Robot };

class Port
{
public:
  enum class Direction { In, Out, Service };

  Port(std::string topic, TopicScope scope, Direction direction, std::type_index message_type)
    : topic_(std::move(topic)), scope_(scope), direction_(direction), message_type_(message_type)
  {
  }
  virtual ~Port() = default;

  const std::string& topic() const { return topic_; }
  Direction direction() const { return direction_; }
  TopicScope scope() const { return scope_; }
  std::type_index messageType() const { return message_type_; }
  template <class Msg>
  bool carries() const { return message_type_ == std::type_index(typeid(Msg)); }
  // Messages published on it (0 for an input).
  uint64_t published() const { return published_; }

protected:
  uint64_t published_ = 0;

private:
  std::string topic_;
  TopicScope scope_;
  Direction direction_;
  std::type_index message_type_;
};

// A command the controller accepts (what it would subscribe to).
template <class Msg>
class InputPort : public Port
{
public:
  InputPort(std::string topic, TopicScope scope, std::function<bool(const Msg&)> accept)
    : Port(std::move(topic), scope, Direction::In, typeid(Msg)), accept_(std::move(accept))
  {
  }
  // False, with the reason logged by the controller, when it rejects the message.
  bool deliver(const Msg& m) { return accept_(m); }

private:
  std::function<bool(const Msg&)> accept_;
};

// What the controller publishes: queued for a reader that drains it (the node, after each step) and
// the latest kept for readers that only look (Python). With nobody draining, the queue stops growing.
template <class Msg>
class OutputPort : public Port
{
public:
  static constexpr size_t kMaxQueued = 1000;

  OutputPort(std::string topic, TopicScope scope) : Port(std::move(topic), scope, Direction::Out, typeid(Msg)) {}

  void publish(const Msg& m)
  {
    latest_ = m;
    has_latest_ = true;
    ++published_;
    if (queue_.size() < kMaxQueued)
      queue_.push_back(m);
  }
  std::vector<Msg> take()
  {
    std::vector<Msg> out;
    out.swap(queue_);
    return out;
  }
  // Each queued message to `visit`, oldest first, then none queued; the queue keeps its storage (a
  // port drained after every step allocates nothing).
  template <class Visit>
  void drain(Visit visit)
  {
    for (const Msg& m : queue_)
      visit(m);
    queue_.clear();
  }
  const Msg* latest() const { return has_latest_ ? &latest_ : nullptr; }

private:
  std::vector<Msg> queue_;
  Msg latest_{};
  bool has_latest_ = false;
};

// A service the owner answers (what it would advertiseService), on the simulation thread: false
// (the reason logged by the owner) fails the call, as a ROS service callback returning false.
template <class Request, class Response>
class ServicePort : public Port
{
public:
  ServicePort(std::string name, TopicScope scope, std::function<bool(const Request&, Response&)> answer)
    : Port(std::move(name), scope, Direction::Service, typeid(Request)), answer_(std::move(answer))
  {
  }
  bool call(const Request& request, Response& response) { return answer_(request, response); }

private:
  std::function<bool(const Request&, Response&)> answer_;
};

// What owns ports: it opens them (subscribe, advertise, serve) and the transports find them.
class MessagePorts
{
public:
  virtual ~MessagePorts() = default;

  // In the order they were opened.
  const std::vector<std::unique_ptr<Port>>& ports() const { return ports_; }
  // The first port carrying Msg, or null.
  template <class Msg>
  InputPort<Msg>* input() const { return portOf<InputPort<Msg>>(); }
  template <class Msg>
  OutputPort<Msg>* output() const { return portOf<OutputPort<Msg>>(); }
  // The port with this topic and direction, or null.
  Port* port(const std::string& topic, Port::Direction direction) const
  {
    for (const std::unique_ptr<Port>& p : ports_)
      if (p->topic() == topic && p->direction() == direction)
        return p.get();
    return nullptr;
  }
  // Messages published on all output ports.
  uint64_t messagesPublished() const
  {
    uint64_t n = 0;
    for (const std::unique_ptr<Port>& p : ports_)
      n += p->published();
    return n;
  }

protected:
  template <class Msg>
  OutputPort<Msg>& advertise(std::string topic, TopicScope scope = TopicScope::Controller)
  {
    ports_.emplace_back(new OutputPort<Msg>(std::move(topic), scope));
    return static_cast<OutputPort<Msg>&>(*ports_.back());
  }
  template <class Msg>
  void subscribe(std::string topic, std::function<bool(const Msg&)> accept, TopicScope scope = TopicScope::Controller)
  {
    ports_.emplace_back(new InputPort<Msg>(std::move(topic), scope, std::move(accept)));
  }

  template <class Request, class Response>
  void serve(std::string name, std::function<bool(const Request&, Response&)> answer,
             TopicScope scope = TopicScope::Controller)
  {
    ports_.emplace_back(new ServicePort<Request, Response>(std::move(name), scope, std::move(answer)));
  }

private:
  template <class P>
  P* portOf() const
  {
    for (const std::unique_ptr<Port>& p : ports_)
      if (P* typed = dynamic_cast<P*>(p.get()))
        return typed;
    return nullptr;
  }

  std::vector<std::unique_ptr<Port>> ports_;
};

}  // namespace bullet_plant
