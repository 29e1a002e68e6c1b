#include "port_topics.h"

#include <typeindex>

#include <geometry_msgs/Wrench.h>
#include <std_msgs/Float64.h>
#include <std_msgs/Float64MultiArray.h>

#include "action_channel.h"
#include "msg_conversions.h"
#include "ros_plant.h"

namespace bullet_plant
{
// How one message type travels over ROS: an input is subscribed, an output advertised and drained.
struct PortTransport
{
  using Delivery = std::function<bool(Port&)>;  // hands one message to the port it runs on
  using Post = std::function<void(Delivery, std::string rejected)>;
  std::function<ros::Subscriber(ros::NodeHandle&, const std::string& topic, Post)> subscribe;
  std::function<CountedPublisher(ros::NodeHandle&, const std::string& topic)> advertise;
  // What the output port holds, published (or, nobody subscribing, let go unbuilt).
  std::function<void(Port&, const CountedPublisher&, Outbox&)> drain;
  // An action (action_messages.h): its goal port's transport serves it; the cancel, result and
  // feedback ports are carried by that server (`by_action`).
  std::function<std::shared_ptr<ActionChannel>(ros::NodeHandle&, const std::string& action, RosPlant&,
                                               ActionChannel::FindPort)>
      serve;
  bool by_action = false;
  // A service: its callback runs the port's answer on the simulation thread and waits for it.
  using FindService = std::function<Port*()>;  // on the simulation thread; null when the owner is gone
  std::function<ros::ServiceServer(ros::NodeHandle&, const std::string& name, RosPlant&, FindService)> advertise_service;
};

namespace
{
// `rejected` says what the warning calls a message the port's owner refused.
template <class Msg, class RosMsg>
PortTransport input(std::function<Msg(const RosMsg&)> fromMsg, std::function<std::string(const Msg&)> rejected)
{
  PortTransport t;
  t.subscribe = [fromMsg, rejected](ros::NodeHandle& nh, const std::string& topic, PortTransport::Post post) {
    return nh.subscribe<RosMsg>(topic, 1, [fromMsg, rejected, post](const boost::shared_ptr<const RosMsg>& m) {
      Msg value = fromMsg(*m);
      post([value](Port& p) {  // a reloaded controller may have changed the port's type
        auto* in = dynamic_cast<InputPort<Msg>*>(&p);
        return in && in->deliver(value);
      }, rejected(value));
    });
  };
  return t;
}

template <class Msg, class RosMsg>
PortTransport output(uint32_t queue_size)
{
  PortTransport t;
  t.advertise = [queue_size](ros::NodeHandle& nh, const std::string& topic) {
    return CountedPublisher::advertise<RosMsg>(nh, topic, queue_size);
  };
  t.drain = [](Port& p, const CountedPublisher& pub, Outbox& outbox) {
    auto& port = static_cast<OutputPort<Msg>&>(p);
    if (pub.subscribed())
      port.drain([&](const Msg& m) { outbox.publish(pub.publisher(), toMsg(m)); });
    else
      port.drain([](const Msg&) {});
  };
  return t;
}

template <class RosAction, class Goal, class Result, class Feedback>
PortTransport action()
{
  PortTransport t;
  t.serve = [](ros::NodeHandle& nh, const std::string& name, RosPlant& plant, ActionChannel::FindPort find_port) {
    return std::make_shared<ActionChannelOf<RosAction, Goal, Result, Feedback>>(
        nh, name, [&plant](std::function<void()> work) { plant.post(std::move(work)); }, std::move(find_port));
  };
  return t;
}

template <class Request, class Response, class RosService>
PortTransport service()
{
  PortTransport t;
  t.advertise_service = [](ros::NodeHandle& nh, const std::string& name, RosPlant& plant, PortTransport::FindService find) {
    using RosRequest = typename RosService::Request;
    using RosResponse = typename RosService::Response;
    boost::function<bool(RosRequest&, RosResponse&)> callback = [&plant, find](RosRequest& req, RosResponse& res) {
      const Request request = fromMsg(req);
      Response response;
      const bool answered = plant.onSimThread<bool>([&] {
        auto* port = dynamic_cast<ServicePort<Request, Response>*>(find());
        return port && port->call(request, response);
      });
      if (answered)
        toMsg(response, res);
      return answered;
    };
    return nh.advertiseService(name, callback);
  };
  return t;
}

PortTransport carriedByAction()
{
  PortTransport t;
  t.by_action = true;
  return t;
}

// The one table of message types the node carries: a port of another type is refused, named.
const PortTransport* transportOf(const Port& port)
{
  static const std::map<std::type_index, PortTransport> inputs = {
      {typeid(double), input<double, std_msgs::Float64>(
                           [](const std_msgs::Float64& m) { return m.data; },
                           [](const double& v) { return "a non-finite command (" + std::to_string(v) + ")"; })},
      {typeid(std::vector<double>), input<std::vector<double>, std_msgs::Float64MultiArray>(
                                        [](const std_msgs::Float64MultiArray& m) { return m.data; },
                                        [](const std::vector<double>&) { return "a command (the controller logs why)"; })},
      {typeid(WrenchCommand), input<WrenchCommand, geometry_msgs::Wrench>(
                                  [](const geometry_msgs::Wrench& m) {
                                    return WrenchCommand{urdf::Vector3(m.force.x, m.force.y, m.force.z),
                                                         urdf::Vector3(m.torque.x, m.torque.y, m.torque.z)};
                                  },
                                  [](const WrenchCommand&) { return "a non-finite wrench"; })},
      {typeid(TransformsCommand), input<TransformsCommand, tf2_msgs::TFMessage>(
                                      [](const tf2_msgs::TFMessage& m) { return fromMsg(m); },
                                      [](const TransformsCommand&) { return "transforms (the plugin logs why)"; })},
      {typeid(TwistCommand), input<TwistCommand, geometry_msgs::Twist>(
                                 [](const geometry_msgs::Twist& m) { return TwistCommand{m.linear.x, m.angular.z, m.linear.y}; },
                                 [](const TwistCommand&) { return "a velocity command (the controller logs why)"; })},
      {typeid(JointTrajectoryCommand), input<JointTrajectoryCommand, trajectory_msgs::JointTrajectory>(
                                           [](const trajectory_msgs::JointTrajectory& m) { return fromMsg(m); },
                                           [](const JointTrajectoryCommand&) { return "a trajectory (the controller logs why)"; })},
      {typeid(ActionGoal<FollowJointTrajectoryGoal>),
       action<control_msgs::FollowJointTrajectoryAction, FollowJointTrajectoryGoal, FollowJointTrajectoryResult,
              TrajectoryStateSample>()},
      {typeid(ActionGoal<GripperCommandGoal>),
       action<control_msgs::GripperCommandAction, GripperCommandGoal, GripperCommandResult, GripperCommandResult>()},
      {typeid(ActionCancel), carriedByAction()},
  };
  static const std::map<std::type_index, PortTransport> outputs = {
      {typeid(JointStateSample), output<JointStateSample, sensor_msgs::JointState>(10)},
      {typeid(ControllerStateSample), output<ControllerStateSample, control_msgs::JointControllerState>(1)},
      {typeid(OdometrySample), output<OdometrySample, nav_msgs::Odometry>(100)},
      {typeid(TransformSample), output<TransformSample, tf2_msgs::TFMessage>(100)},
      {typeid(NavSatFixSample), output<NavSatFixSample, sensor_msgs::NavSatFix>(10)},
      {typeid(ImuSample), output<ImuSample, sensor_msgs::Imu>(10)},
      {typeid(Vector3StampedSample), output<Vector3StampedSample, geometry_msgs::Vector3Stamped>(10)},
      {typeid(WrenchStampedSample), output<WrenchStampedSample, geometry_msgs::WrenchStamped>(10)},
      {typeid(TrajectoryStateSample), output<TrajectoryStateSample, control_msgs::JointTrajectoryControllerState>(1)},
      {typeid(ActionResult<FollowJointTrajectoryResult>), carriedByAction()},
      {typeid(ActionFeedback<TrajectoryStateSample>), carriedByAction()},
      {typeid(ActionResult<GripperCommandResult>), carriedByAction()},
      {typeid(ActionFeedback<GripperCommandResult>), carriedByAction()},
  };
  static const std::map<std::type_index, PortTransport> services = {
      {typeid(EmptyRequest), service<EmptyRequest, EmptyRequest, std_srvs::Empty>()},
      {typeid(SetBiasRequest), service<SetBiasRequest, EmptyRequest, hector_gazebo_plugins::SetBias>()},
      {typeid(QueryTrajectoryStateRequest),
       service<QueryTrajectoryStateRequest, QueryTrajectoryStateResponse, control_msgs::QueryTrajectoryState>()},
  };
  const auto& table = port.direction() == Port::Direction::In    ? inputs
                      : port.direction() == Port::Direction::Out ? outputs
                                                                 : services;
  auto it = table.find(port.messageType());
  return it == table.end() ? nullptr : &it->second;
}
}  // namespace

PortTopics::PortTopics(RosPlant& plant, const ros::NodeHandle& nh, FindOwner find_owner)
  : plant_(plant), nh_(nh), find_owner_(std::move(find_owner)), alive_(std::make_shared<bool>(true))
{
}

PortTopics::~PortTopics() { *alive_ = false; }

std::string PortTopics::topicOf(const std::string& owner, const Port& port) const
{
  if (owner.empty() || port.topic().empty() || port.topic()[0] == '/' || port.scope() == TopicScope::Robot)
    return port.topic();
  return owner + "/" + port.topic();
}

void PortTopics::refresh(const std::vector<std::pair<std::string, const MessagePorts*>>& owners)
{
  std::map<std::string, ros::Subscriber> subscribers;
  std::map<std::string, CountedPublisher> publishers;
  std::map<std::string, std::shared_ptr<ActionChannel>> actions;
  std::map<std::string, ros::ServiceServer> services;
  std::vector<std::pair<Port*, std::string>> action_outputs;
  outputs_.clear();
  for (const auto& owner : owners)
    for (const std::unique_ptr<Port>& port : owner.second->ports())
    {
      const PortTransport* transport = transportOf(*port);
      if (!transport)
      {
        ROS_ERROR("'%s' in %s has a port '%s' whose message type the node cannot carry; add the type to "
                  "port_topics.cpp", owner.first.c_str(), nh_.getNamespace().c_str(), port->topic().c_str());
        continue;
      }
      const std::string topic = topicOf(owner.first, *port);
      if (transport->serve || transport->by_action)
      {
        // <action>/goal, /cancel, /result, /feedback: the goal port's transport serves <action>
        const std::string::size_type slash = topic.rfind('/');
        const std::string action = slash == std::string::npos ? "" : topic.substr(0, slash);
        if (transport->serve)
        {
          auto kept = actions_.find(action);
          actions[action] = kept != actions_.end() ? kept->second : serve(owner.first, *port, action, *transport);
        }
        else if (port->direction() == Port::Direction::Out)
          action_outputs.emplace_back(port.get(), action);
        continue;
      }
      if (port->direction() == Port::Direction::Service)
      {
        auto kept = services_.find(topic);
        services[topic] = kept != services_.end() ? kept->second : advertiseService(owner.first, *port, *transport);
        continue;
      }
      if (port->direction() == Port::Direction::In)
      {
        const std::string key = owner.first + " " + topic;
        auto kept = subscribers_.find(key);
        subscribers[key] = kept != subscribers_.end() ? kept->second : subscribe(owner.first, *port, *transport);
        continue;
      }
      if (!publishers.count(topic))
      {
        auto kept = publishers_.find(topic);
        publishers[topic] = kept != publishers_.end() ? kept->second : transport->advertise(nh_, topic);
      }
      outputs_.push_back(Output{port.get(), transport, publishers[topic]});
    }
  subscribers_.swap(subscribers);
  publishers_.swap(publishers);
  actions_.swap(actions);
  services_.swap(services);
  action_outputs_.clear();
  for (const auto& out : action_outputs)
  {
    auto served = actions_.find(out.second);
    if (served == actions_.end())
      ROS_ERROR("port '%s' in %s belongs to an action '%s' that nothing serves (no goal port)", out.first->topic().c_str(),
                nh_.getNamespace().c_str(), out.second.c_str());
    else
      action_outputs_.emplace_back(out.first, served->second);
  }
}

std::shared_ptr<ActionChannel> PortTopics::serve(const std::string& owner, const Port& goal_port, const std::string& action,
                                                 const PortTransport& transport)
{
  // the owner's ports are found again on the simulation thread by their topics under the action
  const std::string prefix = goal_port.topic().substr(0, goal_port.topic().rfind('/') + 1);
  return transport.serve(nh_, action, plant_, [this, owner, prefix](const std::string& topic) -> Port* {
    const MessagePorts* ports = find_owner_(owner);
    return ports ? ports->port(prefix + topic, Port::Direction::In) : nullptr;
  });
}

ros::ServiceServer PortTopics::advertiseService(const std::string& owner, const Port& port, const PortTransport& transport)
{
  const std::string name = port.topic();
  std::weak_ptr<bool> alive = alive_;
  return transport.advertise_service(nh_, topicOf(owner, port), plant_, [this, alive, owner, name]() -> Port* {
    std::shared_ptr<bool> still = alive.lock();
    if (!still || !*still)
      return nullptr;  // the robot (and its services) went before the call was answered
    const MessagePorts* ports = find_owner_(owner);
    return ports ? ports->port(name, Port::Direction::Service) : nullptr;
  });
}

ros::Subscriber PortTopics::subscribe(const std::string& owner, const Port& port, const PortTransport& transport)
{
  const std::string topic = port.topic(), resolved = nh_.resolveName(topicOf(owner, port));
  std::weak_ptr<bool> alive = alive_;
  auto post = [this, alive, owner, topic, resolved](PortTransport::Delivery deliver, std::string rejected) {
    plant_.post([this, alive, owner, topic, resolved, deliver, rejected] {
      std::shared_ptr<bool> still = alive.lock();
      if (!still || !*still)
        return;  // the robot (and these topics) went before the message was handed over
      const MessagePorts* ports = find_owner_(owner);
      Port* p = ports ? ports->port(topic, Port::Direction::In) : nullptr;
      if (p && !deliver(*p))
        ROS_WARN_THROTTLE(1.0, "Rejected %s on %s", rejected.c_str(), resolved.c_str());
    });
  };
  return transport.subscribe(nh_, topicOf(owner, port), post);
}

void PortTopics::publish()
{
  for (Output& out : outputs_)
  {
    // Most steps give an output nothing (odometry at 30 Hz, steps at 1 kHz): its drain is not called
    // then (with 50 robots that call and its publisher's checks were 0.7 % of the simulation thread).
    const uint64_t published = out.port->published();
    if (published == out.drained)
      continue;
    out.drained = published;
    out.transport->drain(*out.port, out.publisher, plant_.outbox());
  }
  for (auto& out : action_outputs_)
    out.second->drain(*out.first);
}

}  // namespace bullet_plant
