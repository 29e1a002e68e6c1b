// A thread that renders camera frames while the simulation goes on: World hands it each frame as
// a job (the draws' poses copied at the frame's time, so the frame is that of its own time), and
// the camera collects the frame when it is done. Jobs run one after another, in the order given.
#pragma once

#include <condition_variable>
#include <cstdint>
#include <deque>
#include <functional>
#include <mutex>
#include <thread>

namespace bullet_plant
{
class FrameWorker
{
public:
  FrameWorker();
  // Runs the jobs given so far, then stops.
  ~FrameWorker();
  FrameWorker(const FrameWorker&) = delete;
  FrameWorker& operator=(const FrameWorker&) = delete;

  // Queues `job`; its ticket for done and wait. A job must not throw.
  uint64_t submit(std::function<void()> job);
  bool done(uint64_t ticket) const;
  void wait(uint64_t ticket);
  void waitAll();

private:
  void run();

  mutable std::mutex mutex_;
  std::condition_variable queued_, finished_;
  std::deque<std::function<void()>> jobs_;
  uint64_t submitted_ = 0, completed_ = 0;
  bool stopping_ = false;
  std::thread thread_;  // last: it starts once the rest is ready
};

}  // namespace bullet_plant
