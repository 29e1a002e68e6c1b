// transport::CallbackHelper, CallbackHelperT<M> and RawCallbackHelper, as Gazebo 11's: what a Node
// keeps for each subscription, and how a message reaches the subscriber's function (a copy of the
// message's own type, or its serialized bytes).
#pragma once

#include <string>

#include <boost/function.hpp>
#include <boost/make_shared.hpp>
#include <boost/shared_ptr.hpp>

#include "gazebo/transport/TransportTypes.hh"

namespace gazebo
{
namespace transport
{
class GZ_TRANSPORT_VISIBLE CallbackHelper
{
public:
  explicit CallbackHelper(bool _latching = false);
  virtual ~CallbackHelper();

  // The full name of the message type it takes ("gazebo.msgs.GzString"); "" takes any (raw bytes).
  virtual std::string GetMsgType() const = 0;
  // The serialized bytes of a message: false where they do not parse as its type.
  virtual bool HandleData(const std::string& _newdata) = 0;
  // A message in the process: false where it is not of the type the subscriber takes.
  virtual bool HandleMessage(MessagePtr _newMsg) = 0;
  // Messages inside the process (always, here: nothing leaves the process).
  virtual bool IsLocal() const = 0;

  bool GetLatching() const;
  void SetLatching(bool _latch);
  unsigned int GetId() const;

protected:
  bool latching;

private:
  unsigned int id;
};

template <class M>
class CallbackHelperT : public CallbackHelper
{
public:
  CallbackHelperT(const boost::function<void(const boost::shared_ptr<M const>&)>& _cb, bool _latching = false)
    : CallbackHelper(_latching), callback(_cb)
  {
  }

  std::string GetMsgType() const override { return M::descriptor()->full_name(); }

  bool HandleData(const std::string& _newdata) override
  {
    this->SetLatching(false);
    boost::shared_ptr<M> message = boost::make_shared<M>();
    if (!message->ParseFromString(_newdata))
      return false;
    this->callback(message);
    return true;
  }

  bool HandleMessage(MessagePtr _newMsg) override
  {
    this->SetLatching(false);
    if (!_newMsg || _newMsg->GetDescriptor() != M::descriptor())
      return false;
    // The published message itself, read-only (the callback takes it const), shared by every
    // subscriber: Gazebo's gives each its own copy, which a const message makes no different to
    // read; a sensor's scan then costs one copy (the publisher's) however many listen.
    if (boost::shared_ptr<M const> shared = boost::dynamic_pointer_cast<M const>(_newMsg))
    {
      this->callback(shared);
      return true;
    }
    boost::shared_ptr<M> message = boost::make_shared<M>();
    message->CopyFrom(*_newMsg);
    this->callback(message);
    return true;
  }

  bool IsLocal() const override { return true; }

private:
  boost::function<void(const boost::shared_ptr<M const>&)> callback;
};

class GZ_TRANSPORT_VISIBLE RawCallbackHelper : public CallbackHelper
{
public:
  explicit RawCallbackHelper(const boost::function<void(const std::string&)>& _cb);
  std::string GetMsgType() const override;
  bool HandleData(const std::string& _newdata) override;
  bool HandleMessage(MessagePtr _newMsg) override;
  bool IsLocal() const override;

private:
  boost::function<void(const std::string&)> callback;
};
}  // namespace transport
}  // namespace gazebo
