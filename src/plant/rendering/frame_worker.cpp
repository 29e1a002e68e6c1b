#include "rendering/frame_worker.h"

namespace bullet_plant
{
FrameWorker::FrameWorker() : thread_([this] { run(); }) {}

FrameWorker::~FrameWorker()
{
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  queued_.notify_one();
  thread_.join();
}

uint64_t FrameWorker::submit(std::function<void()> job)
{
  uint64_t ticket;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    jobs_.push_back(std::move(job));
    ticket = ++submitted_;
  }
  queued_.notify_one();
  return ticket;
}

bool FrameWorker::done(uint64_t ticket) const
{
  std::lock_guard<std::mutex> lock(mutex_);
  return completed_ >= ticket;
}

void FrameWorker::wait(uint64_t ticket)
{
  std::unique_lock<std::mutex> lock(mutex_);
  finished_.wait(lock, [&] { return completed_ >= ticket; });
}

void FrameWorker::waitAll()
{
  std::unique_lock<std::mutex> lock(mutex_);
  finished_.wait(lock, [&] { return completed_ >= submitted_; });
}

void FrameWorker::run()
{
  std::unique_lock<std::mutex> lock(mutex_);
  for (;;)
  {
    queued_.wait(lock, [&] { return stopping_ || !jobs_.empty(); });
    if (jobs_.empty())
      return;  // stopping, every job run
    std::function<void()> job = std::move(jobs_.front());
    jobs_.pop_front();
    lock.unlock();
    job();
    lock.lock();
    ++completed_;
    finished_.notify_all();
  }
}

}  // namespace bullet_plant
