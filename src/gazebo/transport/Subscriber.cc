// transport::Subscriber (gazebo/transport/Subscriber.hh).
#include "gazebo/transport/Subscriber.hh"

#include "gazebo/transport/Node.hh"

namespace gazebo
{
namespace transport
{
Subscriber::Subscriber(const std::string& _topic, NodePtr _node) : topic(_topic), node(_node) {}
Subscriber::~Subscriber() { this->Unsubscribe(); }
std::string Subscriber::GetTopic() const { return this->topic; }
void Subscriber::SetCallbackId(unsigned int _id) { this->callbackId = _id; }
unsigned int Subscriber::GetCallbackId() const { return this->callbackId; }

void Subscriber::Unsubscribe() const
{
  if (NodePtr alive = this->node.lock())
    alive->RemoveCallback(this->topic, this->callbackId);
}
}  // namespace transport
}  // namespace gazebo
