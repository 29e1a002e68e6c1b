// transport::CallbackHelper and RawCallbackHelper (gazebo/transport/CallbackHelper.hh).
#include "gazebo/transport/CallbackHelper.hh"

#include <atomic>

namespace gazebo
{
namespace transport
{
namespace
{
std::atomic<unsigned int> next_callback_id{ 1 };  // 0 is "every callback" in Node::HandleMessage
}

CallbackHelper::CallbackHelper(bool _latching) : latching(_latching), id(next_callback_id++) {}
CallbackHelper::~CallbackHelper() = default;
bool CallbackHelper::GetLatching() const { return this->latching; }
void CallbackHelper::SetLatching(bool _latch) { this->latching = _latch; }
unsigned int CallbackHelper::GetId() const { return this->id; }

RawCallbackHelper::RawCallbackHelper(const boost::function<void(const std::string&)>& _cb) : callback(_cb) {}
std::string RawCallbackHelper::GetMsgType() const { return ""; }

bool RawCallbackHelper::HandleData(const std::string& _newdata)
{
  this->callback(_newdata);
  return true;
}

bool RawCallbackHelper::HandleMessage(MessagePtr _newMsg)
{
  if (!_newMsg)
    return false;
  std::string data;
  if (!_newMsg->SerializeToString(&data))
    return false;
  this->callback(data);
  return true;
}

bool RawCallbackHelper::IsLocal() const { return true; }
}  // namespace transport
}  // namespace gazebo
