// Gazebo's events: an EventT holds its subscribers' callbacks; Connect returns the ConnectionPtr
// that keeps one connected (resetting or destroying the last copy disconnects it, as a plugin
// does by resetting its member); calling the event calls each subscriber in the order connected.
// A subscriber may connect or disconnect others, or itself, from its callback.
#pragma once

#include <atomic>
#include <functional>
#include <memory>
#include <mutex>
#include <utility>
#include <vector>

// As Gazebo's Event.hh: plugins bind their callbacks with boost::bind and its placeholders (_1 ...),
// which they find through this header, in the global namespace as Boost put them before 1.73
// (without the define, Boost 1.74 says it is deprecated in every file that includes it).
#ifndef BOOST_BIND_GLOBAL_PLACEHOLDERS
#define BOOST_BIND_GLOBAL_PLACEHOLDERS
#endif
#include <boost/bind.hpp>
#include <boost/function.hpp>

#include "gazebo/common/CommonTypes.hh"
#include "gazebo/util/system.hh"

namespace gazebo
{
namespace event
{
class GZ_COMMON_VISIBLE Event
{
public:
  virtual ~Event() = default;
  virtual void Disconnect(int id) = 0;
  bool Signaled() const { return signaled_.load(); }
  void SetSignaled(bool signaled) { signaled_.store(signaled); }

private:
  std::atomic<bool> signaled_{false};
};

// One subscription: disconnects it from its event when the last ConnectionPtr to it goes.
class GZ_COMMON_VISIBLE Connection
{
public:
  Connection(std::weak_ptr<Event> event, int id) : event_(std::move(event)), id_(id) {}
  ~Connection()
  {
    if (auto event = event_.lock())
      event->Disconnect(id_);
  }
  Connection(const Connection&) = delete;
  Connection& operator=(const Connection&) = delete;
  int Id() const { return id_; }

private:
  std::weak_ptr<Event> event_;
  int id_;
};

template <typename T>
class EventT
{
public:
  EventT() : state_(std::make_shared<State>()) {}

  ConnectionPtr Connect(const std::function<T>& subscriber)
  {
    std::lock_guard<std::mutex> lock(state_->mutex);
    const int id = state_->next_id++;
    auto subscribers = std::make_shared<Subscribers>(*state_->subscribers);
    subscribers->push_back(std::make_shared<Slot>(id, subscriber));
    state_->subscribers = std::move(subscribers);
    state_->count.fetch_add(1, std::memory_order_release);
    return std::make_shared<Connection>(state_, id);
  }

  unsigned int ConnectionCount() const
  {
    std::lock_guard<std::mutex> lock(state_->mutex);
    return static_cast<unsigned int>(state_->subscribers->size());
  }

  // Calls every subscriber connected when the call began and still connected when its turn comes.
  template <typename... Args>
  void operator()(Args&&... args)
  {
    Signal(std::forward<Args>(args)...);
  }

  template <typename... Args>
  void Signal(Args&&... args)
  {
    // The list as it is now (connecting or disconnecting makes a new one, so a call never copies
    // it: the plant signals worldUpdateBegin every step), each slot's flag read as its turn comes.
    state_->SetSignaled(true);
    if (state_->count.load(std::memory_order_acquire) == 0)
      return;  // most of the world's events, most steps: not even the lock
    std::shared_ptr<const Subscribers> called;
    {
      std::lock_guard<std::mutex> lock(state_->mutex);
      called = state_->subscribers;
    }
    for (const std::shared_ptr<Slot>& slot : *called)
      if (slot->connected.load(std::memory_order_acquire))
        slot->callback(args...);
  }

private:
  struct Slot
  {
    Slot(int slot_id, const std::function<T>& slot_callback) : id(slot_id), callback(slot_callback) {}
    const int id;
    const std::function<T> callback;
    std::atomic<bool> connected{true};
  };
  using Subscribers = std::vector<std::shared_ptr<Slot>>;

  struct State : Event
  {
    void Disconnect(int id) override
    {
      std::lock_guard<std::mutex> lock(mutex);
      auto remaining = std::make_shared<Subscribers>();
      for (const std::shared_ptr<Slot>& slot : *subscribers)
        if (slot->id == id)
        {
          slot->connected.store(false, std::memory_order_release);
          count.fetch_sub(1, std::memory_order_release);
        }
        else
          remaining->push_back(slot);
      subscribers = std::move(remaining);
    }
    mutable std::mutex mutex;  // guards the list's handle; no callback runs under it
    std::shared_ptr<const Subscribers> subscribers = std::make_shared<Subscribers>();
    std::atomic<int> count{0};  // the list's length, read without the lock
    int next_id = 0;
  };
  std::shared_ptr<State> state_;
};
}  // namespace event
}  // namespace gazebo
