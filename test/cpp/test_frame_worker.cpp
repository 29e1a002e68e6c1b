// frame_worker.cpp: jobs run one after another in the order given, on a thread other than the
// caller's; done and wait by ticket; the worker's end runs every job queued.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <thread>
#include <vector>

#include "rendering/frame_worker.h"

using namespace bullet_plant;

TEST(FrameWorker, JobsRunInTheirOrderOnAThreadOfTheirOwn)
{
  FrameWorker worker;
  std::vector<int> ran;
  std::thread::id where;
  std::atomic<bool> release{false};
  // the first job holds the worker until released: the later ones queue behind it
  const uint64_t first = worker.submit([&] {
    where = std::this_thread::get_id();
    while (!release)
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    ran.push_back(0);
  });
  std::vector<uint64_t> tickets;
  for (int k = 1; k <= 5; ++k)
    tickets.push_back(worker.submit([&ran, k] { ran.push_back(k); }));
  EXPECT_FALSE(worker.done(first));
  EXPECT_FALSE(worker.done(tickets.back()));
  release = true;
  worker.wait(tickets[2]);
  EXPECT_TRUE(worker.done(first));
  EXPECT_TRUE(worker.done(tickets[2]));
  worker.waitAll();
  EXPECT_EQ(ran, (std::vector<int>{0, 1, 2, 3, 4, 5}));
  EXPECT_NE(where, std::this_thread::get_id());
}

TEST(FrameWorker, ItsEndRunsEveryJobQueued)
{
  std::atomic<int> count{0};
  {
    FrameWorker worker;
    for (int k = 0; k < 100; ++k)
      worker.submit([&count] { ++count; });
  }
  EXPECT_EQ(count, 100);
}
