// transport::Node, as Gazebo 11's: advertises and subscribes topics in a namespace ("~/x" is
// /gazebo/NAMESPACE/x). Init() with no name takes the first world's, as Gazebo's takes the master's
// first namespace ("default" where there is none). Subscribers' callbacks run on the transport's
// thread (TopicManager.hh), each with a message of its own.
#pragma once

#include <list>
#include <map>
#include <mutex>
#include <set>
#include <string>
#include <vector>

#include <boost/bind/bind.hpp>
#include <boost/enable_shared_from_this.hpp>
#include <boost/function.hpp>

#include "gazebo/common/Time.hh"
#include "gazebo/transport/CallbackHelper.hh"
#include "gazebo/transport/Publisher.hh"
#include "gazebo/transport/Subscriber.hh"
#include "gazebo/transport/TopicManager.hh"
#include "gazebo/transport/TransportTypes.hh"

namespace gazebo
{
namespace transport
{
class GZ_TRANSPORT_VISIBLE Node : public boost::enable_shared_from_this<Node>
{
public:
  Node();
  virtual ~Node();

  void Init(const std::string& _space = "");
  bool TryInit(const common::Time& _maxWait = common::Time(1, 0));
  bool IsInitialized() const;
  void Fini();

  std::string GetTopicNamespace() const;
  std::string DecodeTopicName(const std::string& _topic);
  std::string EncodeTopicName(const std::string& _topic);
  unsigned int GetId() const;
  void ProcessPublishers();
  void ProcessIncoming();
  bool HasLatchedSubscriber(const std::string& _topic) const;

  // One message on a topic through a publisher made for it (Gazebo's convenience; it waits for a
  // subscriber as Gazebo's does).
  template <typename M>
  void Publish(const std::string& _topic, const google::protobuf::Message& _message)
  {
    this->Publish(_topic, _message);
  }
  void Publish(const std::string& _topic, const google::protobuf::Message& _message)
  {
    PublisherPtr publisher = this->Advertise(_topic, _message.GetTypeName());
    publisher->WaitForConnection();
    publisher->Publish(_message, true);
  }

  template <typename M>
  PublisherPtr Advertise(const std::string& _topic, unsigned int _queueLimit = 1000, double _hzRate = 0)
  {
    return this->Advertise(_topic, M::descriptor()->full_name(), _queueLimit, _hzRate);
  }
  PublisherPtr Advertise(const std::string& _topic, const std::string& _msgTypeName, unsigned int _queueLimit = 1000,
                         double _hzRate = 0);

  template <typename M, typename T>
  SubscriberPtr Subscribe(const std::string& _topic, void (T::*_fp)(const boost::shared_ptr<M const>&), T* _obj,
                          bool _latching = false)
  {
    using namespace boost::placeholders;
    return this->AddCallback(_topic, CallbackHelperPtr(new CallbackHelperT<M>(boost::bind(_fp, _obj, _1), _latching)));
  }
  template <typename M>
  SubscriberPtr Subscribe(const std::string& _topic,
                          const boost::function<void(const boost::shared_ptr<M const>&)>& _cb, bool _latching = false)
  {
    return this->AddCallback(_topic, CallbackHelperPtr(new CallbackHelperT<M>(_cb, _latching)));
  }
  template <typename M>
  SubscriberPtr Subscribe(const std::string& _topic, void (*_fp)(const boost::shared_ptr<M const>&),
                          bool _latching = false)
  {
    return this->AddCallback(_topic, CallbackHelperPtr(new CallbackHelperT<M>(_fp, _latching)));
  }
  template <typename T>
  SubscriberPtr Subscribe(const std::string& _topic, void (T::*_fp)(const std::string&), T* _obj,
                          bool _latching = false)
  {
    using namespace boost::placeholders;
    CallbackHelperPtr helper(new RawCallbackHelper(boost::bind(_fp, _obj, _1)));
    helper->SetLatching(_latching);
    return this->AddCallback(_topic, helper);
  }
  SubscriberPtr Subscribe(const std::string& _topic, void (*_fp)(const std::string&), bool _latching = false)
  {
    CallbackHelperPtr helper(new RawCallbackHelper(_fp));
    helper->SetLatching(_latching);
    return this->AddCallback(_topic, helper);
  }

  // A message for the node's callbacks on a (decoded) topic: all of them, or the one numbered
  // `_callbackId` (a latched message for a new subscription). False where none took it.
  bool HandleData(const std::string& _topic, const std::string& _msg);
  bool HandleMessage(const std::string& _topic, MessagePtr _msg, unsigned int _callbackId = 0);
  void InsertLatchedMsg(const std::string& _topic, const std::string& _msg);
  void InsertLatchedMsg(const std::string& _topic, MessagePtr _msg);
  // The type a topic's callbacks take ("" where the node has none).
  std::string GetMsgType(const std::string& _topic) const;
  void RemoveCallback(const std::string& _topic, unsigned int _id);

private:
  SubscriberPtr AddCallback(const std::string& _topic, CallbackHelperPtr _helper);
  // A copy of the topic's callbacks, to run without holding the lock that subscribing takes.
  std::list<CallbackHelperPtr> callbacksOn(const std::string& _topic) const;

  std::string topicNamespace;
  bool initialized = false;
  unsigned int id;
  std::mutex publisherMutex;
  std::vector<PublisherPtr> publishers;
  mutable std::recursive_mutex incomingMutex;
  std::map<std::string, std::list<CallbackHelperPtr>> callbacks;
  // Held while callbacks run, so that RemoveCallback returns once none of them is running.
  std::recursive_mutex processIncomingMutex;
  std::set<std::string> wrongTypeWarned;
};
}  // namespace transport
}  // namespace gazebo
