#include "outbox.h"

#include <iterator>

namespace bullet_plant
{
constexpr std::chrono::microseconds Outbox::kLatency;
constexpr size_t Outbox::kBatch;
constexpr size_t Outbox::kCapacity;

Outbox::Outbox(unsigned threads)
{
  for (unsigned i = 0; i < threads; ++i)
    lanes_.emplace_back(new Lane);
  for (std::unique_ptr<Lane>& lane : lanes_)
  {
    Lane* served = lane.get();
    lane->thread = std::thread([this, served] { serve(*served); });
  }
}

Outbox::~Outbox()
{
  handOver();
  for (std::unique_ptr<Lane>& lane : lanes_)
  {
    {
      std::lock_guard<std::mutex> lock(lane->mutex);
      lane->stop = true;
    }
    lane->wake.notify_one();
    lane->thread.join();
  }
}

Outbox::Lane& Outbox::laneOf(const ros::Publisher& publisher)
{
  // a publisher's address is the same for every message it sends: its messages keep their order
  return *lanes_[(reinterpret_cast<uintptr_t>(&publisher) / alignof(ros::Publisher)) % lanes_.size()];
}

void Outbox::endOfStep()
{
  if (pending_ >= kBatch || (pending_ > 0 && std::chrono::steady_clock::now() - oldest_pending_ >= kLatency))
    handOver();
}

void Outbox::handOver()
{
  if (pending_ == 0)
    return;
  pending_ = 0;
  for (std::unique_ptr<Lane>& lane : lanes_)
  {
    if (lane->pending.empty())
      continue;
    {
      std::unique_lock<std::mutex> lock(lane->mutex);
      lane->space.wait(lock, [&] { return lane->queue.size() < kCapacity; });
      if (lane->queue.empty())
        lane->queue.swap(lane->pending);  // the vectors' capacity goes round: no allocation
      else
      {
        lane->queue.insert(lane->queue.end(), std::make_move_iterator(lane->pending.begin()),
                           std::make_move_iterator(lane->pending.end()));
        lane->pending.clear();
      }
    }
    lane->wake.notify_one();
  }
}

void Outbox::serve(Lane& lane)
{
  std::vector<Item> batch;
  std::unique_lock<std::mutex> lock(lane.mutex);
  for (;;)
  {
    lane.wake.wait(lock, [&] { return lane.stop || !lane.queue.empty(); });
    if (lane.queue.empty())
      return;  // stopped, everything published
    batch.swap(lane.queue);
    lock.unlock();
    lane.space.notify_one();
    for (const Item& item : batch)
      item.send(item.publisher, item.message);
    batch.clear();
    lock.lock();
  }
}

}  // namespace bullet_plant
