#include "rendering/ray_threads.h"

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

namespace bullet_plant
{
namespace
{
// Runs tasks 0..n-1 on the calling thread and its workers; returns when all are done.
class RayThreadPool
{
public:
  explicit RayThreadPool(int threads)
  {
    for (int i = 1; i < threads; ++i)
      workers_.emplace_back([this] { work(); });
  }
  ~RayThreadPool()
  {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      stop_ = true;
    }
    wake_.notify_all();
    for (std::thread& t : workers_)
      t.join();
  }
  int threads() const { return int(workers_.size()) + 1; }

  void run(int tasks, const std::function<void(int)>& task)
  {
    if (workers_.empty() || tasks <= 1)
    {
      for (int i = 0; i < tasks; ++i)
        task(i);
      return;
    }
    std::unique_lock<std::mutex> lock(mutex_);
    job_ = &task;
    tasks_ = tasks;
    next_ = 0;
    busy_ = int(workers_.size());
    ++generation_;
    lock.unlock();
    wake_.notify_all();
    drain();
    lock.lock();
    done_.wait(lock, [this] { return busy_ == 0; });
    job_ = nullptr;
  }

private:
  void drain()
  {
    for (int i = next_++; i < tasks_; i = next_++)
      (*job_)(i);
  }
  void work()
  {
    uint64_t seen = 0;
    std::unique_lock<std::mutex> lock(mutex_);
    for (;;)
    {
      wake_.wait(lock, [&] { return stop_ || generation_ != seen; });
      if (stop_)
        return;
      seen = generation_;
      lock.unlock();
      drain();
      lock.lock();
      if (--busy_ == 0)
        done_.notify_one();
    }
  }

  std::vector<std::thread> workers_;
  std::mutex mutex_;
  std::condition_variable wake_, done_;
  const std::function<void(int)>* job_ = nullptr;
  int tasks_ = 0;
  std::atomic<int> next_{0};
  int busy_ = 0;
  uint64_t generation_ = 0;
  bool stop_ = false;
};

std::mutex pool_mutex;  // one job at a time; guards the pool's replacement too
std::unique_ptr<RayThreadPool> pool;
int requested_threads = 0;  // 0: the hardware's

RayThreadPool& threadPool()
{
  if (!pool)
  {
    int n = requested_threads > 0 ? requested_threads : int(std::thread::hardware_concurrency());
    pool.reset(new RayThreadPool(std::max(1, n)));
  }
  return *pool;
}

}  // namespace

void parallelTasks(int tasks, const std::function<void(int)>& task)
{
  std::lock_guard<std::mutex> lock(pool_mutex);
  threadPool().run(tasks, task);
}

void setRayThreads(int n)
{
  std::lock_guard<std::mutex> lock(pool_mutex);
  requested_threads = n;
  pool.reset();
}

int rayThreads()
{
  std::lock_guard<std::mutex> lock(pool_mutex);
  return threadPool().threads();
}

}  // namespace bullet_plant
