// Gazebo's events: an EventT holds its subscribers' callbacks; Connect returns the ConnectionPtr
// that keeps one connected (resetting or destroying the last copy disconnects it, as a plugin
// does by resetting its member); calling the event calls each subscriber in the order connected.
// A subscriber may connect or disconnect others, or itself, from its callback.
#pragma once

#include <functional>
#include <map>
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
  bool Signaled() const { return signaled_; }
  void SetSignaled(bool signaled) { signaled_ = signaled; }

private:
  bool signaled_ = false;
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

using ConnectionPtr = std::shared_ptr<Connection>;

template <typename T>
class EventT
{
public:
  EventT() : state_(std::make_shared<State>()) {}

  ConnectionPtr Connect(const std::function<T>& subscriber)
  {
    std::lock_guard<std::recursive_mutex> lock(state_->mutex);
    const int id = state_->next_id++;
    state_->subscribers.emplace(id, std::make_shared<std::function<T>>(subscriber));
    return std::make_shared<Connection>(state_, id);
  }

  unsigned int ConnectionCount() const
  {
    std::lock_guard<std::recursive_mutex> lock(state_->mutex);
    return static_cast<unsigned int>(state_->subscribers.size());
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
    std::vector<std::pair<int, std::shared_ptr<std::function<T>>>> called;
    {
      std::lock_guard<std::recursive_mutex> lock(state_->mutex);
      state_->SetSignaled(true);
      called.assign(state_->subscribers.begin(), state_->subscribers.end());
    }
    for (auto& subscriber : called)
    {
      {
        std::lock_guard<std::recursive_mutex> lock(state_->mutex);
        if (!state_->subscribers.count(subscriber.first))
          continue;
      }
      (*subscriber.second)(args...);
    }
  }

private:
  struct State : Event
  {
    void Disconnect(int id) override
    {
      std::lock_guard<std::recursive_mutex> lock(mutex);
      subscribers.erase(id);
    }
    mutable std::recursive_mutex mutex;
    std::map<int, std::shared_ptr<std::function<T>>> subscribers;
    int next_id = 0;
  };
  std::shared_ptr<State> state_;
};
}  // namespace event
}  // namespace gazebo
