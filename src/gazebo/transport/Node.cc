// transport::Node (gazebo/transport/Node.hh).
#include "gazebo/transport/Node.hh"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <exception>
#include <thread>

#include "gazebo/common/Console.hh"

namespace gazebo
{
namespace transport
{
namespace
{
std::atomic<unsigned int> next_node_id{ 0 };

void replaceFirst(std::string& text, const std::string& from, const std::string& to)
{
  const size_t at = text.find(from);
  if (at != std::string::npos)
    text.replace(at, from.size(), to);
}
}  // namespace

Node::Node() : id(next_node_id++) {}

Node::~Node() { this->Fini(); }

void Node::Init(const std::string& _space)
{
  if (_space.empty())
  {
    // Gazebo waits for the master's namespaces and falls back to "default".
    std::list<std::string> namespaces;
    TopicManager::Instance()->GetTopicNamespaces(namespaces);
    this->topicNamespace = namespaces.empty() ? "default" : namespaces.front();
  }
  else
  {
    this->topicNamespace = _space;
    TopicManager::Instance()->RegisterTopicNamespace(_space);
  }
  this->initialized = true;
}

bool Node::TryInit(const common::Time& _maxWait)
{
  const auto deadline = std::chrono::steady_clock::now() +
                        std::chrono::nanoseconds(static_cast<int64_t>(_maxWait.sec) * 1000000000 + _maxWait.nsec);
  std::list<std::string> namespaces;
  for (;;)
  {
    TopicManager::Instance()->GetTopicNamespaces(namespaces);
    if (!namespaces.empty() || std::chrono::steady_clock::now() >= deadline)
      break;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  if (namespaces.empty())
    return false;
  this->topicNamespace = namespaces.front();
  this->initialized = true;
  return true;
}

bool Node::IsInitialized() const { return this->initialized; }

void Node::Fini()
{
  std::vector<PublisherPtr> ours;
  {
    std::lock_guard<std::mutex> lock(this->publisherMutex);
    ours.swap(this->publishers);
  }
  for (const PublisherPtr& publisher : ours)
    publisher->Fini();
  std::map<std::string, std::list<CallbackHelperPtr>> subscribed;
  {
    std::lock_guard<std::recursive_mutex> running(this->processIncomingMutex);
    std::lock_guard<std::recursive_mutex> lock(this->incomingMutex);
    subscribed.swap(this->callbacks);
  }
  // The node may be going (its destructor): the manager holds it weakly and drops it by its topics.
  for (const auto& topic : subscribed)
    TopicManager::Instance()->Unsubscribe(topic.first, NodePtr());
  this->initialized = false;
}

std::string Node::GetTopicNamespace() const { return this->topicNamespace; }

std::string Node::DecodeTopicName(const std::string& _topic)
{
  std::string result = _topic;
  replaceFirst(result, "~", "/gazebo/" + this->topicNamespace);
  replaceFirst(result, "//", "/");
  return result;
}

std::string Node::EncodeTopicName(const std::string& _topic)
{
  std::string result = _topic;
  replaceFirst(result, "/gazebo/" + this->topicNamespace, "~");
  replaceFirst(result, "//", "/");
  return result;
}

unsigned int Node::GetId() const { return this->id; }
void Node::ProcessPublishers() {}
void Node::ProcessIncoming() {}

bool Node::HasLatchedSubscriber(const std::string& _topic) const
{
  std::lock_guard<std::recursive_mutex> lock(this->incomingMutex);
  const auto found = this->callbacks.find(_topic);
  if (found == this->callbacks.end())
    return false;
  return std::any_of(found->second.begin(), found->second.end(),
                     [](const CallbackHelperPtr& helper) { return helper->GetLatching(); });
}

PublisherPtr Node::Advertise(const std::string& _topic, const std::string& _msgTypeName, unsigned int _queueLimit,
                             double _hzRate)
{
  PublisherPtr publisher =
      TopicManager::Instance()->Advertise(this->DecodeTopicName(_topic), _msgTypeName, _queueLimit, _hzRate);
  publisher->SetNode(shared_from_this());
  std::lock_guard<std::mutex> lock(this->publisherMutex);
  this->publishers.push_back(publisher);
  return publisher;
}

SubscriberPtr Node::AddCallback(const std::string& _topic, CallbackHelperPtr _helper)
{
  const std::string decoded = this->DecodeTopicName(_topic);
  {
    std::lock_guard<std::recursive_mutex> lock(this->incomingMutex);
    this->callbacks[decoded].push_back(_helper);
  }
  SubscriberPtr subscriber(new Subscriber(decoded, shared_from_this()));
  subscriber->SetCallbackId(_helper->GetId());
  TopicManager::Instance()->Subscribe(decoded, shared_from_this(), _helper->GetId(), _helper->GetLatching());
  return subscriber;
}

std::list<CallbackHelperPtr> Node::callbacksOn(const std::string& _topic) const
{
  std::lock_guard<std::recursive_mutex> lock(this->incomingMutex);
  const auto found = this->callbacks.find(_topic);
  return found == this->callbacks.end() ? std::list<CallbackHelperPtr>() : found->second;
}

bool Node::HandleData(const std::string& _topic, const std::string& _msg)
{
  std::lock_guard<std::recursive_mutex> running(this->processIncomingMutex);
  bool handled = false;
  for (const CallbackHelperPtr& helper : this->callbacksOn(_topic))
    handled = helper->HandleData(_msg) || handled;
  return handled;
}

bool Node::HandleMessage(const std::string& _topic, MessagePtr _msg, unsigned int _callbackId)
{
  std::lock_guard<std::recursive_mutex> running(this->processIncomingMutex);
  bool handled = false;
  for (const CallbackHelperPtr& helper : this->callbacksOn(_topic))
  {
    if (_callbackId != 0 && helper->GetId() != _callbackId)
      continue;
    try
    {
      if (helper->HandleMessage(_msg))
        handled = true;
      else if (this->wrongTypeWarned.insert(_topic).second)
        gzerr << "A subscriber to topic[" << _topic << "] takes [" << helper->GetMsgType() << "], not the ["
              << _msg->GetTypeName() << "] published there: it gets none of them\n";
    }
    catch (const std::exception& error)
    {
      gzerr << "A subscriber's callback on topic[" << _topic << "] threw: " << error.what() << "\n";
    }
    catch (...)
    {
      gzerr << "A subscriber's callback on topic[" << _topic << "] threw\n";
    }
  }
  return handled;
}

void Node::InsertLatchedMsg(const std::string& _topic, const std::string& _msg) { this->HandleData(_topic, _msg); }
void Node::InsertLatchedMsg(const std::string& _topic, MessagePtr _msg) { this->HandleMessage(_topic, _msg); }

std::string Node::GetMsgType(const std::string& _topic) const
{
  std::lock_guard<std::recursive_mutex> lock(this->incomingMutex);
  const auto found = this->callbacks.find(_topic);
  if (found == this->callbacks.end() || found->second.empty())
    return "";
  return found->second.front()->GetMsgType();
}

void Node::RemoveCallback(const std::string& _topic, unsigned int _id)
{
  bool none_left = false;
  {
    std::lock_guard<std::recursive_mutex> running(this->processIncomingMutex);
    std::lock_guard<std::recursive_mutex> lock(this->incomingMutex);
    const auto found = this->callbacks.find(_topic);
    if (found == this->callbacks.end())
      return;
    found->second.remove_if([_id](const CallbackHelperPtr& helper) { return helper->GetId() == _id; });
    if (found->second.empty())
    {
      this->callbacks.erase(found);
      none_left = true;
    }
  }
  if (none_left)
    TopicManager::Instance()->Unsubscribe(_topic, shared_from_this());
}
}  // namespace transport
}  // namespace gazebo
