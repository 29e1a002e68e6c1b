// transport::Publisher (gazebo/transport/Publisher.hh).
#include "gazebo/transport/Publisher.hh"

#include <atomic>
#include <chrono>
#include <thread>

#include "gazebo/common/Console.hh"
#include "gazebo/common/Exception.hh"
#include "gazebo/transport/Node.hh"
#include "gazebo/transport/TopicManager.hh"

namespace gazebo
{
namespace transport
{
namespace
{
std::atomic<uint32_t> next_publisher_id{ 1 };
}

Publisher::Publisher(const std::string& _topic, const std::string& _msgType, unsigned int _limit, double _hzRate)
  : topic(_topic)
  , msgType(_msgType)
  , queueLimit(_limit)
  , updatePeriod(_hzRate > 0 ? 1.0 / _hzRate : 0.0)
  , id(next_publisher_id++)
{
}

Publisher::~Publisher() { this->Fini(); }

void Publisher::Fini()
{
  if (!this->topic.empty())
    TopicManager::Instance()->Unadvertise(this->topic, this->id);
}

bool Publisher::HasConnections() const { return TopicManager::Instance()->HasSubscribers(this->topic); }

void Publisher::WaitForConnection() const
{
  while (!this->HasConnections())
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
}

bool Publisher::WaitForConnection(const common::Time& _timeout) const
{
  if (_timeout < common::Time::Zero)
  {
    this->WaitForConnection();
    return true;
  }
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::nanoseconds(
      static_cast<int64_t>(_timeout.sec) * 1000000000 + _timeout.nsec);
  while (!this->HasConnections())
  {
    if (std::chrono::steady_clock::now() >= deadline)
      return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return true;
}

void Publisher::SetPublication(PublicationPtr) {}

void Publisher::PublishImpl(const google::protobuf::Message& _message, bool _block)
{
  if (_message.GetDescriptor()->full_name() != this->msgType)
    gzthrow("Invalid message type[" << _message.GetTypeName() << "] published on topic[" << this->topic
                                    << "], which was advertised with type[" << this->msgType << "]");
  if (!_message.IsInitialized())
  {
    gzerr << "Publishing an uninitialized message on topic[" << this->topic << "]. Required field ["
          << _message.InitializationErrorString() << "] missing.\n";
    return;
  }
  MessagePtr copy(_message.New());
  copy->CopyFrom(_message);
  this->Send(std::move(copy), _block);
}

void Publisher::PublishOwned(MessagePtr _message)
{
  if (_message->GetDescriptor()->full_name() != this->msgType)
    gzthrow("Invalid message type[" << _message->GetTypeName() << "] published on topic[" << this->topic
                                    << "], which was advertised with type[" << this->msgType << "]");
  this->Send(std::move(_message), false);
}

void Publisher::Send(MessagePtr copy, bool _block)
{
  {
    std::lock_guard<std::mutex> lock(this->mutex);
    // Gazebo's rate limit, by the wall clock as Gazebo's.
    if (this->updatePeriod > 0)
    {
      const common::Time now = common::Time::GetWallTime();
      if (this->prevPublishTime != common::Time::Zero && (now - this->prevPublishTime).Double() < this->updatePeriod)
        return;
      this->prevPublishTime = now;
    }
    this->prevMsg = copy;
    if (this->outgoing >= this->queueLimit)
    {
      if (!this->queueLimitWarned)
        gzwarn << "Queue limit reached for topic " << this->topic << ", dropping message (its subscribers take "
               << "them slower than they come)\n";
      this->queueLimitWarned = true;
      return;
    }
    ++this->outgoing;
  }
  // A publisher made with `new` rather than by Advertise has no handle: its messages go uncounted.
  const PublisherPtr self = this->weak_from_this().lock();
  const uint64_t sequence = TopicManager::Instance()->Publish(this->topic, copy, self);
  if (!self)
    this->OnDelivered();
  if (_block)
    TopicManager::Instance()->WaitDelivered(sequence);
}

void Publisher::OnDelivered()
{
  std::lock_guard<std::mutex> lock(this->mutex);
  if (this->outgoing > 0)
    --this->outgoing;
}

unsigned int Publisher::GetOutgoingCount() const
{
  std::lock_guard<std::mutex> lock(this->mutex);
  return this->outgoing;
}

std::string Publisher::GetTopic() const { return this->topic; }
std::string Publisher::GetMsgType() const { return this->msgType; }
void Publisher::SendMessage() {}
void Publisher::SetNode(NodePtr) {}
uint32_t Publisher::Id() const { return this->id; }

std::string Publisher::GetPrevMsg() const
{
  std::lock_guard<std::mutex> lock(this->mutex);
  std::string data;
  if (this->prevMsg)
    this->prevMsg->SerializeToString(&data);
  return data;
}

MessagePtr Publisher::GetPrevMsgPtr() const
{
  std::lock_guard<std::mutex> lock(this->mutex);
  return this->prevMsg;
}
}  // namespace transport
}  // namespace gazebo
