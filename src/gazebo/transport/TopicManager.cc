// transport::TopicManager (gazebo/transport/TopicManager.hh) and the transport functions
// (gazebo/transport/TransportIface.hh).
#include "gazebo/transport/TopicManager.hh"

#include <algorithm>

#include "gazebo/common/Console.hh"
#include "gazebo/common/Exception.hh"
#include "gazebo/transport/Node.hh"
#include "gazebo/transport/Publisher.hh"
#include "gazebo/transport/TransportIface.hh"

namespace gazebo
{
namespace transport
{
namespace
{
// Drops the handles whose object is gone, and those `also` says (given the object, alive).
template <typename T, typename Also>
void dropHandles(std::vector<boost::weak_ptr<T>>& handles, Also also)
{
  handles.erase(std::remove_if(handles.begin(), handles.end(),
                               [&](const boost::weak_ptr<T>& handle) {
                                 const boost::shared_ptr<T> alive = handle.lock();
                                 return !alive || also(alive);
                               }),
                handles.end());
}

template <typename T>
void dropExpired(std::vector<boost::weak_ptr<T>>& handles)
{
  dropHandles(handles, [](const boost::shared_ptr<T>&) { return false; });
}
}  // namespace

TopicManager* TopicManager::Instance()
{
  static TopicManager manager;
  return &manager;
}

TopicManager::TopicManager() = default;

TopicManager::~TopicManager() { this->Fini(); }

void TopicManager::Fini()
{
  {
    std::lock_guard<std::mutex> lock(this->mutex);
    this->stopping = true;
  }
  this->queued.notify_all();
  if (this->thread.joinable() && this->thread.get_id() != std::this_thread::get_id())
    this->thread.join();
}

PublisherPtr TopicManager::Advertise(const std::string& _topic, const std::string& _msgType,
                                     unsigned int _queueLimit, double _hzRate)
{
  std::string existing;
  {
    std::lock_guard<std::mutex> lock(this->mutex);
    Topic& topic = this->topics[_topic];
    dropExpired(topic.publishers);
    if (!topic.publishers.empty() && topic.msgType != _msgType)
      existing = topic.msgType;
    else
      topic.msgType = _msgType;
  }
  if (!existing.empty())
    gzthrow("Advertising on topic[" << _topic << "] with message type[" << _msgType
                                    << "], which is already advertised with message type[" << existing << "]");
  PublisherPtr publisher(new Publisher(_topic, _msgType, _queueLimit, _hzRate));
  std::lock_guard<std::mutex> lock(this->mutex);
  this->topics[_topic].publishers.push_back(publisher);
  return publisher;
}

void TopicManager::Unadvertise(const std::string& _topic, uint32_t _publisherId)
{
  std::lock_guard<std::mutex> lock(this->mutex);
  const auto found = this->topics.find(_topic);
  if (found == this->topics.end())
    return;
  dropHandles(found->second.publishers,
              [_publisherId](const PublisherPtr& publisher) { return publisher->Id() == _publisherId; });
  this->forgetIfUnused(found);
}

void TopicManager::Subscribe(const std::string& _topic, const NodePtr& _node, unsigned int _callbackId,
                             bool _latching)
{
  std::vector<Delivery> latched;
  {
    std::lock_guard<std::mutex> lock(this->mutex);
    Topic& topic = this->topics[_topic];
    dropExpired(topic.subscribers);
    const bool already = std::any_of(topic.subscribers.begin(), topic.subscribers.end(),
                                     [&](const boost::weak_ptr<Node>& node) { return node.lock() == _node; });
    if (!already)
      topic.subscribers.push_back(_node);
    if (_latching)
      for (const auto& handle : topic.publishers)
        if (const PublisherPtr publisher = handle.lock())
          if (MessagePtr last = publisher->GetPrevMsgPtr())
            latched.push_back(Delivery{ 0, _topic, last, boost::weak_ptr<Publisher>(), { _node }, _callbackId });
  }
  for (Delivery& delivery : latched)
    this->enqueue(std::move(delivery));
}

void TopicManager::Unsubscribe(const std::string& _topic, const NodePtr& _node)
{
  std::lock_guard<std::mutex> lock(this->mutex);
  const auto found = this->topics.find(_topic);
  if (found == this->topics.end())
    return;
  dropHandles(found->second.subscribers, [&](const NodePtr& node) { return node == _node; });
  this->forgetIfUnused(found);
}

void TopicManager::forgetIfUnused(std::map<std::string, Topic>::iterator _topic)
{
  // a topic nobody publishes on or listens to any more goes, as Gazebo's publication does: models
  // spawned under new names would otherwise leave their sensors' topics behind for good
  dropExpired(_topic->second.publishers);
  dropExpired(_topic->second.subscribers);
  if (_topic->second.publishers.empty() && _topic->second.subscribers.empty())
    this->topics.erase(_topic);
}

uint64_t TopicManager::Publish(const std::string& _topic, MessagePtr _message, const PublisherPtr& _publisher)
{
  std::vector<boost::weak_ptr<Node>> receivers;
  {
    std::lock_guard<std::mutex> lock(this->mutex);
    const auto found = this->topics.find(_topic);
    if (found != this->topics.end())
      receivers = found->second.subscribers;
  }
  return this->enqueue(Delivery{ 0, _topic, std::move(_message), _publisher, std::move(receivers), 0 });
}

uint64_t TopicManager::enqueue(Delivery delivery)
{
  uint64_t sequence;
  {
    std::lock_guard<std::mutex> lock(this->mutex);
    sequence = delivery.sequence = ++this->published;
    this->deliveries.push_back(std::move(delivery));
    if (!this->thread.joinable() && !this->stopping)
      this->thread = std::thread(&TopicManager::run, this);
  }
  this->queued.notify_one();
  return sequence;
}

void TopicManager::run()
{
  std::unique_lock<std::mutex> lock(this->mutex);
  for (;;)
  {
    this->queued.wait(lock, [this] { return this->stopping || !this->deliveries.empty(); });
    if (this->deliveries.empty())
      return;  // stopping, and everything handed over
    Delivery delivery = std::move(this->deliveries.front());
    this->deliveries.pop_front();
    std::vector<NodePtr> receivers;
    for (const auto& handle : delivery.receivers)
      if (NodePtr node = handle.lock())
        receivers.push_back(node);
    lock.unlock();
    for (const NodePtr& node : receivers)
      node->HandleMessage(delivery.topic, delivery.message, delivery.callbackId);
    if (const PublisherPtr publisher = delivery.publisher.lock())
      publisher->OnDelivered();
    receivers.clear();  // a node whose last handle this was goes here, outside the lock
    lock.lock();
    this->handedOver = delivery.sequence;
    this->delivered.notify_all();
  }
}

void TopicManager::WaitDelivered(uint64_t _sequence)
{
  if (std::this_thread::get_id() == this->thread.get_id())
    return;
  std::unique_lock<std::mutex> lock(this->mutex);
  this->delivered.wait(lock, [&] { return this->handedOver >= _sequence || this->stopping; });
}

void TopicManager::WaitForAll()
{
  uint64_t last;
  {
    std::lock_guard<std::mutex> lock(this->mutex);
    last = this->published;
  }
  this->WaitDelivered(last);
}

bool TopicManager::HasSubscribers(const std::string& _topic) const
{
  std::lock_guard<std::mutex> lock(this->mutex);
  const auto found = this->topics.find(_topic);
  return found != this->topics.end() &&
         std::any_of(found->second.subscribers.begin(), found->second.subscribers.end(),
                     [](const boost::weak_ptr<Node>& node) { return !node.expired(); });
}

std::string TopicManager::GetMsgType(const std::string& _topic) const
{
  std::lock_guard<std::mutex> lock(this->mutex);
  const auto found = this->topics.find(_topic);
  return found == this->topics.end() ? "" : found->second.msgType;
}

void TopicManager::RegisterTopicNamespace(const std::string& _name)
{
  std::lock_guard<std::mutex> lock(this->mutex);
  if (std::find(this->namespaces.begin(), this->namespaces.end(), _name) == this->namespaces.end())
    this->namespaces.push_back(_name);
}

void TopicManager::GetTopicNamespaces(std::list<std::string>& _namespaces) const
{
  std::lock_guard<std::mutex> lock(this->mutex);
  _namespaces = this->namespaces;
}

void TopicManager::ProcessNodes(bool) {}

bool init(const std::string&, unsigned int, uint32_t) { return true; }
void run() {}
bool is_stopped() { return false; }
void stop() {}
void fini() { TopicManager::Instance()->WaitForAll(); }
void clear_buffers() {}

bool get_topic_namespaces(std::list<std::string>& _namespaces)
{
  TopicManager::Instance()->GetTopicNamespaces(_namespaces);
  return !_namespaces.empty();
}
}  // namespace transport
}  // namespace gazebo
