// Where the node's messages leave for ROS. roscpp's publish serializes a message and writes it to
// every subscriber's socket on the calling thread, waking roscpp's poll thread and the subscriber
// on the way: done on the simulation thread, that is time the world does not step. With publishing
// threads (~publishing_threads, default 1) the simulation thread builds each message, queues it
// here, and a publishing thread does the rest on the machine's other core.
//
// The simulation is the same with any number of publishing threads: a message is built on the
// simulation thread from what the step computed and is never read back; the threads only hand it to
// roscpp. A subscriber's own pace never stalls the world: roscpp's publish does not wait for it (it
// keeps each subscriber's queue_size newest messages). Only a publishing thread starved of CPU can
// fall kCapacity messages behind; the simulation thread then waits for it, as it would have
// published those messages itself.
//
// Order: one publisher's messages leave in the order queued (each publisher is served by one
// thread, picked by its address); with one publishing thread, all messages do.
#pragma once

#include <chrono>
#include <condition_variable>
#include <deque>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

#include <boost/make_shared.hpp>
#include <boost/shared_ptr.hpp>
#include <ros/ros.h>

namespace bullet_plant
{
class Outbox
{
public:
  // `threads` 0: every message is published at once, on the thread that queues it.
  explicit Outbox(unsigned threads);
  // Publishes what is queued, then stops the threads.
  ~Outbox();
  Outbox(const Outbox&) = delete;
  Outbox& operator=(const Outbox&) = delete;

  unsigned threads() const { return static_cast<unsigned>(lanes_.size()); }

  // On the simulation thread: `message` published on `publisher` (a publisher that outlives the
  // call; its address picks its thread). An invalid publisher (none advertised) is skipped.
  template <class Msg>
  void publish(const ros::Publisher& publisher, Msg message);

  // After each step: what was queued goes to the threads once there is a batch of it or it has
  // waited kLatency; a hand-over per step would wake a thread a thousand times a second.
  void endOfStep();
  // Before the simulation thread sleeps or waits (pacing, paused): everything queued goes now.
  void handOver();

  // How long a message may wait on the simulation thread before it goes to a publishing thread,
  // and how many make a batch that goes at once.
  static constexpr std::chrono::microseconds kLatency{1000};
  static constexpr size_t kBatch = 64;
  // Messages a publishing thread may have waiting before the simulation thread waits for it.
  static constexpr size_t kCapacity = 16384;

private:
  struct Item
  {
    ros::Publisher publisher;
    boost::shared_ptr<void> message;
    void (*send)(const ros::Publisher&, const boost::shared_ptr<void>&);
  };
  template <class Msg>
  static void sendAs(const ros::Publisher& publisher, const boost::shared_ptr<void>& message)
  {
    publisher.publish(boost::static_pointer_cast<Msg>(message));
  }
  // One publishing thread and what it has to publish.
  struct Lane
  {
    std::vector<Item> pending;  // queued by the simulation thread, not yet handed over
    std::mutex mutex;
    std::condition_variable wake, space;
    std::vector<Item> queue;  // handed over, guarded by mutex
    bool stop = false;
    std::thread thread;
  };
  void serve(Lane& lane);
  Lane& laneOf(const ros::Publisher& publisher);

  std::vector<std::unique_ptr<Lane>> lanes_;
  size_t pending_ = 0;
  std::chrono::steady_clock::time_point oldest_pending_;
};

template <class Msg>
void Outbox::publish(const ros::Publisher& publisher, Msg message)
{
  if (!publisher)
    return;
  if (lanes_.empty())
  {
    publisher.publish(message);
    return;
  }
  if (pending_++ == 0)
    oldest_pending_ = std::chrono::steady_clock::now();
  laneOf(publisher).pending.push_back(Item{publisher, boost::make_shared<Msg>(std::move(message)), &sendAs<Msg>});
}

}  // namespace bullet_plant
