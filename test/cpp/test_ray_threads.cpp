// The sensors' ray threads (src/plant/rendering/ray_threads.cpp, a TBB arena): every task of a job runs
// once, for any number of threads and tasks, and concurrent callers each get all their tasks.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <mutex>
#include <set>
#include <thread>
#include <vector>

#include "rendering/ray_threads.h"

using namespace bullet_plant;

TEST(RayThreads, EveryTaskRunsOnceForAnyNumberOfThreadsAndTasks)
{
  for (int threads : {1, 2, 3, 8})
  {
    setRayThreads(threads);
    EXPECT_EQ(rayThreads(), threads);
    for (int tasks : {0, 1, 2, 5, 1000})
    {
      std::vector<std::atomic<int>> runs(static_cast<size_t>(tasks));
      parallelTasks(tasks, [&](int i) { ++runs[size_t(i)]; });
      for (int i = 0; i < tasks; ++i)
        EXPECT_EQ(runs[size_t(i)].load(), 1) << "task " << i << " of " << tasks << " on " << threads << " threads";
    }
  }
  setRayThreads(0);  // the hardware threads this process may run on (an affinity mask may allow fewer)
  EXPECT_GE(rayThreads(), 1);
  EXPECT_LE(rayThreads(), int(std::max(1u, std::thread::hardware_concurrency())));
}

TEST(RayThreads, ManyThreadsShareAJob)
{
  setRayThreads(4);
  std::mutex mutex;
  std::set<std::thread::id> ran_on;
  // Tasks that wait for each other a little, so that one thread cannot drain the job alone.
  std::atomic<int> started{0};
  parallelTasks(8, [&](int) {
    ++started;
    const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(10);  // a loaded machine
    while (started < 2 && std::chrono::steady_clock::now() < give_up)
      std::this_thread::yield();
    std::lock_guard<std::mutex> lock(mutex);
    ran_on.insert(std::this_thread::get_id());
  });
  EXPECT_GT(ran_on.size(), 1u);
  setRayThreads(0);
}

TEST(RayThreads, ConcurrentCallersEachGetAllTheirTasks)
{
  setRayThreads(3);
  constexpr int kCallers = 4, kTasks = 300;
  std::vector<std::vector<std::atomic<int>>> runs(kCallers);
  for (auto& r : runs)
    r = std::vector<std::atomic<int>>(kTasks);
  std::vector<std::thread> callers;
  for (int c = 0; c < kCallers; ++c)
    callers.emplace_back([&, c] {
      for (int round = 0; round < 20; ++round)
        parallelTasks(kTasks, [&](int i) { ++runs[size_t(c)][size_t(i)]; });
    });
  for (std::thread& t : callers)
    t.join();
  for (int c = 0; c < kCallers; ++c)
    for (int i = 0; i < kTasks; ++i)
      EXPECT_EQ(runs[size_t(c)][size_t(i)].load(), 20) << "caller " << c << ", task " << i;
  setRayThreads(0);
}
